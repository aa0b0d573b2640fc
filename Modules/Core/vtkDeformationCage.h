/**
 * @class   vtkDeformationCage
 * @brief   the deformation boxes of a scene: shared corners with rest and deformed positions,
 * labels
 *
 * vtkDeformationCage is the cage of DESIGN.md section 3 as a
 * vtkUnstructuredGrid, so it flows through VTK pipelines, writers and
 * widgets unchanged:
 *
 * - the points are the **deformed** corner positions;
 * - the point array "RestPosition" (double, 3 components) holds the **rest**
 *   positions;
 * - every box (Sec. 5 of the paper) is one VTK_HEXAHEDRON cell with its 8
 *   corners in VTK's hexahedron order (0-3 the bottom face
 *   counter-clockwise seen from above, 4-7 the top face above them);
 *   neighbouring boxes share corner points, which makes the cage map C0
 *   across their common faces;
 * - the cell array "Label" (int) holds each box's label, the sub-light field
 *   (part) it moves.
 *
 * Build one from a scene's grid with InitializeFromGrid(), or point by point
 * with AddPoint() and AddBox(). Validate() checks that the cage can be
 * rendered and used as a map (see there); vtkCageTransform is the map itself.
 *
 * The class lives in LFD::Core so that every module reads boxes through it
 * (the scene file, vtkBoxCoverageCheck, vtkLabelCellsByBoxes, the renderer):
 * the array names above are known here only.
 *
 * @sa vtkCageTransform vtkLightFieldScene
 */
#ifndef vtkDeformationCage_h
#define vtkDeformationCage_h

#include "lfdCoreModule.h" // For export macro
#include "vtkUnstructuredGrid.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkIdList;
class vtkInformation;
class vtkInformationVector;
class vtkLightField;

class LFDCORE_EXPORT vtkDeformationCage : public vtkUnstructuredGrid
{
public:
  static vtkDeformationCage* New();
  vtkTypeMacro(vtkDeformationCage, vtkUnstructuredGrid);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Replaces the content with a copy of `grid` (a scene's cage: see
   * vtkLightFieldScene). A grid without a "RestPosition" point array is taken
   * as undeformed (rest = points); "RestPosition" is stored as doubles and
   * "Label" as ints whatever their type in `grid`; a grid without "Label"
   * gets label 0 everywhere (which Validate() refuses). A null grid empties
   * the cage.
   */
  void InitializeFromGrid(vtkUnstructuredGrid* grid);

  /**
   * Why the boxes of `grid` (a cage on an algorithm's input port, which
   * InitializeFromGrid() then reads) would be made up rather than read, or
   * "": `grid` is null, has no "Label" cell array of one value per cell, or
   * has a "RestPosition" point array that does not hold 3 values per point.
   * A grid without "RestPosition" passes: it is at rest. The line starts
   * with "the cage".
   */
  static std::string CheckGridArrays(vtkUnstructuredGrid* grid);

  ///@{
  /**
   * Appends a corner point with its rest position (and deformed position,
   * the rest position when omitted). Returns its point id. Creates the
   * points (double precision) and the "RestPosition" array when missing.
   */
  vtkIdType AddPoint(const double rest[3]);
  vtkIdType AddPoint(const double rest[3], const double deformed[3]);
  ///@}

  ///@{
  /**
   * Rest and deformed position of a corner point (no range check).
   * SetDeformedPoint() and SetRestPoint() mark the cage modified.
   */
  void GetRestPoint(vtkIdType id, double rest[3]);
  void SetRestPoint(vtkIdType id, const double rest[3]);
  void GetDeformedPoint(vtkIdType id, double deformed[3]);
  void SetDeformedPoint(vtkIdType id, const double deformed[3]);
  ///@}

  /**
   * Appends a box whose corners are the point ids `corners` (VTK hexahedron
   * order) with label `label`. Returns the box index. The ids are not checked
   * here: Validate() does. Creates the "Label" array when missing.
   */
  int AddBox(const vtkIdType corners[8], int label);

  /**
   * Number of boxes (= number of cells).
   */
  vtkIdType GetNumberOfBoxes();

  /**
   * Label of box `box`, or 0 when the box or the "Label" array is missing.
   */
  int GetBoxLabel(vtkIdType box);

  ///@{
  /**
   * The 8 rest / deformed corners of box `box` as x0 y0 z0 x1 ... z7 (VTK
   * hexahedron order). Return false (and leave `corners` untouched) when the
   * box does not exist, is not a hexahedron or names a point that does not
   * exist.
   */
  bool GetRestCorners(vtkIdType box, double corners[24]);
  bool GetDeformedCorners(vtkIdType box, double corners[24]);
  ///@}

  /**
   * Axis-aligned bounds (xmin, xmax, ymin, ymax, zmin, zmax) of the rest
   * corners of box `box`; false, as GetRestCorners(), when it has none.
   */
  bool GetRestBounds(vtkIdType box, double bounds[6]);

  /**
   * Moves every point back to its rest position (undoes the deformation).
   */
  void SetPointsToRest();

  /**
   * True when some point differs from its rest position.
   */
  bool IsDeformed();

  /**
   * The largest distance between a point's deformed and rest positions (0 for
   * a cage at rest): how far a deformation moves the corners.
   */
  double GetLargestDisplacement();

  /**
   * Checks that the cage can be rendered and used as a map. Returns "" when
   * it can, else one line naming the first bad box (index and label). The
   * cage holds no error state and reports nothing: the caller does. Refused:
   * - the "RestPosition" or "Label" array is missing or of the wrong size;
   * - a cell is not a VTK_HEXAHEDRON or names a point that does not exist;
   * - a label is not in 1..255;
   * - `lightField` is given and its labels do not fit the boxes' (see
   *   ValidateLabels());
   * - the trilinear map of the rest or the deformed box (Eq. 2) folds,
   *   collapses or is inverted: its Jacobian determinant is not positive
   *   (above 1e-12 x BoxSize^3) at every point of a
   *   5 x 5 x 5 parametric lattice (the 8 corners, the centre, the 3 x 3 x 3
   *   interior points at 1/4, 1/2, 3/4, and the edge and face points);
   * - two rest boxes overlap: a point of one box's interior (a 5 x 5 x 5
   *   lattice whose outer layer lies 1e-3 inside the faces) is inside the
   *   other's interior (lfd::Contains with a negative slack). Boxes that only
   *   share faces, edges or corners pass; an overlap thinner than 1e-3 of a
   *   box may go unnoticed.
   */
  std::string Validate(vtkLightField* lightField = nullptr);

  /**
   * The checks of Validate() that one edit can break, for the boxes in
   * `boxes` only: the arrays, each listed box's cell, corners, label and rest
   * and deformed Jacobians, and the rest overlap of each listed box with
   * every other box. An interactive drag validates the boxes it moved at a
   * cost that does not grow with the other boxes' checks. Returns "" or the
   * same line Validate() would give for the first bad listed box; a box
   * index out of range is refused.
   */
  std::string ValidateBoxes(vtkIdList* boxes);

  /**
   * The label part of Validate(), which the renderer also runs: with a Label
   * pass, every box's label must occur in it (else the box would move no
   * sub-light field); without one, the light field is a single part whose
   * object pixels all belong to the boxes' one label, so boxes of two
   * different labels are refused with a message that says to split the
   * light field first. Returns "" or the one-line reason, as Validate().
   */
  std::string ValidateLabels(vtkLightField* lightField);

  /**
   * The "RestPosition" point array, or nullptr.
   */
  vtkDataArray* GetRestPositions();

  ///@{
  /**
   * Retrieve an instance of this class from an information object.
   */
  static vtkDeformationCage* GetData(vtkInformation* info);
  static vtkDeformationCage* GetData(vtkInformationVector* v, int i = 0);
  ///@}

protected:
  vtkDeformationCage();
  ~vtkDeformationCage() override;

private:
  vtkDeformationCage(const vtkDeformationCage&) = delete;
  void operator=(const vtkDeformationCage&) = delete;

  std::string ValidateArrays();
  std::string ValidateBox(vtkIdType box);
  std::string ValidateOverlaps(const std::vector<vtkIdType>& boxes);
  std::string ValidateListed(const std::vector<vtkIdType>& boxes, vtkLightField* lightField);
  bool GetCorners(vtkIdType box, bool rest, double corners[24]);
  vtkDataArray* GetOrCreateRestPositions();
  vtkDataArray* GetOrCreateLabels();
};

#endif
