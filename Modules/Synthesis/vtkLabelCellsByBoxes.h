/**
 * @class   vtkLabelCellsByBoxes
 * @brief   labels the cells of a mesh with the deformation box that holds them
 *
 * vtkLabelCellsByBoxes gives every cell of a mesh (input port 0) the label
 * of the deformation box (DESIGN.md section 2) that contains the cell's
 * centroid (the mean of its points). The boxes come as a vtkUnstructuredGrid
 * on input port 1, read through vtkDeformationCage (InitializeFromGrid()):
 * each box's label and its rest corners (the points when the grid is at
 * rest), since the mesh lives in rest space. A grid that
 * vtkDeformationCage::CheckGridArrays() refuses is an error; cells that are
 * not hexahedra of existing points are skipped with a warning. Boxes need
 * not be axis-aligned: containment inverts each box's trilinear map
 * (vtkHexahedron::EvaluatePosition). Where boxes overlap, the first box (by
 * cell index) wins; cells in no box get label 0.
 *
 * The output is the mesh with its cell array "Label" (int) replaced; every
 * other array is passed through. This is how a synthetic mesh is split into
 * the parts of a cage before it is captured with vtkLightFieldCapture.
 *
 * @sa vtkLightFieldCapture vtkHexahedron
 */
#ifndef vtkLabelCellsByBoxes_h
#define vtkLabelCellsByBoxes_h

#include "lfdSynthesisModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkUnstructuredGrid;

class LFDSYNTHESIS_EXPORT vtkLabelCellsByBoxes : public vtkPolyDataAlgorithm
{
public:
  static vtkLabelCellsByBoxes* New();
  vtkTypeMacro(vtkLabelCellsByBoxes, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's request; a C++ exception thrown by it becomes this
   * algorithm's error (error code UnknownError), see lfdRequestGuard.h.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * The boxes (input port 1).
   */
  void SetBoxesConnection(vtkAlgorithmOutput* boxes);
  void SetBoxesData(vtkUnstructuredGrid* boxes);
  ///@}

protected:
  vtkLabelCellsByBoxes();
  ~vtkLabelCellsByBoxes() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkLabelCellsByBoxes(const vtkLabelCellsByBoxes&) = delete;
  void operator=(const vtkLabelCellsByBoxes&) = delete;
};

#endif
