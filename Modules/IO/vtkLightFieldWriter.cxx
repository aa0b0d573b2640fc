#include "vtkLightFieldWriter.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdJsonFields.h"
#include "lfdLightFieldManifest.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"

#include <vector>

vtkStandardNewMacro(vtkLightFieldWriter);

//------------------------------------------------------------------------------
vtkLightFieldWriter::vtkLightFieldWriter() = default;

//------------------------------------------------------------------------------
vtkLightFieldWriter::~vtkLightFieldWriter()
{
  this->SetDirectory(nullptr);
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldWriter::GetInput()
{
  return vtkLightField::SafeDownCast(this->Superclass::GetInput());
}

//------------------------------------------------------------------------------
int vtkLightFieldWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldWriter::WriteData()
{
  vtkLightField* input = this->GetInput();
  if (!this->Directory || !*this->Directory)
  {
    this->Fail(vtkErrorCode::NoFileNameError, "vtkLightFieldWriter: no Directory set");
    return;
  }
  const std::string directory = lfd::io::TrimSeparators(this->Directory);
  if (!input)
  {
    this->Fail(vtkErrorCode::UnknownError, directory + ": the input is not a vtkLightField");
    return;
  }

  // Validate everything before touching the disk (the tile size and the
  // directory: WriteLightFieldDataset).
  std::vector<int> passes;
  const std::string invalid = lfd::io::CheckLightFieldInput(input, directory, passes);
  if (!invalid.empty())
  {
    this->Fail(vtkErrorCode::UnknownError, invalid);
    return;
  }
  std::vector<lfd::io::ImageFile> files;
  for (int pass : passes)
  {
    for (int i = 0; i < input->GetNumberOfViews(); ++i)
    {
      files.push_back({ lfd::io::LightFieldImageName(pass, i, this->TileSize > 0),
        input->GetPass(pass),
        i,
        input->GetWidth(),
        input->GetHeight() });
    }
  }
  const lfd::io::Json manifest = lfd::io::BuildLightFieldManifest(
    input, passes, input->GetNumberOfViews(), files, this->TileSize > 0);
  const lfd::io::WriteFailure failure = lfd::io::WriteLightFieldDataset(directory,
    manifest,
    files,
    this->TileSize,
    [this](double done) { this->UpdateProgress(done); });
  if (failure.Code != 0)
  {
    this->Fail(failure.Code, failure.Message);
  }
}

//------------------------------------------------------------------------------
vtkTypeBool vtkLightFieldWriter::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // An exception (a view name that is not UTF-8 for the JSON library, the
  // file system, memory) must not cross the pipeline into Python.
  try
  {
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }
  catch (...)
  {
    const std::string message = lfd::CurrentExceptionMessage();
    if (this->Directory)
    {
      lfd::io::RemoveQuietly(lfd::io::TemporaryDirectoryName(this->Directory));
    }
    this->Fail(vtkErrorCode::UnknownError,
      (this->Directory ? std::string(this->Directory) : std::string("vtkLightFieldWriter")) + ": " +
        message);
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldWriter::Fail(unsigned long errorCode, const std::string& message)
{
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< message);
}

//------------------------------------------------------------------------------
void vtkLightFieldWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Directory: " << (this->Directory ? this->Directory : "(none)") << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
}
