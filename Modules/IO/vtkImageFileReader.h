/**
 * @class   vtkImageFileReader
 * @brief   reads a 2D image file of any format OpenImageIO knows into a vtkImageData
 *
 * PNG, JPEG, TIFF, EXR, HDR, ... (whatever OpenImageIO reads). The output
 * has the file's channels as the point scalars ("ImageFile"), of type
 * unsigned char for 8-bit files, unsigned short for 16-bit ones and float
 * for everything else (half, float, double). Rows are flipped so that the
 * bottom image row comes first, the VTK way. Errors (missing or unreadable
 * file) leave the output empty, set GetErrorCode() and report one line
 * naming the file (vtkErrorMacro; a vtkLightFieldErrorObserver gets it).
 *
 * @sa vtkImageFileWriter vtkLightFieldReader
 */
#ifndef vtkImageFileReader_h
#define vtkImageFileReader_h

#include "lfdIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

class LFDIO_EXPORT vtkImageFileReader : public vtkImageAlgorithm
{
public:
  static vtkImageFileReader* New();
  vtkTypeMacro(vtkImageFileReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The image file.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Runs the pipeline request; a C++ exception thrown by it is caught and
   * reported as an error (error code UnknownError, a message naming
   * the file), never passed on to the caller.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkImageFileReader();
  ~vtkImageFileReader() override;

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;

  char* FileName = nullptr;

private:
  vtkImageFileReader(const vtkImageFileReader&) = delete;
  void operator=(const vtkImageFileReader&) = delete;

  int Fail(unsigned long errorCode, const std::string& message);
};

#endif
