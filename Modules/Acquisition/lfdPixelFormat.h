/**
 * @file   lfdPixelFormat.h
 * @brief  The 8-bit GigE Vision pixel formats a capture camera delivers, to
 *         and from RGB.
 *
 * Cameras send RGB8, Mono8 or a Bayer mosaic (BayerRG8, BayerBG8, BayerGB8,
 * BayerGR8: the name lists the colours of the top-left 2 x 2 cell row by
 * row). vtkAravisCamera turns every one into RGB (bilinear demosaicing: each
 * missing colour is the mean of the 3 x 3 neighbours that carry it);
 * vtkSimulatedRigCamera turns its rendered RGB into the format the client
 * asked for, as a sensor would. Images are row-major, top row first.
 * Private to the module: plain C++17, no VTK, no Aravis.
 */
#ifndef lfdPixelFormat_h
#define lfdPixelFormat_h

#include <cmath>
#include <cstddef>
#include <cstring>

namespace lfd
{
/// The pixel formats of vtkAravisCamera, in the order of its PixelFormat
/// setting; the names are the GenICam PixelFormat entries.
enum class PixelFormat
{
  RGB8 = 0,
  BayerRG8,
  BayerBG8,
  BayerGB8,
  BayerGR8,
  Mono8
};

inline const char* PixelFormatName(PixelFormat format)
{
  static const char* const names[] = {
    "RGB8", "BayerRG8", "BayerBG8", "BayerGB8", "BayerGR8", "Mono8"
  };
  return names[static_cast<int>(format)];
}

/// Bytes per pixel on the wire.
inline int PixelFormatBytes(PixelFormat format)
{
  return format == PixelFormat::RGB8 ? 3 : 1;
}

/**
 * The colour (0 red, 1 green, 2 blue) a Bayer mosaic samples at pixel
 * (x, y). Red sits at (rx, ry) of each 2 x 2 cell, blue diagonally
 * opposite, green on the other two.
 */
inline int BayerColour(PixelFormat format, std::size_t x, std::size_t y)
{
  const std::size_t rx = (format == PixelFormat::BayerBG8 || format == PixelFormat::BayerGR8);
  const std::size_t ry = (format == PixelFormat::BayerBG8 || format == PixelFormat::BayerGB8);
  const bool redColumn = (x & 1) == rx;
  const bool redRow = (y & 1) == ry;
  return redColumn == redRow ? (redColumn ? 0 : 2) : 1;
}

/// Rec. 601 luma of an RGB pixel, rounded.
inline unsigned char Luma(const unsigned char* rgb)
{
  return static_cast<unsigned char>(std::lround(0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]));
}

/// RGB (3 bytes a pixel) to `format` (PixelFormatBytes() a pixel), as a
/// sensor of that format would have recorded it.
inline void EncodePixels(const unsigned char* rgb,
  std::size_t width,
  std::size_t height,
  PixelFormat format,
  unsigned char* out)
{
  if (format == PixelFormat::RGB8)
  {
    std::memcpy(out, rgb, 3 * width * height);
    return;
  }
  for (std::size_t y = 0; y < height; ++y)
  {
    for (std::size_t x = 0; x < width; ++x)
    {
      const unsigned char* pixel = rgb + 3 * (y * width + x);
      out[y * width + x] =
        format == PixelFormat::Mono8 ? Luma(pixel) : pixel[BayerColour(format, x, y)];
    }
  }
}

/// `format` back to RGB: grey for Mono8, bilinear demosaicing for Bayer.
inline void DecodePixels(const unsigned char* in,
  std::size_t width,
  std::size_t height,
  PixelFormat format,
  unsigned char* rgb)
{
  if (format == PixelFormat::RGB8)
  {
    std::memcpy(rgb, in, 3 * width * height);
    return;
  }
  for (std::size_t y = 0; y < height; ++y)
  {
    for (std::size_t x = 0; x < width; ++x)
    {
      unsigned char* pixel = rgb + 3 * (y * width + x);
      if (format == PixelFormat::Mono8)
      {
        pixel[0] = pixel[1] = pixel[2] = in[y * width + x];
        continue;
      }
      unsigned sum[3] = { 0, 0, 0 };
      unsigned count[3] = { 0, 0, 0 };
      for (std::size_t v = y > 0 ? y - 1 : 0; v <= y + 1 && v < height; ++v)
      {
        for (std::size_t u = x > 0 ? x - 1 : 0; u <= x + 1 && u < width; ++u)
        {
          const int colour = BayerColour(format, u, v);
          sum[colour] += in[v * width + u];
          ++count[colour];
        }
      }
      const int own = BayerColour(format, x, y);
      for (int c = 0; c < 3; ++c)
      {
        // A 1-pixel-wide image has no neighbour of some colour: 0 there.
        pixel[c] = c == own ? in[y * width + x]
          : count[c] > 0    ? static_cast<unsigned char>((sum[c] + count[c] / 2) / count[c])
                            : 0;
      }
    }
  }
}
}

#endif
