/**
 * @class   vtkCageTransform
 * @brief   the cage map: every rest box sent to its deformed box by its trilinear map
 *
 * vtkCageTransform is the deformation of a vtkDeformationCage as a
 * vtkWarpTransform, so that any VTK filter that takes a transform
 * (vtkTransformPolyDataFilter, vtkTransformFilter, ...) deforms a mesh
 * exactly as the light-field renderer deforms the rays: this is the ground
 * truth of DESIGN.md section 4.5.
 *
 * The forward map takes a rest-space point x. When x lies in rest box b
 * (lfd::Contains on b's rest corners gives its parametric coordinates uvw),
 * it goes to lfd::TrilinearMap(deformed corners of b, uvw) (Eq. 2). Points
 * in no box stay where they are. On a face shared by two boxes the first box
 * (by cell index) is used; both agree there since they share the corners.
 * A box whose corners did not move maps its points to themselves exactly.
 *
 * The derivative inside a box is J_deformed(uvw) J_rest(uvw)^-1 (the
 * Jacobians of the two trilinear maps), the identity outside. The inverse
 * (Inverse(), GetInverse()) is vtkWarpTransform's Newton iteration; tighten
 * InverseTolerance (an absolute distance, default 0.001) for exact work.
 *
 * The cage is not validated here (see vtkDeformationCage::Validate());
 * boxes that are not hexahedra or name missing points are skipped with an
 * error. The cage's corners are read on Update(), i.e. whenever the cage or
 * the transform was modified (GetMTime() includes the cage's).
 *
 * @sa vtkDeformationCage vtkWarpTransform vtkGridTransform
 */
#ifndef vtkCageTransform_h
#define vtkCageTransform_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkWarpTransform.h"

#include <memory> // For std::unique_ptr

class vtkDeformationCage;

class LFDDEFORMATION_EXPORT vtkCageTransform : public vtkWarpTransform
{
public:
  static vtkCageTransform* New();
  vtkTypeMacro(vtkCageTransform, vtkWarpTransform);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The cage whose boxes define the map (shared, not copied).
   */
  virtual void SetCage(vtkDeformationCage* cage);
  vtkGetObjectMacro(Cage, vtkDeformationCage);
  ///@}

  /**
   * Makes another transform of the same type.
   */
  vtkAbstractTransform* MakeTransform() override;

  /**
   * The modification time includes the cage's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkCageTransform();
  ~vtkCageTransform() override;

  /**
   * Reads the rest and deformed corners of every box.
   */
  void InternalUpdate() override;

  /**
   * Copies the cage (shared) and the inverse settings of `transform`.
   */
  void InternalDeepCopy(vtkAbstractTransform* transform) override;

  ///@{
  /**
   * The forward map (see the class description).
   */
  void ForwardTransformPoint(const float in[3], float out[3]) override;
  void ForwardTransformPoint(const double in[3], double out[3]) override;
  ///@}

  ///@{
  /**
   * The forward map and its Jacobian, derivative[i][j] = d out_i / d in_j.
   */
  void ForwardTransformDerivative(const float in[3], float out[3], float derivative[3][3]) override;
  void ForwardTransformDerivative(const double in[3],
    double out[3],
    double derivative[3][3]) override;
  ///@}

  vtkDeformationCage* Cage = nullptr;

private:
  vtkCageTransform(const vtkCageTransform&) = delete;
  void operator=(const vtkCageTransform&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
