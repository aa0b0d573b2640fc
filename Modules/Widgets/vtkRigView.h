/**
 * @class   vtkRigView
 * @brief   3D view of a capture rig: camera and projector frusta, the fitted cylinder, the cage
 *
 * vtkRigView sets up a given vtkRenderer, as vtkImageViewer2 does, to show
 * how a light field was captured (Chen et al. 2005, section 4: the
 * spherical gantry): the frustum of every camera of the light field's rig
 * (vtkCameraFrustumSource), coloured by row; the frusta of its projectors
 * in magenta; the axis of the fitted cylinder and one ring per row (grey);
 * the edges of the cage's boxes as they stand (white; the cage widget draws
 * the editable cage in the main view); the object bounds (yellow outline)
 * when SetObjectBounds() was given; and the current view's frustum as a
 * thick yellow wireframe. Several views can share one render window, each
 * in its own renderer (viewport).
 *
 * Picking: once an interactor is set and the view enabled (On()), a left
 * click on a camera frustum in this view's renderer makes that view the
 * current one and invokes ViewSelectedEvent with the view index (int*) as
 * call data; the click is consumed (the camera does not rotate). A click
 * elsewhere is left to the interactor style.
 *
 * @sa vtkCameraFrustumSource vtkGantryCameraView vtkProjectorView
 */
#ifndef vtkRigView_h
#define vtkRigView_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkCalibrationView.h"
#include "vtkCommand.h" // For vtkCommand::UserEvent

#include <memory> // For std::unique_ptr

class vtkDeformationCage;

class LFDWIDGETS_EXPORT vtkRigView : public vtkCalibrationView
{
public:
  static vtkRigView* New();
  vtkTypeMacro(vtkRigView, vtkCalibrationView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Invoked when a click selects a view; call data: the view index (int*).
   */
  enum Events
  {
    ViewSelectedEvent = vtkCommand::UserEvent + 1000
  };

  ///@{
  /**
   * The cage whose box edges are drawn (its current points).
   */
  void SetCage(vtkDeformationCage* cage);
  vtkDeformationCage* GetCage();
  ///@}

  ///@{
  /**
   * Bounds of the object (xmin, xmax, ymin, ymax, zmin, zmax), drawn as an
   * outline. None by default; ClearObjectBounds() removes them.
   */
  void SetObjectBounds(const double bounds[6]);
  void ClearObjectBounds();
  ///@}

  ///@{
  /**
   * The highlighted view, -1 (default) for none.
   */
  void SetCurrentView(int view);
  vtkGetMacro(CurrentView, int);
  ///@}

  /**
   * Points the renderer's camera at the whole rig (an oblique view from
   * above the first row).
   */
  void ResetCamera() override;

  /**
   * The view whose frustum is under display position (x, y) of this view's
   * renderer, or -1.
   */
  int PickView(int x, int y);

protected:
  vtkRigView();
  ~vtkRigView() override;

  void LightFieldChanged() override;
  bool HandleEvent(unsigned long event, int x, int y) override;
  void UpdateRig();

  int CurrentView = -1;

private:
  vtkRigView(const vtkRigView&) = delete;
  void operator=(const vtkRigView&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
