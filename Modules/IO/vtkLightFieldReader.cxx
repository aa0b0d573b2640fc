#include "vtkLightFieldReader.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkLightFieldReader);

namespace
{
using lfd::io::ElementPath;
using lfd::io::FieldError;
using lfd::io::Json;
using lfd::io::MemberPath;

struct ManifestView
{
  std::string Name;
  std::array<double, 9> K;
  std::array<double, 9> R;
  std::array<double, 3> T;
};

// Everything lightfield.json says, validated; image paths are resolved.
struct Manifest
{
  std::string Path;
  std::string Folder;
  int Width = 0;
  int Height = 0;
  std::vector<ManifestView> Views;
  std::vector<std::string> Images[vtkLightField::NUMBER_OF_PASSES];
  bool HasPass[vtkLightField::NUMBER_OF_PASSES] = {};
  std::vector<std::array<unsigned char, 3>> Palette;
  int ProjectorWidth = 0;
  int ProjectorHeight = 0;
  std::vector<ManifestView> Projectors;
  std::vector<std::string> Masks;
  bool HasProvenance = false;
  std::string Provenance;
};

std::string ManifestPath(const std::string& fileName)
{
  std::error_code ec;
  if (std::filesystem::is_directory(fileName, ec))
  {
    return (std::filesystem::path(lfd::io::TrimSeparators(fileName)) / "lightfield.json").string();
  }
  return fileName;
}

// R must be a rotation: R R^T = I and det R = +1, to a tolerance that
// accepts calibrations printed with 6 decimals.
bool IsRotation(const std::array<double, 9>& R)
{
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      double dot = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        dot += R[3 * a + c] * R[3 * b + c];
      }
      if (std::abs(dot - (a == b ? 1.0 : 0.0)) > 1e-3)
      {
        return false;
      }
    }
  }
  const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
    R[2] * (R[3] * R[7] - R[4] * R[6]);
  return det > 0.0;
}

template<size_t N>
std::array<double, N> GetArray(const Json& object, const std::string& parent, const char* key)
{
  const std::string path = MemberPath(parent, key);
  const std::vector<double> values =
    lfd::io::GetNumbers(lfd::io::RequireMember(object, parent, key), path, N);
  std::array<double, N> result;
  std::copy(values.begin(), values.end(), result.begin());
  return result;
}

// The views of a rig (lightfield.json "views" or "projectors.views"):
// a non-empty array of {name, K, R, t}.
std::vector<ManifestView> ParseViews(const Json& views, const std::string& key)
{
  if (!views.is_array() || views.empty())
  {
    throw FieldError(key, "expected a non-empty array of views, found " + lfd::io::Describe(views));
  }
  std::vector<ManifestView> parsed;
  for (size_t i = 0; i < views.size(); ++i)
  {
    const std::string path = ElementPath(key, i);
    ManifestView view;
    if (const Json* name = lfd::io::FindMember(views[i], path, "name"))
    {
      view.Name = lfd::io::GetString(*name, MemberPath(path, "name"));
    }
    view.K = GetArray<9>(views[i], path, "K");
    view.R = GetArray<9>(views[i], path, "R");
    view.T = GetArray<3>(views[i], path, "t");
    if (view.K[8] == 0.0 || view.K[0] == 0.0 || view.K[4] == 0.0)
    {
      throw FieldError(
        MemberPath(path, "K"), "not an intrinsic matrix (zero focal length or K[8])");
    }
    if (!IsRotation(view.R))
    {
      throw FieldError(MemberPath(path, "R"), "not a rotation matrix (R R^T != I or det R != 1)");
    }
    parsed.push_back(view);
  }
  return parsed;
}

// The optional "projectors": {width, height, views, masks}.
void ParseProjectors(const Json& document, Manifest& manifest)
{
  const Json* projectors = lfd::io::FindMember(document, "", "projectors");
  if (!projectors)
  {
    return;
  }
  if (!projectors->is_object())
  {
    throw FieldError("projectors",
      "expected an object {width, height, views, masks}, found " + lfd::io::Describe(*projectors));
  }
  manifest.ProjectorWidth = static_cast<int>(lfd::io::GetInteger(
    lfd::io::RequireMember(*projectors, "projectors", "width"), "projectors.width", 1, 1 << 20));
  manifest.ProjectorHeight = static_cast<int>(lfd::io::GetInteger(
    lfd::io::RequireMember(*projectors, "projectors", "height"), "projectors.height", 1, 1 << 20));
  manifest.Projectors =
    ParseViews(lfd::io::RequireMember(*projectors, "projectors", "views"), "projectors.views");
  if (const Json* masks = lfd::io::FindMember(*projectors, "projectors", "masks"))
  {
    if (!masks->is_array() || masks->size() != manifest.Projectors.size())
    {
      throw FieldError("projectors.masks",
        "expected an array of " + std::to_string(manifest.Projectors.size()) +
          " image file names (one per projector), found " + lfd::io::Describe(*masks));
    }
    for (size_t i = 0; i < masks->size(); ++i)
    {
      const std::string image = lfd::io::GetString((*masks)[i], ElementPath("projectors.masks", i));
      manifest.Masks.push_back(lfd::io::ResolvePath(manifest.Folder, image));
    }
  }
}

// Parses and validates the manifest; throws FieldError for a malformed field,
// std::runtime_error for anything else.
void ParseManifest(const Json& document, Manifest& manifest)
{
  const std::string format =
    lfd::io::GetString(lfd::io::RequireMember(document, "", "format"), "format");
  if (format != "lfd-lightfield")
  {
    throw FieldError("format", "expected \"lfd-lightfield\", found \"" + format + "\"");
  }
  const Json& versionValue = lfd::io::RequireMember(document, "", "version");
  const long long version =
    lfd::io::GetInteger(versionValue, "version", 0, std::numeric_limits<int>::max());
  if (version != lfd::io::LightFieldManifestVersion)
  {
    throw FieldError("version",
      "unsupported version " + std::to_string(version) + " (this reader reads version " +
        std::to_string(lfd::io::LightFieldManifestVersion) + ")");
  }
  manifest.Width = static_cast<int>(
    lfd::io::GetInteger(lfd::io::RequireMember(document, "", "width"), "width", 1, 1 << 20));
  manifest.Height = static_cast<int>(
    lfd::io::GetInteger(lfd::io::RequireMember(document, "", "height"), "height", 1, 1 << 20));

  manifest.Views = ParseViews(lfd::io::RequireMember(document, "", "views"), "views");

  const Json& passes = lfd::io::RequireMember(document, "", "passes");
  if (!passes.is_object())
  {
    throw FieldError(
      "passes", "expected an object {pass: [image, ...]}, found " + lfd::io::Describe(passes));
  }
  for (auto it = passes.begin(); it != passes.end(); ++it)
  {
    const std::string path = MemberPath("passes", it.key().c_str());
    const int pass = vtkLightField::GetPassFromName(it.key().c_str());
    if (pass < 0)
    {
      throw FieldError(
        path, "unknown pass (expected coaxial, coded, flood, label, depth or confidence)");
    }
    if (!it->is_array() || it->size() != manifest.Views.size())
    {
      throw FieldError(path,
        "expected an array of " + std::to_string(manifest.Views.size()) +
          " image file names (one per view), found " + lfd::io::Describe(*it));
    }
    manifest.HasPass[pass] = true;
    for (size_t i = 0; i < it->size(); ++i)
    {
      const std::string image = lfd::io::GetString((*it)[i], ElementPath(path, i));
      manifest.Images[pass].push_back(lfd::io::ResolvePath(manifest.Folder, image));
    }
  }

  if (const Json* palette = lfd::io::FindMember(document, "", "palette"))
  {
    if (!palette->is_array())
    {
      throw FieldError(
        "palette", "expected an array of [r, g, b], found " + lfd::io::Describe(*palette));
    }
    for (size_t i = 0; i < palette->size(); ++i)
    {
      const std::string path = ElementPath("palette", i);
      const Json& colour = (*palette)[i];
      if (!colour.is_array() || colour.size() != 3)
      {
        throw FieldError(path, "expected [r, g, b], found " + lfd::io::Describe(colour));
      }
      std::array<unsigned char, 3> rgb;
      for (size_t c = 0; c < 3; ++c)
      {
        rgb[c] =
          static_cast<unsigned char>(lfd::io::GetInteger(colour[c], ElementPath(path, c), 0, 255));
      }
      manifest.Palette.push_back(rgb);
    }
  }

  ParseProjectors(document, manifest);

  if (const Json* provenance = lfd::io::FindMember(document, "", "provenance"))
  {
    manifest.HasProvenance = true;
    manifest.Provenance =
      provenance->is_string() ? provenance->get<std::string>() : provenance->dump();
  }
}

void FillRig(const std::vector<ManifestView>& views, int width, int height, vtkCameraRig* rig)
{
  rig->SetNumberOfViews(static_cast<int>(views.size()));
  rig->SetImageSize(width, height);
  for (size_t i = 0; i < views.size(); ++i)
  {
    const ManifestView& view = views[i];
    const int index = static_cast<int>(i);
    rig->SetView(index, view.K.data(), view.R.data(), view.T.data());
    if (!view.Name.empty())
    {
      rig->SetViewName(index, view.Name.c_str());
    }
  }
}

// Reads and validates the manifest that FileName names. On failure returns
// false with the vtkErrorCode and the one-line message.
bool LoadManifest(const char* fileName,
  Manifest& manifest,
  unsigned long& errorCode,
  std::string& error)
{
  if (!fileName || !*fileName)
  {
    errorCode = vtkErrorCode::NoFileNameError;
    error = "vtkLightFieldReader: no FileName set";
    return false;
  }
  manifest.Path = ManifestPath(fileName);
  manifest.Folder = lfd::io::ParentFolder(manifest.Path);
  Json document;
  if (!lfd::io::ParseJsonFile(manifest.Path, document, error))
  {
    std::error_code ec;
    errorCode = std::filesystem::exists(manifest.Path, ec) ? vtkErrorCode::FileFormatError
                                                           : vtkErrorCode::FileNotFoundError;
    return false;
  }
  try
  {
    ParseManifest(document, manifest);
  }
  catch (const std::exception& e)
  {
    errorCode = vtkErrorCode::FileFormatError;
    error = manifest.Path + ": " + e.what();
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
struct vtkLightFieldReader::Internals
{
  Manifest Parsed;
};

//------------------------------------------------------------------------------
vtkLightFieldReader::vtkLightFieldReader()
  : Internal(new Internals)
{
  this->ReadAllPasses();
}

//------------------------------------------------------------------------------
vtkLightFieldReader::~vtkLightFieldReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldReader::SetReadPass(int pass, bool read)
{
  if (pass < 0 || pass >= vtkLightField::NUMBER_OF_PASSES)
  {
    vtkErrorMacro("SetReadPass: invalid pass " << pass << ".");
    return;
  }
  if (this->ReadPass[pass] != read)
  {
    this->ReadPass[pass] = read;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldReader::GetReadPass(int pass) const
{
  return pass >= 0 && pass < vtkLightField::NUMBER_OF_PASSES && this->ReadPass[pass];
}

//------------------------------------------------------------------------------
void vtkLightFieldReader::ReadAllPasses()
{
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    this->ReadPass[pass] = true;
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldReader::ReadNoPasses()
{
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    this->ReadPass[pass] = false;
  }
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkLightFieldReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  Manifest& manifest = this->Internal->Parsed;
  manifest = Manifest();
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  if (!LoadManifest(this->FileName, manifest, errorCode, error))
  {
    this->Fail(output, errorCode, error);
    return 0;
  }
  SetOutputLayout(
    outputs, manifest.Width, manifest.Height, static_cast<int>(manifest.Views.size()));
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  const Manifest& manifest = this->Internal->Parsed;

  const int views = static_cast<int>(manifest.Views.size());
  output->Initialize();
  output->SetLayout(manifest.Width, manifest.Height, views);

  vtkNew<vtkCameraRig> rig;
  FillRig(manifest.Views, manifest.Width, manifest.Height, rig);

  std::vector<int> passes;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (manifest.HasPass[pass] && this->ReadPass[pass])
    {
      passes.push_back(pass);
    }
  }
  const double total = static_cast<double>(passes.size()) * views;
  int done = 0;
  this->UpdateProgress(0.0);
  for (int pass : passes)
  {
    const std::string passKey = MemberPath("passes", vtkLightField::GetPassName(pass));
    const int channels = vtkLightField::GetPassComponents(pass);
    vtkDataArray* array = output->AllocatePass(pass);
    for (int i = 0; i < views; ++i)
    {
      std::string field = ElementPath(passKey, i);
      for (char& c : field)
      {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      }
      if (!this->ReadImageInto(
            manifest.Images[pass][i], field, manifest.Width, manifest.Height, array, i, output))
      {
        return 0;
      }
      this->UpdateProgress(++done / total);
    }
  }

  if (!manifest.Projectors.empty())
  {
    vtkNew<vtkCameraRig> projectors;
    FillRig(manifest.Projectors, manifest.ProjectorWidth, manifest.ProjectorHeight, projectors);
    output->SetProjectors(projectors);
  }
  if (!manifest.Masks.empty())
  {
    vtkNew<vtkImageData> masks;
    masks->SetDimensions(
      manifest.ProjectorWidth, manifest.ProjectorHeight, static_cast<int>(manifest.Masks.size()));
    vtkNew<vtkUnsignedCharArray> mask;
    mask->SetName("Mask");
    mask->SetNumberOfComponents(3);
    mask->SetNumberOfTuples(masks->GetNumberOfPoints());
    masks->GetPointData()->SetScalars(mask);
    for (size_t i = 0; i < manifest.Masks.size(); ++i)
    {
      if (!this->ReadImageInto(manifest.Masks[i],
            ElementPath("projectors.masks", i),
            manifest.ProjectorWidth,
            manifest.ProjectorHeight,
            mask,
            static_cast<int>(i),
            output))
      {
        return 0;
      }
    }
    output->SetProjectorMasks(masks);
  }
  if (!manifest.Palette.empty())
  {
    vtkNew<vtkUnsignedCharArray> palette;
    palette->SetNumberOfComponents(3);
    palette->SetNumberOfTuples(static_cast<vtkIdType>(manifest.Palette.size()));
    for (size_t i = 0; i < manifest.Palette.size(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        palette->SetTypedComponent(static_cast<vtkIdType>(i), c, manifest.Palette[i][c]);
      }
    }
    output->SetPalette(palette);
  }
  output->SetRig(rig);
  output->SetProvenance(manifest.HasProvenance ? manifest.Provenance.c_str() : nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReader::ReadImageInto(const std::string& image,
  const std::string& field,
  int width,
  int height,
  vtkDataArray* array,
  int slice,
  vtkLightField* output)
{
  const std::string& path = this->Internal->Parsed.Path;
  const std::string where = path + ": field \"" + field + "\": image " + image;
  const int channels = array->GetNumberOfComponents();
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  lfd::io::ImageHeader header;
  if (!lfd::io::ReadImageHeader(image, header, error, errorCode))
  {
    this->Fail(output, errorCode, where + ": " + error);
    return false;
  }
  if (header.Width != width || header.Height != height)
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      where + ": image is " + std::to_string(header.Width) + "x" + std::to_string(header.Height) +
        ", the manifest says " + std::to_string(width) + "x" + std::to_string(height));
    return false;
  }
  if (header.Channels != channels)
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      where + ": image has " + std::to_string(header.Channels) + " channels, expected " +
        std::to_string(channels));
    return false;
  }
  if (!lfd::io::ReadViewPixels(image, header, array, slice, error))
  {
    this->Fail(output, vtkErrorCode::FileFormatError, where + ": " + error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadPass:";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    os << " " << vtkLightField::GetPassName(pass) << "=" << (this->ReadPass[pass] ? "on" : "off");
  }
  os << "\n";
}
