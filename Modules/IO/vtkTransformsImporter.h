/**
 * @class   vtkTransformsImporter
 * @brief   imports a nerfstudio / instant-ngp `transforms.json` and its images as a
 * vtkLightField
 *
 * `transforms.json` is how NeRF tools exchange calibrated images (instant-ngp,
 * Mueller et al. 2022; nerfstudio, Tancik et al. 2023). FileName is the JSON
 * file; `file_path` of each frame is relative to its folder (or to
 * ImageDirectory when set). Keys read:
 *
 * - intrinsics at the top level, each overridable in a frame (per-frame
 *   intrinsics): `fl_x` (or `camera_angle_x`, the horizontal field of view
 *   in radians, as in the NeRF synthetic scenes), `fl_y` (default `fl_x`),
 *   `cx` and `cy` (default `w` / 2 and `h` / 2), `w` and `h` (required; one
 *   size for all frames), distortion `k1 k2 p1 p2` and `k3` (default 0);
 *   `camera_model`, when given, is `OPENCV` or `PINHOLE` (a fisheye model
 *   is refused). Like COLMAP's, the principal point counts from the corner
 *   of the top-left pixel: the rig's is half a pixel less.
 * - `frames[i].transform_matrix`: the 4 x 4 camera-to-world matrix of the
 *   frame in OpenGL's camera axes (x right, y up, looking along -z). The rig
 *   uses OpenCV's (y down, looking along +z): R is the transpose of the
 *   matrix's rotation with its y and z columns negated, and t = -R C for
 *   its last column C. The world frame is the file's, unchanged (nerfstudio's
 *   own `applied_transform` is not undone).
 *
 * Views follow the order of `frames`; a view's name is its `file_path`.
 * Errors are one line naming the file and the field
 * ('transforms.json: field "frames[2].transform_matrix[3]": expected [0, 0,
 * 0, 1] ...'), and whatever vtkCalibratedImageImporter checks.
 *
 * @sa vtkTransformsExporter vtkCalibratedImageImporter
 */
#ifndef vtkTransformsImporter_h
#define vtkTransformsImporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageImporter.h"

class LFDIO_EXPORT vtkTransformsImporter : public vtkCalibratedImageImporter
{
public:
  static vtkTransformsImporter* New();
  vtkTypeMacro(vtkTransformsImporter, vtkCalibratedImageImporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkTransformsImporter();
  ~vtkTransformsImporter() override;

#ifndef __VTK_WRAP__
  bool ParseCalibration(std::vector<CalibratedView>& views,
    unsigned long& errorCode,
    std::string& error) override;
  std::string GetFormatDescription() override;
  std::string DescribeField(const std::string& field) override;
#endif

private:
  vtkTransformsImporter(const vtkTransformsImporter&) = delete;
  void operator=(const vtkTransformsImporter&) = delete;
};

#endif
