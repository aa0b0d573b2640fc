/**
 * @file   lfdLightFieldManifest.h
 * @brief  the light-field dataset format: image names and lightfield.json
 *
 * One definition of the dataset format (Data/README.md) for the writers
 * that produce it: vtkLightFieldWriter (a whole light field at once) and
 * vtkIncrementalLightFieldWriter (a capture, view after view). Private to
 * the IO module (nlohmann::json).
 */
#ifndef lfdLightFieldManifest_h
#define lfdLightFieldManifest_h

#include "lfdJsonFields.h"

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
}
}

#endif
