/**
 * @file   lfdImageFiles.h
 * @brief  2D image files through OpenImageIO, in VTK's row order (private to LFD::IO)
 *
 * Files store the top image row first; VTK images and vtkLightField store the
 * bottom row first (see vtkLightField.h). These functions flip rows on the
 * way in and out by handing OpenImageIO a negative row stride, so no pixel is
 * copied twice.
 */
#ifndef lfdImageFiles_h
#define lfdImageFiles_h

#include <string>

class vtkDataArray;

namespace lfd
{
namespace io
{
/**
 * What a file holds: size, channels and the VTK scalar type that keeps its
 * values (VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT or VTK_FLOAT).
 */
struct ImageHeader
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  int ScalarType = 0;
  int TileWidth = 0; // 0: stored in scanlines, not tiles
  int TileHeight = 0;
};

/**
 * The pixel format in words, for messages: "3 channels of 8-bit",
 * "1 channel of 32-bit float".
 */
std::string DescribePixels(int channels, int scalarType);

/**
 * Reads the header of `path`. On failure returns false and sets `error`
 * (without the file name).
 */
bool ReadImageHeader(const std::string& path, ImageHeader& header, std::string& error);

/**
 * ReadImageHeader() that tells a missing file from an unreadable one: on
 * failure `error` is "file not found" when `path` does not exist (the
 * reader's message otherwise) and `errorCode` is vtkErrorCode's
 * FileNotFoundError (FileFormatError otherwise).
 */
bool ReadImageHeader(const std::string& path,
  ImageHeader& header,
  std::string& error,
  unsigned long& errorCode);

/**
 * Reads the first subimage of `path` into `data` (Width x Height x
 * `channels` values of VTK type `scalarType`, bottom row first), converting
 * the pixel type. `header` receives the file's header. A file with 1
 * channel is expanded to `channels` grey channels; otherwise the file must
 * have at least `channels` channels (extra ones are ignored) and the caller
 * checks the header against what it expects before calling.
 */
bool ReadImagePixels(const std::string& path,
  const ImageHeader& header,
  int channels,
  int scalarType,
  void* data,
  std::string& error);

/**
 * ReadImagePixels() into view `view` of a vtkLightField pass array, whose
 * components and scalar type give the channels and the type (each view holds
 * header.Width x header.Height tuples).
 */
bool ReadViewPixels(const std::string& path,
  const ImageHeader& header,
  vtkDataArray* pass,
  int view,
  std::string& error);

/**
 * Writes `data` (width x height x channels values of VTK type `scalarType`,
 * bottom row first) to `path`; the format follows the extension. Float data
 * goes to EXR as 32-bit float (uncompressed-exact, zip compression).
 */
bool WriteImagePixels(const std::string& path,
  int width,
  int height,
  int channels,
  int scalarType,
  const void* data,
  std::string& error);

/**
 * WriteImagePixels() to a tiled, MIP-mapped TIFF (`tileSize` x `tileSize`
 * tiles, zip compression, every level down to 1x1): the file an image
 * cache reads tile by tile. Colour levels (3 channels) are box-filtered;
 * one-channel passes (labels, depth, confidence) are subsampled, never
 * averaged. Level 0 holds `data` exactly.
 */
bool WriteTiledImagePixels(const std::string& path,
  int width,
  int height,
  int channels,
  int scalarType,
  const void* data,
  int tileSize,
  std::string& error);
}
}

#endif
