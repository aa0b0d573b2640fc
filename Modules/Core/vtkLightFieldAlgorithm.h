/**
 * @class   vtkLightFieldAlgorithm
 * @brief   superclass of algorithms that produce a vtkLightField
 *
 * Like vtkImageAlgorithm or vtkPolyDataAlgorithm for their types:
 * vtkLightFieldAlgorithm declares a vtkLightField on every output port,
 * creates it in RequestDataObject (VTK 9.1 cannot instantiate a class
 * outside VTK from its type name) and dispatches the pipeline passes to
 * RequestInformation, RequestUpdateExtent and RequestData, which subclasses
 * override. By default it has no input and one output.
 *
 * @sa vtkLightField
 */
#ifndef vtkLightFieldAlgorithm_h
#define vtkLightFieldAlgorithm_h

#include "lfdCoreModule.h" // For export macro
#include "vtkAlgorithm.h"

class vtkLightField;

class LFDCORE_EXPORT vtkLightFieldAlgorithm : public vtkAlgorithm
{
public:
  static vtkLightFieldAlgorithm* New();
  vtkTypeMacro(vtkLightFieldAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The light field on an output port (port 0 by default).
   */
  vtkLightField* GetOutput();
  vtkLightField* GetOutput(int port);
  ///@}

  /**
   * Dispatches the pipeline requests to the Request* methods below.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkLightFieldAlgorithm();
  ~vtkLightFieldAlgorithm() override;

  /**
   * Puts a vtkLightField on every output port that does not hold one.
   */
  virtual int RequestDataObject(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  ///@{
  /**
   * The pipeline passes; the defaults do nothing and succeed.
   */
  virtual int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);
  virtual int RequestUpdateExtent(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);
  virtual int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);
  ///@}

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkLightFieldAlgorithm(const vtkLightFieldAlgorithm&) = delete;
  void operator=(const vtkLightFieldAlgorithm&) = delete;
};

#endif
