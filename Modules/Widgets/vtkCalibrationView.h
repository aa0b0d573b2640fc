/**
 * @class   vtkCalibrationView
 * @brief   base of the calibration views: a light field shown in a given renderer
 *
 * The rig, gantry-camera and projector views (vtkRigView,
 * vtkGantryCameraView, vtkProjectorView) each set up a renderer given to
 * them, as vtkImageViewer2 does, so that several share one render window
 * (one viewport each). vtkCalibrationView holds what they share: the
 * renderer and the props added to it, the light field shown, a Refresh()
 * before each render of the renderer (a view rebuilds what changed), and the
 * interactor events a view handles once enabled (On(), after
 * SetInteractor()), ahead of the interactor style (Priority 0.5, as VTK's
 * widgets). An event the view handles is consumed; any other is left to the
 * style.
 *
 * @sa vtkRigView vtkGantryCameraView vtkProjectorView
 */
#ifndef vtkCalibrationView_h
#define vtkCalibrationView_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkInteractorObserver.h"

#include <initializer_list> // For std::initializer_list
#include <memory>           // For std::unique_ptr

class vtkLightField;
class vtkProp;
class vtkRenderer;

class LFDWIDGETS_EXPORT vtkCalibrationView : public vtkInteractorObserver
{
public:
  vtkTypeMacro(vtkCalibrationView, vtkInteractorObserver);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The renderer this view draws into (its props are added to it and
   * removed from the previous one); also the renderer its events are taken
   * in.
   */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  ///@}

  ///@{
  /**
   * The light field shown.
   */
  void SetLightField(vtkLightField* lightField);
  vtkLightField* GetLightField();
  ///@}

  /**
   * Rebuilds what changed since the last call; called before each render
   * of the renderer.
   */
  virtual void Refresh() {}

  /**
   * Points the renderer's camera at what the view shows.
   */
  virtual void ResetCamera() = 0;

  /**
   * Enables the view's interaction (needs an interactor).
   */
  void SetEnabled(int enabling) override;

protected:
  vtkCalibrationView();
  ~vtkCalibrationView() override;

  /// A prop of this view, added to its renderer.
  void AddViewProp(vtkProp* prop);
  /// Called after SetLightField().
  virtual void LightFieldChanged() {}
  /// Handles an interactor event in this view's renderer at display (x, y);
  /// true when it was handled (then it is consumed and the window rendered).
  virtual bool HandleEvent(unsigned long event, int x, int y) = 0;
  /// The interactor events HandleEvent() wants.
  void SetHandledEvents(std::initializer_list<unsigned long> events);

private:
  vtkCalibrationView(const vtkCalibrationView&) = delete;
  void operator=(const vtkCalibrationView&) = delete;

  static void ProcessEvents(vtkObject* caller, unsigned long event, void* self, void* data);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
