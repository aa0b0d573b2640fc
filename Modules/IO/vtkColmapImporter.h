/**
 * @class   vtkColmapImporter
 * @brief   imports a COLMAP sparse model (text: cameras.txt, images.txt) and its images as a
 * vtkLightField
 *
 * COLMAP (Schoenberger and Frahm, "Structure-from-Motion Revisited", CVPR
 * 2016) writes a reconstruction as a folder holding `cameras.txt`,
 * `images.txt` and `points3D.txt` (`colmap model_converter --output_type
 * TXT` turns the binary model into it). FileName is that folder; the images
 * named in images.txt are found in ImageDirectory (COLMAP's `--image_path`;
 * by default the model folder itself).
 *
 * - `cameras.txt`: one camera per line, `CAMERA_ID MODEL WIDTH HEIGHT
 *   PARAMS...`. The models map onto the rig's OpenCV camera (K and the
 *   distortion k1, k2, p1, p2, k3 of lfdLensDistortion.h): SIMPLE_PINHOLE
 *   (f, cx, cy), PINHOLE (fx, fy, cx, cy), SIMPLE_RADIAL (f, cx, cy, k),
 *   RADIAL (f, cx, cy, k1, k2), OPENCV (fx, fy, cx, cy, k1, k2, p1, p2) and
 *   FULL_OPENCV (fx, fy, cx, cy, k1, k2, p1, p2, k3, k4, k5, k6) when its
 *   rational terms k4, k5, k6 are 0. COLMAP puts the centre of the top-left
 *   pixel at (0.5, 0.5), the rig at (0, 0): the principal point is moved by
 *   half a pixel.
 * - `images.txt`: two lines per registered image, `IMAGE_ID QW QX QY QZ TX
 *   TY TZ CAMERA_ID NAME` then its 2D points (ignored). The quaternion
 *   (Hamilton, w first, normalised here) and T are the world-to-camera
 *   rotation and translation, the rig's `x ~ K [R | t] X`.
 *
 * Views are the registered images sorted by name (COLMAP numbers images in
 * the order it met them); each view's name is the image's NAME. All cameras
 * the images use must have one size (the rig's image size), which the
 * images must have too.
 *
 * Errors name the file and line ("images.txt:7: QW QX QY QZ: not a
 * rotation (zero quaternion)"): a missing file, a wrong number of fields, a
 * token that is not a number, an unsupported camera model, a FULL_OPENCV
 * camera with rational terms, an unknown CAMERA_ID, a repeated id or name,
 * no registered image, cameras of different sizes, and whatever
 * vtkCalibratedImageImporter checks (the rig's validation, the images).
 *
 * @sa vtkColmapExporter vtkCalibratedImageImporter
 */
#ifndef vtkColmapImporter_h
#define vtkColmapImporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageImporter.h"

class LFDIO_EXPORT vtkColmapImporter : public vtkCalibratedImageImporter
{
public:
  static vtkColmapImporter* New();
  vtkTypeMacro(vtkColmapImporter, vtkCalibratedImageImporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkColmapImporter();
  ~vtkColmapImporter() override;

#ifndef __VTK_WRAP__
  bool ParseCalibration(std::vector<CalibratedView>& views,
    unsigned long& errorCode,
    std::string& error) override;
  std::string GetFormatDescription() override;
  std::string DescribeField(const std::string& field) override;
#endif

private:
  vtkColmapImporter(const vtkColmapImporter&) = delete;
  void operator=(const vtkColmapImporter&) = delete;
};

#endif
