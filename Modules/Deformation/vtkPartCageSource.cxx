#include "vtkPartCageSource.h"

#include "lfdTrilinear.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDeformationCage.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

vtkStandardNewMacro(vtkPartCageSource);

namespace
{
/// What the slabs need of one part: its extent along the axis and the sum of
/// its cell centroids' coordinates along it.
struct PartExtent
{
  int Label = 0;
  double Min = std::numeric_limits<double>::max();
  double Max = std::numeric_limits<double>::lowest();
  double CentroidSum = 0.0;
  vtkIdType NumberOfCells = 0;

  double MeanCentroid() const { return this->CentroidSum / this->NumberOfCells; }
};
}

//------------------------------------------------------------------------------
vtkPartCageSource::vtkPartCageSource() {}

//------------------------------------------------------------------------------
vtkPartCageSource::~vtkPartCageSource() = default;

//------------------------------------------------------------------------------
void vtkPartCageSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Axis: " << this->Axis << "\n";
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "UsedAxis: " << this->UsedAxis << "\n";
}

//------------------------------------------------------------------------------
int vtkPartCageSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkPartCageSource::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkDataSet* mesh = vtkDataSet::GetData(inInfo[0]);
  vtkDeformationCage* cage = vtkDeformationCage::GetData(outInfo);
  cage->InitializeFromGrid(nullptr);
  this->UsedAxis = -1;
  if (!mesh)
  {
    vtkErrorMacro("No input mesh on port 0.");
    return 0;
  }
  vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
  if (!labels || labels->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The input mesh has no one-component cell array \"Label\" (the part of each "
                  "cell, 1..N).");
    return 0;
  }
  const vtkIdType numberOfCells = mesh->GetNumberOfCells();
  if (numberOfCells == 0)
  {
    vtkErrorMacro("The input mesh has no cells: there is no part to cage.");
    return 0;
  }

  double bounds[6];
  mesh->GetBounds(bounds);
  double size = 0.0;
  int axis = this->Axis;
  for (int a = 0; a < 3; ++a)
  {
    const double side = bounds[2 * a + 1] - bounds[2 * a];
    if (side > size)
    {
      size = side;
      if (this->Axis < 0)
      {
        axis = a;
      }
    }
  }
  if (!(size > 0.0))
  {
    vtkErrorMacro("The input mesh has zero size (all its points coincide).");
    return 0;
  }
  if (axis < 0)
  {
    axis = 0;
  }

  std::map<int, PartExtent> parts;
  vtkNew<vtkIdList> cellPoints;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    const double value = labels->GetComponent(c, 0);
    if (value > 255.0)
    {
      vtkErrorMacro("Cell " << c << " has label " << value << ", above 255.");
      return 0;
    }
    const int label = static_cast<int>(std::lround(value));
    if (label < 1)
    {
      continue;
    }
    mesh->GetCellPoints(c, cellPoints);
    const vtkIdType n = cellPoints->GetNumberOfIds();
    if (n == 0)
    {
      continue;
    }
    PartExtent& part = parts[label];
    part.Label = label;
    double centroid = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      mesh->GetPoint(cellPoints->GetId(i), p);
      part.Min = std::min(part.Min, p[axis]);
      part.Max = std::max(part.Max, p[axis]);
      centroid += p[axis];
    }
    part.CentroidSum += centroid / n;
    ++part.NumberOfCells;
  }
  if (parts.empty())
  {
    vtkErrorMacro("No cell of the input mesh has a label in 1..255.");
    return 0;
  }

  std::vector<PartExtent> order;
  for (const auto& entry : parts)
  {
    order.push_back(entry.second);
  }
  std::stable_sort(order.begin(),
    order.end(),
    [](const PartExtent& a, const PartExtent& b) { return a.MeanCentroid() < b.MeanCentroid(); });

  // Layer k of the cage lies at faces[k] along the axis; the boundary between
  // two parts is the middle of the overlap (or of the gap) of their extents.
  const double pad = this->Margin * size;
  const size_t numberOfParts = order.size();
  std::vector<double> faces(numberOfParts + 1);
  faces.front() = bounds[2 * axis] - pad;
  faces.back() = bounds[2 * axis + 1] + pad;
  for (size_t k = 1; k < numberOfParts; ++k)
  {
    const PartExtent& a = order[k - 1];
    const PartExtent& b = order[k];
    faces[k] = 0.5 * (std::max(a.Min, b.Min) + std::min(a.Max, b.Max));
  }
  for (size_t k = 0; k < numberOfParts; ++k)
  {
    if (!(faces[k + 1] > faces[k]))
    {
      vtkErrorMacro(
        "Parts " << order[k].Label << " and " << order[k + 1 < numberOfParts ? k + 1 : k].Label
                 << " cannot be separated by slabs along axis " << axis << ": the box of part "
                 << order[k].Label << " would span [" << faces[k] << ", " << faces[k + 1] << "].");
      return 0;
    }
  }

  // The cross-section (u, v) = the two other axes in cyclic order, so that
  // the points follow VTK's hexahedron order in world x, y, z.
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = bounds[2 * a] - pad;
    hi[a] = bounds[2 * a + 1] + pad;
    if (a != axis && !(hi[a] > lo[a]))
    {
      vtkErrorMacro("The cage has no thickness along axis "
        << a << " (the mesh is flat there and Margin is " << this->Margin << ").");
      return 0;
    }
  }
  // Point ids: layer k, cross-section corner (i, j) -> 4k + 2i + j.
  for (size_t k = 0; k <= numberOfParts; ++k)
  {
    for (int i = 0; i < 2; ++i)
    {
      for (int j = 0; j < 2; ++j)
      {
        double p[3];
        p[axis] = faces[k];
        p[u] = i ? hi[u] : lo[u];
        p[v] = j ? hi[v] : lo[v];
        cage->AddPoint(p);
      }
    }
  }
  const auto& corner = lfd::HexCorner; // VTK hexahedron order
  for (size_t k = 0; k < numberOfParts; ++k)
  {
    vtkIdType ids[8];
    for (int c = 0; c < 8; ++c)
    {
      ids[c] = static_cast<vtkIdType>(4 * (k + corner[c][axis]) + 2 * corner[c][u] + corner[c][v]);
    }
    cage->AddBox(ids, order[k].Label);
  }
  this->UsedAxis = axis;
  return 1;
}
