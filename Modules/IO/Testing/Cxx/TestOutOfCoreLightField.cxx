// A light field larger than its image cache (issue 14 item 2): written tiled
// by vtkLightFieldWriter (TileSize), read back exactly, then read out of core
// (vtkLightFieldReader::SetCacheSize) with a cache a quarter of its pixels.
// vtkLightFieldRenderer's frames from the cache equal the in-memory frames
// pixel for pixel, and the cache's statistics show it ran out of memory: it
// read more bytes than it holds and read tiles again on a second orbit,
// where a cache as large as the data reads none. Errors: an untiled dataset
// and a missing tile file are one message naming the image.
//
// `lfd tile` (vtkLightFieldTiler) streams: it writes the files
// vtkLightFieldWriter writes from the light field read whole, byte for
// byte, while its peak memory does not grow with the number of views. The
// proxy out of core: a Depth pass served by the cache too renders the same
// frames, through the proxy, as from memory.
#include "lfdIOTestUtilities.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldImageCache.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldTiler.h"
#include "vtkLightFieldWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <malloc.h> // malloc_trim

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
  return a && b && a->GetDataType() == b->GetDataType() &&
    a->GetNumberOfValues() == b->GetNumberOfValues() &&
    std::memcmp(a->GetVoidPointer(0),
      b->GetVoidPointer(0),
      static_cast<size_t>(a->GetNumberOfValues()) * a->GetDataTypeSize()) == 0;
}

// A Depth pass for MakeLightField's ring: the depth (camera z) of a sphere
// of radius 1 at the rig's centre, about, as each camera sees it (0: no
// surface): a proxy that rays meet.
void AddSphereDepth(vtkLightField* lightField)
{
  auto* depth = vtkFloatArray::SafeDownCast(lightField->AllocatePass(vtkLightField::DEPTH));
  const int size = lightField->GetWidth();
  for (int v = 0; v < lightField->GetNumberOfViews(); ++v)
  {
    double K[9];
    lightField->GetRig()->GetIntrinsics(v, K);
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        // Offsets from the axis at the sphere's centre, 4 in front of the camera.
        const double u = 4.0 * (x - K[2]) / K[0];
        const double w = 4.0 * (y - K[5]) / K[4];
        const double r2 = u * u + w * w;
        depth->SetValue(lightField->GetPointIndex(v, x, y),
          r2 < 1.0 ? static_cast<float>(4.0 - std::sqrt(1.0 - r2)) : 0.0f);
      }
    }
  }
}

// The process's resident memory now and its peak since the last ResetPeak(),
// in bytes (/proc/self/status: VmRSS and VmHWM).
long long ResidentBytes(const char* key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind(key, 0) == 0)
    {
      return 1024LL * std::atoll(line.c_str() + std::strlen(key));
    }
  }
  return -1;
}

void ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

// How far the process's peak resident memory rises above its resident
// memory while `work` runs, in bytes; freed heap memory is given back to
// the system first, so that reusing it counts.
template<typename Work>
long long PeakGrowth(Work&& work)
{
  malloc_trim(0);
  ResetPeak();
  const long long before = ResidentBytes("VmRSS:");
  work();
  return ResidentBytes("VmHWM:") - before;
}

// Tiles `source` into `target`; the error message, empty on success.
std::string Tile(const std::string& source, const std::string& target)
{
  vtkNew<vtkLightFieldTiler> tiler;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(tiler);
  tiler->SetFileName(source.c_str());
  tiler->SetDirectory(target.c_str());
  tiler->SetTileSize(64);
  tiler->Write();
  return catcher->GetErrorMessage();
}

std::string FileContents(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

size_t CountFiles(const std::string& directory)
{
  size_t count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(directory))
  {
    count += entry.is_regular_file() ? 1 : 0;
  }
  return count;
}

// Renders `frames` views on an orbit around the ring from both light fields;
// returns how many frames differ in any pixel. `lit` counts the pixels that
// are not black (background) in the in-memory frames.
int CompareOrbit(vtkLightField* inMemory,
  vtkLightField* outOfCore,
  int frames,
  vtkIdType* lit = nullptr,
  int focal = vtkLightFieldRenderer::FOCAL_AUTOMATIC)
{
  vtkNew<vtkLightFieldRenderer> memory;
  vtkNew<vtkLightFieldRenderer> cached;
  memory->SetInputData(inMemory);
  cached->SetInputData(outOfCore);
  memory->SetFocalSurface(focal);
  cached->SetFocalSurface(focal);
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
    vtkPointData* expected = memory->GetOutput()->GetPointData();
    vtkPointData* actual = cached->GetOutput()->GetPointData();
    different += SameArray(expected->GetScalars(), actual->GetScalars()) &&
        SameArray(expected->GetArray("Depth"), actual->GetArray("Depth"))
      ? 0
      : 1;
  }
  return different;
}

// `lfd tile` streams (vtkLightFieldTiler), with every pass; the proxy's
// Depth pass out of core renders as from memory.
void TestTilingAndProxy(const std::string& folder)
{
  // Two untiled datasets of 8 and 32 views of 128^2 (RGB, label, depth):
  // tiling the larger must not hold more of it in memory.
  constexpr int Image = 128;
  const vtkTypeInt64 viewBytes = vtkTypeInt64(Image) * Image * (3 + 1 + 4);
  long long peak[2] = { 0, 0 };
  const int counts[2] = { 8, 32 };
  std::string message;
  for (int i = 0; i < 2; ++i)
  {
    const std::string name = folder + "/views" + std::to_string(counts[i]);
    {
      vtkSmartPointer<vtkLightField> lightField = MakeLightField(Image, counts[i]);
      AddSphereDepth(lightField);
      lfdtest::Check(Write(lightField, name + ".lf", 0), "written untiled: " + name + ".lf");
    }
    peak[i] = PeakGrowth([&] { message = Tile(name + ".lf", name + "-tiled.lf"); });
    lfdtest::CheckEqual(message, std::string(), "vtkLightFieldTiler error, " + name);
  }
  // The measure sees a light field read whole: the way `lfd tile` did it.
  const std::string whole = folder + "/views32-whole.lf";
  vtkSmartPointer<vtkLightField> source;
  const long long wholePeak = PeakGrowth(
    [&]
    {
      source = Read(folder + "/views32.lf", 0, message);
      Write(source, whole, 64);
    });
  std::cout << "     peak memory while tiling: 8 views +" << peak[0] / 1024 << " KiB, 32 views +"
            << peak[1] / 1024 << " KiB; 32 views read whole and written +" << wholePeak / 1024
            << " KiB (one view: " << viewBytes / 1024 << " KiB)\n";
  lfdtest::CheckRange(static_cast<double>(wholePeak),
    static_cast<double>(16 * viewBytes),
    1e300,
    "peak memory of 32 views read whole, then written tiled (bytes)");
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LFD_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(LFD_TEST_ASAN)
  // (AddressSanitizer keeps freed blocks in its quarantine: the growth of
  // the resident memory then follows how much was freed, not how much was
  // held at once; under it 8 views read +8 to +19 MB, 32 views +9 to +11.)
  std::cout << "     (the two tilings' peaks are not compared under AddressSanitizer)\n";
#else
  lfdtest::CheckRange(static_cast<double>(peak[1] - peak[0]),
    -1e300,
    static_cast<double>(4 * viewBytes),
    "peak memory of tiling 32 views over that of 8 views (bytes; reading the dataset whole: +" +
      std::to_string(24 * viewBytes) + ")");
#endif

  // The dataset vtkLightFieldWriter writes from the light field read whole:
  // the same manifest and files, the same pixels. (Not the same bytes: a
  // TIFF holds the time it was written, and OpenImageIO leaves the padding
  // of partial tiles of the coarser levels unset; every level's pixels are
  // computed from the same first level by the same code.)
  const std::string streamed = folder + "/views32-tiled.lf";
  lfdtest::CheckEqual(CountFiles(streamed),
    CountFiles(whole),
    "files of the streamed tiling (manifest, 3 passes x 32 views: 97)");
  lfdtest::Check(
    FileContents(streamed + "/lightfield.json") == FileContents(whole + "/lightfield.json"),
    "the streamed tiling's manifest equals the whole one's");
  vtkSmartPointer<vtkLightField> inMemory = Read(streamed, 0, message);
  for (int pass : { vtkLightField::COAXIAL, vtkLightField::LABEL, vtkLightField::DEPTH })
  {
    lfdtest::Check(SameArray(inMemory->GetPass(pass), source->GetPass(pass)),
      std::string("the streamed tiling's ") + vtkLightField::GetPassName(pass) +
        " read back equals the source's");
  }

  // The proxy through the cache: Depth is served by it too.
  vtkSmartPointer<vtkLightField> outOfCore = Read(streamed, 16 << 20, message);
  auto* cache = vtkLightFieldImageCache::SafeDownCast(outOfCore->GetTexelSource());
  lfdtest::Check(cache && cache->HasPass(vtkLightField::DEPTH) &&
      !outOfCore->GetPass(vtkLightField::DEPTH) && inMemory->GetPass(vtkLightField::DEPTH),
    "out of core: the Depth pass served by the image cache, no Depth array");
  lfdtest::CheckEqual(
    CompareOrbit(inMemory, outOfCore, 6, nullptr, vtkLightFieldRenderer::FOCAL_PROXY),
    0,
    "frames through the proxy (Radiance and Depth) that differ");
  // The proxy is used: its frames are not the plane's.
  vtkNew<vtkLightFieldRenderer> plane;
  vtkNew<vtkLightFieldRenderer> proxy;
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.4, 6.0);
  camera->SetViewAngle(35.0);
  for (vtkLightFieldRenderer* renderer : { plane.Get(), proxy.Get() })
  {
    renderer->SetInputData(outOfCore);
    renderer->SetCamera(camera);
    renderer->SetWidth(96);
    renderer->SetHeight(96);
  }
  plane->SetFocalSurfaceToPlane();
  proxy->SetFocalSurfaceToProxy();
  plane->Update();
  proxy->Update();
  lfdtest::Check(!SameArray(plane->GetOutput()->GetPointData()->GetArray("Depth"),
                   proxy->GetOutput()->GetPointData()->GetArray("Depth")),
    "the proxy's frame has the surface's depth, not the plane's");
  lfdtest::CheckEqual(std::string(cache->GetError()), std::string(), "no Depth tile failed");
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

  TestTilingAndProxy(folder);

  // A missing tile file is named before anything is read.
  std::filesystem::remove(tiled + "/label/view_0005.tif");
  Read(tiled, Bytes / 4, message);
  lfdtest::CheckFailure(
    "missing tile file", true, message, { "passes.label[5]", "label/view_0005.tif", "not found" });
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
