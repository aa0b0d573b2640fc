/**
 * @class   vtkPartCageSource
 * @brief   builds a cage of one box per labelled part, as slabs along an axis
 *
 * vtkPartCageSource turns a labelled mesh (input port 0: a vtkDataSet, in
 * practice a vtkPolyData, with an integer cell array "Label"; 1..N = parts,
 * 0 or less = background and ignored) into a vtkDeformationCage of the kind
 * the paper deforms: the fish of Fig. 13 and the twisted objects of Fig. 1
 * (Chen, Ofek, Shum, Levoy, "Interactive Deformation of Light Fields",
 * I3D 2005) are covered by a row of boxes, one per part, stacked along the
 * object's long axis.
 *
 * The boxes are slabs along Axis (0, 1, 2 or -1 = the longest axis of the
 * mesh bounds):
 * - parts are ordered by the mean of their cell centroids along the axis;
 * - the boundary between two consecutive parts is the middle of the overlap
 *   of their extents along the axis (or the middle of the gap between them);
 * - the first and last faces lie at the mesh extent along the axis, pushed
 *   out by Margin times the mesh size (its largest bounding-box side);
 * - every box's cross-section is the mesh bounds in the two other axes,
 *   pushed out by the same margin.
 *
 * Consecutive boxes share their 4 boundary corners, so the cage map is C0
 * across them (DESIGN.md section 2): N parts give N boxes on 4 (N + 1)
 * points, in VTK's hexahedron order with a positive Jacobian (boxes are
 * axis-aligned with corner 1 along +x, 3 along +y, 4 along +z). Points
 * are created in layers: layer k (k = 0..N along the axis) holds the points
 * 4k..4k+3. Each box carries its part's label. The cage is at rest (points
 * = rest positions); pose it with vtkCagePoseFilter or by moving points.
 *
 * Errors (vtkErrorMacro, empty output): no input, no "Label" cell array, no
 * cell with a label in 1..255, a label above 255, a mesh of zero size, or
 * parts that slabs cannot separate (one part's extent nested in another's so
 * that the boundaries are not increasing).
 *
 * @sa vtkDeformationCage vtkCagePoseFilter
 */
#ifndef vtkPartCageSource_h
#define vtkPartCageSource_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkDeformationCageAlgorithm.h"

class vtkDeformationCage;

class LFDDEFORMATION_EXPORT vtkPartCageSource : public vtkDeformationCageAlgorithm
{
public:
  static vtkPartCageSource* New();
  vtkTypeMacro(vtkPartCageSource, vtkDeformationCageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The slab axis: 0 (x), 1 (y), 2 (z) or -1 (default) for the longest side
   * of the mesh bounds.
   */
  vtkSetClampMacro(Axis, int, -1, 2);
  vtkGetMacro(Axis, int);
  ///@}

  ///@{
  /**
   * How far the cage reaches beyond the mesh, as a fraction of the mesh size
   * (its largest bounding-box side), on the outer faces and the sides.
   * Default 0.05.
   */
  vtkSetClampMacro(Margin, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Margin, double);
  ///@}

  /**
   * The axis used by the last update (the resolved one when Axis is -1), or
   * -1 before any successful update.
   */
  vtkGetMacro(UsedAxis, int);

protected:
  vtkPartCageSource();
  ~vtkPartCageSource() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Axis = -1;
  double Margin = 0.05;
  int UsedAxis = -1;

private:
  vtkPartCageSource(const vtkPartCageSource&) = delete;
  void operator=(const vtkPartCageSource&) = delete;
};

#endif
