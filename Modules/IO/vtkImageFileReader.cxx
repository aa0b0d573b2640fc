#include "vtkImageFileReader.h"

#include "lfdExceptions.h"
#include "lfdImageFiles.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkImageFileReader);

//------------------------------------------------------------------------------
vtkImageFileReader::vtkImageFileReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkImageFileReader::~vtkImageFileReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
vtkTypeBool vtkImageFileReader::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // An exception (memory for a huge image, the file system) must not cross
  // the pipeline into Python.
  try
  {
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }
  catch (...)
  {
    vtkImageData* output = vtkImageData::GetData(outputVector);
    if (output)
    {
      output->Initialize();
    }
    return this->Fail(vtkErrorCode::UnknownError,
      (this->FileName ? std::string(this->FileName) : std::string("vtkImageFileReader")) + ": " +
        lfd::CurrentExceptionMessage());
  }
}

//------------------------------------------------------------------------------
int vtkImageFileReader::Fail(unsigned long errorCode, const std::string& message)
{
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< message);
  return 0;
}

//------------------------------------------------------------------------------
int vtkImageFileReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    return this->Fail(vtkErrorCode::NoFileNameError, "vtkImageFileReader: no FileName set");
  }
  lfd::io::ImageHeader header;
  std::string error;
  unsigned long errorCode = vtkErrorCode::NoError;
  if (!lfd::io::ReadImageHeader(this->FileName, header, error, errorCode))
  {
    return this->Fail(errorCode, std::string(this->FileName) + ": " + error);
  }
  vtkInformation* info = outputs->GetInformationObject(0);
  int extent[6] = { 0, header.Width - 1, 0, header.Height - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, header.ScalarType, header.Channels);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageFileReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkImageData* output = vtkImageData::GetData(outputs);
  output->Initialize();
  if (!this->FileName || !*this->FileName)
  {
    return this->Fail(vtkErrorCode::NoFileNameError, "vtkImageFileReader: no FileName set");
  }
  lfd::io::ImageHeader header;
  std::string error;
  unsigned long errorCode = vtkErrorCode::NoError;
  if (!lfd::io::ReadImageHeader(this->FileName, header, error, errorCode))
  {
    return this->Fail(errorCode, std::string(this->FileName) + ": " + error);
  }
  output->SetExtent(0, header.Width - 1, 0, header.Height - 1, 0, 0);
  output->AllocateScalars(header.ScalarType, header.Channels);
  vtkDataArray* scalars = output->GetPointData()->GetScalars();
  scalars->SetName("ImageFile");
  if (!lfd::io::ReadImagePixels(this->FileName,
        header,
        header.Channels,
        header.ScalarType,
        scalars->GetVoidPointer(0),
        error))
  {
    output->Initialize();
    return this->Fail(vtkErrorCode::FileFormatError, std::string(this->FileName) + ": " + error);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkImageFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
