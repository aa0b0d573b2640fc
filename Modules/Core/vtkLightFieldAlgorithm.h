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
 * A failure is reported once, by Fail(): GetErrorCode() tells its kind and a
 * vtkLightFieldErrorObserver gets its one-line message.
 *
 * @sa vtkLightField vtkLightFieldErrorObserver
 */
#ifndef vtkLightFieldAlgorithm_h
#define vtkLightFieldAlgorithm_h

#include "lfdCoreModule.h" // For export macro
#include "vtkAlgorithm.h"

#include <string> // For std::string

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
   * Dispatches the pipeline requests to the Request* methods below. A C++
   * exception thrown by any of them (std::bad_alloc, a parser's or the file
   * system's) is caught here and reported like any other failure: error
   * code UnknownError, message DescribeFailure(what).
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

  /**
   * The one-line message of a failure that escaped as an exception; the
   * default prefixes the class name, readers override it to name their file.
   */
  virtual std::string DescribeFailure(const std::string& problem);

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * REQUEST_INFORMATION for output port 0: the whole extent of `views` views
   * of width x height pixels, unit spacing, zero origin (vtkLightField's
   * layout).
   */
  static void SetOutputLayout(vtkInformationVector* outputVector, int width, int height, int views);

  /**
   * Records a failure: empties `output` (no points, an empty rig, no
   * provenance; may be null), sets the error code and reports the one-line
   * message (naming the file and field, or line, that is wrong) with
   * vtkErrorMacro: a vtkLightFieldErrorObserver gets it back.
   */
  void Fail(vtkLightField* output, unsigned long errorCode, const std::string& message);

  /**
   * Clears the error code at the start of a request.
   */
  void ClearError();

private:
  vtkTypeBool DispatchRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  vtkLightFieldAlgorithm(const vtkLightFieldAlgorithm&) = delete;
  void operator=(const vtkLightFieldAlgorithm&) = delete;
};

#endif
