/**
 * @file   lfdStudioViews.h
 * @brief  The renderers LightField Studio shows in its one VTK render window:
 *         the main view, the gantry camera, the projector and the rig.
 *
 * lfdStudioViews is Qt-free: it lays out four vtkRenderers as viewports of
 * the window it is given (the Studio's QVTKOpenGLNativeWidget window, or a
 * plain vtkRenderWindow) and fills them from a vtkLightFieldSceneLogic:
 * - the main view is a vtkLightFieldEditor in the main renderer: the
 *   deformed light field, the cage widget whose drags are the logic's
 *   commands, progressive refinement and the frame time;
 * - the gantry camera view is a vtkGantryCameraView: one captured view's
 *   photo in any pass, the rest boxes projected over it and the view's
 *   coverage (Chen et al. 2005, section 4.1);
 * - the projector view is a vtkProjectorView: one projector's colour mask,
 *   painted with a brush; each stroke becomes one command of the logic
 *   ("Paint projector mask");
 * - the rig view is a vtkRigView: camera and projector frusta, the fitted
 *   cylinder, the shown cage and the object bounds; a click on a camera
 *   frustum invokes vtkRigView::ViewSelectedEvent (the Studio then shows
 *   that view, SetCameraView()).
 * The main view's cage widget and the projector view's brush edit the
 * logic; the other views read it. The views hidden by the layout take no
 * events.
 */
#ifndef lfdStudioViews_h
#define lfdStudioViews_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

class vtkDeformationCage;
class vtkGantryCameraView;
class vtkLightFieldEditor;
class vtkProjectorView;
class vtkRenderer;
class vtkRigView;
class vtkLightField;
class vtkLightFieldSceneLogic;
class vtkObject;
class vtkRenderWindow;

class lfdStudioViews
{
public:
  /// The layouts of the View menu.
  enum Layout
  {
    MAIN_ONLY = 0,
    MAIN_AND_CAMERA,
    FOUR_UP
  };

  lfdStudioViews(vtkLightFieldSceneLogic* logic, vtkRenderWindow* window);
  ~lfdStudioViews();
  lfdStudioViews(const lfdStudioViews&) = delete;
  lfdStudioViews& operator=(const lfdStudioViews&) = delete;

  ///@{
  /// Viewports of the renderers for `layout`; the hidden views are removed
  /// from the window so they cost nothing.
  void SetLayout(int layout);
  int GetLayout() const { return this->CurrentLayout; }
  ///@}

  /// Shows the logic's scene anew (after a load) in every view: its light
  /// field (null: none; the main view then shows nothing), settings and
  /// camera.
  void SetLightField(vtkLightField* lightField);

  /// Shows the scene at `time` of its keyframes (a negative time: the
  /// current, editable cage); `cage` is that cage, drawn in the rig view.
  void ShowCage(double time, vtkDeformationCage* cage);

  /// Puts the main view's camera where the scene's camera is.
  void ResetCamera();

  ///@{
  /// The gantry camera view's view index (also the rig view's current view)
  /// and pass (a vtkLightField::Pass or vtkGantryCameraView::NORMALISED),
  /// and the projector view's projector; out-of-range values are clamped.
  void SetCameraView(int view);
  int GetCameraView();
  void SetPass(int pass);
  int GetPass();
  void SetProjector(int projector);
  int GetProjector();
  ///@}

  /// The palette colour boxes of label `label` are drawn with.
  void GetLabelColour(int label, unsigned char rgb[3]);

  /// Whether the main view shows the last frame time (on by default).
  void SetFrameTimeVisible(bool visible);

  /// The light field shown (null: none).
  vtkLightField* GetLightField();

  /// The coverage of the gantry camera view's view (the smallest fraction
  /// of a label's pixels inside its rest boxes), -1 when it has none.
  double GetCoverage();

  ///@{
  /// The views, for their settings (brush, boxes) and events.
  vtkRenderer* GetMainRenderer();
  vtkLightFieldEditor* GetEditor();
  vtkGantryCameraView* GetGantryCameraView();
  vtkProjectorView* GetProjectorView();
  vtkRigView* GetRigView();
  ///@}

private:
  /// Applies a finished brush stroke to the logic: one undoable command.
  void ApplyStroke(vtkObject*, unsigned long, void*);

  vtkLightFieldSceneLogic* Logic;
  vtkRenderWindow* Window;
  vtkSmartPointer<vtkLightField> LightField;
  int CurrentLayout = MAIN_ONLY;

  vtkNew<vtkRenderer> Main;
  vtkNew<vtkRenderer> CameraRenderer;
  vtkNew<vtkRenderer> ProjectorRenderer;
  vtkNew<vtkRenderer> RigRenderer;
  vtkNew<vtkLightFieldEditor> Editor;
  vtkNew<vtkGantryCameraView> Camera;
  vtkNew<vtkProjectorView> Projector;
  vtkNew<vtkRigView> Rig;
};

#endif
