/**
 * @class   vtkDeformationCageAlgorithm
 * @brief   superclass of algorithms that produce a vtkDeformationCage
 *
 * Like vtkUnstructuredGridAlgorithm for its type: one input and one output
 * port by default, a vtkDeformationCage on the output created in
 * RequestDataObject (VTK 9.1 cannot instantiate a class outside VTK from its
 * type name), and the data pass dispatched to RequestData, which subclasses
 * override.
 *
 * @sa vtkDeformationCage vtkPartCageSource vtkCagePoseFilter
 */
#ifndef vtkDeformationCageAlgorithm_h
#define vtkDeformationCageAlgorithm_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkAlgorithm.h"

class vtkDeformationCage;

class LFDDEFORMATION_EXPORT vtkDeformationCageAlgorithm : public vtkAlgorithm
{
public:
  vtkTypeMacro(vtkDeformationCageAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Sets the data on input port 0.
   */
  void SetInputData(vtkDataObject* input);

  /**
   * The cage on output port 0.
   */
  vtkDeformationCage* GetOutput();

  /**
   * Dispatches REQUEST_DATA_OBJECT and REQUEST_DATA; a C++ exception thrown
   * by them is caught and reported as an error (error code UnknownError).
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkDeformationCageAlgorithm();
  ~vtkDeformationCageAlgorithm() override;

  /**
   * Puts a vtkDeformationCage on the output when it holds none.
   */
  virtual int RequestDataObject(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  /**
   * The data pass; the default does nothing and succeeds.
   */
  virtual int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  int FillOutputPortInformation(int port, vtkInformation* info) override;

private:
  vtkDeformationCageAlgorithm(const vtkDeformationCageAlgorithm&) = delete;
  void operator=(const vtkDeformationCageAlgorithm&) = delete;
};

#endif
