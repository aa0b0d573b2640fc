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
#include <sstream>
#include <string>
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

/// The slab axis (`requested`, or the longest side of `bounds` when it is
/// -1) and the mesh size (its longest side); "" or why there is none.
std::string ChooseAxis(const double bounds[6], int requested, int& axis, double& size)
{
  size = 0.0;
  axis = requested;
  for (int a = 0; a < 3; ++a)
  {
    const double side = bounds[2 * a + 1] - bounds[2 * a];
    if (side > size)
    {
      size = side;
      if (requested < 0)
      {
        axis = a;
      }
    }
  }
  if (!(size > 0.0))
  {
    return "The input mesh has zero size (all its points coincide).";
  }
  axis = std::max(axis, 0);
  return std::string();
}

/// The extent of every part (label 1..255) along `axis`, ordered by the mean
/// of its cells' centroids; "" or why the labels cannot be caged.
std::string CollectParts(vtkDataSet* mesh,
  vtkDataArray* labels,
  int axis,
  std::vector<PartExtent>& order)
{
  std::map<int, PartExtent> parts;
  vtkNew<vtkIdList> cellPoints;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const double value = labels->GetComponent(c, 0);
    if (value > 255.0)
    {
      std::ostringstream why;
      why << "Cell " << c << " has label " << value << ", above 255.";
      return why.str();
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
    return "No cell of the input mesh has a label in 1..255.";
  }
  order.clear();
  for (const auto& entry : parts)
  {
    order.push_back(entry.second);
  }
  std::stable_sort(order.begin(),
    order.end(),
    [](const PartExtent& a, const PartExtent& b) { return a.MeanCentroid() < b.MeanCentroid(); });
  return std::string();
}

/// Layer k of the cage lies at faces[k] along the axis, from `first` to
/// `last`; the boundary between two parts is the middle of the overlap (or
/// of the gap) of their extents. "" or why two parts cannot be separated.
std::string SlabFaces(const std::vector<PartExtent>& order,
  int axis,
  double first,
  double last,
  std::vector<double>& faces)
{
  const size_t numberOfParts = order.size();
  faces.assign(numberOfParts + 1, 0.0);
  faces.front() = first;
  faces.back() = last;
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
      std::ostringstream why;
      why << "Parts " << order[k].Label << " and " << order[k + 1 < numberOfParts ? k + 1 : k].Label
          << " cannot be separated by slabs along axis " << axis << ": the box of part "
          << order[k].Label << " would span [" << faces[k] << ", " << faces[k + 1] << "].";
      return why.str();
    }
  }
  return std::string();
}

/// One box per part between consecutive faces, across [lo, hi] on the two
/// other axes; neighbouring slabs share their 4 corners.
void AddSlabs(vtkDeformationCage* cage,
  const std::vector<PartExtent>& order,
  const std::vector<double>& faces,
  int axis,
  const double lo[3],
  const double hi[3])
{
  // The cross-section (u, v) = the two other axes in cyclic order, so that
  // the points follow VTK's hexahedron order in world x, y, z.
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  // Point ids: layer k, cross-section corner (i, j) -> 4k + 2i + j.
  for (double face : faces)
  {
    for (int i = 0; i < 2; ++i)
    {
      for (int j = 0; j < 2; ++j)
      {
        double p[3];
        p[axis] = face;
        p[u] = i ? hi[u] : lo[u];
        p[v] = j ? hi[v] : lo[v];
        cage->AddPoint(p);
      }
    }
  }
  const auto& corner = lfd::HexCorner; // VTK hexahedron order
  for (size_t k = 0; k < order.size(); ++k)
  {
    vtkIdType ids[8];
    for (int c = 0; c < 8; ++c)
    {
      ids[c] = static_cast<vtkIdType>(4 * (k + corner[c][axis]) + 2 * corner[c][u] + corner[c][v]);
    }
    cage->AddBox(ids, order[k].Label);
  }
}
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
  if (mesh->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input mesh has no cells: there is no part to cage.");
    return 0;
  }

  double bounds[6];
  mesh->GetBounds(bounds);
  int axis = 0;
  double size = 0.0;
  std::vector<PartExtent> order;
  std::vector<double> faces;
  std::string why = ChooseAxis(bounds, this->Axis, axis, size);
  if (why.empty())
  {
    why = CollectParts(mesh, labels, axis, order);
  }
  const double pad = this->Margin * size;
  if (why.empty())
  {
    why = SlabFaces(order, axis, bounds[2 * axis] - pad, bounds[2 * axis + 1] + pad, faces);
  }
  double lo[3], hi[3];
  for (int a = 0; a < 3 && why.empty(); ++a)
  {
    lo[a] = bounds[2 * a] - pad;
    hi[a] = bounds[2 * a + 1] + pad;
    if (a != axis && !(hi[a] > lo[a]))
    {
      std::ostringstream thin;
      thin << "The cage has no thickness along axis " << a
           << " (the mesh is flat there and Margin is " << this->Margin << ").";
      why = thin.str();
    }
  }
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  AddSlabs(cage, order, faces, axis, lo, hi);
  this->UsedAxis = axis;
  return 1;
}
