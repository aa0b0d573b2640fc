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
 * - the gantry camera view shows one captured view's photo in one pass
 *   (coaxial, coded, flood, label in palette colours, depth and confidence
 *   in grey);
 * - the projector view shows one projector's colour mask;
 * - the rig view (3D) shows the camera centres coloured by ring row, the
 *   projector centres, the deformed cage and the light field's bounds.
 * Only the main view's cage widget edits the logic (through the editor);
 * the other views read it.
 */
#ifndef lfdStudioViews_h
#define lfdStudioViews_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

class vtkActor;
class vtkActor2D;
class vtkDeformationCage;
class vtkImageActor;
class vtkImageData;
class vtkLightField;
class vtkLightFieldEditor;
class vtkLightFieldSceneLogic;
class vtkObject;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkTextActor;

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
  /// The gantry camera view's view index and pass, and the projector
  /// view's projector; out-of-range values are clamped.
  void SetCameraView(int view);
  int GetCameraView() const { return this->CameraView; }
  void SetPass(int pass);
  int GetPass() const { return this->Pass; }
  void SetProjector(int projector);
  int GetProjector() const { return this->Projector; }
  ///@}

  /// The palette colour boxes of label `label` are drawn with.
  void GetLabelColour(int label, unsigned char rgb[3]);

  /// Whether the main view shows the last frame time (on by default).
  void SetFrameTimeVisible(bool visible);

  /// The light field shown (null: none).
  vtkLightField* GetLightField();

  vtkRenderer* GetMainRenderer();
  vtkLightFieldEditor* GetEditor();

private:
  void UpdateCameraImage();
  void UpdateProjectorImage();
  void UpdateRig();

  vtkLightFieldSceneLogic* Logic;
  vtkRenderWindow* Window;
  vtkSmartPointer<vtkLightField> LightField;
  int CurrentLayout = MAIN_ONLY;
  int CameraView = 0;
  int Pass = 0;
  int Projector = 0;

  vtkNew<vtkRenderer> Main;
  vtkNew<vtkRenderer> Camera;
  vtkNew<vtkRenderer> ProjectorView;
  vtkNew<vtkRenderer> Rig;
  vtkNew<vtkLightFieldEditor> Editor;
  vtkNew<vtkActor> RigCageEdges;
  vtkNew<vtkImageActor> CameraImage;
  vtkNew<vtkTextActor> CameraCaption;
  vtkNew<vtkImageActor> ProjectorImage;
  vtkNew<vtkTextActor> ProjectorCaption;
  vtkNew<vtkActor> RigCameras;
  vtkNew<vtkActor> RigBounds;
};

#endif
