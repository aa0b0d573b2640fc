/**
 * @class   vtkLightFieldEditor
 * @brief   the interactive editing view without Qt: the deformed light field, the cage widget and
 * the scene logic in one vtkRenderer
 *
 * vtkLightFieldEditor is the main view of LightField Studio as a plain VTK
 * class, so that a C++ program or a Python script opens an editing window in
 * a few lines (Examples/EditScene.py):
 *
 * ```python
 * editor = lfd.vtkLightFieldEditor()
 * editor.GetLogic().Load("swim.json")
 * editor.Initialize()      # a vtkRenderWindow of 800 x 600 with an interactor
 * editor.Start()           # drag the corners; Ctrl+Z / Ctrl+Shift+Z undo / redo
 * ```
 *
 * It wires
 * - a vtkLightFieldSceneLogic (GetLogic(); one of its own unless one is
 *   set), whose light field and cage the view shows;
 * - a vtkLightFieldActor with a vtkLightFieldMapper drawing the light field
 *   deformed by the logic's cage (Chen, Ofek, Shum and Levoy, "Interactive
 *   Deformation of Light Fields", I3D 2005, Sec. 6: RENDER_VIEW at every
 *   frame), with the scene's focal distance, subdivision, widened search,
 *   object threshold and background;
 * - a vtkCageWidget on the logic's cage with ApplyToCage off: each drag (or
 *   any edit the widget brackets with Start/Interaction/EndInteractionEvent)
 *   is `BeginInteraction(); MovePoints(ids, positions) ...;
 *   EndInteraction()` on the logic, so one drag is one undoable command. A
 *   move the logic refuses (a box would fold) is not rendered: the handles
 *   go back to the logic's cage, i.e. to the last valid position of the
 *   drag, and the logic's message (its ErrorEvent, which a front end may
 *   observe too) is shown in the status line (GetStatusActor()) until the
 *   next applied edit. The handles the object hides cannot be picked: the
 *   widget's occluder is the mapper's depth image;
 * - the renderer (SetRenderer(): a viewport of the caller's window, as the
 *   Studio does; otherwise Initialize() makes a renderer, a render window
 *   and an interactor of its own).
 *
 * **Progressive refinement.** While a drag lasts the render window renders
 * at the interactor's DesiredUpdateRate, at which the mapper computes the
 * light field at 1 / InteractiveSubsampling of the resolution; the
 * EndInteractionEvent sets the StillUpdateRate back and renders once, at full
 * resolution. The frame time of the previous render of the renderer
 * (GetLastFrameTime()) and the resolution of the current one ("coarse 1/4"
 * or "full") are shown in the lower right corner (GetFrameTimeActor()).
 *
 * **Undo.** The logic's CageModifiedEvent (undo, redo, any other edit)
 * puts the handles on the logic's cage; SettingsModifiedEvent re-applies
 * the render settings. With UndoKeys on (the default), Ctrl+Z undoes and
 * Ctrl+Shift+Z redoes in the interactor (a front end with its own shortcuts,
 * such as the Studio's Edit menu, turns it off).
 *
 * **Time.** ShowTime() shows the scene at a time of its keyframes (the
 * logic's GetCageAtTime(): Catmull-Rom through the keys) for a timeline to
 * scrub; the widget then shows that pose and does not edit. ShowCurrentCage()
 * returns to the editable cage. EditAtTime() makes the pose at a time the
 * current cage (one undoable command) and shows it for editing, so that the
 * logic's SetKeyframe(time) keys the result.
 *
 * @sa vtkLightFieldSceneLogic vtkCageWidget vtkLightFieldMapper
 */
#ifndef vtkLightFieldEditor_h
#define vtkLightFieldEditor_h

#include "lfdSceneModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkCageWidget;
class vtkLightFieldActor;
class vtkLightFieldMapper;
class vtkLightFieldSceneLogic;
class vtkRenderWindow;
class vtkRenderWindowInteractor;
class vtkRenderer;
class vtkTextActor;

class LFDSCENE_EXPORT vtkLightFieldEditor : public vtkObject
{
public:
  static vtkLightFieldEditor* New();
  vtkTypeMacro(vtkLightFieldEditor, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene logic edited (never null: a new one by default). Setting one
   * after Initialize() shows it at once (as Initialize() does).
   */
  virtual void SetLogic(vtkLightFieldSceneLogic* logic);
  vtkGetObjectMacro(Logic, vtkLightFieldSceneLogic);
  ///@}

  ///@{
  /**
   * The renderer the view draws in, whose render window must have an
   * interactor by Initialize(). Not set: Initialize() creates a renderer, a
   * render window of 800 x 600 titled "LightField Editor" and an interactor
   * with a trackball camera style.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  /**
   * Shows the logic's scene: reads its light field (false, with the
   * logic's ErrorEvent, when there is none or it cannot be read: the view
   * then shows only the cage), sets the renderer's camera to the scene's,
   * applies the render settings and enables the widget. Call again after
   * the logic loads another scene.
   */
  bool Initialize();

  ///@{
  /**
   * The renderer's render window and its interactor (nullptr before
   * Initialize() when no renderer was set).
   */
  vtkRenderWindow* GetRenderWindow();
  vtkRenderWindowInteractor* GetInteractor();
  ///@}

  /**
   * Renders the render window.
   */
  void Render();

  /**
   * Renders, then runs the interactor's event loop until the window closes.
   */
  void Start();

  ///@{
  /**
   * The parts the editor wires (to tune them: the mapper's
   * InteractiveSubsampling, the widget's representation, the texts'
   * properties).
   */
  vtkLightFieldActor* GetActor();
  vtkLightFieldMapper* GetMapper();
  vtkCageWidget* GetWidget();
  vtkTextActor* GetFrameTimeActor();
  vtkTextActor* GetStatusActor();
  ///@}

  ///@{
  /**
   * Ctrl+Z undoes and Ctrl+Shift+Z redoes through the logic. Default on.
   */
  vtkSetMacro(UndoKeys, bool);
  vtkGetMacro(UndoKeys, bool);
  vtkBooleanMacro(UndoKeys, bool);
  ///@}

  ///@{
  /**
   * The timeline. ShowTime() shows the cage at `time` (false, with the
   * logic's ErrorEvent, when it is refused; false without one when the
   * scene has no cage) and stops editing; ShowCurrentCage() shows and edits
   * the current cage again. EditAtTime() moves every point to its position
   * at `time` (one command, "Move N points", skipped when none moves) and
   * shows the current cage. GetShowingTime() tells whether a time is shown,
   * GetTime() which (the last one shown or edited).
   */
  bool ShowTime(double time);
  void ShowCurrentCage();
  bool EditAtTime(double time);
  vtkGetMacro(ShowingTime, bool);
  vtkGetMacro(Time, double);
  ///@}

  ///@{
  /**
   * The duration of the last render of the renderer in seconds, and whether
   * the mapper computed it at a coarse resolution.
   */
  vtkGetMacro(LastFrameTime, double);
  vtkGetMacro(LastFrameCoarse, bool);
  ///@}

  /**
   * Whether a drag (an interaction of the widget) is under way.
   */
  vtkGetMacro(Interacting, bool);

protected:
  vtkLightFieldEditor();
  ~vtkLightFieldEditor() override;

  vtkLightFieldSceneLogic* Logic = nullptr;
  vtkRenderer* Renderer = nullptr;
  bool UndoKeys = true;
  bool ShowingTime = false;
  double Time = 0.0;
  double LastFrameTime = 0.0;
  bool LastFrameCoarse = false;
  bool Interacting = false;

private:
  vtkLightFieldEditor(const vtkLightFieldEditor&) = delete;
  void operator=(const vtkLightFieldEditor&) = delete;

  static void OnEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData);
  void OnWidgetEvent(unsigned long event);
  void OnLogicEvent(unsigned long event, void* callData);
  void OnKeyPress();
  void OnRenderEvent(unsigned long event);
  void ApplySettings();
  void CreateWindow();
  void ObserveInteractor(vtkRenderWindowInteractor* interactor);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
