#include "vtkLightFieldWriter.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdPinholeCamera.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
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

// The "views" of a rig: [{name, K, R, t, distortion}, ...], the distortion
// only when it is not all zero (datasets without one stay byte-identical).
Json ViewsToJson(vtkCameraRig* rig)
{
  Json viewList = Json::array();
  for (int i = 0; i < rig->GetNumberOfViews(); ++i)
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
    if (rig->GetCamera(i).Lens.Active)
    {
      double distortion[5];
      rig->GetDistortion(i, distortion);
      view["distortion"] = MatrixToJson(distortion, 5);
    }
    viewList.push_back(view);
  }
  return viewList;
}

// One image file to write: slice `Slice` (Width x Height tuples) of `Array`.
struct ImageFile
{
  std::string Name; // relative to the dataset directory
  vtkDataArray* Array;
  int Slice;
  int Width;
  int Height;
};

// A failed step of the write: the vtkErrorCode and the one-line message
// (Code 0: no failure).
struct WriteFailure
{
  unsigned long Code = 0;
  std::string Message;
};

// Validates the light field before anything touches the disk: a size, one
// camera per view, cameras the reader accepts, passes of their documented
// types and projector masks of the projectors' size. Returns the problem
// (empty when valid) and the passes to write.
std::string CheckInput(vtkLightField* input, const std::string& directory, std::vector<int>& passes)
{
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  vtkCameraRig* rig = input->GetRig();
  if (width < 1 || height < 1 || views < 1)
  {
    return directory + ": the light field is empty (" + std::to_string(width) + "x" +
      std::to_string(height) + " pixels, " + std::to_string(views) + " views)";
  }
  if (!rig || rig->GetNumberOfViews() != views)
  {
    return directory + ": the rig has " + std::to_string(rig ? rig->GetNumberOfViews() : 0) +
      " views, the light field " + std::to_string(views);
  }
  // The reader's validation of the cameras: never write a dataset that
  // vtkLightFieldReader would refuse.
  vtkCameraRig* projectors = input->GetProjectors();
  for (vtkCameraRig* checked : { rig, projectors })
  {
    std::string field, problem;
    const int invalid = checked->FindInvalidView(field, problem);
    if (invalid >= 0)
    {
      const std::string view = std::string(checked == rig ? "views" : "projectors.views") + "[" +
        std::to_string(invalid) + "]";
      return directory + ": " + view + (field.empty() ? "" : "." + field) + ": " + problem;
    }
  }
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
      return directory + ": pass " + vtkLightField::GetPassName(pass) + " is a " +
        array->GetDataTypeAsString() + " array of " +
        std::to_string(array->GetNumberOfComponents()) + " components, expected " +
        vtkImageScalarTypeNameMacro(vtkLightField::GetPassScalarType(pass)) + " x " +
        std::to_string(vtkLightField::GetPassComponents(pass)) + " per pixel";
    }
    passes.push_back(pass);
  }
  if (vtkImageData* masks = input->GetProjectorMasks())
  {
    const int* dims = masks->GetDimensions();
    vtkDataArray* maskArray = masks->GetPointData()->GetArray("Mask");
    if (!maskArray || maskArray->GetDataType() != VTK_UNSIGNED_CHAR ||
      maskArray->GetNumberOfComponents() != 3 || dims[0] != projectors->GetImageSize()[0] ||
      dims[1] != projectors->GetImageSize()[1] || dims[2] != projectors->GetNumberOfViews())
    {
      return directory + ": the projector masks are " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
        (maskArray ? "" : " without a \"Mask\" array") + ", expected an RGB uint8 \"Mask\" of " +
        std::to_string(projectors->GetImageSize()[0]) + "x" +
        std::to_string(projectors->GetImageSize()[1]) + "x" +
        std::to_string(projectors->GetNumberOfViews()) + " (projector size x projectors)";
    }
  }
  return std::string();
}

// The "projectors" entry of the manifest; their masks join `files`.
Json ProjectorsToJson(vtkLightField* input, std::vector<ImageFile>& files)
{
  vtkCameraRig* projectors = input->GetProjectors();
  Json projectorEntry;
  projectorEntry["width"] = projectors->GetImageSize()[0];
  projectorEntry["height"] = projectors->GetImageSize()[1];
  projectorEntry["views"] = ViewsToJson(projectors);
  if (vtkImageData* masks = input->GetProjectorMasks())
  {
    vtkDataArray* maskArray = masks->GetPointData()->GetArray("Mask");
    Json maskNames = Json::array();
    for (int i = 0; i < projectors->GetNumberOfViews(); ++i)
    {
      char name[48];
      std::snprintf(name, sizeof(name), "projectors/mask_%04d.png", i);
      maskNames.push_back(name);
      files.push_back(
        { name, maskArray, i, projectors->GetImageSize()[0], projectors->GetImageSize()[1] });
    }
    projectorEntry["masks"] = maskNames;
  }
  return projectorEntry;
}

// lightfield.json for the validated light field and its `passes`; the image
// files of the projector masks join `files`.
Json BuildManifest(vtkLightField* input,
  const std::vector<int>& passes,
  std::vector<ImageFile>& files)
{
  const int views = input->GetNumberOfViews();
  Json manifest;
  manifest["format"] = "lfd-lightfield";
  manifest["version"] = lfd::io::LightFieldManifestVersion;
  manifest["width"] = input->GetWidth();
  manifest["height"] = input->GetHeight();
  manifest["views"] = ViewsToJson(input->GetRig());
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
  if (vtkUnsignedCharArray* palette = input->GetPalette())
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
  if (input->GetProjectors()->GetNumberOfViews() > 0)
  {
    manifest["projectors"] = ProjectorsToJson(input, files);
  }
  if (const char* provenance = input->GetProvenance())
  {
    // Provenance that is JSON is kept as JSON (depth-bounded like every
    // JSON we read), anything else as a string.
    Json parsed;
    std::string notJson;
    manifest["provenance"] =
      lfd::io::ParseJsonText(provenance, parsed, notJson) ? parsed : Json(provenance);
  }
  return manifest;
}

// Writes the images and the manifest into a temporary sibling of
// `directory`, then puts it in place of `directory` (nothing half-written
// is ever seen there); `progress` is told the fraction done.
WriteFailure WriteDataset(const std::string& directory,
  const Json& manifest,
  const std::vector<ImageFile>& files,
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
    if (!lfd::io::WriteImagePixels(image,
          file.Width,
          file.Height,
          file.Array->GetNumberOfComponents(),
          file.Array->GetDataType(),
          file.Array->GetVoidPointer(sliceValues * file.Slice),
          error))
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
  std::vector<int> passes;
  const std::string invalid = CheckInput(input, directory, passes);
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
      files.push_back(
        { ImageName(pass, i), input->GetPass(pass), i, input->GetWidth(), input->GetHeight() });
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
  const Json manifest = BuildManifest(input, passes, files);
  const WriteFailure failure =
    WriteDataset(directory, manifest, files, [this](double done) { this->UpdateProgress(done); });
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
}
