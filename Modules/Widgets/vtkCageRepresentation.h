/**
 * @class   vtkCageRepresentation
 * @brief   the geometry, picking, selection and edits of vtkCageWidget: one handle per cage point
 *
 * vtkCageRepresentation shows and edits a vtkDeformationCage, the boxes of
 * Chen, Ofek, Shum and Levoy, "Interactive Deformation of Light Fields"
 * (I3D 2005), Sec. 5, whose corners the animator drags to deform the light
 * field. It is the representation half of VTK's widget/representation split
 * (as vtkBoxRepresentation is for vtkBoxWidget2): vtkCageWidget turns mouse
 * and key events into calls of the methods below, which any other front end
 * (a Qt dock, a Python script) can call as well.
 *
 * **Geometry.** One handle (a sphere glyph) per cage *point*: a corner
 * shared by two boxes is one handle and moves both boxes. The box edges are
 * drawn as lines coloured by each box's label through the palette
 * (SetPalette(); an edge shared by boxes of different labels takes the
 * colour of the lowest box index). Handles are drawn in HandleColor, the
 * hovered one in HoverColor, the selected ones in SelectedColor. All handles
 * are one glyph actor and all edges one line actor, whatever the number of
 * boxes.
 *
 * **Picking** (PickPoint()) takes the *visible, nearest* handle under the
 * cursor: among the points whose projection lies within PickTolerance
 * pixels of the cursor, the hidden ones are dropped, then the one nearest
 * to the cursor wins, and among those within one pixel of that distance the
 * one nearest to the eye. A point is hidden
 * - behind another box: the segment from the eye (the camera position, or
 *   for a parallel projection the point moved back along the direction of
 *   projection) to the point crosses a deformed face of a box that does not
 *   use that point. Faces are the exact bilinear patches of the trilinear
 *   boxes (lfd::IntersectBilinearPatch, the renderer's ray-face kernel);
 * - behind the object: when an occluder depth image is set
 *   (SetOccluderDepth(), e.g. the depth the light-field mapper wrote), the
 *   point's z-buffer depth exceeds the occluder's depth at its pixel by more
 *   than OccluderTolerance. The renderer's own z-buffer is not read (the
 *   handles and edges are in it too).
 * Rubber-band selection uses the same visibility test.
 *
 * **Selection**: SelectPoint() (replace or extend/toggle), SelectBox(),
 * SelectFace() (faces numbered as vtkHexahedron's: 0 = (0,4,7,3),
 * 1 = (1,2,6,5), 2 = (0,1,5,4), 3 = (3,7,6,2), 4 = (0,3,2,1),
 * 5 = (4,5,6,7)), SelectAll(), ClearSelection(), SelectInRectangle()
 * (rubber band), GetSelectedPointIds(). Every change invokes
 * SelectionChangedEvent on the representation.
 *
 * **Edits.** Every edit moves a set of points; the proposed absolute
 * deformed positions are GetMovedPointIds() / GetMovedPositions() (for the
 * current or last interaction). With ApplyToCage on (the default, the
 * standalone case) the representation writes them into the cage and calls
 * its Modified(), after validating the boxes that use a moved point
 * (vtkDeformationCage::ValidateBoxes): an interactive drag that would fold
 * a box is clamped (the handles stay at the last valid position along the
 * drag, found by bisection), and an API edit that would fold one is
 * refused (returns false, nothing changes). With ApplyToCage off the cage
 * is never touched: the handles show the proposal, the owner pushes it to
 * the scene logic (vtkLightFieldSceneLogic::MovePoints, which validates) on
 * each InteractionEvent and, if refused, calls UpdateFromCage() to put the
 * handles back on the cage's points.
 *
 * - Transforms of the selection about the pivot (SetPivotMode(): the
 *   selection's centroid, the PivotPoint, or the centre of the PivotBox):
 *   TranslateSelection(), RotateSelection(), ScaleSelection() (numeric
 *   entry) and the interactive StartTransform() / UpdateTransform() /
 *   ConfirmTransform() / CancelTransform() with the Constraint (an axis, or
 *   the plane perpendicular to an axis, as in Blender's lattice edit mode).
 * - Face operations: TwistFace(), TaperFace(); Bend() of the selection
 *   through a lattice (vtkLatticeCageFilter's free-form deformation);
 *   MirrorSelection() across a plane; ResetSelection() / ResetBox() to rest.
 *
 * **Events.** Each API edit (the numeric transforms, face operations,
 * mirror, reset) is one interaction: the representation invokes
 * StartInteractionEvent, InteractionEvent and EndInteractionEvent on itself
 * (vtkCageWidget relays them, and SelectionChangedEvent, to its own
 * observers). Interactive drags are bracketed by the widget, which invokes
 * the same three events on itself.
 *
 * @sa vtkCageWidget vtkDeformationCage vtkLabelPalette vtkLatticeCageFilter
 */
#ifndef vtkCageRepresentation_h
#define vtkCageRepresentation_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkCommand.h"       // For vtkCommand::UserEvent
#include "vtkWidgetRepresentation.h"

class vtkActor;
class vtkActor2D;
class vtkDeformationCage;
class vtkIdList;
class vtkImageData;
class vtkPoints;
class vtkUnsignedCharArray;

class LFDWIDGETS_EXPORT vtkCageRepresentation : public vtkWidgetRepresentation
{
public:
  static vtkCageRepresentation* New();
  vtkTypeMacro(vtkCageRepresentation, vtkWidgetRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Invoked on the representation (and relayed by vtkCageWidget) whenever
   * the set of selected points changes.
   */
  enum
  {
    SelectionChangedEvent = vtkCommand::UserEvent + 1001
  };

  /**
   * The interaction states (GetInteractionState()).
   */
  enum InteractionStateType
  {
    Outside = 0, ///< the cursor is over no handle
    OnHandle,    ///< the cursor is over a (visible) handle: HoverPointId
    Dragging,    ///< a handle drag moves the selection in the view plane
    RubberBand,  ///< a rectangle selection is being drawn
    Translating, ///< modal grab (G)
    Rotating,    ///< modal rotate (R)
    Scaling      ///< modal scale (S)
  };

  /**
   * Pivot of rotations and scalings (SetPivotMode()).
   */
  enum PivotModeType
  {
    PivotAtCentroid = 0, ///< the centroid of the selected points' positions
    PivotAtPoint,        ///< PivotPoint
    PivotAtBoxCentre     ///< the mean of the 8 deformed corners of PivotBox
  };

  /**
   * Constraint of interactive transforms (SetConstraint()).
   */
  enum ConstraintType
  {
    ConstraintNone = 0, ///< translate in the view plane, rotate about the view axis
    ConstraintX,        ///< along / about / scale along the X axis
    ConstraintY,
    ConstraintZ,
    ConstraintPlaneX, ///< in the plane perpendicular to X (scale Y and Z)
    ConstraintPlaneY,
    ConstraintPlaneZ
  };

  ///@{
  /**
   * The cage shown and edited. The representation keeps its own copy of
   * the handle positions, read from the cage by SetCage() and
   * UpdateFromCage() and whenever the cage is modified outside an
   * interaction. Setting a cage clears the selection.
   */
  virtual void SetCage(vtkDeformationCage* cage);
  vtkGetObjectMacro(Cage, vtkDeformationCage);
  ///@}

  /**
   * Puts the handles back on the cage's points (after the owner's logic
   * refused a proposal) and forgets the moved points of the current
   * interaction.
   */
  void UpdateFromCage();

  ///@{
  /**
   * The label colours (3 x uint8 per label, tuple 0 = unlabelled; see
   * vtkLabelPalette). Default nullptr: vtkLabelPalette's colours for as
   * many labels as the cage's largest label. A label beyond the palette is
   * drawn grey.
   */
  virtual void SetPalette(vtkUnsignedCharArray* palette);
  vtkGetObjectMacro(Palette, vtkUnsignedCharArray);
  ///@}

  ///@{
  /**
   * Write edits into the cage (default on, the standalone case), or only
   * propose them (GetMovedPointIds(), GetMovedPositions()) for an owner
   * that applies them through the scene logic.
   */
  vtkSetMacro(ApplyToCage, bool);
  vtkGetMacro(ApplyToCage, bool);
  vtkBooleanMacro(ApplyToCage, bool);
  ///@}

  ///@{
  /**
   * The points moved by the current (or last) interaction and their
   * proposed absolute deformed positions, in the same order. Both lists
   * are replaced (empty when nothing moved).
   */
  void GetMovedPointIds(vtkIdList* ids);
  void GetMovedPositions(vtkPoints* positions);
  ///@}

  /**
   * The position of point `id`'s handle (the proposal during an
   * interaction); false for an id out of range.
   */
  bool GetHandlePosition(vtkIdType id, double position[3]);

  ///@{
  /**
   * Handle radius as a fraction of the mean diagonal of the rest boxes.
   * Default 0.05.
   */
  vtkSetClampMacro(HandleSize, double, 1e-4, 0.5);
  vtkGetMacro(HandleSize, double);
  ///@}

  ///@{
  /**
   * Colours (RGB in 0..1) of the handles: normal, hovered, selected.
   */
  vtkSetVector3Macro(HandleColor, double);
  vtkGetVector3Macro(HandleColor, double);
  vtkSetVector3Macro(HoverColor, double);
  vtkGetVector3Macro(HoverColor, double);
  vtkSetVector3Macro(SelectedColor, double);
  vtkGetVector3Macro(SelectedColor, double);
  ///@}

  ///@{
  /**
   * Width of the box edges in pixels. Default 2.
   */
  vtkSetClampMacro(EdgeWidth, double, 0.5, 20.0);
  vtkGetMacro(EdgeWidth, double);
  ///@}

  ///@{
  /**
   * Largest distance in pixels between the cursor and a handle's projected
   * centre for the handle to be picked. Default 8.
   */
  vtkSetClampMacro(PickTolerance, double, 1.0, 100.0);
  vtkGetMacro(PickTolerance, double);
  ///@}

  ///@{
  /**
   * The depth of what hides handles (the object drawn by the light-field
   * mapper): a one-component image of the renderer's viewport size in the
   * renderer's z-buffer convention (0 near .. 1 far, 1 = nothing; pixel
   * (i, j) is viewport pixel (i, j) from the lower left). An image of
   * another size is sampled at the nearest pixel. nullptr (default): no
   * object occludes.
   */
  virtual void SetOccluderDepth(vtkImageData* depth);
  vtkGetObjectMacro(OccluderDepth, vtkImageData);
  ///@}

  ///@{
  /**
   * How much deeper than the occluder (in z-buffer units) a handle may be
   * and still count as visible. Default 1e-4.
   */
  vtkSetClampMacro(OccluderTolerance, double, 0.0, 1.0);
  vtkGetMacro(OccluderTolerance, double);
  ///@}

  /**
   * The visible, nearest point under display position (x, y) (see the
   * class description), or -1. Needs a renderer.
   */
  vtkIdType PickPoint(double x, double y);

  /**
   * Whether point `id` is visible from the renderer's camera: used by a
   * shown box (see SetBoxVisibility), not behind a face of a shown box that
   * does not use it, nor behind the occluder depth.
   */
  bool IsPointVisible(vtkIdType id);

  ///@{
  /**
   * Shows or hides box `box` of the cage (default: every box shown), as
   * Blender hides parts of a lattice: a hidden box draws no edges and hides
   * nothing behind it, and a handle whose boxes are all hidden is neither
   * drawn nor picked. The cage is not changed. A cage with another number
   * of boxes shows them all again.
   */
  void SetBoxVisibility(vtkIdType box, bool visible);
  bool GetBoxVisibility(vtkIdType box);
  ///@}

  /**
   * The point under the cursor (updated by ComputeInteractionState()), -1
   * for none.
   */
  vtkGetMacro(HoverPointId, vtkIdType);

  ///@{
  /**
   * Selection. SelectPoint() with `extend` false replaces the selection by
   * the point; with `extend` true it toggles the point in the selection
   * (shift-click). SelectBox() and SelectFace() replace the selection by the
   * box's 8 corners / the face's 4 corners (faces as in the class
   * description) and make the box the PivotBox. SelectInRectangle() selects
   * the visible points whose projections lie in the display rectangle
   * (corners in any order), replacing the selection or, with `extend`,
   * adding to it. Bad ids are errors and change nothing.
   */
  void SelectPoint(vtkIdType id, bool extend);
  void SelectBox(vtkIdType box);
  void SelectFace(vtkIdType box, int face);
  void SelectAll();
  void ClearSelection();
  void SelectInRectangle(double x0, double y0, double x1, double y1, bool extend);
  void GetSelectedPointIds(vtkIdList* ids);
  bool IsPointSelected(vtkIdType id);
  vtkIdType GetNumberOfSelectedPoints();
  ///@}

  ///@{
  /**
   * The pivot of rotations and scalings. Default PivotAtCentroid.
   */
  vtkSetClampMacro(PivotMode, int, PivotAtCentroid, PivotAtBoxCentre);
  vtkGetMacro(PivotMode, int);
  void SetPivotModeToCentroid() { this->SetPivotMode(PivotAtCentroid); }
  void SetPivotModeToPoint() { this->SetPivotMode(PivotAtPoint); }
  void SetPivotModeToBoxCentre() { this->SetPivotMode(PivotAtBoxCentre); }
  ///@}

  ///@{
  /**
   * The pivot for PivotAtPoint mode (world coordinates). Default (0, 0, 0).
   */
  vtkSetVector3Macro(PivotPoint, double);
  vtkGetVector3Macro(PivotPoint, double);
  ///@}

  ///@{
  /**
   * The box whose centre is the pivot in PivotAtBoxCentre mode; -1 (default)
   * means the box using the most selected points (the lowest index on
   * ties). SelectBox() and SelectFace() set it.
   */
  vtkSetMacro(PivotBox, vtkIdType);
  vtkGetMacro(PivotBox, vtkIdType);
  ///@}

  /**
   * The current pivot (see PivotMode); false when it is undefined (no
   * selection for PivotAtCentroid, no box for PivotAtBoxCentre).
   */
  bool GetPivot(double pivot[3]);

  ///@{
  /**
   * The constraint of interactive transforms (ConstraintType). Default
   * ConstraintNone. UpdateTransform() uses the current value, so a key can
   * change it in the middle of a transform.
   */
  vtkSetClampMacro(Constraint, int, ConstraintNone, ConstraintPlaneZ);
  vtkGetMacro(Constraint, int);
  ///@}

  ///@{
  /**
   * Numeric transforms of the selection, each one interaction
   * (Start/Interaction/EndInteractionEvent): translate by (dx, dy, dz);
   * rotate by `degrees` about the axis through the pivot (right-handed,
   * the axis need not be unit); scale by (sx, sy, sz) along X, Y, Z about
   * the pivot. Return false (nothing moves, no event) when nothing is
   * selected, the parameters are invalid or, with ApplyToCage, a box would
   * fold.
   */
  bool TranslateSelection(double dx, double dy, double dz);
  bool RotateSelection(const double axis[3], double degrees);
  bool ScaleSelection(double sx, double sy, double sz);
  ///@}

  ///@{
  /**
   * Face operations, each one interaction. TwistFace() rotates the face's
   * 4 corners by `degrees` about the box axis through the face's centre
   * (the line from the opposite face's centre to this face's centre,
   * right-handed about the outward direction). TaperFace() scales the
   * face's corners about the face's centre by `scale` perpendicular to that
   * axis. Bend() bends the selected points by `degrees` about the
   * coordinate axis `axis` (0, 1, 2): the free-form deformation of
   * vtkLatticeCageFilter over the selection's bounding box, with
   * LatticeResolution control points along the longest of the two other
   * axes placed on a circular arc of that total angle (the bar's middle
   * stays, its ends turn by +-degrees/2). Return false as the numeric
   * transforms.
   */
  bool TwistFace(vtkIdType box, int face, double degrees);
  bool TaperFace(vtkIdType box, int face, double scale);
  bool Bend(int axis, double degrees);
  ///@}

  ///@{
  /**
   * Control points of Bend()'s lattice along the bent axis (3..16).
   * Default 5.
   */
  vtkSetClampMacro(LatticeResolution, int, 3, 16);
  vtkGetMacro(LatticeResolution, int);
  ///@}

  /**
   * Mirrors the deformation of the selected points across the plane
   * through `origin` with normal `normal`: for each selected point p whose
   * rest position, reflected across the plane, is the rest position of a
   * point q (within 1e-6 of the cage's rest diagonal), q's displacement
   * from rest becomes the reflection of p's displacement (its component
   * along the normal flips). When both p and q are selected, the one on
   * the normal's side of the plane is the source. Points on the plane and
   * points without a mirror image are left alone. One interaction; false
   * when no point moves or a box would fold (ApplyToCage).
   */
  bool MirrorSelection(const double origin[3], const double normal[3]);

  ///@{
  /**
   * Puts the selected points / the 8 corners of `box` back at their rest
   * positions. One interaction; false when there is nothing to reset.
   */
  bool ResetSelection();
  bool ResetBox(vtkIdType box);
  ///@}

  ///@{
  /**
   * Interactive transforms of the selection (the widget's G/R/S keys):
   * StartTransform() remembers the selection's positions and the cursor
   * (`mode` is Translating, Rotating or Scaling; false when nothing is
   * selected), UpdateTransform() moves the selection for the cursor's new
   * position under the Constraint (translate: the cursor's motion in the
   * plane through the pivot parallel to the view plane, or along the
   * constrained axis as the axis appears on screen, or in the constrained
   * plane; rotate: the angle swept around the pivot's projection, about
   * the view direction or the constrained axis; scale: the ratio of the
   * cursor's distances to the pivot's projection, uniformly, along the
   * axis or in the plane), ConfirmTransform() ends it, CancelTransform()
   * puts the points back where they started. A handle drag is
   * StartTransform(Dragging, ...) (translate through the picked handle).
   * The widget brackets these with the interaction events.
   */
  bool StartTransform(int mode, double x, double y);
  void UpdateTransform(double x, double y);
  void ConfirmTransform();
  void CancelTransform();
  ///@}

  ///@{
  /**
   * The rubber band (display coordinates): drawn from the start to the
   * current corner, SelectInRectangle() on the end.
   */
  void StartRubberBand(double x, double y);
  void UpdateRubberBand(double x, double y);
  void EndRubberBand(double x, double y, bool extend);
  ///@}

  ///@{
  /**
   * vtkWidgetRepresentation API. ComputeInteractionState() picks the
   * handle under (X, Y) and sets the hover highlight; PlaceWidget() does
   * nothing (the cage places the handles); GetBounds() is the bounds of
   * the handles.
   */
  void BuildRepresentation() override;
  int ComputeInteractionState(int X, int Y, int modify = 0) override;
  void PlaceWidget(double bounds[6]) override;
  double* GetBounds() VTK_SIZEHINT(6) override;
  void SetInteractionState(int state);
  ///@}

  ///@{
  /**
   * Rendering (vtkProp API).
   */
  void GetActors(vtkPropCollection* pc) override;
  void GetActors2D(vtkPropCollection* pc) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  int RenderOverlay(vtkViewport* viewport) override;
  int RenderTranslucentPolygonalGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override;
  ///@}

protected:
  vtkCageRepresentation();
  ~vtkCageRepresentation() override;

  vtkDeformationCage* Cage = nullptr;
  vtkUnsignedCharArray* Palette = nullptr;
  vtkImageData* OccluderDepth = nullptr;
  bool ApplyToCage = true;
  double HandleSize = 0.05;
  double HandleColor[3] = { 0.9, 0.9, 0.9 };
  double HoverColor[3] = { 1.0, 1.0, 0.2 };
  double SelectedColor[3] = { 1.0, 0.45, 0.0 };
  double EdgeWidth = 2.0;
  double PickTolerance = 8.0;
  double OccluderTolerance = 1e-4;
  vtkIdType HoverPointId = -1;
  int PivotMode = PivotAtCentroid;
  double PivotPoint[3] = { 0.0, 0.0, 0.0 };
  vtkIdType PivotBox = -1;
  int Constraint = ConstraintNone;
  int LatticeResolution = 5;

private:
  vtkCageRepresentation(const vtkCageRepresentation&) = delete;
  void operator=(const vtkCageRepresentation&) = delete;

  // Reads the cage into the handles when it changed outside an interaction.
  void SyncFromCage(bool force);
  // Moves the points of Internals->Moving to Internals->Proposed: the
  // proposal, and with ApplyToCage the validated (or clamped) cage points.
  bool Propose(bool clamp);
  // One API edit of Internals->Moving to Internals->Proposed, bracketed by
  // the interaction events.
  bool RunEdit();
  bool SetSelection(const vtkIdType* ids, vtkIdType count, bool extend);
  bool CheckBoxFace(vtkIdType box, int face);
  void ComputeTransform(double x, double y);
  void UpdateGeometry();
  vtkUnsignedCharArray* GetUsedPalette();

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
