/**
 * @class   vtkLightFieldSceneLogic
 * @brief   the scene behind every front end: light field, cage, keyframes, camera and render
 * settings, edited through an undo/redo stack
 *
 * vtkLightFieldSceneLogic is the one place where scene behaviour lives, in
 * the manner of 3D Slicer's Logic classes: no GUI, testable, scriptable from
 * Python (`lfd.vtkLightFieldSceneLogic`). The `lfd` command line, the Python
 * API and the Studio all go through it, so a user action is the same edit
 * whichever front end makes it.
 *
 * It owns:
 * - the scene document (GetScene(): a vtkLightFieldScene, `scene.json`),
 *   read with Load() and written with Save();
 * - the cage (GetCage()): a vtkDeformationCage that the scene document
 *   shares (the scene's GetCage() is this object);
 * - the light field the scene names (GetLightField(): read through the
 *   scene's path on first use and cached until that path changes), or one
 *   given with SetLightField();
 * - the keyframes, the view camera and the render settings, held by the
 *   scene document.
 *
 * It builds cages (from a labelled mesh with vtkPartCageSource, from N slabs
 * along an axis, from a Sederberg-Parry lattice with vtkLatticeCageFilter),
 * gives the cage at a time of the keyframes (Catmull-Rom or linear through
 * vtkKeyframeInterpolator) and validates the cage.
 *
 * Every edit is a command on an undo/redo stack, modelled on Qt's
 * QUndoStack without Qt: MovePoints(), AddBox(), RemoveBox(), SplitBox(),
 * SetBoxLabel(), SetKeyframe(), RemoveKeyframe(), the Build...() methods and
 * the settings (SetSize(), SetFocalDistance(), SetSubdivision(),
 * SetWidenedSearch(), SetObjectThreshold(), SetBackground(), SetCamera()).
 * An edit that would leave the scene invalid (a move that folds a box, a
 * label out of 1..255, a degenerate camera) is not applied: the method
 * returns false and reports the reason with vtkErrorMacro (an ErrorEvent
 * whose text names the box, field or value). Undo() and Redo() replay the
 * stack; the scene then saves byte for byte as it did before.
 *
 * SetProjectorMask() paints the light field's projector masks (Chen et al.
 * 2005, section 4.1: masks painted by hand), also one undoable command.
 *
 * Each applied, undone or redone command invokes the event of what it
 * changed (CageModifiedEvent, KeyframesModifiedEvent,
 * SettingsModifiedEvent or ProjectorMasksModifiedEvent; a cage build that drops the keyframes
 * invokes both of the first two), then ModifiedEvent, then UndoStackModifiedEvent. A refused edit
 * invokes only ErrorEvent.
 *
 * A drag is one command: between BeginInteraction() and EndInteraction(),
 * consecutive MovePoints() of the same points merge into one, whose undo
 * puts the points back where the drag started. Validation per drag is cheap:
 * a move re-checks only the boxes using a moved point (their deformed
 * trilinear map, Eq. 2 of the paper, must not fold; rest boxes do not
 * change on a move); GetNumberOfBoxesLastValidated() tells how many.
 *
 * @sa vtkLightFieldScene vtkDeformationCage vtkKeyframeInterpolator
 */
#ifndef vtkLightFieldSceneLogic_h
#define vtkLightFieldSceneLogic_h

#include "lfdSceneModule.h" // For export macro
#include "vtkCommand.h"     // For vtkCommand::UserEvent
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkCamera;
class vtkCameraRig;
class vtkDataSet;
class vtkDeformationCage;
class vtkGroundTruthEvaluator;
class vtkIdList;
class vtkImageData;
class vtkLatticeCageFilter;
class vtkLightField;
class vtkLightFieldRenderer;
class vtkLightFieldScene;
class vtkPoints;
class vtkPolyData;

class LFDSCENE_EXPORT vtkLightFieldSceneLogic : public vtkObject
{
public:
  static vtkLightFieldSceneLogic* New();
  vtkTypeMacro(vtkLightFieldSceneLogic, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The events a command invokes (after the change, before ModifiedEvent).
   */
  enum Events
  {
    CageModifiedEvent = vtkCommand::UserEvent + 900,
    KeyframesModifiedEvent,
    SettingsModifiedEvent,
    UndoStackModifiedEvent,
    ProjectorMasksModifiedEvent
  };

  ///@{
  /**
   * Reads / writes `scene.json` (see vtkLightFieldScene). Load() replaces
   * the scene, drops the cached light field and clears the undo stack; on
   * failure both return false, report the scene's error line with
   * vtkErrorMacro and change nothing.
   */
  bool Load(const char* fileName);
  bool Save(const char* fileName);
  ///@}

  /**
   * Empties the scene (defaults of vtkLightFieldScene, no cage, no light
   * field) and clears the undo stack.
   */
  void NewScene();

  /**
   * Adopts `scene`, a document built elsewhere (a demo, a script), as 3D
   * Slicer's logics are given their scene: its cage is copied into the
   * logic's cage, which the document then shares; the cached light field is
   * dropped and the undo stack cleared. Null starts a new scene.
   */
  void SetScene(vtkLightFieldScene* scene);

  /**
   * The scene document. Change it through the logic's commands: an edit made
   * on the document directly is not undoable.
   */
  vtkLightFieldScene* GetScene();

  /**
   * The cage (never null; no boxes when the scene has none). Change it
   * through the logic's commands.
   */
  vtkDeformationCage* GetCage();

  ///@{
  /**
   * The light field. GetLightField() reads the one the scene names on first
   * use and keeps it until the resolved path changes; it returns nullptr
   * (with an ErrorEvent naming the scene file or the dataset) when the scene
   * names none or it cannot be read. SetLightField() gives one built in
   * memory, used until the next Load() or NewScene().
   */
  vtkLightField* GetLightField();
  void SetLightField(vtkLightField* lightField);
  ///@}

  /**
   * Checks the whole cage (vtkDeformationCage::Validate), against the light
   * field when one was set or already read (this does not read one). False
   * with an ErrorEvent naming the scene file and the box when it is refused.
   */
  bool Validate();

  /**
   * Fills `cage` with the scene's cage at `time`: the points are the
   * Catmull-Rom interpolation of the keyframes (the current points when the
   * scene has none), then validated against `lightField` (may be null).
   * False with an ErrorEvent naming the scene file when a keyframe or the
   * cage is refused; false without one when the scene has no cage.
   */
  bool GetCageAtTime(double time, vtkLightField* lightField, vtkDeformationCage* cage);

  ///@{
  /**
   * How GetCageAtTime() (and so an animation export of this logic)
   * interpolates the keyframes: vtkKeyframeInterpolator::CATMULL_ROM (the
   * default, what `lfd animate` always rendered) or
   * vtkKeyframeInterpolator::LINEAR. It is the scene's (saved in scene.json
   * as "interpolation"); SetInterpolation() is an undoable command, refused
   * for a value that is neither.
   */
  bool SetInterpolation(int interpolation);
  int GetInterpolation();
  ///@}

  /**
   * Fills `cage` with the scene's cage as it stands (the current points),
   * validated against `lightField` (may be null), as GetCageAtTime().
   */
  bool GetCurrentCage(vtkLightField* lightField, vtkDeformationCage* cage);

  /**
   * True when the scene has a cage (at least one point).
   */
  bool HasCage();

  /**
   * The time of frame `frame` of an animation of `frames` frames spread
   * evenly from the first to the last keyframe time (0 without keyframes).
   */
  double GetAnimationTime(int frame, int frames);

  ///@{
  /**
   * The scene's view on a renderer or a ground-truth evaluator: camera,
   * image size, focal distance, subdivision (0 = "auto" in all three),
   * widened search and object threshold. ConfigureRenderer() also gives the
   * renderer `lightField`, `cage` (null: no deformation) and the background.
   */
  void ApplyView(vtkLightFieldRenderer* renderer);
  void ApplyView(vtkGroundTruthEvaluator* evaluator);
  void ConfigureRenderer(vtkLightFieldRenderer* renderer,
    vtkLightField* lightField,
    vtkDeformationCage* cage);
  ///@}

  /**
   * Labels the cells of `mesh` by the scene's rest boxes (a triangle takes
   * the box holding its centroid, vtkLabelCellsByBoxes) into `labelled`: how
   * a mesh gets the parts the scene's light field was split into. False
   * with an ErrorEvent when the labelling fails.
   */
  bool LabelMesh(vtkPolyData* mesh, vtkPolyData* labelled);

  /**
   * Places `camera` on a circle `scale` times the rig radius around the rig
   * axis, at azimuth `phi` (radians from view 0's frame, see
   * vtkCameraRig::GetAzimuthFrame) and `height` along the axis, looking at
   * the rig centre with view up along the axis and `viewAngle` degrees:
   * novel views around a ring. The rig must have a fitted cylinder.
   */
  static void OrbitCamera(vtkCameraRig* rig,
    double phi,
    double scale,
    double height,
    double viewAngle,
    vtkCamera* camera);

  ///@{
  /**
   * Cage builds, each one undoable command that replaces the cage and
   * drops the keyframes (they name the old points):
   * - BuildCageFromLabels(): one slab box per labelled part of `mesh` (a
   *   cell array "Label"), along `axis` (0, 1, 2; -1 the longest side), see
   *   vtkPartCageSource;
   * - BuildCageFromSlabs(): `count` boxes stacked along `axis` (0, 1, 2; -1
   *   the coordinate axis nearest the rig's ring axis, which needs a light
   *   field with a fitted ring) filling `bounds` (xmin, xmax, ymin, ymax,
   *   zmin, zmax), all with label `label`, sharing their corners;
   * - BuildCageFromLattice(): the current rest boxes deformed by the
   *   lattice of `lattice` (its control point displacements, region and
   *   subdivision as configured; its input is set here).
   * False with an ErrorEvent when the build fails or its cage is refused.
   */
  bool BuildCageFromLabels(vtkDataSet* mesh, int axis);
  bool BuildCageFromSlabs(const double bounds[6], int count, int axis, int label);
  bool BuildCageFromLattice(vtkLatticeCageFilter* lattice);
  ///@}

  /**
   * Replaces the cage by a copy of `cage` (one undoable command, "Replace
   * cage"; the keyframes are dropped), refused when the whole cage does not
   * validate.
   */
  bool ReplaceCage(vtkDeformationCage* cage);

  ///@{
  /**
   * Moves cage points to deformed positions: `ids` and `positions` have the
   * same count. Only the boxes using a moved point are validated; a move
   * that folds one of them is refused.
   */
  bool MovePoints(vtkIdList* ids, vtkPoints* positions);
  bool MovePoint(vtkIdType id, const double position[3]);
  bool MovePoint(vtkIdType id, double x, double y, double z)
  {
    const double position[3] = { x, y, z };
    return this->MovePoint(id, position);
  }
  ///@}

  /**
   * Adds an axis-aligned box on 8 new points (at rest) filling `bounds`
   * with label `label`; keyframes get the new points at their rest position.
   * Returns the new box's index, or -1 when refused (an overlap with another
   * rest box, a label out of 1..255, empty bounds).
   */
  vtkIdType AddBox(const double bounds[6], int label);

  /**
   * Removes box `box`, and the points no other box uses (point ids above
   * them shift down, in the cage and in every keyframe).
   */
  bool RemoveBox(vtkIdType box);

  /**
   * Splits box `box` in two halves across its parametric axis `axis` (0: u,
   * corners 0-1; 1: v, corners 0-3; 2: w, corners 0-4). The 4 new points sit
   * at the trilinear midpoints of the box's 4 edges along that axis, in rest
   * space, in the current points and in every keyframe, so the deformation
   * is unchanged. Both halves keep the label. A neighbour sharing one of
   * those edges keeps its corners: moving a new point then opens that face.
   */
  bool SplitBox(vtkIdType box, int axis);

  /**
   * Sets the label of box `box` (1..255; with a light field, one that it
   * holds).
   */
  bool SetBoxLabel(vtkIdType box, int label);

  ///@{
  /**
   * SetKeyframe() records the current cage points as the keyframe at `time`
   * (replacing the one at that time; keyframes are kept in time order).
   * RemoveKeyframe() removes keyframe `index`.
   */
  bool SetKeyframe(double time);
  bool RemoveKeyframe(int index);
  ///@}

  ///@{
  /**
   * Render settings, each one undoable command validated as scene.json is
   * (see vtkLightFieldScene): image size in [1, lfd::MaximumRenderSize], the
   * focal distance finite, the subdivision 0 ("auto") or in
   * [1, lfd::MaximumSubdivision], the widened search in [0, 64], the object
   * threshold in [0, 255], the background in [0, 1]. SetCamera() copies
   * position, focal point, view up and view angle of `camera`, which must
   * pass lfd::CheckLookAt.
   */
  bool SetSize(int width, int height);
  bool SetFocalDistance(double distance);
  bool SetSubdivision(int subdivision);
  bool SetWidenedSearch(int views);
  bool SetObjectThreshold(double threshold);
  bool SetBackground(double r, double g, double b);
  bool SetCamera(vtkCamera* camera);
  ///@}

  /**
   * Replaces projector `projector`'s slice of the light field's projector
   * masks (vtkLightField::GetProjectorMasks()) by `mask`: an RGB uint8
   * image (scalars or a "Mask" array) of the masks' width x height, rows
   * bottom first, e.g. vtkProjectorView::GetStrokeMask(). One undoable
   * command ("Paint projector mask") that invokes
   * ProjectorMasksModifiedEvent; its undo restores the slice exactly, in
   * the masks it painted. Refused (false, ErrorEvent naming the projector)
   * without a light field or masks, for a projector out of range, or a mask
   * of another size or type. The masks live in the light field, not in
   * scene.json: save them as images (vtkProjectorView::WriteMask()).
   */
  bool SetProjectorMask(int projector, vtkImageData* mask);

  ///@{
  /**
   * One drag, one command: MovePoints() calls between the two that move
   * the same points merge into one command. Nested calls count.
   */
  void BeginInteraction();
  void EndInteraction();
  ///@}

  ///@{
  /**
   * The undo/redo stack. Undo() and Redo() return false when there is
   * nothing to undo or redo. The names ("Move 3 points", "Add box",
   * "Set focal distance", ...) are those an Edit menu shows after
   * "Undo " / "Redo "; "" when there is none.
   */
  bool Undo();
  bool Redo();
  bool CanUndo() const;
  bool CanRedo() const;
  void ClearUndo();
  std::string GetUndoName() const;
  std::string GetRedoName() const;
  int GetNumberOfCommands() const;
  int GetUndoIndex() const;
  ///@}

  /**
   * How many boxes the last validation checked: those using a moved point
   * after MovePoints(), every box after Validate() or a build.
   */
  vtkGetMacro(NumberOfBoxesLastValidated, vtkIdType);

protected:
  vtkLightFieldSceneLogic();
  ~vtkLightFieldSceneLogic() override;

  vtkIdType NumberOfBoxesLastValidated = 0;

private:
  vtkLightFieldSceneLogic(const vtkLightFieldSceneLogic&) = delete;
  void operator=(const vtkLightFieldSceneLogic&) = delete;

  bool Refuse(const std::string& reason);
  std::string Where() const;
  bool CheckCage(vtkIdList* boxes);
  bool FillCage(const double* time, vtkLightField* lightField, vtkDeformationCage* cage);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
