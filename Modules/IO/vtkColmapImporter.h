/**
 * @class   vtkColmapImporter
 * @brief   imports a COLMAP sparse model (binary: cameras.bin, images.bin; or text:
 * cameras.txt, images.txt) and its images as a vtkLightField
 *
 * COLMAP (Schoenberger and Frahm, "Structure-from-Motion Revisited", CVPR
 * 2016) writes a reconstruction as a folder holding `cameras.bin`,
 * `images.bin` and `points3D.bin` (`colmap mapper` writes them), or the
 * same model as text, `cameras.txt`, `images.txt` and `points3D.txt`
 * (`colmap model_converter --output_type TXT`). FileName is that folder:
 * the binary model is read when it holds `cameras.bin` (as COLMAP itself
 * prefers), else the text model; `points3D` is not read. The images named
 * in the model are found in ImageDirectory (COLMAP's `--image_path`; by
 * default the model folder itself).
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
 * - `cameras.bin`, `images.bin`: the same records, little-endian, as
 *   lfdColmapModel.h lays them out (MODEL_ID for MODEL; the 2D points of
 *   each image are skipped).
 *
 * Views are the registered images sorted by name (COLMAP numbers images in
 * the order it met them); each view's name is the image's NAME. All cameras
 * the images use must have one size (the rig's image size), which the
 * images must have too.
 *
 * Errors name the file and the line or record ("images.txt:7: QW QX QY QZ:
 * not a rotation (a zero quaternion)", "images.bin: record 3 of 24: truncated
 * in TX (the file ends at byte 200)"): a missing file, a wrong number of
 * fields, a token that is not a number, a value that is not finite, a
 * truncated record, a NAME without its terminating 0 byte, bytes after the
 * last record, an unsupported camera model, a FULL_OPENCV camera with
 * rational terms, an unknown CAMERA_ID, a repeated id or name, no registered
 * image, cameras of different sizes, and whatever vtkCalibratedImageImporter
 * checks (the rig's validation, the images).
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

  /**
   * Whether the model read last was binary (cameras.bin, images.bin).
   */
  vtkGetMacro(BinaryModel, bool);

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

  bool BinaryModel = false;

private:
  vtkColmapImporter(const vtkColmapImporter&) = delete;
  void operator=(const vtkColmapImporter&) = delete;
};

#endif
