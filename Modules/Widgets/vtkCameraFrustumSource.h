/**
 * @class   vtkCameraFrustumSource
 * @brief   the viewing frusta of a camera rig as polygons, one pyramid per view
 *
 * vtkCameraFrustumSource draws each calibrated camera of a vtkCameraRig (the
 * gantry's cameras, or a light field's projectors) as a pyramid: its apex
 * at the camera centre, its base the image rectangle (the outer edges of
 * the corner pixels) back-projected to Depth along the optical axis through
 * the view's own K, R, t and lens distortion. Each view gives 5 polygons
 * (4 sides and the base), so a cell picked in a renderer names its view:
 * the cell data arrays are "View" (int, the view index) and "Row" (int,
 * the rig's row of the view after vtkCameraRig::FitCylinder(), 0 without
 * a fit), by which a mapper colours a ring by row.
 *
 * Depth 0 (default) sizes the frusta from the rig: a quarter of the fitted
 * radius, or of the distance between the first two camera centres without
 * a fit (1 when there is a single camera). View -1 (default) draws every
 * view; a view index draws that view only (a highlight).
 *
 * @sa vtkRigView vtkCameraRig
 */
#ifndef vtkCameraFrustumSource_h
#define vtkCameraFrustumSource_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkCameraRig;

class LFDWIDGETS_EXPORT vtkCameraFrustumSource : public vtkPolyDataAlgorithm
{
public:
  static vtkCameraFrustumSource* New();
  vtkTypeMacro(vtkCameraFrustumSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The cameras to draw. Default nullptr (empty output).
   */
  virtual void SetRig(vtkCameraRig* rig);
  vtkGetObjectMacro(Rig, vtkCameraRig);
  ///@}

  ///@{
  /**
   * Distance of each frustum's base from its camera centre along the
   * optical axis, in world units; 0 (default) chooses one from the rig.
   */
  vtkSetClampMacro(Depth, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Depth, double);
  ///@}

  ///@{
  /**
   * The one view to draw, or -1 (default) for all of them.
   */
  vtkSetClampMacro(View, int, -1, VTK_INT_MAX);
  vtkGetMacro(View, int);
  ///@}

  /**
   * The depth used by the last update (Depth, or the one chosen from the
   * rig).
   */
  vtkGetMacro(UsedDepth, double);

  /**
   * The rig's modification time counts.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkCameraFrustumSource();
  ~vtkCameraFrustumSource() override;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkCameraRig* Rig = nullptr;
  double Depth = 0.0;
  int View = -1;
  double UsedDepth = 0.0;

private:
  vtkCameraFrustumSource(const vtkCameraFrustumSource&) = delete;
  void operator=(const vtkCameraFrustumSource&) = delete;
};

#endif
