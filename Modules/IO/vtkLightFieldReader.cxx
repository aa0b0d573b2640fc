#include "vtkLightFieldReader.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdLimits.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightFieldImageCache.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
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
  std::array<double, 5> Distortion{}; // k1, k2, p1, p2, k3; none = 0
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

// The passes an out-of-core reader serves through the image cache: the
// ones the renderer samples per ray (Depth: the proxy's walk).
bool IsCachedPass(int pass)
{
  return pass == vtkLightField::COAXIAL || pass == vtkLightField::LABEL ||
    pass == vtkLightField::DEPTH;
}

std::string LowerCase(const char* text)
{
  std::string lower(text);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower;
}

// The manifest's field of view `view`'s image of `pass`: "passes.coaxial[3]".
std::string ImageField(int pass, int view)
{
  return ElementPath(
    MemberPath("passes", LowerCase(vtkLightField::GetPassName(pass)).c_str()), view);
}

std::string ManifestPath(const std::string& fileName)
{
  std::error_code ec;
  if (std::filesystem::is_directory(fileName, ec))
  {
    return (std::filesystem::path(lfd::io::TrimSeparators(fileName)) / "lightfield.json").string();
  }
  return fileName;
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
// a non-empty array of {name, K, R, t, distortion (optional)}.
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
    if (lfd::io::FindMember(views[i], path, "distortion"))
    {
      view.Distortion = GetArray<5>(views[i], path, "distortion");
    }
    parsed.push_back(view);
  }
  return parsed;
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
    rig->SetDistortion(index, view.Distortion.data());
    if (!view.Name.empty())
    {
      rig->SetViewName(index, view.Name.c_str());
    }
  }
}

// The rig's one validation (vtkCameraRig::FindInvalidView), reported on the
// field of the view that fails it; the distortion is checked over the
// `width` x `height` image.
void ValidateViews(const std::vector<ManifestView>& views,
  int width,
  int height,
  const std::string& key)
{
  vtkNew<vtkCameraRig> rig;
  FillRig(views, width, height, rig);
  std::string field, problem;
  const int invalid = rig->FindInvalidView(field, problem);
  if (invalid >= 0)
  {
    const std::string view = ElementPath(key, static_cast<size_t>(invalid));
    throw FieldError(field.empty() ? view : MemberPath(view, field.c_str()), problem);
  }
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
  ValidateViews(
    manifest.Projectors, manifest.ProjectorWidth, manifest.ProjectorHeight, "projectors.views");
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
      const std::string image = lfd::io::GetPath((*masks)[i], ElementPath("projectors.masks", i));
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
  ValidateViews(manifest.Views, manifest.Width, manifest.Height, "views");

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
    if (pass < 0 || it.key() != LowerCase(vtkLightField::GetPassName(pass)))
    {
      // Exact lower-case names: "Coaxial" next to "coaxial" would otherwise
      // be two lists for one pass, one of them silently ignored.
      throw FieldError(path,
        "unknown pass (expected coaxial, coded, flood, label, depth or confidence, in lower case)");
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
      const std::string image = lfd::io::GetPath((*it)[i], ElementPath(path, i));
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
void vtkLightFieldReader::GetPieceViews(int views, int piece, int pieces, int range[2])
{
  const auto boundary = [views, pieces](int p)
  { return static_cast<int>(static_cast<std::int64_t>(views) * std::min(p, pieces) / pieces); };
  range[0] = boundary(piece);
  range[1] = boundary(piece + 1);
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
  // The memory the passes to read will take, checked before anything is
  // allocated (a manifest may announce any size).
  int bytesPerPixel = 0;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (manifest.HasPass[pass] && this->ReadPass[pass] &&
      !(this->CacheSize > 0 && IsCachedPass(pass)))
    {
      bytesPerPixel += vtkLightField::GetPassComponents(pass) *
        vtkDataArray::GetDataTypeSize(vtkLightField::GetPassScalarType(pass));
    }
  }
  std::string tooLarge = lfd::CheckLightFieldSize(manifest.Width,
    manifest.Height,
    static_cast<std::int64_t>(manifest.Views.size()),
    bytesPerPixel);
  if (tooLarge.empty())
  {
    tooLarge = lfd::CheckLightFieldSize(manifest.ProjectorWidth,
      manifest.ProjectorHeight,
      static_cast<std::int64_t>(manifest.Masks.size()),
      3);
  }
  if (!tooLarge.empty())
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      manifest.Path + ": the light field is too large to read: " + tooLarge);
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

  // Every image's header is checked against the manifest before any pass is
  // allocated: a wrong size, bit depth or channel count fails at once.
  struct Image
  {
    const std::string* Path;
    std::string Field;
    int Pass; // -1 for a projector mask
    int Slice;
    lfd::io::ImageHeader Header;
  };
  std::vector<Image> images;
  int piece[2];
  GetPieceViews(views, this->Piece, this->NumberOfPieces, piece);
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (!manifest.HasPass[pass] || !this->ReadPass[pass])
    {
      continue;
    }
    for (int i = piece[0]; i < piece[1]; ++i)
    {
      images.push_back({ &manifest.Images[pass][i], ImageField(pass, i), pass, i, {} });
    }
  }
  for (size_t i = 0; i < manifest.Masks.size(); ++i)
  {
    images.push_back(
      { &manifest.Masks[i], ElementPath("projectors.masks", i), -1, static_cast<int>(i), {} });
  }
  for (Image& image : images)
  {
    const bool mask = image.Pass < 0;
    if (!this->CheckImage(*image.Path,
          image.Field,
          mask ? manifest.ProjectorWidth : manifest.Width,
          mask ? manifest.ProjectorHeight : manifest.Height,
          mask ? VTK_UNSIGNED_CHAR : vtkLightField::GetPassScalarType(image.Pass),
          mask ? 3 : vtkLightField::GetPassComponents(image.Pass),
          image.Header,
          output))
    {
      return 0;
    }
    if (this->CacheSize > 0 && !mask && IsCachedPass(image.Pass) && image.Header.TileWidth <= 0)
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        manifest.Path + ": field \"" + image.Field + "\": image " + *image.Path +
          ": not tiled, so it cannot be read through the image cache (convert the dataset with "
          "`lfd tile`)");
      return 0;
    }
  }
  vtkSmartPointer<vtkLightFieldImageCache> cache;
  if (this->CacheSize > 0)
  {
    cache = vtkSmartPointer<vtkLightFieldImageCache>::New();
    cache->SetCacheSize(this->CacheSize);
    for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
    {
      if (manifest.HasPass[pass] && this->ReadPass[pass] && IsCachedPass(pass))
      {
        cache->SetPassFiles(pass, manifest.Images[pass], manifest.Width, manifest.Height);
      }
    }
    // Only the passes read into memory are left to read.
    images.erase(std::remove_if(images.begin(),
                   images.end(),
                   [](const Image& image) { return image.Pass >= 0 && IsCachedPass(image.Pass); }),
      images.end());
  }

  output->SetLayout(manifest.Width, manifest.Height, views);
  vtkNew<vtkCameraRig> rig;
  FillRig(manifest.Views, manifest.Width, manifest.Height, rig);
  // The rig is fitted once, as it is read; one no cylinder fits (fewer than 3
  // views, collinear centres) is read as it is, unfitted.
  std::string noCylinder;
  rig->FitCylinder(noCylinder);
  vtkNew<vtkImageData> masks;
  vtkNew<vtkUnsignedCharArray> mask;
  if (!manifest.Masks.empty())
  {
    masks->SetDimensions(
      manifest.ProjectorWidth, manifest.ProjectorHeight, static_cast<int>(manifest.Masks.size()));
    mask->SetName("Mask");
    mask->SetNumberOfComponents(3);
    mask->SetNumberOfTuples(masks->GetNumberOfPoints());
    masks->GetPointData()->SetScalars(mask);
  }
  // Every selected pass read into memory whole, even when this piece holds
  // none of its views (the cached passes stay on disk).
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (manifest.HasPass[pass] && this->ReadPass[pass] && !(cache && IsCachedPass(pass)))
    {
      output->AllocatePass(pass);
    }
  }
  // The images decoded on every thread (vtkSMPTools), each straight into
  // its slice of its array, a block of them at a time (the progress said
  // between blocks, on this thread). The failure said is the first image,
  // in the order above, that fails: every image before it is read, and none
  // of the blocks after its own is started, as when they are read in turn.
  // (The demo's fish, 1080 images on 2 cores: 1.30-1.48 s read on one
  // thread, 1.10-1.18 s on two; lfd render of its swim 2.4-3.1 -> 2.1-2.3 s.)
  std::vector<vtkDataArray*> arrays(images.size());
  for (std::size_t i = 0; i < images.size(); ++i)
  {
    arrays[i] =
      images[i].Pass < 0 ? static_cast<vtkDataArray*>(mask) : output->GetPass(images[i].Pass);
  }
  std::vector<std::string> errors(images.size());
  std::atomic<std::size_t> failed{ images.size() };
  // (Blocks of an image a thread, or of 2% of the images when more.)
  const std::size_t block =
    std::max<std::size_t>(static_cast<std::size_t>(vtkSMPTools::GetEstimatedNumberOfThreads()),
      (images.size() + 49) / 50);
  this->UpdateProgress(0.0);
  for (std::size_t start = 0; start < images.size() && failed.load() == images.size();
       start += block)
  {
    const std::size_t stop = std::min(images.size(), start + block);
    vtkSMPTools::For(static_cast<vtkIdType>(start),
      static_cast<vtkIdType>(stop),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (auto i = static_cast<std::size_t>(begin);
             i < static_cast<std::size_t>(end) && i < failed.load();
             ++i)
        {
          const Image& image = images[i];
          if (!lfd::io::ReadViewPixels(
                *image.Path, image.Header, arrays[i], image.Slice, errors[i]))
          {
            std::size_t first = failed.load();
            while (i < first && !failed.compare_exchange_weak(first, i))
            {
            }
          }
        }
      });
    this->UpdateProgress(static_cast<double>(stop) / static_cast<double>(images.size()));
  }
  if (failed.load() < images.size())
  {
    const Image& image = images[failed.load()];
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      this->ImageProblem(*image.Path, image.Field, errors[failed.load()]));
    return 0;
  }

  if (!manifest.Projectors.empty())
  {
    vtkNew<vtkCameraRig> projectors;
    FillRig(manifest.Projectors, manifest.ProjectorWidth, manifest.ProjectorHeight, projectors);
    output->SetProjectors(projectors);
  }
  if (!manifest.Masks.empty())
  {
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
  output->SetTexelSource(cache);
  output->SetProvenance(manifest.HasProvenance ? manifest.Provenance.c_str() : nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
const char* vtkLightFieldReader::GetImageFileName(int pass, int view)
{
  const Manifest& manifest = this->Internal->Parsed;
  return pass >= 0 && pass < vtkLightField::NUMBER_OF_PASSES && view >= 0 &&
      view < static_cast<int>(manifest.Images[pass].size())
    ? manifest.Images[pass][view].c_str()
    : nullptr;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReader::ReadView(int pass, int view, vtkDataArray* pixels)
{
  const char* image = this->GetImageFileName(pass, view);
  if (!image || !pixels || pixels->GetDataType() != vtkLightField::GetPassScalarType(pass))
  {
    this->Fail(nullptr,
      vtkErrorCode::UnknownError,
      "ReadView: " +
        std::string(!image ? "the manifest lists no such image"
                           : "expected an array of the pass's scalar type") +
        " (pass " + std::to_string(pass) + ", view " + std::to_string(view) + ")");
    return false;
  }
  const Manifest& manifest = this->Internal->Parsed;
  const int components = vtkLightField::GetPassComponents(pass);
  lfd::io::ImageHeader header;
  if (!this->CheckImage(image,
        ImageField(pass, view),
        manifest.Width,
        manifest.Height,
        vtkLightField::GetPassScalarType(pass),
        components,
        header,
        nullptr))
  {
    return false;
  }
  pixels->SetNumberOfComponents(components);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(manifest.Width) * manifest.Height);
  std::string error;
  if (!lfd::io::ReadViewPixels(image, header, pixels, 0, error))
  {
    this->Fail(nullptr,
      vtkErrorCode::FileFormatError,
      this->ImageProblem(image, ImageField(pass, view), error));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReader::CheckImage(const std::string& image,
  const std::string& field,
  int width,
  int height,
  int scalarType,
  int channels,
  lfd::io::ImageHeader& header,
  vtkLightField* output)
{
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  if (!lfd::io::ReadImageHeader(image, header, error, errorCode))
  {
    this->Fail(output, errorCode, this->ImageProblem(image, field, error));
    return false;
  }
  if (header.Width != width || header.Height != height)
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      this->ImageProblem(image,
        field,
        "image is " + std::to_string(header.Width) + "x" + std::to_string(header.Height) +
          ", the manifest says " + std::to_string(width) + "x" + std::to_string(height)));
    return false;
  }
  if (header.Channels != channels || header.ScalarType != scalarType)
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      this->ImageProblem(image,
        field,
        "image has " + lfd::io::DescribePixels(header.Channels, header.ScalarType) + ", expected " +
          lfd::io::DescribePixels(channels, scalarType)));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldReader::ImageProblem(const std::string& image,
  const std::string& field,
  const std::string& problem) const
{
  return this->Internal->Parsed.Path + ": field \"" + field + "\": image " + image + ": " + problem;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldReader::DescribeFailure(const std::string& problem)
{
  return (this->FileName ? std::string(this->FileName) : std::string("vtkLightFieldReader")) +
    ": " + problem;
}

//------------------------------------------------------------------------------
void vtkLightFieldReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CacheSize: " << this->CacheSize << "\n";
  os << indent << "ReadPass:";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    os << " " << vtkLightField::GetPassName(pass) << "=" << (this->ReadPass[pass] ? "on" : "off");
  }
  os << "\n";
  os << indent << "Piece: " << this->Piece << " of " << this->NumberOfPieces << "\n";
}
