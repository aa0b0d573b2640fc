#include "vtkDeformationCage.h"

#include "lfdTrilinear.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLightField.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkDeformationCage);

namespace
{
constexpr const char* RestPositionName = "RestPosition";
constexpr const char* LabelName = "Label";

std::string FormatPoint(const glm::dvec3& p)
{
  std::ostringstream text;
  text << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return text.str();
}

/**
 * Why the trilinear map of `box` is not one-to-one, or "" when it is: its
 * Jacobian determinant must be positive on a 5 x 5 x 5 parametric lattice
 * (corners, centre, edge and face midpoints, interior points at 1/4 and 3/4).
 * A positive determinant at the corners alone does not exclude a fold
 * inside a strongly twisted box; the lattice catches the usual ones.
 */
std::string FindFold(const lfd::Hexahedron& box)
{
  const double size = lfd::BoxSize(box);
  // Below this the box is flat (a volume ~1e-12 of its bounding cube).
  const double flat = 1e-12 * size * size * size;
  double minimum = VTK_DOUBLE_MAX, maximum = -VTK_DOUBLE_MAX;
  glm::dvec3 where(0.5);
  for (int k = 0; k <= 4; ++k)
  {
    for (int j = 0; j <= 4; ++j)
    {
      for (int i = 0; i <= 4; ++i)
      {
        const glm::dvec3 uvw(0.25 * i, 0.25 * j, 0.25 * k);
        const double det = glm::determinant(lfd::TrilinearJacobian(box, uvw));
        if (det < minimum)
        {
          minimum = det;
          where = uvw;
        }
        maximum = std::max(maximum, det);
      }
    }
  }
  std::ostringstream why;
  if (!(size > 0.0))
  {
    why << "is collapsed to a point";
  }
  else if (maximum < -flat)
  {
    why << "is inverted (Jacobian determinant negative everywhere, " << minimum << " at uvw "
        << FormatPoint(where) << "; corners not in VTK hexahedron order?)";
  }
  else if (minimum < -flat)
  {
    why << "folds (Jacobian determinant " << minimum << " at uvw " << FormatPoint(where)
        << ", up to " << maximum << " elsewhere)";
  }
  else if (!(minimum > flat))
  {
    why << "collapses (Jacobian determinant " << minimum << " at uvw " << FormatPoint(where)
        << ", up to " << maximum << " elsewhere)";
  }
  return why.str();
}

/// Points of the box interior used to detect overlaps: a 5 x 5 x 5 lattice
/// whose outer layer lies 1e-3 inside the faces, so shared faces never count.
std::vector<glm::dvec3> InteriorSamples(const lfd::Hexahedron& box)
{
  constexpr double t[5] = { 1e-3, 0.25, 0.5, 0.75, 1.0 - 1e-3 };
  std::vector<glm::dvec3> samples;
  samples.reserve(125);
  for (double w : t)
  {
    for (double v : t)
    {
      for (double u : t)
      {
        samples.push_back(lfd::TrilinearMap(box, glm::dvec3(u, v, w)));
      }
    }
  }
  return samples;
}

bool BoundsOverlap(const lfd::AxisBounds& a, const lfd::AxisBounds& b)
{
  return a.Min.x < b.Max.x && b.Min.x < a.Max.x && a.Min.y < b.Max.y && b.Min.y < a.Max.y &&
    a.Min.z < b.Max.z && b.Min.z < a.Max.z;
}
} // namespace

//------------------------------------------------------------------------------
vtkDeformationCage::vtkDeformationCage()
{
  this->GetOrCreateRestPositions();
  this->GetOrCreateLabels();
}

//------------------------------------------------------------------------------
vtkDeformationCage::~vtkDeformationCage() = default;

//------------------------------------------------------------------------------
void vtkDeformationCage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfBoxes: " << this->GetNumberOfBoxes() << "\n";
  os << indent << "Deformed: " << (this->IsDeformed() ? "yes" : "no") << "\n";
}

//------------------------------------------------------------------------------
vtkDataArray* vtkDeformationCage::GetRestPositions()
{
  return this->GetPointData()->GetArray(RestPositionName);
}

//------------------------------------------------------------------------------
vtkDataArray* vtkDeformationCage::GetOrCreateRestPositions()
{
  vtkDataArray* rest = this->GetRestPositions();
  if (rest && rest->GetNumberOfComponents() == 3 && rest->IsA("vtkDoubleArray"))
  {
    return rest;
  }
  vtkNew<vtkDoubleArray> positions;
  positions->SetName(RestPositionName);
  positions->SetNumberOfComponents(3);
  const vtkIdType count = this->GetNumberOfPoints();
  positions->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    if (rest && rest->GetNumberOfComponents() == 3 && i < rest->GetNumberOfTuples())
    {
      rest->GetTuple(i, x);
    }
    else
    {
      this->GetPoint(i, x);
    }
    positions->SetTypedTuple(i, x);
  }
  this->GetPointData()->AddArray(positions);
  return positions;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkDeformationCage::GetOrCreateLabels()
{
  vtkDataArray* labels = this->GetCellData()->GetArray(LabelName);
  if (labels && labels->GetNumberOfComponents() == 1 && labels->IsA("vtkIntArray"))
  {
    return labels;
  }
  vtkNew<vtkIntArray> values;
  values->SetName(LabelName);
  const vtkIdType count = this->GetNumberOfCells();
  values->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const bool known =
      labels && labels->GetNumberOfComponents() == 1 && i < labels->GetNumberOfTuples();
    values->SetValue(i, known ? static_cast<int>(labels->GetComponent(i, 0)) : 0);
  }
  this->GetCellData()->AddArray(values);
  return values;
}

//------------------------------------------------------------------------------
void vtkDeformationCage::InitializeFromGrid(vtkUnstructuredGrid* grid)
{
  this->Initialize();
  if (grid)
  {
    this->DeepCopy(grid);
  }
  this->GetOrCreateRestPositions();
  this->GetOrCreateLabels();
  this->Modified();
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::CheckGridArrays(vtkUnstructuredGrid* grid)
{
  if (!grid)
  {
    return "the cage is missing";
  }
  vtkDataArray* labels = grid->GetCellData()->GetArray(LabelName);
  if (!labels || labels->GetNumberOfComponents() != 1 ||
    labels->GetNumberOfTuples() != grid->GetNumberOfCells())
  {
    return "the cage has no cell array \"Label\" of one value per box (the label of its part)";
  }
  vtkDataArray* rest = grid->GetPointData()->GetArray(RestPositionName);
  if (rest &&
    (rest->GetNumberOfComponents() != 3 || rest->GetNumberOfTuples() != grid->GetNumberOfPoints()))
  {
    return "the cage's point array \"RestPosition\" has " +
      std::to_string(rest->GetNumberOfTuples()) + " tuples of " +
      std::to_string(rest->GetNumberOfComponents()) + " components; expected " +
      std::to_string(grid->GetNumberOfPoints()) + " tuples of 3";
  }
  return std::string();
}

//------------------------------------------------------------------------------
vtkIdType vtkDeformationCage::AddPoint(const double rest[3])
{
  return this->AddPoint(rest, rest);
}

//------------------------------------------------------------------------------
vtkIdType vtkDeformationCage::AddPoint(const double rest[3], const double deformed[3])
{
  if (!this->GetPoints())
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    this->SetPoints(points);
  }
  vtkDataArray* positions = this->GetOrCreateRestPositions();
  const vtkIdType id = this->GetPoints()->InsertNextPoint(deformed);
  positions->InsertTuple(id, rest);
  this->Modified();
  return id;
}

//------------------------------------------------------------------------------
void vtkDeformationCage::GetRestPoint(vtkIdType id, double rest[3])
{
  this->GetOrCreateRestPositions()->GetTuple(id, rest);
}

//------------------------------------------------------------------------------
void vtkDeformationCage::SetRestPoint(vtkIdType id, const double rest[3])
{
  vtkDataArray* positions = this->GetOrCreateRestPositions();
  positions->SetTuple(id, rest);
  positions->Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeformationCage::GetDeformedPoint(vtkIdType id, double deformed[3])
{
  this->GetPoint(id, deformed);
}

//------------------------------------------------------------------------------
void vtkDeformationCage::SetDeformedPoint(vtkIdType id, const double deformed[3])
{
  this->GetPoints()->SetPoint(id, deformed);
  this->GetPoints()->Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkDeformationCage::AddBox(const vtkIdType corners[8], int label)
{
  vtkDataArray* labels = this->GetOrCreateLabels();
  if (!this->Connectivity)
  {
    // Initialize() drops the cell storage the constructor allocated.
    this->AllocateEstimate(16, 8);
  }
  const vtkIdType box = this->InsertNextCell(VTK_HEXAHEDRON, 8, corners);
  labels->InsertTuple1(box, label);
  this->Modified();
  return static_cast<int>(box);
}

//------------------------------------------------------------------------------
vtkIdType vtkDeformationCage::GetNumberOfBoxes()
{
  return this->GetNumberOfCells();
}

//------------------------------------------------------------------------------
int vtkDeformationCage::GetBoxLabel(vtkIdType box)
{
  vtkDataArray* labels = this->GetCellData()->GetArray(LabelName);
  if (!labels || box < 0 || box >= labels->GetNumberOfTuples() || box >= this->GetNumberOfCells())
  {
    return 0;
  }
  return static_cast<int>(labels->GetComponent(box, 0));
}

//------------------------------------------------------------------------------
bool vtkDeformationCage::GetCorners(vtkIdType box, bool rest, double corners[24])
{
  if (box < 0 || box >= this->GetNumberOfCells() || this->GetCellType(box) != VTK_HEXAHEDRON)
  {
    return false;
  }
  vtkDataArray* positions = rest ? this->GetRestPositions() : nullptr;
  if (rest && (!positions || positions->GetNumberOfComponents() != 3))
  {
    return false;
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  this->GetCellPoints(box, count, ids);
  const vtkIdType points = rest ? positions->GetNumberOfTuples() : this->GetNumberOfPoints();
  if (count != 8 ||
    std::any_of(ids, ids + 8, [points](vtkIdType id) { return id < 0 || id >= points; }))
  {
    return false;
  }
  for (int i = 0; i < 8; ++i)
  {
    if (rest)
    {
      positions->GetTuple(ids[i], corners + 3 * i);
    }
    else
    {
      this->GetPoint(ids[i], corners + 3 * i);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeformationCage::GetRestCorners(vtkIdType box, double corners[24])
{
  return this->GetCorners(box, true, corners);
}

//------------------------------------------------------------------------------
bool vtkDeformationCage::GetDeformedCorners(vtkIdType box, double corners[24])
{
  return this->GetCorners(box, false, corners);
}

//------------------------------------------------------------------------------
bool vtkDeformationCage::GetRestBounds(vtkIdType box, double bounds[6])
{
  double corners[24];
  if (!this->GetRestCorners(box, corners))
  {
    return false;
  }
  const lfd::AxisBounds extent = lfd::BoxBounds(lfd::HexahedronFromArray(corners));
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = extent.Min[k];
    bounds[2 * k + 1] = extent.Max[k];
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkDeformationCage::SetPointsToRest()
{
  vtkDataArray* positions = this->GetRestPositions();
  vtkPoints* points = this->GetPoints();
  if (!positions || !points)
  {
    return;
  }
  const vtkIdType count = std::min(points->GetNumberOfPoints(), positions->GetNumberOfTuples());
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(i, positions->GetTuple3(i));
  }
  points->Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkDeformationCage::IsDeformed()
{
  return this->GetLargestDisplacement() > 0.0;
}

//------------------------------------------------------------------------------
double vtkDeformationCage::GetLargestDisplacement()
{
  vtkDataArray* positions = this->GetRestPositions();
  if (!positions)
  {
    return 0.0;
  }
  const vtkIdType count = std::min(this->GetNumberOfPoints(), positions->GetNumberOfTuples());
  double largest = 0.0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double rest[3], deformed[3];
    positions->GetTuple(i, rest);
    this->GetPoint(i, deformed);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(rest, deformed)));
  }
  return largest;
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateArrays()
{
  vtkDataArray* positions = this->GetRestPositions();
  if (!positions || positions->GetNumberOfComponents() != 3 ||
    positions->GetNumberOfTuples() != this->GetNumberOfPoints())
  {
    return "cage: the point array \"RestPosition\" is missing or does not hold 3 components per "
           "point";
  }
  vtkDataArray* labels = this->GetCellData()->GetArray(LabelName);
  if (!labels || labels->GetNumberOfComponents() != 1 ||
    labels->GetNumberOfTuples() != this->GetNumberOfBoxes())
  {
    return "cage: the cell array \"Label\" is missing or does not hold one value per box";
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateBox(vtkIdType b)
{
  const vtkIdType numberOfPoints = this->GetNumberOfPoints();
  const int label = this->GetBoxLabel(b);
  std::ostringstream nameText;
  nameText << "cage: box " << b << " (label " << label << ")";
  const std::string name = nameText.str();

  if (this->GetCellType(b) != VTK_HEXAHEDRON)
  {
    return name + " is not a hexahedron (VTK cell type " + std::to_string(this->GetCellType(b)) +
      ", expected " + std::to_string(VTK_HEXAHEDRON) + ")";
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  this->GetCellPoints(b, count, ids);
  if (count != 8)
  {
    return name + " has " + std::to_string(count) + " corners, expected 8";
  }
  for (int i = 0; i < 8; ++i)
  {
    if (ids[i] < 0 || ids[i] >= numberOfPoints)
    {
      return name + ": corner " + std::to_string(i) + " is point " + std::to_string(ids[i]) +
        ", out of range [0, " + std::to_string(numberOfPoints) + ")";
    }
  }
  if (label < 1 || label > 255)
  {
    return name + ": label out of range [1, 255]";
  }

  double corners[24];
  this->GetRestCorners(b, corners);
  std::string fold = FindFold(lfd::HexahedronFromArray(corners));
  if (!fold.empty())
  {
    return name + ": the rest box " + fold;
  }
  this->GetDeformedCorners(b, corners);
  fold = FindFold(lfd::HexahedronFromArray(corners));
  if (!fold.empty())
  {
    return name + ": the deformed box " + fold;
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateOverlaps(const std::vector<vtkIdType>& boxes)
{
  // Rest boxes must not overlap: a rest-space point belongs to one part.
  // Each listed box is tested against every box not tested with it yet, so
  // a full validation tests every pair once, in the order (a, b), a < b.
  const vtkIdType numberOfBoxes = this->GetNumberOfBoxes();
  std::vector<lfd::Hexahedron> rest(numberOfBoxes);
  std::vector<lfd::AxisBounds> bounds(numberOfBoxes);
  std::vector<bool> known(numberOfBoxes, false);
  for (vtkIdType b = 0; b < numberOfBoxes; ++b)
  {
    // Boxes not listed were not checked: one that is not a box is skipped.
    double corners[24];
    known[b] = this->GetRestCorners(b, corners);
    if (known[b])
    {
      rest[b] = lfd::HexahedronFromArray(corners);
      bounds[b] = lfd::BoxBounds(rest[b]);
    }
  }
  std::vector<std::vector<glm::dvec3>> samples(numberOfBoxes);
  const auto samplesOf = [&](vtkIdType b) -> const std::vector<glm::dvec3>&
  {
    if (samples[b].empty())
    {
      samples[b] = InteriorSamples(rest[b]);
    }
    return samples[b];
  };
  std::vector<bool> done(numberOfBoxes, false);
  for (vtkIdType listed : boxes)
  {
    for (vtkIdType other = 0; other < numberOfBoxes; ++other)
    {
      if (other == listed || done[other] || !known[other] ||
        !BoundsOverlap(bounds[listed], bounds[other]))
      {
        continue;
      }
      const vtkIdType a = std::min(listed, other), b = std::max(listed, other);
      for (int pass = 0; pass < 2; ++pass)
      {
        const vtkIdType inner = pass ? b : a;
        const vtkIdType outer = pass ? a : b;
        for (const glm::dvec3& p : samplesOf(inner))
        {
          glm::dvec3 uvw;
          // A negative slack: touching faces do not count, only interiors.
          if (lfd::Contains(rest[outer], p, uvw, -1e-9))
          {
            std::ostringstream message;
            message << "cage: box " << b << " (label " << this->GetBoxLabel(b) << ") overlaps box "
                    << a << " (label " << this->GetBoxLabel(a) << ") in rest space: the point "
                    << FormatPoint(p) << " of box " << inner << " lies inside box " << outer;
            return message.str();
          }
        }
      }
    }
    done[listed] = true;
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateListed(const std::vector<vtkIdType>& boxes,
  vtkLightField* lightField)
{
  std::string why = this->ValidateArrays();
  for (auto b = boxes.begin(); b != boxes.end() && why.empty(); ++b)
  {
    why = this->ValidateBox(*b);
  }
  if (why.empty() && lightField)
  {
    why = this->ValidateLabels(lightField);
  }
  return why.empty() ? this->ValidateOverlaps(boxes) : why;
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::Validate(vtkLightField* lightField)
{
  std::vector<vtkIdType> all(this->GetNumberOfBoxes());
  std::iota(all.begin(), all.end(), 0);
  return this->ValidateListed(all, lightField);
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateBoxes(vtkIdList* boxes)
{
  const vtkIdType numberOfBoxes = this->GetNumberOfBoxes();
  std::vector<vtkIdType> listed;
  std::vector<bool> seen(numberOfBoxes, false);
  for (vtkIdType i = 0; boxes && i < boxes->GetNumberOfIds(); ++i)
  {
    const vtkIdType b = boxes->GetId(i);
    if (b < 0 || b >= numberOfBoxes)
    {
      return "cage: box " + std::to_string(b) + " does not exist (the cage has " +
        std::to_string(numberOfBoxes) + " boxes)";
    }
    if (!seen[b])
    {
      seen[b] = true;
      listed.push_back(b);
    }
  }
  return this->ValidateListed(listed, nullptr);
}

//------------------------------------------------------------------------------
std::string vtkDeformationCage::ValidateLabels(vtkLightField* lightField)
{
  const vtkIdType numberOfBoxes = this->GetNumberOfBoxes();
  if (lightField->HasPass(vtkLightField::LABEL))
  {
    // A box moves the rays of its label only (paper Sec. 4), so a label the
    // light field's Label pass never holds is an error.
    for (vtkIdType b = 0; b < numberOfBoxes; ++b)
    {
      const int label = this->GetBoxLabel(b);
      if (!lightField->HasLabel(label))
      {
        return "cage: box " + std::to_string(b) + " (label " + std::to_string(label) +
          "): the light field's Label pass has no sub-light field " + std::to_string(label);
      }
    }
    return std::string();
  }
  // Unsplit: one part, so one label (boxes of a lattice or a tessellation
  // share it). Which rays two labels would move needs a split.
  for (vtkIdType b = 1; b < numberOfBoxes; ++b)
  {
    if (this->GetBoxLabel(b) != this->GetBoxLabel(0))
    {
      return "cage: box 0 (label " + std::to_string(this->GetBoxLabel(0)) + ") and box " +
        std::to_string(b) + " (label " + std::to_string(this->GetBoxLabel(b)) +
        ") move different parts, but the light field has no Label pass (it is one part): split "
        "it first (lfd split projector|scanline|propagate ...) or give every box the same label";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkDeformationCage::GetData(vtkInformation* info)
{
  return info ? vtkDeformationCage::SafeDownCast(info->Get(DATA_OBJECT())) : nullptr;
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkDeformationCage::GetData(vtkInformationVector* v, int i)
{
  return vtkDeformationCage::GetData(v->GetInformationObject(i));
}
