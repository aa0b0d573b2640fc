/**
 * @file   lfdLightFieldManifest.h
 * @brief  the light-field dataset format: image names and lightfield.json
 *
 * One definition of the dataset format (Data/README.md) for the writers
 * that produce it: vtkLightFieldWriter (a whole light field at once),
 * vtkLightFieldTiler (a dataset rewritten tiled, image after image) and
 * vtkIncrementalLightFieldWriter (a capture, view after view). Private to
 * the IO module (nlohmann::json).
 */
#ifndef lfdLightFieldManifest_h
#define lfdLightFieldManifest_h

#include "lfdJsonFields.h"

#include <functional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkLightField;

namespace lfd
{
namespace io
{
/// One image file to write: slice `Slice` (Width x Height tuples) of `Array`.
struct ImageFile
{
  std::string Name; // relative to the dataset directory
  vtkDataArray* Array;
  int Slice;
  int Width;
  int Height;
  /// When set, fills the slice just before the file is written (false: the
  /// failure, in one line, in its argument), so that a dataset can be
  /// streamed through one slice held in memory (vtkLightFieldTiler).
  std::function<bool(std::string&)> Read = {};
};

/// A failed write of a dataset: the vtkErrorCode and the one-line message
/// (Code 0: no failure).
struct WriteFailure
{
  unsigned long Code = 0;
  std::string Message;
};

/// The file of a pass's view, relative to the dataset directory:
/// "coaxial/view_0007.png" (Depth: ".exr"; tiled: ".tif" for every pass).
std::string LightFieldImageName(int pass, int view, bool tiled = false);

/**
 * Validates a light field before anything touches the disk: a size, one
 * camera per view, cameras the reader accepts, passes of their documented
 * types and projector masks of the projectors' size. Returns the problem,
 * after `directory` (empty when valid), and appends the passes it holds to
 * `passes`.
 */
std::string CheckLightFieldInput(vtkLightField* input,
  const std::string& directory,
  std::vector<int>& passes);

/**
 * lightfield.json for the first `views` views of a validated light field
 * with `passes`: its rig's first `views` cameras and their images (tiled
 * TIFF names when `tiled`); the image files of the projector masks join
 * `files`.
 */
Json BuildLightFieldManifest(vtkLightField* input,
  const std::vector<int>& passes,
  int views,
  std::vector<ImageFile>& files,
  bool tiled = false);

/**
 * Writes a dataset: the images `files` (tiled, MIP-mapped TIFF with
 * `tileSize` x `tileSize` tiles when `tileSize` > 0, except the projector
 * masks; PNG and EXR otherwise) and `manifest` into a temporary sibling of
 * `directory`, then puts it in place of `directory`, so nothing
 * half-written is ever seen there; `progress` is told the fraction done.
 * Refused before anything is written: a `tileSize` that is not 0 or a
 * multiple of 16 from 16 to 4096, and a `directory` that exists and is
 * neither empty nor a light-field dataset (no lightfield.json).
 */
WriteFailure WriteLightFieldDataset(const std::string& directory,
  const Json& manifest,
  const std::vector<ImageFile>& files,
  int tileSize,
  const std::function<void(double)>& progress);
}
}

#endif
