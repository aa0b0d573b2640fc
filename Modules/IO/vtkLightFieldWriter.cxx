#include "vtkLightFieldWriter.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdLightFieldManifest.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"

#include <filesystem>
#include <functional>
#include <vector>

vtkStandardNewMacro(vtkLightFieldWriter);

namespace fs = std::filesystem;

namespace
{
using lfd::io::ImageFile;
using lfd::io::Json;

// A failed step of the write: the vtkErrorCode and the one-line message
// (Code 0: no failure).
struct WriteFailure
{
  unsigned long Code = 0;
  std::string Message;
};

// Writes the images and the manifest into a temporary sibling of
// `directory`, then puts it in place of `directory` (nothing half-written
// is ever seen there); `progress` is told the fraction done.
WriteFailure WriteDataset(const std::string& directory,
  const Json& manifest,
  const std::vector<ImageFile>& files,
  int tileSize,
  const std::function<void(double)>& progress)
{
  std::error_code ec;
  const std::string temporary = lfd::io::TemporaryDirectoryName(directory);
  lfd::io::RemoveQuietly(temporary);
  fs::create_directories(temporary, ec);
  if (ec)
  {
    return { vtkErrorCode::CannotOpenFileError,
      directory + ": cannot create the directory: " + ec.message() };
  }
  for (const ImageFile& file : files)
  {
    fs::create_directories((fs::path(temporary) / file.Name).parent_path(), ec);
    if (ec)
    {
      lfd::io::RemoveQuietly(temporary);
      return { vtkErrorCode::CannotOpenFileError,
        directory + ": cannot create a pass directory: " + ec.message() };
    }
  }
  progress(0.0);
  std::string error;
  for (size_t done = 0; done < files.size(); ++done)
  {
    const ImageFile& file = files[done];
    const vtkIdType sliceValues =
      static_cast<vtkIdType>(file.Width) * file.Height * file.Array->GetNumberOfComponents();
    const std::string image = (fs::path(temporary) / file.Name).string();
    const void* pixels = file.Array->GetVoidPointer(sliceValues * file.Slice);
    const int components = file.Array->GetNumberOfComponents();
    // Projector masks stay PNG: only the views' passes are read tile by tile.
    const bool tiled = tileSize > 0 && file.Name.compare(0, 11, "projectors/") != 0;
    if (!(tiled ? lfd::io::WriteTiledImagePixels(image,
                    file.Width,
                    file.Height,
                    components,
                    file.Array->GetDataType(),
                    pixels,
                    tileSize,
                    error)
                : lfd::io::WriteImagePixels(image,
                    file.Width,
                    file.Height,
                    components,
                    file.Array->GetDataType(),
                    pixels,
                    error)))
    {
      lfd::io::RemoveQuietly(temporary);
      return { vtkErrorCode::OutOfDiskSpaceError, directory + ": " + file.Name + ": " + error };
    }
    progress((done + 1.0) / (files.size() + 1.0));
  }
  const std::string manifestPath = (fs::path(temporary) / "lightfield.json").string();
  const std::string manifestText = manifest.dump(2) + "\n";
  if (!lfd::io::WriteFileContents(manifestPath, manifestText.data(), manifestText.size(), error))
  {
    lfd::io::RemoveQuietly(temporary);
    return { vtkErrorCode::OutOfDiskSpaceError, directory + ": lightfield.json: " + error };
  }
  if (!lfd::io::CommitDirectory(temporary, directory, error))
  {
    return { vtkErrorCode::CannotOpenFileError, directory + ": " + error };
  }
  progress(1.0);
  return {};
}
}

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

  // Validate everything before touching the disk.
  if (this->TileSize != 0 &&
    (this->TileSize < 16 || this->TileSize > 4096 || this->TileSize % 16 != 0))
  {
    this->Fail(vtkErrorCode::UnknownError,
      directory + ": tile size " + std::to_string(this->TileSize) +
        ": expected a multiple of 16 from 16 to 4096");
    return;
  }
  std::vector<int> passes;
  const std::string invalid = lfd::io::CheckLightFieldInput(input, directory, passes);
  if (!invalid.empty())
  {
    this->Fail(vtkErrorCode::UnknownError, invalid);
    return;
  }
  std::vector<ImageFile> files;
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
  std::error_code ec;
  if (fs::exists(directory, ec))
  {
    const bool isDataset = fs::is_directory(directory, ec) &&
      (fs::is_empty(directory, ec) || fs::exists(fs::path(directory) / "lightfield.json", ec));
    if (!isDataset)
    {
      this->Fail(vtkErrorCode::CannotOpenFileError,
        directory +
          ": exists and is not a light-field dataset (no lightfield.json); refusing to replace it");
      return;
    }
  }
  const Json manifest = lfd::io::BuildLightFieldManifest(
    input, passes, input->GetNumberOfViews(), files, this->TileSize > 0);
  const WriteFailure failure = WriteDataset(directory,
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
