#include "vtkLabelCellsByBoxes.h"

#include "lfdRequestGuard.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkHexahedron.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <vector>

vtkStandardNewMacro(vtkLabelCellsByBoxes);

namespace
{
struct Box
{
  std::array<double, 24> Corners; // rest corners, VTK hexahedron order
  std::array<double, 6> Bounds;
  int Label;
};

// Finds, for each centroid, the first box whose trilinear map holds it.
struct LabelByBoxes
{
  const std::vector<double>& Centroids;
  const std::vector<Box>& Boxes;
  vtkIntArray* Labels;
  vtkSMPThreadLocalObject<vtkHexahedron> Hexahedron;

  LabelByBoxes(const std::vector<double>& centroids,
    const std::vector<Box>& boxes,
    vtkIntArray* labels)
    : Centroids(centroids)
    , Boxes(boxes)
    , Labels(labels)
  {
  }

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkHexahedron* hexahedron = this->Hexahedron.Local();
    double closest[3], pcoords[3], weights[8], dist2;
    int subId;
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      double x[3] = {
        this->Centroids[3 * cell], this->Centroids[3 * cell + 1], this->Centroids[3 * cell + 2]
      };
      int label = 0;
      for (const Box& box : this->Boxes)
      {
        if (x[0] < box.Bounds[0] || x[0] > box.Bounds[1] || x[1] < box.Bounds[2] ||
          x[1] > box.Bounds[3] || x[2] < box.Bounds[4] || x[2] > box.Bounds[5])
        {
          continue;
        }
        for (int corner = 0; corner < 8; ++corner)
        {
          hexahedron->GetPoints()->SetPoint(corner, box.Corners.data() + 3 * corner);
        }
        if (hexahedron->EvaluatePosition(x, closest, subId, pcoords, dist2, weights) == 1)
        {
          label = box.Label;
          break;
        }
      }
      this->Labels->SetValue(cell, label);
    }
  }

  void Reduce() {}
};
}

//------------------------------------------------------------------------------
vtkLabelCellsByBoxes::vtkLabelCellsByBoxes()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
void vtkLabelCellsByBoxes::SetBoxesConnection(vtkAlgorithmOutput* boxes)
{
  this->SetInputConnection(1, boxes);
}

//------------------------------------------------------------------------------
void vtkLabelCellsByBoxes::SetBoxesData(vtkUnstructuredGrid* boxes)
{
  this->SetInputDataInternal(1, boxes);
}

//------------------------------------------------------------------------------
int vtkLabelCellsByBoxes::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLabelCellsByBoxes::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !grid || !output)
  {
    vtkErrorMacro("Need a mesh on input port 0 and the boxes on input port 1.");
    return 0;
  }
  const std::string why = vtkDeformationCage::CheckGridArrays(grid);
  if (!why.empty())
  {
    vtkErrorMacro("The boxes on input port 1: " << why << ".");
    return 0;
  }
  vtkNew<vtkDeformationCage> cage;
  cage->InitializeFromGrid(grid);

  std::vector<Box> boxes;
  int skipped = 0;
  for (vtkIdType c = 0; c < cage->GetNumberOfBoxes(); ++c)
  {
    Box box;
    if (!cage->GetRestCorners(c, box.Corners.data()) || !cage->GetRestBounds(c, box.Bounds.data()))
    {
      ++skipped;
      continue;
    }
    box.Label = cage->GetBoxLabel(c);
    // Grow the bounds like EvaluatePosition's parametric tolerance does.
    for (int k = 0; k < 3; ++k)
    {
      const double pad = 1e-3 * (box.Bounds[2 * k + 1] - box.Bounds[2 * k]) + 1e-12;
      box.Bounds[2 * k] -= pad;
      box.Bounds[2 * k + 1] += pad;
    }
    boxes.push_back(box);
  }
  if (skipped > 0)
  {
    vtkWarningMacro(<< skipped << " cells of the boxes input are not hexahedra; ignored.");
  }

  const vtkIdType numberOfCells = input->GetNumberOfCells();
  vtkNew<vtkIdList> ids;
  std::vector<double> centroids(3 * numberOfCells, 0.0);
  for (vtkIdType cell = 0; cell < numberOfCells; ++cell)
  {
    input->GetCellPoints(cell, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      input->GetPoint(ids->GetId(i), x);
      for (int k = 0; k < 3; ++k)
      {
        centroids[3 * cell + k] += x[k] / n;
      }
    }
  }

  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  labels->SetNumberOfTuples(numberOfCells);
  LabelByBoxes worker(centroids, boxes, labels);
  vtkSMPTools::For(0, numberOfCells, worker);

  output->ShallowCopy(input);
  output->GetCellData()->RemoveArray("Label");
  output->GetCellData()->AddArray(labels);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLabelCellsByBoxes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkLabelCellsByBoxes);
