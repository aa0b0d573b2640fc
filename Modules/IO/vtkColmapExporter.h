/**
 * @class   vtkColmapExporter
 * @brief   writes a vtkLightField as a COLMAP text model and its images
 *
 * Writes a light field as COLMAP sees a reconstruction (Schoenberger and
 * Frahm, CVPR 2016): `images/<name>.png` (the Coaxial views) and the text model
 * `sparse/cameras.txt`, `sparse/images.txt`, `sparse/points3D.txt` (no
 * points), so that `colmap` (e.g. `point_triangulator`, `image_undistorter`)
 * or vtkColmapImporter reads it (`FileName` = `sparse`, `ImageDirectory` =
 * `images`). Views with the same K and distortion share one camera; a
 * camera without distortion is PINHOLE, one with k3 = 0 OPENCV, else
 * FULL_OPENCV (k4 = k5 = k6 = 0). The principal point is moved by half a
 * pixel to COLMAP's pixel-centre convention, R is written as its unit
 * quaternion (w >= 0). A view whose K has a skew is refused (COLMAP has
 * none).
 *
 * Numbers are written with 17 significant digits: exporting and importing
 * back gives the same rig to rounding (1e-12 relative).
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

protected:
  vtkColmapExporter();
  ~vtkColmapExporter() override;

#ifndef __VTK_WRAP__
  bool FormatCalibration(vtkCameraRig* rig,
    const std::vector<std::string>& imageNames,
    std::map<std::string, std::string>& files,
    std::string& error) override;
  std::string GetMarkerFile() override
  {
    return "sparse/cameras.txt";
  }
#endif

private:
  vtkColmapExporter(const vtkColmapExporter&) = delete;
  void operator=(const vtkColmapExporter&) = delete;
};

#endif
