#include "vtkLightFieldWriter.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldWriter);

namespace fs = std::filesystem;

namespace
{
using lfd::io::Json;

std::string LowerCase(const char* text)
{
  std::string lower(text);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower;
}

// "coaxial/view_0007.png", relative to the dataset directory.
std::string ImageName(int pass, int view)
{
  char name[32];
  std::snprintf(name,
    sizeof(name),
    "view_%04d.%s",
    view,
    vtkLightField::GetPassScalarType(pass) == VTK_FLOAT ? "exr" : "png");
  return LowerCase(vtkLightField::GetPassName(pass)) + "/" + name;
}

Json MatrixToJson(const double* values, int count)
{
  Json array = Json::array();
  for (int i = 0; i < count; ++i)
  {
    array.push_back(values[i]);
  }
  return array;
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
  this->ErrorMessage.clear();
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
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  vtkCameraRig* rig = input->GetRig();
  if (width < 1 || height < 1 || views < 1)
  {
    this->Fail(vtkErrorCode::UnknownError,
      directory + ": the light field is empty (" + std::to_string(width) + "x" +
        std::to_string(height) + " pixels, " + std::to_string(views) + " views)");
    return;
  }
  if (!rig || rig->GetNumberOfViews() != views)
  {
    this->Fail(vtkErrorCode::UnknownError,
      directory + ": the rig has " + std::to_string(rig ? rig->GetNumberOfViews() : 0) +
        " views, the light field " + std::to_string(views));
    return;
  }
  std::vector<int> passes;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    vtkDataArray* array = input->GetPass(pass);
    if (!array)
    {
      continue;
    }
    if (array->GetDataType() != vtkLightField::GetPassScalarType(pass) ||
      array->GetNumberOfComponents() != vtkLightField::GetPassComponents(pass) ||
      array->GetNumberOfTuples() != input->GetNumberOfPoints())
    {
      this->Fail(vtkErrorCode::UnknownError,
        directory + ": pass " + vtkLightField::GetPassName(pass) + " is a " +
          array->GetDataTypeAsString() + " array of " +
          std::to_string(array->GetNumberOfComponents()) + " components, expected " +
          vtkImageScalarTypeNameMacro(vtkLightField::GetPassScalarType(pass)) + " x " +
          std::to_string(vtkLightField::GetPassComponents(pass)) + " per pixel");
      return;
    }
    passes.push_back(pass);
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

  // The manifest.
  Json manifest;
  manifest["format"] = "lfd-lightfield";
  manifest["version"] = 1;
  manifest["width"] = width;
  manifest["height"] = height;
  Json viewList = Json::array();
  for (int i = 0; i < views; ++i)
  {
    double K[9], R[9], t[3];
    rig->GetIntrinsics(i, K);
    rig->GetRotation(i, R);
    rig->GetTranslation(i, t);
    Json view;
    const char* name = rig->GetViewName(i);
    view["name"] = name ? name : "";
    view["K"] = MatrixToJson(K, 9);
    view["R"] = MatrixToJson(R, 9);
    view["t"] = MatrixToJson(t, 3);
    viewList.push_back(view);
  }
  manifest["views"] = viewList;
  Json passMap = Json::object();
  for (int pass : passes)
  {
    Json names = Json::array();
    for (int i = 0; i < views; ++i)
    {
      names.push_back(ImageName(pass, i));
    }
    passMap[LowerCase(vtkLightField::GetPassName(pass))] = names;
  }
  manifest["passes"] = passMap;
  if (vtkUnsignedCharArray* palette =
        vtkUnsignedCharArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("LabelPalette")))
  {
    if (palette->GetNumberOfComponents() == 3)
    {
      Json colours = Json::array();
      for (vtkIdType i = 0; i < palette->GetNumberOfTuples(); ++i)
      {
        colours.push_back({ palette->GetTypedComponent(i, 0),
          palette->GetTypedComponent(i, 1),
          palette->GetTypedComponent(i, 2) });
      }
      manifest["palette"] = colours;
    }
  }
  if (const char* provenance = input->GetProvenance())
  {
    Json parsed = Json::parse(provenance, nullptr, false);
    manifest["provenance"] = parsed.is_discarded() ? Json(provenance) : parsed;
  }

  // Everything goes to the temporary sibling first.
  const std::string temporary = lfd::io::TemporaryDirectoryName(directory);
  lfd::io::RemoveQuietly(temporary);
  fs::create_directories(temporary, ec);
  if (ec)
  {
    this->Fail(vtkErrorCode::CannotOpenFileError,
      temporary + ": cannot create the directory: " + ec.message());
    return;
  }
  for (int pass : passes)
  {
    fs::create_directories(fs::path(temporary) / LowerCase(vtkLightField::GetPassName(pass)), ec);
    if (ec)
    {
      lfd::io::RemoveQuietly(temporary);
      this->Fail(vtkErrorCode::CannotOpenFileError,
        temporary + ": cannot create a pass directory: " + ec.message());
      return;
    }
  }
  const double total = static_cast<double>(passes.size()) * views;
  int done = 0;
  this->UpdateProgress(0.0);
  std::string error;
  for (int pass : passes)
  {
    vtkDataArray* array = input->GetPass(pass);
    const int channels = vtkLightField::GetPassComponents(pass);
    const vtkIdType viewValues = static_cast<vtkIdType>(width) * height * channels;
    for (int i = 0; i < views; ++i)
    {
      const std::string image = (fs::path(temporary) / ImageName(pass, i)).string();
      if (!lfd::io::WriteImagePixels(image,
            width,
            height,
            channels,
            array->GetDataType(),
            array->GetVoidPointer(viewValues * i),
            error))
      {
        lfd::io::RemoveQuietly(temporary);
        this->Fail(vtkErrorCode::OutOfDiskSpaceError, image + ": " + error);
        return;
      }
      this->UpdateProgress(++done / (total + 1.0));
    }
  }
  const std::string manifestPath = (fs::path(temporary) / "lightfield.json").string();
  {
    std::ofstream stream(manifestPath, std::ios::binary);
    stream << manifest.dump(2) << "\n";
    stream.close();
    if (!stream)
    {
      lfd::io::RemoveQuietly(temporary);
      this->Fail(vtkErrorCode::OutOfDiskSpaceError, manifestPath + ": cannot write the manifest");
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
void vtkLightFieldWriter::Fail(unsigned long errorCode, const std::string& message)
{
  this->SetErrorCode(errorCode);
  this->ErrorMessage = message;
  vtkErrorMacro(<< message);
}

//------------------------------------------------------------------------------
void vtkLightFieldWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Directory: " << (this->Directory ? this->Directory : "(none)") << "\n";
  os << indent << "ErrorMessage: " << (this->ErrorMessage.empty() ? "(none)" : this->ErrorMessage)
     << "\n";
}
