#include "vtkCalibratedImageExporter.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkLightField.h"

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace
{
bool IsPlainFileName(const std::string& name)
{
  if (name.empty() || name[0] == '.')
  {
    return false;
  }
  for (const char c : name)
  {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
      c == '.' || c == '_' || c == '-';
    if (!plain)
    {
      return false;
    }
  }
  return true;
}

// The views' names as .png file names when they are plain and sort in view
// order, else view_NNNN.png.
std::vector<std::string> ImageNames(vtkCameraRig* rig)
{
  const int views = rig->GetNumberOfViews();
  std::vector<std::string> names;
  for (int i = 0; i < views; ++i)
  {
    const char* name = rig->GetViewName(i);
    std::string stem = name ? name : "";
    stem = stem.substr(0, stem.rfind('.'));
    const std::string file = stem + ".png";
    if (!IsPlainFileName(stem) || (!names.empty() && !(names.back() < file)))
    {
      names.clear();
      break;
    }
    names.push_back(file);
  }
  if (names.empty())
  {
    for (int i = 0; i < views; ++i)
    {
      char file[32];
      std::snprintf(file, sizeof(file), "view_%04d.png", i);
      names.emplace_back(file);
    }
  }
  return names;
}
}

//------------------------------------------------------------------------------
vtkCalibratedImageExporter::vtkCalibratedImageExporter() = default;

//------------------------------------------------------------------------------
vtkCalibratedImageExporter::~vtkCalibratedImageExporter()
{
  this->SetDirectoryName(nullptr);
}

//------------------------------------------------------------------------------
vtkLightField* vtkCalibratedImageExporter::GetInput()
{
  return vtkLightField::SafeDownCast(this->Superclass::GetInput());
}

//------------------------------------------------------------------------------
int vtkCalibratedImageExporter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkCalibratedImageExporter::CheckNoSkew(vtkCameraRig* rig, int view)
{
  double K[9];
  rig->GetIntrinsics(view, K);
  if (K[1] != 0.0)
  {
    return "view " + std::to_string(view) + ": K has a skew (k12 = " + std::to_string(K[1]) +
      "), which the format cannot hold";
  }
  return std::string();
}

//------------------------------------------------------------------------------
void vtkCalibratedImageExporter::WriteData()
{
  vtkLightField* input = this->GetInput();
  if (!this->DirectoryName || !*this->DirectoryName)
  {
    this->Fail(
      vtkErrorCode::NoFileNameError, this->GetClassName() + std::string(": no DirectoryName set"));
    return;
  }
  const std::string directory = lfd::io::TrimSeparators(this->DirectoryName);
  vtkDataArray* coaxial = input ? input->GetPass(vtkLightField::COAXIAL) : nullptr;
  if (!coaxial || input->GetNumberOfViews() < 1)
  {
    this->Fail(vtkErrorCode::UnknownError, directory + ": the input has no Coaxial pass to export");
    return;
  }
  vtkCameraRig* rig = input->GetRig();
  const std::vector<std::string> names = ImageNames(rig);
  std::map<std::string, std::string> files;
  std::string error;
  if (!this->FormatCalibration(rig, names, files, error))
  {
    this->Fail(vtkErrorCode::UnknownError, directory + ": " + error);
    return;
  }
  std::error_code ec;
  if (fs::exists(directory, ec) &&
    !(fs::is_directory(directory, ec) &&
      (fs::is_empty(directory, ec) || fs::exists(fs::path(directory) / this->GetMarkerFile(), ec))))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError,
      directory + ": exists and is not an export of this format (no " + this->GetMarkerFile() +
        "); refusing to replace it");
    return;
  }
  const std::string temporary = lfd::io::TemporaryDirectoryName(directory);
  lfd::io::RemoveQuietly(temporary);
  fs::create_directories(fs::path(temporary) / "images", ec);
  for (const auto& file : files)
  {
    fs::create_directories((fs::path(temporary) / file.first).parent_path(), ec);
  }
  if (ec)
  {
    lfd::io::RemoveQuietly(temporary);
    this->Fail(vtkErrorCode::CannotOpenFileError,
      directory + ": cannot create the directory: " + ec.message());
    return;
  }
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const vtkIdType viewValues =
    static_cast<vtkIdType>(width) * height * coaxial->GetNumberOfComponents();
  for (size_t i = 0; i < names.size(); ++i)
  {
    const std::string image = (fs::path(temporary) / "images" / names[i]).string();
    if (!lfd::io::WriteImagePixels(image,
          width,
          height,
          coaxial->GetNumberOfComponents(),
          coaxial->GetDataType(),
          coaxial->GetVoidPointer(viewValues * static_cast<vtkIdType>(i)),
          error))
    {
      lfd::io::RemoveQuietly(temporary);
      this->Fail(
        vtkErrorCode::OutOfDiskSpaceError, directory + ": images/" + names[i] + ": " + error);
      return;
    }
    this->UpdateProgress(0.95 * (i + 1) / names.size());
  }
  for (const auto& file : files)
  {
    const std::string path = (fs::path(temporary) / file.first).string();
    if (!lfd::io::WriteFileContents(path, file.second.data(), file.second.size(), error))
    {
      lfd::io::RemoveQuietly(temporary);
      this->Fail(vtkErrorCode::OutOfDiskSpaceError, directory + ": " + file.first + ": " + error);
      return;
    }
  }
  if (!lfd::io::CommitDirectory(temporary, directory, error))
  {
    this->Fail(vtkErrorCode::CannotOpenFileError, directory + ": " + error);
    return;
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
vtkTypeBool vtkCalibratedImageExporter::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  try
  {
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }
  catch (...)
  {
    const std::string message = lfd::CurrentExceptionMessage();
    if (this->DirectoryName)
    {
      lfd::io::RemoveQuietly(lfd::io::TemporaryDirectoryName(this->DirectoryName));
    }
    this->Fail(vtkErrorCode::UnknownError,
      (this->DirectoryName ? std::string(this->DirectoryName) : std::string(this->GetClassName())) +
        ": " + message);
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkCalibratedImageExporter::Fail(unsigned long errorCode, const std::string& message)
{
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< message);
}

//------------------------------------------------------------------------------
void vtkCalibratedImageExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DirectoryName: " << (this->DirectoryName ? this->DirectoryName : "(none)")
     << "\n";
}
