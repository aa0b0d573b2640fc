/**
 * @class   vtkColmapExporter
 * @brief   writes a vtkLightField as a COLMAP sparse model (text or binary) and its images
 *
 * Writes a light field as COLMAP sees a reconstruction (Schoenberger and
 * Frahm, CVPR 2016): `images/<name>.png` (the Coaxial views) and the text model
 * `sparse/cameras.txt`, `sparse/images.txt`, `sparse/points3D.txt` (no
 * points), or with Binary on the binary model `sparse/cameras.bin`,
 * `images.bin`, `points3D.bin` (lfdColmapModel.h), so that `colmap` (e.g. `point_triangulator`,
 * `image_undistorter`) or vtkColmapImporter reads it (`FileName` = `sparse`, `ImageDirectory` =
 * `images`). Views with the same K and distortion share one camera; a
 * camera without distortion is PINHOLE, one with k3 = 0 OPENCV, else
 * FULL_OPENCV (k4 = k5 = k6 = 0). The principal point is moved by half a
 * pixel to COLMAP's pixel-centre convention, R is written as its unit
 * quaternion (w >= 0). A view whose K has a skew is refused (COLMAP has
 * none).
 *
 * Text numbers are written with 17 significant digits, binary ones as
 * their 8 bytes: exporting and importing back gives the same rig to
 * rounding (1e-12 relative).
 *
 * @sa vtkColmapImporter vtkCalibratedImageExporter
 */
#ifndef vtkColmapExporter_h
#define vtkColmapExporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageExporter.h"

class LFDIO_EXPORT vtkColmapExporter : public vtkCalibratedImageExporter
{
public:
  static vtkColmapExporter* New();
  vtkTypeMacro(vtkColmapExporter, vtkCalibratedImageExporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Write the binary model (`.bin`) instead of the text model (`.txt`).
   * Default off. A folder is replaced only by an export of the same kind.
   */
  vtkSetMacro(Binary, bool);
  vtkGetMacro(Binary, bool);
  vtkBooleanMacro(Binary, bool);
  ///@}

protected:
  vtkColmapExporter();
  ~vtkColmapExporter() override;

#ifndef __VTK_WRAP__
  bool FormatCalibration(vtkCameraRig* rig,
    const std::vector<std::string>& imageNames,
    std::map<std::string, std::string>& files,
    std::string& error) override;
  std::string GetMarkerFile() override;
#endif

  bool Binary = false;

private:
  vtkColmapExporter(const vtkColmapExporter&) = delete;
  void operator=(const vtkColmapExporter&) = delete;
};

#endif
