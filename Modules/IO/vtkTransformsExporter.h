/**
 * @class   vtkTransformsExporter
 * @brief   writes a vtkLightField as a nerfstudio / instant-ngp transforms.json and its images
 *
 * Writes a light field as nerfstudio and instant-ngp read it: `images/<name>.png`
 * (the Coaxial views) and `transforms.json` with `camera_model` "OPENCV",
 * `w`, `h`, and `fl_x fl_y cx cy k1 k2 p1 p2` (`k3` when any view has one)
 * at the top level when every view shares them, else in each frame
 * (per-frame intrinsics); each frame has `file_path` (`images/<name>`) and
 * `transform_matrix`, the camera-to-world matrix in OpenGL camera axes (the
 * inverse of vtkTransformsImporter's conversion). The principal point
 * counts from the top-left pixel's corner. A view whose K has a skew is
 * refused.
 *
 * Numbers are written with 17 significant digits: exporting and importing
 * back gives the same rig to rounding (1e-12 relative).
 *
 * @sa vtkTransformsImporter vtkCalibratedImageExporter
 */
#ifndef vtkTransformsExporter_h
#define vtkTransformsExporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageExporter.h"

class LFDIO_EXPORT vtkTransformsExporter : public vtkCalibratedImageExporter
{
public:
  static vtkTransformsExporter* New();
  vtkTypeMacro(vtkTransformsExporter, vtkCalibratedImageExporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkTransformsExporter();
  ~vtkTransformsExporter() override;

#ifndef __VTK_WRAP__
  bool FormatCalibration(vtkCameraRig* rig,
    const std::vector<std::string>& imageNames,
    std::map<std::string, std::string>& files,
    std::string& error) override;
  std::string GetMarkerFile() override
  {
    return "transforms.json";
  }
#endif

private:
  vtkTransformsExporter(const vtkTransformsExporter&) = delete;
  void operator=(const vtkTransformsExporter&) = delete;
};

#endif
