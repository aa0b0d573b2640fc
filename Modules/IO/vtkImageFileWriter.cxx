#include "vtkImageFileWriter.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

vtkStandardNewMacro(vtkImageFileWriter);

//------------------------------------------------------------------------------
vtkImageFileWriter::vtkImageFileWriter() = default;

//------------------------------------------------------------------------------
vtkImageFileWriter::~vtkImageFileWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
vtkImageData* vtkImageFileWriter::GetInput()
{
  return vtkImageData::SafeDownCast(this->Superclass::GetInput());
}

//------------------------------------------------------------------------------
int vtkImageFileWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkImageFileWriter::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // An exception (memory, the file system) must not cross the pipeline into
  // Python.
  try
  {
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }
  catch (...)
  {
    this->Fail(vtkErrorCode::UnknownError,
      (this->FileName ? std::string(this->FileName) : std::string("vtkImageFileWriter")) + ": " +
        lfd::CurrentExceptionMessage());
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkImageFileWriter::Fail(unsigned long errorCode, const std::string& message)
{
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< message);
}

//------------------------------------------------------------------------------
void vtkImageFileWriter::WriteData()
{
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(vtkErrorCode::NoFileNameError, "vtkImageFileWriter: no FileName set");
    return;
  }
  const std::string file = this->FileName;
  vtkImageData* input = this->GetInput();
  vtkDataArray* scalars = input ? input->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    this->Fail(vtkErrorCode::UnknownError, file + ": the input image has no point scalars");
    return;
  }
  int dims[3];
  input->GetDimensions(dims);
  if (dims[2] != 1 || dims[0] < 1 || dims[1] < 1)
  {
    this->Fail(vtkErrorCode::UnknownError,
      file + ": only 2D images can be written, the input is " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
    return;
  }
  vtkSmartPointer<vtkDataArray> data = scalars;
  const int type = scalars->GetDataType();
  if (type == VTK_DOUBLE)
  {
    data = vtkSmartPointer<vtkFloatArray>::New();
    data->DeepCopy(scalars);
  }
  else if (type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT && type != VTK_FLOAT)
  {
    this->Fail(vtkErrorCode::UnknownError,
      file + ": unsupported scalar type " + scalars->GetDataTypeAsString() +
        " (use unsigned char, unsigned short, float or double)");
    return;
  }
  const std::string temporary = lfd::io::TemporaryFileName(file);
  std::string error;
  if (!lfd::io::WriteImagePixels(temporary,
        dims[0],
        dims[1],
        data->GetNumberOfComponents(),
        data->GetDataType(),
        data->GetVoidPointer(0),
        error))
  {
    lfd::io::RemoveQuietly(temporary);
    this->Fail(vtkErrorCode::CannotOpenFileError, file + ": " + error);
    return;
  }
  if (!lfd::io::CommitFile(temporary, file, error))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, file + ": " + error);
  }
}

//------------------------------------------------------------------------------
void vtkImageFileWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
