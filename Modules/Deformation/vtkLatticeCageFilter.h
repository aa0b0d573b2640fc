/**
 * @class   vtkLatticeCageFilter
 * @brief   samples a smooth lattice deformation (Sederberg-Parry FFD) into the boxes of a cage
 *
 * The paper's boxes (Chen, Ofek, Shum, Levoy, "Interactive Deformation of
 * Light Fields", I3D 2005, Sec. 5) deform each part by one trilinear map,
 * so a part can twist but not curve. vtkLatticeCageFilter lets a part bend
 * (DESIGN.md section 4.4): it deforms the cage by a free-form deformation
 * of Sederberg and Parry ("Free-Form Deformation of Solid Geometric
 * Models", SIGGRAPH 1986), a lattice of (l+1) x (m+1) x (n+1) control
 * points over an axis-aligned region whose trivariate Bernstein polynomial
 * moves every point of the region (kernel: lfdBernstein.h), and samples it
 * into boxes:
 *
 * - the input (a vtkDeformationCage, or any vtkUnstructuredGrid read as one
 *   by vtkDeformationCage::InitializeFromGrid) gives the rest boxes and
 *   their labels; its deformed positions are ignored;
 * - every rest box is split into Subdivision^3 sub-boxes whose rest corners
 *   are the images of the box's parametric sub-grid under its trilinear map
 *   (Eq. 2); sub-boxes carry the label of their box, and corners at the same
 *   rest position (within 1e-9 of the region's diagonal) are one point, so
 *   the output is C0 across the faces of sub-boxes and of neighbouring
 *   boxes alike. The input's points keep their ids (0..N-1); new points
 *   follow;
 * - every point's deformed position is the FFD of its rest position.
 *
 * The output is an ordinary cage (scene.json's "cage"): its trilinear boxes
 * interpolate the FFD at their corners, and the error at the boxes' centres
 * falls as the boxes shrink (about 1 / Subdivision^2). Subdivision = 1
 * keeps the input's boxes and points and only moves them.
 *
 * The lattice is given by control-point displacements (zero = at rest, the
 * identity); SetLatticeDimensions() sets the number of control points per
 * axis and puts them all back at rest. Points outside Region do not move
 * (SP86); the default region is the rest bounds of the input cage. As with
 * vtkCagePoseFilter, strong deformations may fold boxes, which
 * vtkDeformationCage::Validate() reports.
 *
 * Errors (vtkErrorMacro, empty output): no input, an input without points
 * or with a box that is not a hexahedron of existing points, a region with
 * no volume.
 *
 * @sa vtkDeformationCage vtkCagePoseFilter vtkPartCageSource vtkCageTransform
 */
#ifndef vtkLatticeCageFilter_h
#define vtkLatticeCageFilter_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkDeformationCageAlgorithm.h"

#include <vector> // For the control-point displacements

class LFDDEFORMATION_EXPORT vtkLatticeCageFilter : public vtkDeformationCageAlgorithm
{
public:
  static vtkLatticeCageFilter* New();
  vtkTypeMacro(vtkLatticeCageFilter, vtkDeformationCageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Control points per axis, (l+1, m+1, n+1), each 2..16 (degrees 1..15).
   * Setting them puts every control point back at rest. Default (2, 2, 2):
   * a trilinear lattice.
   */
  void SetLatticeDimensions(int nx, int ny, int nz);
  void SetLatticeDimensions(const int dimensions[3])
  {
    this->SetLatticeDimensions(dimensions[0], dimensions[1], dimensions[2]);
  }
  vtkGetVector3Macro(LatticeDimensions, int);
  ///@}

  ///@{
  /**
   * The displacement of control point (i, j, k) from its rest position
   * X0 + (i/l, j/m, k/n) * region size. An index outside the lattice is an
   * error (and leaves the lattice unchanged; Get returns zero).
   */
  void SetControlPointDisplacement(int i, int j, int k, double dx, double dy, double dz);
  void SetControlPointDisplacement(int i, int j, int k, const double displacement[3])
  {
    this->SetControlPointDisplacement(i, j, k, displacement[0], displacement[1], displacement[2]);
  }
  void GetControlPointDisplacement(int i, int j, int k, double displacement[3]);
  ///@}

  /**
   * Puts every control point back at rest (the identity).
   */
  void ResetControlPoints();

  ///@{
  /**
   * The lattice's region (xmin, xmax, ymin, ymax, zmin, zmax). A region
   * with some min not below its max (the default, (0, -1, 0, -1, 0, -1))
   * means the rest bounds of the input cage.
   */
  vtkSetVector6Macro(Region, double);
  vtkGetVector6Macro(Region, double);
  ///@}

  /**
   * The region used by the last update (Region, or the input's rest bounds).
   */
  vtkGetVector6Macro(UsedRegion, double);

  ///@{
  /**
   * Each input box becomes Subdivision^3 sub-boxes (1..32). Default 1.
   */
  vtkSetClampMacro(Subdivision, int, 1, 32);
  vtkGetMacro(Subdivision, int);
  ///@}

  /**
   * The free-form deformation of the rest point `rest` with the current
   * control points over UsedRegion (the region of the last update).
   */
  void EvaluateDeformation(const double rest[3], double deformed[3]);

protected:
  vtkLatticeCageFilter();
  ~vtkLatticeCageFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int LatticeDimensions[3] = { 2, 2, 2 };
  std::vector<double> Displacements; // 3 per control point, i fastest
  double Region[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  double UsedRegion[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  int Subdivision = 1;

private:
  vtkLatticeCageFilter(const vtkLatticeCageFilter&) = delete;
  void operator=(const vtkLatticeCageFilter&) = delete;

  int ControlPointIndex(int i, int j, int k);
};

#endif
