#include "lfdImageFiles.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkType.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <memory>

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

std::string LastOIIOError(const std::string& fallback)
{
  std::string message = OIIO::geterror();
  return message.empty() ? fallback : message;
}

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
bool ReadImageHeader(const std::string& path, ImageHeader& header, std::string& error)
{
  auto input = OpenImage(path, error);
  if (!input)
  {
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  header.Width = spec.width;
  header.Height = spec.height;
  header.Channels = spec.nchannels;
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
  std::error_code ec;
  if (std::filesystem::exists(path, ec))
  {
    errorCode = vtkErrorCode::FileFormatError;
  }
  else
  {
    errorCode = vtkErrorCode::FileNotFoundError;
    error = "file not found";
  }
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
    error = input->geterror();
    if (error.empty())
    {
      error = "cannot read the pixels";
    }
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
  if (!output->open(path, spec))
  {
    error = output->geterror();
    return false;
  }
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(type.size()) * channels;
  const OIIO::stride_t rowBytes = pixelBytes * width;
  const char* last = static_cast<const char*>(data) + rowBytes * (height - 1);
  if (!output->write_image(type, last, pixelBytes, -rowBytes) || !output->close())
  {
    error = output->geterror();
    if (error.empty())
    {
      error = "cannot write the pixels";
    }
    return false;
  }
  return true;
}
}
}
