#include "lfdImageFiles.h"

#include "lfdFileUtilities.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkType.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <mutex>
#include <sstream>
#include <vector>

#include <fcntl.h>  // open
#include <unistd.h> // dup, dup2, close

namespace lfd
{
namespace io
{
namespace
{
OIIO::TypeDesc ToTypeDesc(int scalarType)
{
  switch (scalarType)
  {
    case VTK_UNSIGNED_CHAR:
      return OIIO::TypeDesc::UINT8;
    case VTK_UNSIGNED_SHORT:
      return OIIO::TypeDesc::UINT16;
    case VTK_FLOAT:
      return OIIO::TypeDesc::FLOAT;
    default:
      return OIIO::TypeDesc::UNKNOWN;
  }
}

// OpenImageIO reports one failure on several lines (its own and the
// codec's, e.g. "Read error: hit end of file" then "PNG read error: ...:
// Read error: hit end of file"): keep the lines no other line contains,
// joined on one line.
std::string OneLine(const std::string& message, const std::string& fallback)
{
  std::vector<std::string> lines;
  std::istringstream stream(message);
  std::string line;
  while (std::getline(stream, line))
  {
    if (!line.empty())
    {
      lines.push_back(line);
    }
  }
  std::string joined;
  for (size_t i = 0; i < lines.size(); ++i)
  {
    bool contained = false;
    for (size_t j = 0; j < lines.size() && !contained; ++j)
    {
      contained =
        j != i && lines[j].find(lines[i]) != std::string::npos && (lines[j] != lines[i] || j < i);
    }
    if (!contained)
    {
      joined += (joined.empty() ? "" : "; ") + lines[i];
    }
  }
  return joined.empty() ? fallback : joined;
}

std::string LastOIIOError(const std::string& fallback)
{
  return OneLine(OIIO::geterror(), fallback);
}

// libpng prints its errors and warnings on stderr ("libpng error: ...")
// before OpenImageIO reports them: while an image is decoded, stderr goes to
// /dev/null, so that a corrupt image costs one error line, ours. Decodes on
// several threads (vtkLightFieldReader) share the silence: the first to
// start sends stderr away, the last to end brings it back.
class SilencedStderr
{
public:
  SilencedStderr()
  {
    std::lock_guard<std::mutex> lock(Shared().Mutex);
    if (Shared().Decoding++ > 0)
    {
      return;
    }
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    Shared().Saved = null >= 0 ? ::dup(STDERR_FILENO) : -1;
    if (Shared().Saved >= 0)
    {
      ::dup2(null, STDERR_FILENO);
    }
    if (null >= 0)
    {
      ::close(null);
    }
  }
  ~SilencedStderr()
  {
    std::lock_guard<std::mutex> lock(Shared().Mutex);
    if (--Shared().Decoding == 0 && Shared().Saved >= 0)
    {
      ::dup2(Shared().Saved, STDERR_FILENO);
      ::close(Shared().Saved);
      Shared().Saved = -1;
    }
  }
  SilencedStderr(const SilencedStderr&) = delete;
  SilencedStderr& operator=(const SilencedStderr&) = delete;

private:
  struct State
  {
    std::mutex Mutex;
    int Decoding = 0; // the decodes under way
    int Saved = -1;   // stderr while they are
  };
  static State& Shared()
  {
    static State state;
    return state;
  }
};

// Opens `path` for reading; alpha stays as stored (no premultiplication on
// read or write), so that 8-bit RGBA values round-trip exactly.
OIIO::ImageInput::unique_ptr OpenImage(const std::string& path, std::string& error)
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    error = LastOIIOError("cannot open the image");
  }
  return input;
}
}

//------------------------------------------------------------------------------
std::string DescribePixels(int channels, int scalarType)
{
  return std::to_string(channels) + (channels == 1 ? " channel" : " channels") + " of " +
    (scalarType == VTK_FLOAT               ? "32-bit float"
        : scalarType == VTK_UNSIGNED_SHORT ? "16-bit"
                                           : "8-bit");
}

//------------------------------------------------------------------------------
bool ReadImageHeader(const std::string& path, ImageHeader& header, std::string& error)
{
  // A FIFO or a device would block or never end: refuse it unopened.
  if (!CheckRegularFile(path, error))
  {
    return false;
  }
  SilencedStderr silenced;
  auto input = OpenImage(path, error);
  if (!input)
  {
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  header.Width = spec.width;
  header.Height = spec.height;
  header.Channels = spec.nchannels;
  header.TileWidth = spec.tile_width;
  header.TileHeight = spec.tile_height;
  switch (spec.format.basetype)
  {
    case OIIO::TypeDesc::UINT8:
    case OIIO::TypeDesc::INT8:
      header.ScalarType = VTK_UNSIGNED_CHAR;
      break;
    case OIIO::TypeDesc::UINT16:
    case OIIO::TypeDesc::INT16:
      header.ScalarType = VTK_UNSIGNED_SHORT;
      break;
    default:
      header.ScalarType = VTK_FLOAT;
      break;
  }
  if (spec.depth > 1)
  {
    error = "volume images are not supported";
    return false;
  }
  input->close();
  return true;
}

//------------------------------------------------------------------------------
bool ReadImageHeader(const std::string& path,
  ImageHeader& header,
  std::string& error,
  unsigned long& errorCode)
{
  if (ReadImageHeader(path, header, error))
  {
    return true;
  }
  std::string problem;
  errorCode = CheckRegularFile(path, problem) || problem != "file not found"
    ? vtkErrorCode::FileFormatError
    : vtkErrorCode::FileNotFoundError;
  return false;
}

//------------------------------------------------------------------------------
bool ReadImagePixels(const std::string& path,
  const ImageHeader& header,
  int channels,
  int scalarType,
  void* data,
  std::string& error)
{
  const OIIO::TypeDesc type = ToTypeDesc(scalarType);
  if (!CheckRegularFile(path, error))
  {
    return false;
  }
  SilencedStderr silenced;
  auto input = OpenImage(path, error);
  if (!input)
  {
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != header.Width || spec.height != header.Height ||
    spec.nchannels != header.Channels)
  {
    error = "the image changed while it was read";
    return false;
  }
  const bool expand = spec.nchannels == 1 && channels > 1;
  if (!expand && spec.nchannels < channels)
  {
    error = "the image has " + std::to_string(spec.nchannels) + " channels, " +
      std::to_string(channels) + " are needed";
    return false;
  }
  const int readChannels = expand ? 1 : channels;
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(type.size()) * channels;
  const OIIO::stride_t rowBytes = pixelBytes * spec.width;
  // Top file row goes to the last VTK row: start there and walk rows backwards.
  char* last = static_cast<char*>(data) + rowBytes * (spec.height - 1);
  if (!input->read_image(0, 0, 0, readChannels, type, last, pixelBytes, -rowBytes))
  {
    error = OneLine(input->geterror(), "cannot read the pixels");
    return false;
  }
  if (expand)
  {
    const size_t valueBytes = type.size();
    char* bytes = static_cast<char*>(data);
    const size_t pixels = static_cast<size_t>(spec.width) * spec.height;
    for (size_t p = 0; p < pixels; ++p)
    {
      char* pixel = bytes + p * pixelBytes;
      for (int c = 1; c < channels; ++c)
      {
        std::copy(pixel, pixel + valueBytes, pixel + c * valueBytes);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool ReadViewPixels(const std::string& path,
  const ImageHeader& header,
  vtkDataArray* pass,
  int view,
  std::string& error)
{
  const int channels = pass->GetNumberOfComponents();
  const vtkIdType viewValues = static_cast<vtkIdType>(header.Width) * header.Height * channels;
  return ReadImagePixels(
    path, header, channels, pass->GetDataType(), pass->GetVoidPointer(viewValues * view), error);
}

//------------------------------------------------------------------------------
bool WriteImagePixels(const std::string& path,
  int width,
  int height,
  int channels,
  int scalarType,
  const void* data,
  std::string& error)
{
  const OIIO::TypeDesc type = ToTypeDesc(scalarType);
  if (type == OIIO::TypeDesc::UNKNOWN)
  {
    error = "unsupported scalar type (use unsigned char, unsigned short or float)";
    return false;
  }
  auto output = OIIO::ImageOutput::create(path);
  if (!output)
  {
    error = LastOIIOError("no image format for this file name");
    return false;
  }
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (type == OIIO::TypeDesc::FLOAT)
  {
    spec.attribute("compression", "zip");
  }
  // Encoded in memory, then written by WriteFileContents(), which checks
  // every write, the fsync and the close: image codecs do not all report a
  // full disk (libpng's writes are unchecked).
  OIIO::Filesystem::IOVecOutput encoded;
  const bool inMemory = output->supports("ioproxy") && output->set_ioproxy(&encoded);
  if (!output->open(path, spec))
  {
    error = OneLine(output->geterror(), "cannot write the image");
    return false;
  }
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(type.size()) * channels;
  const OIIO::stride_t rowBytes = pixelBytes * width;
  const char* last = static_cast<const char*>(data) + rowBytes * (height - 1);
  if (!output->write_image(type, last, pixelBytes, -rowBytes) || !output->close())
  {
    error = OneLine(output->geterror(), "cannot write the pixels");
    return false;
  }
  if (inMemory)
  {
    const std::vector<unsigned char>& bytes = encoded.buffer();
    return WriteFileContents(path, bytes.data(), bytes.size(), error);
  }
  return true;
}

//------------------------------------------------------------------------------
bool WriteTiledImagePixels(const std::string& path,
  int width,
  int height,
  int channels,
  int scalarType,
  const void* data,
  int tileSize,
  std::string& error)
{
  const OIIO::TypeDesc type = ToTypeDesc(scalarType);
  if (type == OIIO::TypeDesc::UNKNOWN)
  {
    error = "unsupported scalar type (use unsigned char, unsigned short or float)";
    return false;
  }
  auto output = OIIO::ImageOutput::create("tif");
  if (!output)
  {
    error = LastOIIOError("no TIFF writer");
    return false;
  }
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.tile_width = tileSize;
  spec.tile_height = tileSize;
  spec.tile_depth = 1;
  spec.attribute("compression", "zip");
  // TIFF has no MIP levels of its own: they are subimages of halving size,
  // which OpenImageIO reads as MIP levels when the file says it is a texture.
  spec.attribute("textureformat", "Plain Texture");
  OIIO::ImageBuf level(spec);
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(type.size()) * channels;
  const OIIO::stride_t rowBytes = pixelBytes * width;
  const char* last = static_cast<const char*>(data) + rowBytes * (height - 1);
  level.set_pixels(level.roi(), type, last, pixelBytes, -rowBytes);
  // Labels and depths are categorical or discontinuous: their coarser
  // levels take one pixel of the finer one, never a blend.
  const bool filtered = channels == 3;
  OIIO::ImageOutput::OpenMode mode = OIIO::ImageOutput::Create;
  OIIO::ImageSpec levelSpec = spec;
  while (true)
  {
    levelSpec.width = levelSpec.full_width = level.spec().width;
    levelSpec.height = levelSpec.full_height = level.spec().height;
    if (!output->open(path, levelSpec, mode) ||
      !output->write_image(level.spec().format, level.localpixels()))
    {
      error = OneLine(output->geterror(), "cannot write the tiled image");
      return false;
    }
    const int w = level.spec().width;
    const int h = level.spec().height;
    if (w == 1 && h == 1)
    {
      break;
    }
    const OIIO::ROI coarser(0, std::max(1, w / 2), 0, std::max(1, h / 2), 0, 1, 0, channels);
    level = filtered ? OIIO::ImageBufAlgo::resize(level, "box", 0.0f, coarser)
                     : OIIO::ImageBufAlgo::resample(level, false, coarser);
    if (level.has_error())
    {
      error = OneLine(level.geterror(), "cannot compute a MIP level");
      return false;
    }
    mode = OIIO::ImageOutput::AppendSubimage;
  }
  if (!output->close())
  {
    error = OneLine(output->geterror(), "cannot write the tiled image");
    return false;
  }
  return true;
}
}
}
