// A light field larger than its image cache (issue 14 item 2): written tiled
// by vtkLightFieldWriter (TileSize), read back exactly, then read out of core
// (vtkLightFieldReader::SetCacheSize) with a cache a quarter of its pixels.
// vtkLightFieldRenderer's frames from the cache equal the in-memory frames
// pixel for pixel, and the cache's statistics show it ran out of memory: it
// read more bytes than it holds and read tiles again on a second orbit,
// where a cache as large as the data reads none. Errors: an untiled dataset
// and a missing tile file are one message naming the image.
#include "lfdIOTestUtilities.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldImageCache.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>

namespace TestOutOfCoreLightFieldHelpers
{
// OpenImageIO's release builds hold at least 10 MiB of tiles whatever the
// budget: the light field is 4 x that, 72 views of 384^2 (RGB + label).
constexpr int Size = 384;
constexpr int Views = 72;
constexpr vtkTypeInt64 Bytes = vtkTypeInt64(Size) * Size * Views * 4;

vtkSmartPointer<vtkLightField> MakeLightField(int size, int views)
{
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->SetLayout(size, size, views);
  const double center[3] = { 0, 0, 0 };
  const double axis[3] = { 0, 1, 0 };
  const double height = 0.0;
  lightField->GetRig()->MakeCylinder(center, axis, 4.0, views, 1, &height, size, size, 40.0);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::COAXIAL));
  auto* label = vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::LABEL));
  unsigned char* colour = rgb->GetPointer(0);
  unsigned char* part = label->GetPointer(0);
  // Smooth bands that differ per view, so every texel read matters.
  for (vtkIdType i = 0; i < lightField->GetNumberOfPoints(); ++i)
  {
    const int x = static_cast<int>(i % size);
    const int y = static_cast<int>(i / size % size);
    const int v = static_cast<int>(i / (size * size));
    colour[3 * i] = static_cast<unsigned char>(x + 3 * v);
    colour[3 * i + 1] = static_cast<unsigned char>(y * 2 + v);
    colour[3 * i + 2] = static_cast<unsigned char>((x ^ y) + 5 * v);
    part[i] = static_cast<unsigned char>(1 + (x / 48 + y / 64 + v) % 3);
  }
  return lightField;
}

bool Write(vtkLightField* lightField, const std::string& directory, int tileSize)
{
  vtkNew<vtkLightFieldWriter> writer;
  writer->SetInputData(lightField);
  writer->SetDirectory(directory.c_str());
  writer->SetTileSize(tileSize);
  return writer->Write() == 1 && writer->GetErrorCode() == 0;
}

vtkSmartPointer<vtkLightField> Read(const std::string& directory,
  vtkTypeInt64 cacheSize,
  std::string& message)
{
  vtkNew<vtkLightFieldReader> reader;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(reader);
  reader->SetFileName(directory.c_str());
  reader->SetCacheSize(cacheSize);
  reader->Update();
  message = catcher->GetErrorMessage();
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->ShallowCopy(reader->GetOutput());
  return lightField;
}

bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  auto* x = vtkUnsignedCharArray::SafeDownCast(a);
  auto* y = vtkUnsignedCharArray::SafeDownCast(b);
  return x && y && x->GetNumberOfValues() == y->GetNumberOfValues() &&
    std::memcmp(x->GetPointer(0), y->GetPointer(0), x->GetNumberOfValues()) == 0;
}

// Renders `frames` views on an orbit around the ring from both light fields;
// returns how many frames differ in any pixel. `lit` counts the pixels that
// are not black (background) in the in-memory frames.
int CompareOrbit(vtkLightField* inMemory,
  vtkLightField* outOfCore,
  int frames,
  vtkIdType* lit = nullptr)
{
  vtkNew<vtkLightFieldRenderer> memory;
  vtkNew<vtkLightFieldRenderer> cached;
  memory->SetInputData(inMemory);
  cached->SetInputData(outOfCore);
  vtkNew<vtkCamera> camera;
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(35.0);
  int different = 0;
  for (int f = 0; f < frames; ++f)
  {
    const double phi = 2.0 * 3.14159265358979323846 * (f + 0.37) / frames;
    camera->SetPosition(6.0 * std::sin(phi), 0.4, 6.0 * std::cos(phi));
    for (vtkLightFieldRenderer* renderer : { memory.Get(), cached.Get() })
    {
      renderer->SetWidth(96);
      renderer->SetHeight(96);
      renderer->SetCamera(camera);
      renderer->Update();
    }
    auto* pixels =
      vtkUnsignedCharArray::SafeDownCast(memory->GetOutput()->GetPointData()->GetScalars());
    for (vtkIdType p = 0; lit && p < pixels->GetNumberOfTuples(); ++p)
    {
      *lit += pixels->GetValue(3 * p) || pixels->GetValue(3 * p + 1) || pixels->GetValue(3 * p + 2);
    }
    different += SameArray(memory->GetOutput()->GetPointData()->GetScalars(),
                   cached->GetOutput()->GetPointData()->GetScalars())
      ? 0
      : 1;
  }
  return different;
}
}

int TestOutOfCoreLightField(int, char*[])
{
  using namespace TestOutOfCoreLightFieldHelpers;
  const std::string folder = lfdtest::ScratchFolder("TestOutOfCoreLightField");
  const std::string tiled = folder + "/tiled.lf";
  vtkSmartPointer<vtkLightField> original = MakeLightField(Size, Views);
  lfdtest::Check(Write(original, tiled, 64), "written with 64 x 64 tiles");

  // Read into memory, the tiled images give back the light field exactly.
  std::string message;
  vtkSmartPointer<vtkLightField> inMemory = Read(tiled, 0, message);
  lfdtest::Check(SameArray(inMemory->GetPass(vtkLightField::COAXIAL),
                   original->GetPass(vtkLightField::COAXIAL)) &&
      SameArray(inMemory->GetPass(vtkLightField::LABEL), original->GetPass(vtkLightField::LABEL)),
    "the tiled dataset read into memory equals the light field written");

  // Out of core at a quarter of the pixels' bytes.
  vtkSmartPointer<vtkLightField> outOfCore = Read(tiled, Bytes / 4, message);
  auto* cache = vtkLightFieldImageCache::SafeDownCast(outOfCore->GetTexelSource());
  lfdtest::Check(cache && !outOfCore->GetPass(vtkLightField::COAXIAL) &&
      !outOfCore->GetPass(vtkLightField::LABEL) && outOfCore->HasPass(vtkLightField::LABEL) &&
      outOfCore->GetNumberOfViews() == Views,
    "out of core: the rig and an image cache, no pixel arrays");
  if (!cache)
  {
    return EXIT_FAILURE;
  }
  lfdtest::Check(outOfCore->HasLabel(3) && !outOfCore->HasLabel(4),
    "labels 1..3 present, 4 absent (scanned through the cache)");
  vtkIdType lit = 0;
  lfdtest::CheckEqual(
    CompareOrbit(inMemory, outOfCore, 12, &lit), 0, "frames of a first orbit that differ");
  lfdtest::CheckRange(static_cast<double>(lit) / (12 * 96 * 96),
    0.5,
    1.0,
    "fraction of the orbit's pixels that show the light field (not background)");
  const vtkTypeInt64 firstOrbit = cache->GetTilesRead();
  lfdtest::CheckEqual(
    CompareOrbit(inMemory, outOfCore, 12), 0, "frames of a second orbit that differ");
  const vtkTypeInt64 reread = cache->GetTilesRead() - firstOrbit;
  std::cout << "     cache " << cache->GetCacheSize() << " bytes, read " << cache->GetBytesRead()
            << " bytes in " << cache->GetTilesRead() << " tiles, " << reread
            << " of them again on the second orbit\n";
  lfdtest::Check(cache->GetBytesRead() > 2 * cache->GetCacheSize(),
    "the cache read more than twice the bytes it may hold");
  lfdtest::Check(
    reread > firstOrbit / 4, "the second orbit read over a quarter of its tiles again");
  lfdtest::CheckEqual(std::string(cache->GetError()), std::string(), "no tile failed");

  // With room for everything the second orbit reads nothing.
  vtkSmartPointer<vtkLightField> roomy = Read(tiled, 2 * Bytes, message);
  auto* large = vtkLightFieldImageCache::SafeDownCast(roomy->GetTexelSource());
  CompareOrbit(inMemory, roomy, 12);
  const vtkTypeInt64 once = large->GetTilesRead();
  CompareOrbit(inMemory, roomy, 12);
  lfdtest::CheckEqual(large->GetTilesRead() - once,
    vtkTypeInt64(0),
    "tiles read again by a cache as large as the data");

  // An untiled dataset cannot be read through the cache.
  const std::string untiled = folder + "/untiled.lf";
  lfdtest::Check(Write(MakeLightField(32, 4), untiled, 0), "written untiled (PNG)");
  Read(untiled, Bytes / 4, message);
  lfdtest::CheckFailure("untiled dataset out of core",
    true,
    message,
    { "passes.coaxial[0]", "coaxial/view_0000.png", "not tiled", "lfd tile" });

  // A missing tile file is named before anything is read.
  std::filesystem::remove(tiled + "/label/view_0005.tif");
  Read(tiled, Bytes / 4, message);
  lfdtest::CheckFailure(
    "missing tile file", true, message, { "passes.label[5]", "label/view_0005.tif", "not found" });
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
