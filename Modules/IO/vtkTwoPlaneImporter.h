/**
 * @class   vtkTwoPlaneImporter
 * @brief   imports a folder of images taken from a regular grid of camera positions (a
 * two-plane light field) as a vtkLightField
 *
 * A two-plane light field (Levoy and Hanrahan, "Light Field Rendering",
 * SIGGRAPH 1996) is a grid of views: cameras on a plane, all looking the same
 * way, orthogonally to it, as the Stanford (New) Light Field Archive's gantry
 * captures are stored. FileName is the folder; every image file in it (png,
 * jpg, jpeg, tif, tiff, exr, bmp, ppm, pgm; other files are ignored) is one
 * view, and its name says where: the first two fields of the name (split
 * at '_', extension removed) that are whole numbers are its row and its
 * column, so the archive's `out_RR_CC_<y>_<x>_.png`, `RR_CC.png` and
 * `view_RR_CC.jpg` all work. The rows and columns must fill the grid
 * between the smallest and the largest index of each, once each.
 *
 * The rig (vtkCameraRig::IsTwoPlane() is true): the camera of row r, column
 * c has its centre at (c Spacing, r Spacing, 0), or, with a PositionsFile,
 * at the (x, y, 0) that file gives its image; R = identity (it looks
 * along +Z, image x along +X, image y, downwards, along +Y: rows grow down
 * the grid, columns to the right), K = [FocalLength 0 cx; 0 FocalLength cy;
 * 0 0 1] with the principal point at the image centre ((w - 1) / 2,
 * (h - 1) / 2). Views are ordered by row, then column, and named after
 * their files. The archive's images are rectified to a common image plane,
 * which is exactly this rig: views that share one K focus at infinity
 * (vtkLightFieldRenderer::SetFocalDepth 0, its default).
 *
 * Errors name the folder or the file (one line through vtkErrorMacro, see
 * vtkCalibratedImageImporter, which also checks every image's size and
 * pixel format against the first): a FileName that is not a folder, a folder
 * without images, a name without a row and a column, two files for one
 * grid cell, a cell without a file, a FocalLength not set.
 *
 * @sa vtkCalibratedImageImporter vtkCameraRig vtkLightFieldRenderer
 */
#ifndef vtkTwoPlaneImporter_h
#define vtkTwoPlaneImporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageImporter.h"

class LFDIO_EXPORT vtkTwoPlaneImporter : public vtkCalibratedImageImporter
{
public:
  static vtkTwoPlaneImporter* New();
  vtkTypeMacro(vtkTwoPlaneImporter, vtkCalibratedImageImporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Distance between neighbouring camera positions (rows and columns), world
   * units. Default 1.
   */
  vtkSetClampMacro(Spacing, double, 1e-9, 1e6);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Per-image camera positions instead of the regular Spacing: a text file
   * with one line per image, `NAME X Y` (the image's file name, its camera
   * centre on the camera plane in world units; blank lines and lines
   * starting with '#' are skipped). Every image of the folder needs a line,
   * once; a line naming no image of the folder is an error too (each error
   * names the file and the line). nullptr (default): the regular grid.
   */
  vtkSetStringMacro(PositionsFile);
  vtkGetStringMacro(PositionsFile);
  ///@}

  ///@{
  /**
   * Focal length of every view in pixels; must be set (default 0: refused).
   */
  vtkSetClampMacro(FocalLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FocalLength, double);
  ///@}

protected:
  vtkTwoPlaneImporter();
  ~vtkTwoPlaneImporter() override;

#ifndef __VTK_WRAP__
  bool ParseCalibration(std::vector<CalibratedView>& views,
    unsigned long& errorCode,
    std::string& error) override;
  std::string GetFormatDescription() override;
#endif

  double Spacing = 1.0;
  double FocalLength = 0.0;
  char* PositionsFile = nullptr;

private:
  vtkTwoPlaneImporter(const vtkTwoPlaneImporter&) = delete;
  void operator=(const vtkTwoPlaneImporter&) = delete;
};

#endif
