/**
 * @class   vtkLabelCellsByBoxes
 * @brief   labels the cells of a mesh with the deformation box that holds them
 *
 * vtkLabelCellsByBoxes gives every cell of a mesh (input port 0) the label
 * of the deformation box (DESIGN.md section 2) that contains the cell's
 * centroid (the mean of its points). The boxes come as a vtkUnstructuredGrid
 * on input port 1 (a cage, as vtkDeformationCage stores it): VTK_HEXAHEDRON
 * cells, a cell array "Label" and, when present, a point array
 * "RestPosition" with the rest-space corners, used instead of the points
 * (the mesh lives in rest space). Boxes need not be axis-aligned: containment
 * inverts each box's trilinear map (vtkHexahedron::EvaluatePosition). Where
 * boxes overlap, the first box (by cell index) wins; cells in no box get
 * label 0.
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
