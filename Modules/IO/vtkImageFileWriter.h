/**
 * @class   vtkImageFileWriter
 * @brief   writes a 2D vtkImageData to any format OpenImageIO knows, atomically
 *
 * The format follows the file name's extension: 8-bit data (unsigned char,
 * 1, 2, 3 or 4 components) to PNG, JPEG, TIFF, ...; float data to EXR or
 * TIFF (double is written as float; unsigned short keeps 16 bits where the
 * format allows). The input's point scalars are written, rows flipped from
 * VTK's order (bottom first) to the file's (top first). The file is written
 * under a temporary name in the same folder and renamed onto FileName when
 * complete, so a reader never sees half an image. Errors set GetErrorCode()
 * and report one line naming the file (vtkErrorMacro; a
 * vtkLightFieldErrorObserver gets it).
 *
 * @sa vtkImageFileReader vtkLightFieldWriter
 */
#ifndef vtkImageFileWriter_h
#define vtkImageFileWriter_h

#include "lfdIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For std::string

class vtkImageData;

class LFDIO_EXPORT vtkImageFileWriter : public vtkWriter
{
public:
  static vtkImageFileWriter* New();
  vtkTypeMacro(vtkImageFileWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The image file; its extension selects the format.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * The input image.
   */
  vtkImageData* GetInput();

  /**
   * Runs the pipeline request; a C++ exception thrown by it is caught and
   * reported as an error (error code UnknownError, a message naming
   * the file), never passed on to the caller.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkImageFileWriter();
  ~vtkImageFileWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;

private:
  vtkImageFileWriter(const vtkImageFileWriter&) = delete;
  void operator=(const vtkImageFileWriter&) = delete;

  void Fail(unsigned long errorCode, const std::string& message);
};

#endif
