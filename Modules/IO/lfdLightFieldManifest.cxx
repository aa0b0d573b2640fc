#include "lfdLightFieldManifest.h"

#include "lfdJsonFields.h"
#include "lfdPinholeCamera.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "vtkErrorCode.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace lfd
{
namespace io
{
namespace
{
std::string LowerCase(const char* text)
{
  std::string lower(text);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower;
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

// The first `count` "views" of a rig: [{name, K, R, t, distortion}, ...], the distortion
// only when it is not all zero (datasets without one stay byte-identical).
Json ViewsToJson(vtkCameraRig* rig, int count)
{
  Json viewList = Json::array();
  for (int i = 0; i < count; ++i)
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

// The "projectors" entry of the manifest; their masks join `files`.
Json ProjectorsToJson(vtkLightField* input, std::vector<ImageFile>& files)
{
  vtkCameraRig* projectors = input->GetProjectors();
  Json projectorEntry;
  projectorEntry["width"] = projectors->GetImageSize()[0];
  projectorEntry["height"] = projectors->GetImageSize()[1];
  projectorEntry["views"] = ViewsToJson(projectors, projectors->GetNumberOfViews());
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

}

//------------------------------------------------------------------------------
std::string LightFieldImageName(int pass, int view, bool tiled)
{
  char name[32];
  std::snprintf(name,
    sizeof(name),
    "view_%04d.%s",
    view,
    tiled                                                   ? "tif"
      : vtkLightField::GetPassScalarType(pass) == VTK_FLOAT ? "exr"
                                                            : "png");
  return LowerCase(vtkLightField::GetPassName(pass)) + "/" + name;
}

//------------------------------------------------------------------------------
std::string CheckLightFieldInput(vtkLightField* input,
  const std::string& directory,
  std::vector<int>& passes)
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

//------------------------------------------------------------------------------
Json BuildLightFieldManifest(vtkLightField* input,
  const std::vector<int>& passes,
  int views,
  std::vector<ImageFile>& files,
  bool tiled)
{
  Json manifest;
  manifest["format"] = "lfd-lightfield";
  manifest["version"] = lfd::io::LightFieldManifestVersion;
  manifest["width"] = input->GetWidth();
  manifest["height"] = input->GetHeight();
  manifest["views"] = ViewsToJson(input->GetRig(), views);
  Json passMap = Json::object();
  for (int pass : passes)
  {
    Json names = Json::array();
    for (int i = 0; i < views; ++i)
    {
      names.push_back(LightFieldImageName(pass, i, tiled));
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

//------------------------------------------------------------------------------
WriteFailure WriteLightFieldDataset(const std::string& directory,
  const Json& manifest,
  const std::vector<ImageFile>& files,
  int tileSize,
  const std::function<void(double)>& progress)
{
  if (tileSize != 0 && (tileSize < 16 || tileSize > 4096 || tileSize % 16 != 0))
  {
    return { vtkErrorCode::UnknownError,
      directory + ": tile size " + std::to_string(tileSize) +
        ": expected a multiple of 16 from 16 to 4096" };
  }
  std::error_code ec;
  if (fs::exists(directory, ec))
  {
    const bool isDataset = fs::is_directory(directory, ec) &&
      (fs::is_empty(directory, ec) || fs::exists(fs::path(directory) / "lightfield.json", ec));
    if (!isDataset)
    {
      return {
        vtkErrorCode::CannotOpenFileError,
        directory +
          ": exists and is not a light-field dataset (no lightfield.json); refusing to replace it"
      };
    }
  }
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
    if (file.Read && !file.Read(error))
    {
      lfd::io::RemoveQuietly(temporary);
      return { vtkErrorCode::FileFormatError, error };
    }
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
}
