#include "vtkLatticeCageFilter.h"

#include "lfdBernstein.h"
#include "lfdTessellation.h"
#include "lfdTrilinear.h"

#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointLocator.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkLatticeCageFilter);

namespace
{
/// True when the region (xmin, xmax, ...) has a positive side along every axis.
bool HasVolume(const double region[6])
{
  return region[1] > region[0] && region[3] > region[2] && region[5] > region[4];
}

/// Index of `node` in the (k+1)^3 node ids of one box's sub-grid, u fastest.
std::size_t GridIndex(int k, const glm::ivec3& node)
{
  return static_cast<std::size_t>(node.x + (k + 1) * (node.y + (k + 1) * node.z));
}

/// The kernel's lattice of the filter's control points over `region`.
lfd::Lattice MakeLattice(const int dimensions[3],
  const std::vector<double>& displacements,
  const double region[6])
{
  lfd::Lattice lattice;
  lattice.Degree = glm::ivec3(dimensions[0] - 1, dimensions[1] - 1, dimensions[2] - 1);
  lattice.Origin = glm::dvec3(region[0], region[2], region[4]);
  lattice.Size = glm::dvec3(region[1] - region[0], region[3] - region[2], region[5] - region[4]);
  lattice.Displacements.resize(displacements.size() / 3);
  for (size_t c = 0; c < lattice.Displacements.size(); ++c)
  {
    lattice.Displacements[c] =
      glm::dvec3(displacements[3 * c], displacements[3 * c + 1], displacements[3 * c + 2]);
  }
  return lattice;
}
}

//------------------------------------------------------------------------------
vtkLatticeCageFilter::vtkLatticeCageFilter()
{
  this->ResetControlPoints();
}

//------------------------------------------------------------------------------
vtkLatticeCageFilter::~vtkLatticeCageFilter() = default;

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LatticeDimensions: (" << this->LatticeDimensions[0] << ", "
     << this->LatticeDimensions[1] << ", " << this->LatticeDimensions[2] << ")\n";
  int moved = 0;
  for (size_t c = 0; c < this->Displacements.size(); c += 3)
  {
    moved += this->Displacements[c] != 0.0 || this->Displacements[c + 1] != 0.0 ||
      this->Displacements[c + 2] != 0.0;
  }
  os << indent << "Displaced control points: " << moved << "\n";
  os << indent << "Region: (" << this->Region[0] << ", " << this->Region[1] << ", "
     << this->Region[2] << ", " << this->Region[3] << ", " << this->Region[4] << ", "
     << this->Region[5] << ")" << (HasVolume(this->Region) ? "" : " (the input's rest bounds)")
     << "\n";
  os << indent << "UsedRegion: (" << this->UsedRegion[0] << ", " << this->UsedRegion[1] << ", "
     << this->UsedRegion[2] << ", " << this->UsedRegion[3] << ", " << this->UsedRegion[4] << ", "
     << this->UsedRegion[5] << ")\n";
  os << indent << "Subdivision: " << this->Subdivision << "\n";
}

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::SetLatticeDimensions(int nx, int ny, int nz)
{
  const int limit = lfd::MaxLatticeDegree + 1;
  const int dimensions[3] = {
    std::clamp(nx, 2, limit), std::clamp(ny, 2, limit), std::clamp(nz, 2, limit)
  };
  if (std::equal(dimensions, dimensions + 3, this->LatticeDimensions))
  {
    return;
  }
  std::copy(dimensions, dimensions + 3, this->LatticeDimensions);
  this->ResetControlPoints();
}

//------------------------------------------------------------------------------
int vtkLatticeCageFilter::ControlPointIndex(int i, int j, int k)
{
  const int* n = this->LatticeDimensions;
  if (i < 0 || i >= n[0] || j < 0 || j >= n[1] || k < 0 || k >= n[2])
  {
    vtkErrorMacro("Control point (" << i << ", " << j << ", " << k << ") is outside the lattice of "
                                    << n[0] << " x " << n[1] << " x " << n[2]
                                    << " control points.");
    return -1;
  }
  return i + n[0] * (j + n[1] * k);
}

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::SetControlPointDisplacement(int i,
  int j,
  int k,
  double dx,
  double dy,
  double dz)
{
  const int c = this->ControlPointIndex(i, j, k);
  if (c < 0)
  {
    return;
  }
  double* d = &this->Displacements[3 * c];
  if (d[0] != dx || d[1] != dy || d[2] != dz)
  {
    d[0] = dx;
    d[1] = dy;
    d[2] = dz;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::GetControlPointDisplacement(int i, int j, int k, double displacement[3])
{
  const int c = this->ControlPointIndex(i, j, k);
  for (int a = 0; a < 3; ++a)
  {
    displacement[a] = c < 0 ? 0.0 : this->Displacements[3 * c + a];
  }
}

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::ResetControlPoints()
{
  const int* n = this->LatticeDimensions;
  this->Displacements.assign(3 * static_cast<size_t>(n[0]) * n[1] * n[2], 0.0);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLatticeCageFilter::EvaluateDeformation(const double rest[3], double deformed[3])
{
  glm::dvec3 p(rest[0], rest[1], rest[2]);
  if (HasVolume(this->UsedRegion))
  {
    p = lfd::FreeFormDeformation(
      MakeLattice(this->LatticeDimensions, this->Displacements, this->UsedRegion), p);
  }
  deformed[0] = p.x;
  deformed[1] = p.y;
  deformed[2] = p.z;
}

//------------------------------------------------------------------------------
int vtkLatticeCageFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLatticeCageFilter::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inInfo[0]);
  vtkDeformationCage* output = vtkDeformationCage::GetData(outInfo);
  output->InitializeFromGrid(nullptr);
  std::fill(this->UsedRegion, this->UsedRegion + 6, 0.0);
  this->UsedRegion[1] = this->UsedRegion[3] = this->UsedRegion[5] = -1.0;
  if (!input)
  {
    vtkErrorMacro("No input cage on port 0.");
    return 0;
  }
  vtkNew<vtkDeformationCage> cage;
  cage->InitializeFromGrid(input);
  const vtkIdType numberOfPoints = cage->GetNumberOfPoints();
  if (numberOfPoints == 0)
  {
    vtkErrorMacro("The input cage has no points: there is nothing to deform.");
    return 0;
  }

  // The rest positions, input points first so that they keep their ids.
  double bounds[6] = {
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN
  };
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    cage->GetRestPoint(i, p);
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], p[a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], p[a]);
    }
  }
  const double* region = HasVolume(this->Region) ? this->Region : bounds;
  if (!HasVolume(region))
  {
    vtkErrorMacro("The lattice region ("
      << region[0] << ", " << region[1] << ", " << region[2] << ", " << region[3] << ", "
      << region[4] << ", " << region[5] << ") has no volume: the input cage is flat; set Region.");
    return 0;
  }
  const double diagonal = std::sqrt((region[1] - region[0]) * (region[1] - region[0]) +
    (region[3] - region[2]) * (region[3] - region[2]) +
    (region[5] - region[4]) * (region[5] - region[4]));
  double searchBounds[6];
  for (int a = 0; a < 3; ++a)
  {
    searchBounds[2 * a] = std::min(bounds[2 * a], region[2 * a]) - 1e-3 * diagonal;
    searchBounds[2 * a + 1] = std::max(bounds[2 * a + 1], region[2 * a + 1]) + 1e-3 * diagonal;
  }
  vtkNew<vtkPoints> rest;
  rest->SetDataTypeToDouble();
  vtkNew<vtkPointLocator> locator;
  locator->SetTolerance(1e-9 * diagonal);
  locator->InitPointInsertion(rest, searchBounds, numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    cage->GetRestPoint(i, p);
    locator->InsertNextPoint(p); // id i: the points start empty
  }

  // Tessellation (DESIGN.md 4.4): each box's parametric sub-grid, its
  // corners being the box's own points and the rest shared by position.
  const int k = this->Subdivision;
  const vtkIdType numberOfBoxes = cage->GetNumberOfBoxes();
  std::vector<vtkIdType> grid(static_cast<size_t>(k + 1) * (k + 1) * (k + 1));
  std::vector<vtkIdType> boxes; // 8 corner ids per output box
  std::vector<int> labels;
  for (vtkIdType b = 0; b < numberOfBoxes; ++b)
  {
    double corners[24];
    if (!cage->GetRestCorners(b, corners))
    {
      vtkErrorMacro("Box " << b << " of the input cage is not a hexahedron of 8 existing points.");
      return 0;
    }
    const lfd::Hexahedron box = lfd::HexahedronFromArray(corners);
    vtkIdType npts;
    const vtkIdType* ids;
    cage->GetCellPoints(b, npts, ids);
    lfd::ForEachSubGridNode(k,
      [&](const glm::ivec3& node)
      {
        vtkIdType& id = grid[GridIndex(k, node)];
        const glm::ivec3 corner = node / k;
        if (node == corner * k)
        {
          // A corner of the box: its own point.
          for (int c = 0; c < 8; ++c)
          {
            if (corner == lfd::SubBoxNode(glm::ivec3(0), c))
            {
              id = ids[c];
            }
          }
          return;
        }
        const glm::dvec3 p = lfd::TrilinearMap(box, lfd::SubGridPoint(k, node));
        const double x[3] = { p.x, p.y, p.z };
        id = locator->IsInsertedPoint(x);
        if (id < 0)
        {
          id = locator->InsertNextPoint(x);
        }
      });
    const int label = cage->GetBoxLabel(b);
    lfd::ForEachSubBox(k,
      [&](const glm::ivec3& cell)
      {
        for (int c = 0; c < 8; ++c)
        {
          boxes.push_back(grid[GridIndex(k, lfd::SubBoxNode(cell, c))]);
        }
        labels.push_back(label);
      });
  }

  std::copy(region, region + 6, this->UsedRegion);
  const lfd::Lattice lattice = MakeLattice(this->LatticeDimensions, this->Displacements, region);
  for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
  {
    double p[3];
    rest->GetPoint(i, p);
    const glm::dvec3 q = lfd::FreeFormDeformation(lattice, glm::dvec3(p[0], p[1], p[2]));
    const double deformed[3] = { q.x, q.y, q.z };
    output->AddPoint(p, deformed);
  }
  for (size_t b = 0; b < labels.size(); ++b)
  {
    output->AddBox(&boxes[8 * b], labels[b]);
  }
  return 1;
}
