#include "vtkCageRepresentation.h"

#include "lfdRayWarp.h"
#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDeformationCage.h"
#include "vtkDoubleArray.h"
#include "vtkGlyph3D.h"
#include "vtkHexahedron.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLabelPalette.h"
#include "vtkLatticeCageFilter.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkProperty2D.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkCageRepresentation);
vtkCxxSetObjectMacro(vtkCageRepresentation, Palette, vtkUnsignedCharArray);
vtkCxxSetObjectMacro(vtkCageRepresentation, OccluderDepth, vtkImageData);

namespace
{
glm::dvec3 ToVec(const double v[3])
{
  return glm::dvec3(v[0], v[1], v[2]);
}

/// Rotation of `v` by `radians` about the unit `axis` (Rodrigues).
glm::dvec3 Rotate(const glm::dvec3& v, const glm::dvec3& axis, double radians)
{
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

/// The renderer's world <-> display map: x, y in pixels of the render
/// window, z in the z-buffer's 0 (near) .. 1 (far), as vtkSelectVisiblePoints.
struct ViewProjection
{
  double Matrix[16];
  double Inverse[16];
  double Origin[2];
  double Size[2];

  explicit ViewProjection(vtkRenderer* renderer)
  {
    vtkMatrix4x4* m = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), 0.0, 1.0);
    std::copy(&m->Element[0][0], &m->Element[0][0] + 16, this->Matrix);
    vtkMatrix4x4::Invert(this->Matrix, this->Inverse);
    const int* origin = renderer->GetOrigin();
    const int* size = renderer->GetSize();
    this->Origin[0] = origin[0];
    this->Origin[1] = origin[1];
    this->Size[0] = std::max(size[0], 1);
    this->Size[1] = std::max(size[1], 1);
  }

  glm::dvec3 ToDisplay(const glm::dvec3& p) const
  {
    const double in[4] = { p.x, p.y, p.z, 1.0 };
    double out[4];
    vtkMatrix4x4::MultiplyPoint(this->Matrix, in, out);
    const double w = out[3] != 0.0 ? out[3] : 1.0;
    return glm::dvec3(this->Origin[0] + (out[0] / w + 1.0) * 0.5 * this->Size[0],
      this->Origin[1] + (out[1] / w + 1.0) * 0.5 * this->Size[1],
      out[2] / w);
  }

  glm::dvec3 ToWorld(double x, double y, double z) const
  {
    const double in[4] = { 2.0 * (x - this->Origin[0]) / this->Size[0] - 1.0,
      2.0 * (y - this->Origin[1]) / this->Size[1] - 1.0,
      z,
      1.0 };
    double out[4];
    vtkMatrix4x4::MultiplyPoint(this->Inverse, in, out);
    const double w = out[3] != 0.0 ? out[3] : 1.0;
    return glm::dvec3(out[0] / w, out[1] / w, out[2] / w);
  }
};
}

//------------------------------------------------------------------------------
class vtkCageRepresentation::vtkInternals
{
public:
  // Cage copy: handle positions (the proposal during an interaction), boxes,
  // labels and which boxes use each point.
  std::vector<glm::dvec3> Positions;
  std::vector<std::array<vtkIdType, 8>> Boxes;
  std::vector<int> Labels;
  std::vector<std::vector<vtkIdType>> PointBoxes;
  std::vector<vtkIdType> BoxIds;       // the cage's box of each of Boxes
  std::vector<char> HiddenBoxes;       // by the cage's box index
  vtkNew<vtkDoubleArray> HandleScales; // 0 hides a handle's glyph

  bool BoxShown(size_t b) const { return !this->HiddenBoxes[this->BoxIds[b]]; }
  bool PointShown(vtkIdType id) const
  {
    const std::vector<vtkIdType>& boxes = this->PointBoxes[id];
    return boxes.empty() ||
      std::any_of(boxes.begin(), boxes.end(), [this](vtkIdType b) { return this->BoxShown(b); });
  }
  std::vector<char> Selected;
  double Diagonal = 1.0;    // of the rest cage's bounds: tolerances
  double BoxDiagonal = 1.0; // mean over the rest boxes: the handle size
  vtkMTimeType SyncTime = 0;
  bool Dirty = true;

  // The current interaction.
  int Mode = vtkCageRepresentation::Outside;
  bool InInteraction = false;
  bool Rejected = false;
  std::vector<vtkIdType> Moving;
  std::vector<glm::dvec3> Start;
  std::vector<glm::dvec3> Proposed;
  glm::dvec3 Reference{ 0.0 };
  double StartEvent[2] = { 0.0, 0.0 };
  double BandStart[2] = { 0.0, 0.0 };
  std::vector<vtkIdType> MovedIds;
  std::vector<glm::dvec3> MovedPositions;

  // Rendering: one glyph actor for every handle, one line actor for every
  // edge, the rubber band.
  vtkNew<vtkPoints> Points;
  vtkNew<vtkPolyData> Handles;
  vtkNew<vtkUnsignedCharArray> HandleColors;
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkGlyph3D> Glyph;
  vtkNew<vtkPolyDataMapper> HandleMapper;
  vtkNew<vtkActor> HandleActor;
  vtkNew<vtkPolyData> Edges;
  vtkNew<vtkPolyDataMapper> EdgeMapper;
  vtkNew<vtkActor> EdgeActor;
  vtkNew<vtkPolyData> Band;
  vtkNew<vtkPolyDataMapper2D> BandMapper;
  vtkNew<vtkActor2D> BandActor;
  vtkNew<vtkUnsignedCharArray> DefaultPalette;
  int DefaultPaletteLabels = 0;
  double Bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };

  vtkInternals()
  {
    this->Points->SetDataTypeToDouble();
    this->Handles->SetPoints(this->Points);
    this->HandleColors->SetNumberOfComponents(3);
    this->Handles->GetPointData()->SetScalars(this->HandleColors);
    // Scale 1 shows a handle, 0 collapses the glyph of a hidden one.
    this->HandleScales->SetName("HandleScale");
    this->Handles->GetPointData()->AddArray(this->HandleScales);
    this->Sphere->SetThetaResolution(12);
    this->Sphere->SetPhiResolution(8);
    this->Glyph->SetInputData(this->Handles);
    this->Glyph->SetSourceConnection(this->Sphere->GetOutputPort());
    this->Glyph->SetScaleModeToScaleByScalar();
    this->Glyph->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "HandleScale");
    this->Glyph->SetInputArrayToProcess(
      3, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    this->Glyph->SetColorModeToColorByScalar();
    this->HandleMapper->SetInputConnection(this->Glyph->GetOutputPort());
    this->HandleMapper->SetColorModeToDirectScalars();
    this->HandleActor->SetMapper(this->HandleMapper);
    this->Edges->SetPoints(this->Points);
    this->EdgeMapper->SetInputData(this->Edges);
    this->EdgeMapper->SetColorModeToDirectScalars();
    this->EdgeMapper->SetScalarModeToUseCellData();
    this->EdgeActor->SetMapper(this->EdgeMapper);
    this->EdgeActor->GetProperty()->SetLighting(false);
    this->BandMapper->SetInputData(this->Band);
    this->BandActor->SetMapper(this->BandMapper);
    this->BandActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    this->BandActor->GetProperty()->SetLineWidth(1.0);
    this->BandActor->VisibilityOff();
  }

  vtkIdType NumberOfPoints() const { return static_cast<vtkIdType>(this->Positions.size()); }

  /// The boxes that use any of `ids`.
  void AffectedBoxes(const std::vector<vtkIdType>& ids, vtkIdList* boxes) const
  {
    std::vector<char> seen(this->Boxes.size(), 0);
    boxes->Reset();
    for (vtkIdType id : ids)
    {
      for (vtkIdType b : this->PointBoxes[id])
      {
        if (!seen[b])
        {
          seen[b] = 1;
          boxes->InsertNextId(b);
        }
      }
    }
  }

  std::vector<vtkIdType> SelectedIds() const
  {
    std::vector<vtkIdType> ids;
    for (vtkIdType i = 0; i < this->NumberOfPoints(); ++i)
    {
      if (this->Selected[i])
      {
        ids.push_back(i);
      }
    }
    return ids;
  }

  glm::dvec3 FaceCentre(vtkIdType box, int face) const
  {
    glm::dvec3 c(0.0);
    for (int k = 0; k < 4; ++k)
    {
      c += this->Positions[this->Boxes[box][vtkHexahedron::GetFaceArray(face)[k]]];
    }
    return c * 0.25;
  }

  /// Moving / Proposed for the 4 corners of a face: `map` takes a corner
  /// relative to the face's centre and the unit box axis through the face
  /// (from the opposite face's centre; vtkHexahedron numbers opposite faces
  /// 2k and 2k + 1). False for a box flat along that axis.
  template<typename Map>
  bool MapFace(vtkIdType box, int face, Map map)
  {
    const glm::dvec3 centre = this->FaceCentre(box, face);
    const glm::dvec3 axis = centre - this->FaceCentre(box, face ^ 1);
    if (!(glm::length(axis) > 0.0))
    {
      return false;
    }
    this->Moving.clear();
    this->Proposed.clear();
    for (int k = 0; k < 4; ++k)
    {
      const vtkIdType id = this->Boxes[box][vtkHexahedron::GetFaceArray(face)[k]];
      this->Moving.push_back(id);
      this->Proposed.push_back(centre + map(this->Positions[id] - centre, glm::normalize(axis)));
    }
    return true;
  }

  glm::dvec3 BoxCentre(vtkIdType box) const
  {
    glm::dvec3 c(0.0);
    for (vtkIdType id : this->Boxes[box])
    {
      c += this->Positions[id];
    }
    return c * 0.125;
  }
};

//------------------------------------------------------------------------------
vtkCageRepresentation::vtkCageRepresentation()
  : Internals(new vtkInternals)
{
  this->InteractionState = Outside;
}

//------------------------------------------------------------------------------
vtkCageRepresentation::~vtkCageRepresentation()
{
  this->SetCage(nullptr);
  this->SetPalette(nullptr);
  this->SetOccluderDepth(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SetCage(vtkDeformationCage* cage)
{
  if (cage == this->Cage)
  {
    return;
  }
  if (this->Cage)
  {
    this->Cage->UnRegister(this);
  }
  this->Cage = cage;
  if (this->Cage)
  {
    this->Cage->Register(this);
  }
  this->Internals->Mode = Outside;
  this->Internals->InInteraction = false;
  this->Internals->Selected.clear();
  this->UpdateFromCage();
  this->PivotBox = -1;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::UpdateFromCage()
{
  if (this->Internals->InInteraction)
  {
    this->Internals->Rejected = true;
  }
  this->Internals->MovedIds.clear();
  this->Internals->MovedPositions.clear();
  this->SyncFromCage(true);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SyncFromCage(bool force)
{
  vtkInternals& in = *this->Internals;
  const vtkMTimeType cageTime = this->Cage ? this->Cage->GetMTime() : 0;
  if (!force && (cageTime == in.SyncTime || in.InInteraction))
  {
    return;
  }
  in.SyncTime = cageTime;
  in.Dirty = true;
  const vtkIdType n = this->Cage ? this->Cage->GetNumberOfPoints() : 0;
  in.Positions.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    this->Cage->GetPoint(i, p);
    in.Positions[i] = ToVec(p);
  }
  in.Boxes.clear();
  in.Labels.clear();
  in.BoxIds.clear();
  in.PointBoxes.assign(n, {});
  const vtkIdType numberOfBoxes = this->Cage ? this->Cage->GetNumberOfBoxes() : 0;
  if (static_cast<vtkIdType>(in.HiddenBoxes.size()) != numberOfBoxes)
  {
    in.HiddenBoxes.assign(numberOfBoxes, 0);
  }
  vtkNew<vtkIdList> cellIds;
  for (vtkIdType b = 0; b < numberOfBoxes; ++b)
  {
    // Validate() refuses other cells; they are not drawn or edited here.
    this->Cage->GetCellPoints(b, cellIds);
    std::array<vtkIdType, 8> corners;
    bool ok = this->Cage->GetCellType(b) == VTK_HEXAHEDRON && cellIds->GetNumberOfIds() == 8;
    for (int k = 0; ok && k < 8; ++k)
    {
      corners[k] = cellIds->GetId(k);
      ok = corners[k] >= 0 && corners[k] < n;
    }
    if (!ok)
    {
      continue;
    }
    const vtkIdType index = static_cast<vtkIdType>(in.Boxes.size());
    in.Boxes.push_back(corners);
    in.BoxIds.push_back(b);
    in.Labels.push_back(this->Cage->GetBoxLabel(b));
    for (vtkIdType id : corners)
    {
      if (std::find(in.PointBoxes[id].begin(), in.PointBoxes[id].end(), index) ==
        in.PointBoxes[id].end())
      {
        in.PointBoxes[id].push_back(index);
      }
    }
  }
  // Handle size and tolerances scale with the rest cage.
  in.Diagonal = 1.0;
  vtkDataArray* rest = this->Cage ? this->Cage->GetRestPositions() : nullptr;
  if (rest && rest->GetNumberOfTuples() > 0)
  {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      double range[2];
      rest->GetRange(range, c);
      d2 += (range[1] - range[0]) * (range[1] - range[0]);
    }
    in.Diagonal = d2 > 0.0 ? std::sqrt(d2) : 1.0;
  }
  in.BoxDiagonal = in.Diagonal;
  if (rest && !in.Boxes.empty())
  {
    double sum = 0.0;
    for (const auto& box : in.Boxes)
    {
      double a[3], b[3];
      rest->GetTuple(box[0], a);
      rest->GetTuple(box[6], b);
      sum += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    }
    in.BoxDiagonal = sum > 0.0 ? sum / in.Boxes.size() : in.Diagonal;
  }
  if (static_cast<vtkIdType>(in.Selected.size()) != n)
  {
    const bool hadSelection =
      std::find(in.Selected.begin(), in.Selected.end(), 1) != in.Selected.end();
    in.Selected.assign(n, 0);
    this->HoverPointId = -1;
    if (hadSelection)
    {
      this->InvokeEvent(SelectionChangedEvent);
    }
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::GetMovedPointIds(vtkIdList* ids)
{
  ids->Reset();
  for (vtkIdType id : this->Internals->MovedIds)
  {
    ids->InsertNextId(id);
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::GetMovedPositions(vtkPoints* positions)
{
  positions->Reset();
  for (const glm::dvec3& p : this->Internals->MovedPositions)
  {
    positions->InsertNextPoint(p.x, p.y, p.z);
  }
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::GetHandlePosition(vtkIdType id, double position[3])
{
  this->SyncFromCage(false);
  if (id < 0 || id >= this->Internals->NumberOfPoints())
  {
    return false;
  }
  const glm::dvec3& p = this->Internals->Positions[id];
  position[0] = p.x;
  position[1] = p.y;
  position[2] = p.z;
  return true;
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::Propose(bool clamp)
{
  vtkInternals& in = *this->Internals;
  const std::vector<vtkIdType>& ids = in.Moving;
  in.Dirty = true;
  if (!this->ApplyToCage || !this->Cage)
  {
    for (size_t k = 0; k < ids.size(); ++k)
    {
      in.Positions[ids[k]] = in.Proposed[k];
    }
    in.MovedIds = ids;
    in.MovedPositions = in.Proposed;
    return true;
  }
  // Standalone: the cage must stay valid (a box the move folds is refused,
  // or the move clamped to the last valid point along it).
  vtkPoints* points = this->Cage->GetPoints();
  vtkNew<vtkIdList> boxes;
  in.AffectedBoxes(ids, boxes);
  std::vector<glm::dvec3> from(ids.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    from[k] = in.Positions[ids[k]];
  }
  auto tryFraction = [&](double t)
  {
    for (size_t k = 0; k < ids.size(); ++k)
    {
      const glm::dvec3 p = from[k] + t * (in.Proposed[k] - from[k]);
      points->SetPoint(ids[k], p.x, p.y, p.z);
    }
    return this->Cage->ValidateBoxes(boxes).empty();
  };
  double accepted = 1.0;
  if (!tryFraction(1.0))
  {
    if (!clamp)
    {
      tryFraction(0.0);
      return false;
    }
    // Bisection for the farthest valid fraction of the move.
    double lo = 0.0;
    double hi = 1.0;
    for (int i = 0; i < 12; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      (tryFraction(mid) ? lo : hi) = mid;
    }
    tryFraction(lo);
    accepted = lo;
  }
  in.MovedIds = ids;
  in.MovedPositions.resize(ids.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    in.Positions[ids[k]] = from[k] + accepted * (in.Proposed[k] - from[k]);
    in.MovedPositions[k] = in.Positions[ids[k]];
  }
  points->Modified();
  this->Cage->Modified();
  in.SyncTime = this->Cage->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::RunEdit()
{
  vtkInternals& in = *this->Internals;
  if (in.Moving.empty() || in.Mode != Outside)
  {
    return false;
  }
  in.InInteraction = true;
  in.Rejected = false;
  const bool accepted = this->Propose(false);
  if (accepted)
  {
    this->InvokeEvent(vtkCommand::StartInteractionEvent);
    this->InvokeEvent(vtkCommand::InteractionEvent);
    this->InvokeEvent(vtkCommand::EndInteractionEvent);
  }
  in.InInteraction = false;
  this->Modified();
  return accepted && !in.Rejected;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SetBoxVisibility(vtkIdType box, bool visible)
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  if (box < 0 || box >= static_cast<vtkIdType>(in.HiddenBoxes.size()))
  {
    vtkErrorMacro(
      "SetBoxVisibility: no box " << box << " in a cage of " << in.HiddenBoxes.size() << " boxes.");
    return;
  }
  if (in.HiddenBoxes[box] != (visible ? 0 : 1))
  {
    in.HiddenBoxes[box] = visible ? 0 : 1;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::GetBoxVisibility(vtkIdType box)
{
  this->SyncFromCage(false);
  const vtkInternals& in = *this->Internals;
  return box >= 0 && box < static_cast<vtkIdType>(in.HiddenBoxes.size()) && !in.HiddenBoxes[box];
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::IsPointVisible(vtkIdType id)
{
  this->SyncFromCage(false);
  const vtkInternals& in = *this->Internals;
  if (!this->Renderer || id < 0 || id >= in.NumberOfPoints() || !in.PointShown(id))
  {
    return false;
  }
  const ViewProjection view(this->Renderer);
  const glm::dvec3 p = in.Positions[id];
  const glm::dvec3 display = view.ToDisplay(p);
  if (this->OccluderDepth)
  {
    // The object's depth at the point's pixel (nearest sample).
    int dims[3];
    this->OccluderDepth->GetDimensions(dims);
    const int i = static_cast<int>((display.x - view.Origin[0]) * dims[0] / view.Size[0]);
    const int j = static_cast<int>((display.y - view.Origin[1]) * dims[1] / view.Size[1]);
    if (i >= 0 && j >= 0 && i < dims[0] && j < dims[1] &&
      display.z >
        this->OccluderDepth->GetScalarComponentAsDouble(i, j, 0, 0) + this->OccluderTolerance)
    {
      return false;
    }
  }
  // The segment from the near plane to the point, along the view ray.
  const glm::dvec3 origin = view.ToWorld(display.x, display.y, 0.0);
  const glm::dvec3 direction = p - origin;
  const std::vector<vtkIdType>& own = in.PointBoxes[id];
  for (vtkIdType b = 0; b < static_cast<vtkIdType>(in.Boxes.size()); ++b)
  {
    if (!in.BoxShown(b) || std::find(own.begin(), own.end(), b) != own.end())
    {
      continue;
    }
    for (int face = 0; face < 6; ++face)
    {
      const int* c = lfd::HexFacePatch[face];
      lfd::PatchHit hits[2];
      const int n = lfd::IntersectBilinearPatch(in.Positions[in.Boxes[b][c[0]]],
        in.Positions[in.Boxes[b][c[1]]],
        in.Positions[in.Boxes[b][c[2]]],
        in.Positions[in.Boxes[b][c[3]]],
        origin,
        direction,
        hits);
      for (int k = 0; k < n; ++k)
      {
        if (hits[k].T > 0.0 && hits[k].T < 1.0 - 1e-9)
        {
          return false;
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkCageRepresentation::PickPoint(double x, double y)
{
  this->SyncFromCage(false);
  const vtkInternals& in = *this->Internals;
  if (!this->Renderer)
  {
    return -1;
  }
  const ViewProjection view(this->Renderer);
  struct Candidate
  {
    double Distance;
    double Depth;
    vtkIdType Id;
  };
  std::vector<Candidate> candidates;
  for (vtkIdType i = 0; i < in.NumberOfPoints(); ++i)
  {
    const glm::dvec3 d = view.ToDisplay(in.Positions[i]);
    const double distance = std::hypot(d.x - x, d.y - y);
    if (distance <= this->PickTolerance && d.z >= 0.0 && d.z <= 1.0)
    {
      candidates.push_back({ distance, d.z, i });
    }
  }
  std::sort(candidates.begin(),
    candidates.end(),
    [](const Candidate& a, const Candidate& b) { return a.Distance < b.Distance; });
  // The visible candidate nearest to the cursor; within a pixel of it, the
  // one nearest to the eye.
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
  {
    if (best && c.Distance > best->Distance + 1.0)
    {
      break;
    }
    if ((!best || c.Depth < best->Depth) && this->IsPointVisible(c.Id))
    {
      best = &c;
    }
  }
  return best ? best->Id : -1;
}

//------------------------------------------------------------------------------
int vtkCageRepresentation::ComputeInteractionState(int X, int Y, int vtkNotUsed(modify))
{
  const vtkIdType hover = this->PickPoint(X, Y);
  if (hover != this->HoverPointId)
  {
    this->HoverPointId = hover;
    this->Internals->Dirty = true;
    this->Modified();
  }
  if (this->Internals->Mode == Outside && this->InteractionState != RubberBand)
  {
    this->InteractionState = hover >= 0 ? OnHandle : Outside;
  }
  return this->InteractionState;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SetInteractionState(int state)
{
  state = std::max(static_cast<int>(Outside), std::min(state, static_cast<int>(Scaling)));
  if (this->InteractionState != state)
  {
    this->InteractionState = state;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::SetSelection(const vtkIdType* ids, vtkIdType count, bool extend)
{
  vtkInternals& in = *this->Internals;
  std::vector<char> selected = in.Selected;
  if (!extend)
  {
    std::fill(selected.begin(), selected.end(), 0);
  }
  for (vtkIdType k = 0; k < count; ++k)
  {
    selected[ids[k]] = 1;
  }
  if (selected == in.Selected)
  {
    return false;
  }
  in.Selected.swap(selected);
  in.Dirty = true;
  this->Modified();
  this->InvokeEvent(SelectionChangedEvent);
  return true;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SelectPoint(vtkIdType id, bool extend)
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  if (id < 0 || id >= in.NumberOfPoints())
  {
    vtkErrorMacro("SelectPoint: point " << id << " does not exist (the cage has "
                                        << in.NumberOfPoints() << " points).");
    return;
  }
  if (extend && in.Selected[id])
  {
    in.Selected[id] = 0;
    in.Dirty = true;
    this->Modified();
    this->InvokeEvent(SelectionChangedEvent);
    return;
  }
  this->SetSelection(&id, 1, extend);
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::CheckBoxFace(vtkIdType box, int face)
{
  this->SyncFromCage(false);
  const vtkIdType n = static_cast<vtkIdType>(this->Internals->Boxes.size());
  if (box < 0 || box >= n)
  {
    vtkErrorMacro("Box " << box << " does not exist (the cage has " << n << " boxes).");
    return false;
  }
  if (face < -1 || face > 5)
  {
    vtkErrorMacro("Face " << face << " does not exist (a box has faces 0..5).");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SelectBox(vtkIdType box)
{
  if (this->CheckBoxFace(box, -1))
  {
    this->SetPivotBox(box);
    this->SetSelection(this->Internals->Boxes[box].data(), 8, false);
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SelectFace(vtkIdType box, int face)
{
  if (this->CheckBoxFace(box, face))
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = this->Internals->Boxes[box][vtkHexahedron::GetFaceArray(face)[k]];
    }
    this->SetPivotBox(box);
    this->SetSelection(ids, 4, false);
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SelectAll()
{
  this->SyncFromCage(false);
  std::vector<vtkIdType> ids(this->Internals->NumberOfPoints());
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(ids.size()); ++i)
  {
    ids[i] = i;
  }
  this->SetSelection(ids.data(), static_cast<vtkIdType>(ids.size()), false);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::ClearSelection()
{
  this->SyncFromCage(false);
  this->SetSelection(nullptr, 0, false);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::SelectInRectangle(double x0,
  double y0,
  double x1,
  double y1,
  bool extend)
{
  this->SyncFromCage(false);
  if (!this->Renderer)
  {
    return;
  }
  const ViewProjection view(this->Renderer);
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < this->Internals->NumberOfPoints(); ++i)
  {
    const glm::dvec3 d = view.ToDisplay(this->Internals->Positions[i]);
    if (d.x >= std::min(x0, x1) && d.x <= std::max(x0, x1) && d.y >= std::min(y0, y1) &&
      d.y <= std::max(y0, y1) && d.z >= 0.0 && d.z <= 1.0 && this->IsPointVisible(i))
    {
      ids.push_back(i);
    }
  }
  this->SetSelection(ids.data(), static_cast<vtkIdType>(ids.size()), extend);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::GetSelectedPointIds(vtkIdList* ids)
{
  this->SyncFromCage(false);
  ids->Reset();
  for (vtkIdType id : this->Internals->SelectedIds())
  {
    ids->InsertNextId(id);
  }
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::IsPointSelected(vtkIdType id)
{
  this->SyncFromCage(false);
  return id >= 0 && id < this->Internals->NumberOfPoints() && this->Internals->Selected[id];
}

//------------------------------------------------------------------------------
vtkIdType vtkCageRepresentation::GetNumberOfSelectedPoints()
{
  this->SyncFromCage(false);
  return static_cast<vtkIdType>(
    std::count(this->Internals->Selected.begin(), this->Internals->Selected.end(), 1));
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::GetPivot(double pivot[3])
{
  this->SyncFromCage(false);
  const vtkInternals& in = *this->Internals;
  glm::dvec3 c(0.0);
  if (this->PivotMode == PivotAtPoint)
  {
    c = ToVec(this->PivotPoint);
  }
  else if (this->PivotMode == PivotAtBoxCentre)
  {
    vtkIdType box = this->PivotBox;
    if (box < 0 || box >= static_cast<vtkIdType>(in.Boxes.size()))
    {
      // The box using the most selected points.
      int most = 0;
      box = -1;
      for (vtkIdType b = 0; b < static_cast<vtkIdType>(in.Boxes.size()); ++b)
      {
        const int count = static_cast<int>(std::count_if(in.Boxes[b].begin(),
          in.Boxes[b].end(),
          [&in](vtkIdType id) { return in.Selected[id] != 0; }));
        if (count > most)
        {
          most = count;
          box = b;
        }
      }
      if (box < 0)
      {
        return false;
      }
    }
    c = in.BoxCentre(box);
  }
  else
  {
    const std::vector<vtkIdType> ids = in.SelectedIds();
    if (ids.empty())
    {
      return false;
    }
    for (vtkIdType id : ids)
    {
      c += in.Positions[id];
    }
    c /= static_cast<double>(ids.size());
  }
  pivot[0] = c.x;
  pivot[1] = c.y;
  pivot[2] = c.z;
  return true;
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::TranslateSelection(double dx, double dy, double dz)
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  in.Moving = in.SelectedIds();
  in.Proposed.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Proposed.push_back(in.Positions[id] + glm::dvec3(dx, dy, dz));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::RotateSelection(const double axis[3], double degrees)
{
  double pivot[3];
  const glm::dvec3 a = ToVec(axis);
  if (!(glm::length(a) > 0.0) || !std::isfinite(degrees) || !this->GetPivot(pivot))
  {
    return false;
  }
  vtkInternals& in = *this->Internals;
  in.Moving = in.SelectedIds();
  in.Proposed.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Proposed.push_back(ToVec(pivot) +
      Rotate(
        in.Positions[id] - ToVec(pivot), glm::normalize(a), vtkMath::RadiansFromDegrees(degrees)));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::ScaleSelection(double sx, double sy, double sz)
{
  double pivot[3];
  if (!(sx > 0.0 && sy > 0.0 && sz > 0.0) || !this->GetPivot(pivot))
  {
    return false;
  }
  vtkInternals& in = *this->Internals;
  in.Moving = in.SelectedIds();
  in.Proposed.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Proposed.push_back(
      ToVec(pivot) + glm::dvec3(sx, sy, sz) * (in.Positions[id] - ToVec(pivot)));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::TwistFace(vtkIdType box, int face, double degrees)
{
  const double radians = vtkMath::RadiansFromDegrees(degrees);
  return this->CheckBoxFace(box, face) && std::isfinite(degrees) &&
    this->Internals->MapFace(box,
      face,
      [radians](const glm::dvec3& q, const glm::dvec3& axis)
      { return Rotate(q, axis, radians); }) &&
    this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::TaperFace(vtkIdType box, int face, double scale)
{
  return this->CheckBoxFace(box, face) && scale > 0.0 &&
    this->Internals->MapFace(box,
      face,
      [scale](const glm::dvec3& q, const glm::dvec3& axis)
      {
        const glm::dvec3 along = glm::dot(q, axis) * axis;
        return along + scale * (q - along);
      }) &&
    this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::Bend(int axis, double degrees)
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  const std::vector<vtkIdType> ids = in.SelectedIds();
  if (axis < 0 || axis > 2 || !std::isfinite(degrees) || degrees == 0.0 || ids.empty() ||
    !this->Cage)
  {
    return false;
  }
  // The lattice region: the selection's bounds, padded so that a flat
  // selection still has a volume and every point lies inside.
  glm::dvec3 lo(VTK_DOUBLE_MAX), hi(-VTK_DOUBLE_MAX);
  for (vtkIdType id : ids)
  {
    lo = glm::min(lo, in.Positions[id]);
    hi = glm::max(hi, in.Positions[id]);
  }
  const double pad = 1e-3 * in.Diagonal;
  lo -= pad;
  hi += pad;
  const glm::dvec3 size = hi - lo;
  // The bar's long axis u among the two others; it bends towards w = A x u.
  const int u = size[(axis + 1) % 3] >= size[(axis + 2) % 3] ? (axis + 1) % 3 : (axis + 2) % 3;
  glm::dvec3 axisA(0.0), axisU(0.0);
  axisA[axis] = 1.0;
  axisU[u] = 1.0;
  const glm::dvec3 axisW = glm::cross(axisA, axisU);
  const glm::dvec3 middle = 0.5 * (lo + hi);
  const double theta = vtkMath::RadiansFromDegrees(degrees);
  const double radius = size[u] / theta;

  int dims[3] = { 2, 2, 2 };
  dims[u] = this->LatticeResolution;
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetLatticeDimensions(dims);
  lattice->SetRegion(lo.x, hi.x, lo.y, hi.y, lo.z, hi.z);
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        const int index[3] = { i, j, k };
        glm::dvec3 rest;
        for (int c = 0; c < 3; ++c)
        {
          rest[c] = lo[c] + size[c] * index[c] / (dims[c] - 1);
        }
        // Control point on the arc: the bar's middle line bends on a circle
        // of radius size[u] / theta, its cross-sections turn with it.
        const glm::dvec3 q = rest - middle;
        const double phi = glm::dot(q, axisU) / radius;
        const double h = glm::dot(q, axisW);
        const glm::dvec3 bent = middle + glm::dot(q, axisA) * axisA +
          (radius * std::sin(phi) - h * std::sin(phi)) * axisU +
          (radius * (1.0 - std::cos(phi)) + h * std::cos(phi)) * axisW;
        const glm::dvec3 displacement = bent - rest;
        lattice->SetControlPointDisplacement(
          i, j, k, displacement.x, displacement.y, displacement.z);
      }
    }
  }
  // The filter's update fixes the region EvaluateDeformation() uses.
  lattice->SetInputData(this->Cage);
  lattice->Update();
  in.Moving = ids;
  in.Proposed.clear();
  for (vtkIdType id : ids)
  {
    double p[3];
    const double current[3] = { in.Positions[id].x, in.Positions[id].y, in.Positions[id].z };
    lattice->EvaluateDeformation(current, p);
    in.Proposed.push_back(ToVec(p));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::MirrorSelection(const double origin[3], const double normal[3])
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  vtkDataArray* restArray = this->Cage ? this->Cage->GetRestPositions() : nullptr;
  const glm::dvec3 n = ToVec(normal);
  if (!restArray || !(glm::length(n) > 0.0))
  {
    return false;
  }
  const glm::dvec3 unit = glm::normalize(n);
  const glm::dvec3 o = ToVec(origin);
  const vtkIdType count = in.NumberOfPoints();
  std::vector<glm::dvec3> rest(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    rest[i] = ToVec(restArray->GetTuple3(i));
  }
  const double tolerance = 1e-6 * in.Diagonal;
  auto reflect = [&unit](const glm::dvec3& v) { return v - 2.0 * glm::dot(v, unit) * unit; };
  in.Moving.clear();
  in.Proposed.clear();
  for (vtkIdType p : in.SelectedIds())
  {
    const double side = glm::dot(rest[p] - o, unit);
    if (std::abs(side) <= tolerance)
    {
      continue;
    }
    const glm::dvec3 image = o + reflect(rest[p] - o);
    vtkIdType q = -1;
    for (vtkIdType i = 0; i < count && q < 0; ++i)
    {
      q = glm::distance(rest[i], image) <= tolerance ? i : -1;
    }
    // A selected pair copies from the normal's side.
    if (q < 0 || (in.Selected[q] && side < 0.0))
    {
      continue;
    }
    in.Moving.push_back(q);
    in.Proposed.push_back(rest[q] + reflect(in.Positions[p] - rest[p]));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::ResetSelection()
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  in.Moving = in.SelectedIds();
  vtkDataArray* rest = this->Cage ? this->Cage->GetRestPositions() : nullptr;
  if (!rest)
  {
    return false;
  }
  in.Proposed.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Proposed.push_back(ToVec(rest->GetTuple3(id)));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::ResetBox(vtkIdType box)
{
  vtkDataArray* rest = this->Cage ? this->Cage->GetRestPositions() : nullptr;
  if (!this->CheckBoxFace(box, -1) || !rest)
  {
    return false;
  }
  vtkInternals& in = *this->Internals;
  in.Moving.assign(in.Boxes[box].begin(), in.Boxes[box].end());
  in.Proposed.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Proposed.push_back(ToVec(rest->GetTuple3(id)));
  }
  return this->RunEdit();
}

//------------------------------------------------------------------------------
bool vtkCageRepresentation::StartTransform(int mode, double x, double y)
{
  this->SyncFromCage(false);
  vtkInternals& in = *this->Internals;
  double pivot[3];
  if ((mode != Dragging && mode != Translating && mode != Rotating && mode != Scaling) ||
    !this->Renderer || in.Mode != Outside || !this->GetPivot(pivot))
  {
    return false;
  }
  in.Moving = in.SelectedIds();
  if (in.Moving.empty())
  {
    return false;
  }
  in.Start.clear();
  for (vtkIdType id : in.Moving)
  {
    in.Start.push_back(in.Positions[id]);
  }
  // A drag follows the grabbed handle; the modal transforms the pivot.
  in.Reference = ToVec(pivot);
  if (mode == Dragging && this->HoverPointId >= 0)
  {
    in.Reference = in.Positions[this->HoverPointId];
  }
  in.StartEvent[0] = x;
  in.StartEvent[1] = y;
  in.Mode = mode;
  in.InInteraction = true;
  in.Rejected = false;
  in.MovedIds.clear();
  in.MovedPositions.clear();
  this->SetInteractionState(mode);
  return true;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::ComputeTransform(double x, double y)
{
  vtkInternals& in = *this->Internals;
  const ViewProjection view(this->Renderer);
  const glm::dvec3 ref = view.ToDisplay(in.Reference);
  const glm::dvec2 centre(ref.x, ref.y);
  const glm::dvec2 from(in.StartEvent[0], in.StartEvent[1]);
  const glm::dvec2 to(x, y);
  const int axis = this->Constraint == ConstraintNone ? -1 : (this->Constraint - 1) % 3;
  const bool plane = this->Constraint >= ConstraintPlaneX;
  glm::dvec3 a(0.0);
  if (axis >= 0)
  {
    a[axis] = 1.0;
  }
  in.Proposed = in.Start;
  if (in.Mode == Dragging || in.Mode == Translating)
  {
    // Motion in the plane through the reference parallel to the view plane.
    glm::dvec3 d = view.ToWorld(to.x, to.y, ref.z) - view.ToWorld(from.x, from.y, ref.z);
    if (axis >= 0 && !plane)
    {
      // Along the axis as it appears on screen.
      const glm::dvec3 tip = view.ToDisplay(in.Reference + in.Diagonal * a);
      const glm::dvec2 screenAxis(tip.x - ref.x, tip.y - ref.y);
      const double length2 = glm::dot(screenAxis, screenAxis);
      d = length2 > 1e-12 ? (glm::dot(to - from, screenAxis) / length2 * in.Diagonal) * a
                          : glm::dvec3(0.0);
    }
    else if (plane)
    {
      d -= glm::dot(d, a) * a;
    }
    for (glm::dvec3& p : in.Proposed)
    {
      p += d;
    }
    return;
  }
  const glm::dvec2 v0 = from - centre;
  const glm::dvec2 v1 = to - centre;
  if (in.Mode == Rotating)
  {
    // The angle swept on screen, counter-clockwise positive about the axis
    // towards the viewer.
    const glm::dvec3 towardsViewer =
      glm::normalize(view.ToWorld(ref.x, ref.y, 0.0) - view.ToWorld(ref.x, ref.y, 1.0));
    double angle = std::atan2(v0.x * v1.y - v0.y * v1.x, glm::dot(v0, v1));
    glm::dvec3 rotationAxis = towardsViewer;
    if (axis >= 0)
    {
      rotationAxis = a;
      angle = glm::dot(a, towardsViewer) < 0.0 ? -angle : angle;
    }
    for (glm::dvec3& p : in.Proposed)
    {
      p = in.Reference + Rotate(p - in.Reference, rotationAxis, angle);
    }
    return;
  }
  const double start = glm::length(v0);
  const double f = start > 1.0 ? glm::length(v1) / start : 1.0;
  glm::dvec3 scale(f);
  if (axis >= 0)
  {
    scale = plane ? glm::dvec3(f) : glm::dvec3(1.0);
    scale[axis] = plane ? 1.0 : f;
  }
  for (glm::dvec3& p : in.Proposed)
  {
    p = in.Reference + scale * (p - in.Reference);
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::UpdateTransform(double x, double y)
{
  if (this->Internals->Mode == Outside || !this->Renderer)
  {
    return;
  }
  this->ComputeTransform(x, y);
  this->Propose(true);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::ConfirmTransform()
{
  vtkInternals& in = *this->Internals;
  in.Mode = Outside;
  in.InInteraction = false;
  this->SetInteractionState(this->HoverPointId >= 0 ? OnHandle : Outside);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::CancelTransform()
{
  vtkInternals& in = *this->Internals;
  if (in.Mode == Outside)
  {
    return;
  }
  in.Proposed = in.Start;
  this->Propose(true);
  this->ConfirmTransform();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::StartRubberBand(double x, double y)
{
  vtkInternals& in = *this->Internals;
  in.BandStart[0] = x;
  in.BandStart[1] = y;
  this->SetInteractionState(RubberBand);
  this->UpdateRubberBand(x, y);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::UpdateRubberBand(double x, double y)
{
  vtkInternals& in = *this->Internals;
  vtkNew<vtkPoints> corners;
  corners->InsertNextPoint(in.BandStart[0], in.BandStart[1], 0.0);
  corners->InsertNextPoint(x, in.BandStart[1], 0.0);
  corners->InsertNextPoint(x, y, 0.0);
  corners->InsertNextPoint(in.BandStart[0], y, 0.0);
  vtkNew<vtkCellArray> line;
  const vtkIdType loop[5] = { 0, 1, 2, 3, 0 };
  line->InsertNextCell(5, loop);
  in.Band->SetPoints(corners);
  in.Band->SetLines(line);
  in.BandActor->VisibilityOn();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::EndRubberBand(double x, double y, bool extend)
{
  vtkInternals& in = *this->Internals;
  in.BandActor->VisibilityOff();
  this->SetInteractionState(Outside);
  this->SelectInRectangle(in.BandStart[0], in.BandStart[1], x, y, extend);
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkCageRepresentation::GetUsedPalette()
{
  if (this->Palette)
  {
    return this->Palette;
  }
  // The default palette for labels 1..largest, as every view shows it.
  vtkInternals& in = *this->Internals;
  int largest = 1;
  for (int label : in.Labels)
  {
    largest = std::max(largest, std::min(label, 255));
  }
  if (largest != in.DefaultPaletteLabels)
  {
    vtkLabelPalette::BuildDefault(largest, in.DefaultPalette);
    in.DefaultPaletteLabels = largest;
  }
  return in.DefaultPalette;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::UpdateGeometry()
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = in.NumberOfPoints();
  in.Points->SetNumberOfPoints(n);
  in.HandleColors->SetNumberOfTuples(n);
  in.HandleScales->SetNumberOfTuples(n);
  vtkMath::UninitializeBounds(in.Bounds);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const glm::dvec3& p = in.Positions[i];
    in.Points->SetPoint(i, p.x, p.y, p.z);
    in.HandleScales->SetValue(i, in.PointShown(i) ? 1.0 : 0.0);
    const double* rgb = in.Selected[i] ? this->SelectedColor : this->HandleColor;
    rgb = i == this->HoverPointId ? this->HoverColor : rgb;
    in.HandleColors->SetTypedTuple(i,
      std::array<unsigned char, 3>{ static_cast<unsigned char>(255.0 * rgb[0] + 0.5),
        static_cast<unsigned char>(255.0 * rgb[1] + 0.5),
        static_cast<unsigned char>(255.0 * rgb[2] + 0.5) }
        .data());
    for (int c = 0; c < 3; ++c)
    {
      in.Bounds[2 * c] = i == 0 ? p[c] : std::min(in.Bounds[2 * c], p[c]);
      in.Bounds[2 * c + 1] = i == 0 ? p[c] : std::max(in.Bounds[2 * c + 1], p[c]);
    }
  }
  in.Points->Modified();
  in.HandleColors->Modified();
  in.HandleScales->Modified();
  in.Handles->Modified();
  in.Sphere->SetRadius(this->HandleSize * in.BoxDiagonal);

  // Each edge once, coloured by the label of the lowest box using it.
  vtkUnsignedCharArray* palette = this->GetUsedPalette();
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  for (size_t b = 0; b < in.Boxes.size(); ++b)
  {
    for (vtkIdType edge = 0; in.BoxShown(b) && edge < 12; ++edge)
    {
      const vtkIdType* e = vtkHexahedron::GetEdgeArray(edge);
      const vtkIdType p0 = in.Boxes[b][e[0]];
      const vtkIdType p1 = in.Boxes[b][e[1]];
      edges.emplace(std::make_pair(std::min(p0, p1), std::max(p0, p1)), in.Labels[b]);
    }
  }
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  for (const auto& edge : edges)
  {
    const vtkIdType ids[2] = { edge.first.first, edge.first.second };
    lines->InsertNextCell(2, ids);
    unsigned char rgb[3] = { 128, 128, 128 };
    if (edge.second >= 0 && edge.second < palette->GetNumberOfTuples() &&
      palette->GetNumberOfComponents() == 3)
    {
      palette->GetTypedTuple(edge.second, rgb);
    }
    colors->InsertNextTypedTuple(rgb);
  }
  in.Edges->SetLines(lines);
  in.Edges->GetCellData()->SetScalars(colors);
  in.Edges->Modified();
  in.EdgeActor->GetProperty()->SetLineWidth(this->EdgeWidth);
  in.Dirty = false;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::BuildRepresentation()
{
  this->SyncFromCage(false);
  if (this->Internals->Dirty || this->GetMTime() > this->BuildTime ||
    (this->Palette && this->Palette->GetMTime() > this->BuildTime))
  {
    this->UpdateGeometry();
    this->BuildTime.Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::PlaceWidget(double vtkNotUsed(bounds)[6]) {}

//------------------------------------------------------------------------------
double* vtkCageRepresentation::GetBounds()
{
  this->BuildRepresentation();
  return this->Internals->Bounds;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::GetActors(vtkPropCollection* pc)
{
  pc->AddItem(this->Internals->EdgeActor);
  pc->AddItem(this->Internals->HandleActor);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::GetActors2D(vtkPropCollection* pc)
{
  pc->AddItem(this->Internals->BandActor);
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->EdgeActor->ReleaseGraphicsResources(w);
  this->Internals->HandleActor->ReleaseGraphicsResources(w);
  this->Internals->BandActor->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
int vtkCageRepresentation::RenderOpaqueGeometry(vtkViewport* viewport)
{
  this->BuildRepresentation();
  if (this->Internals->Positions.empty())
  {
    return 0;
  }
  return this->Internals->EdgeActor->RenderOpaqueGeometry(viewport) +
    this->Internals->HandleActor->RenderOpaqueGeometry(viewport);
}

//------------------------------------------------------------------------------
int vtkCageRepresentation::RenderTranslucentPolygonalGeometry(vtkViewport* vtkNotUsed(viewport))
{
  return 0;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkCageRepresentation::HasTranslucentPolygonalGeometry()
{
  return 0;
}

//------------------------------------------------------------------------------
int vtkCageRepresentation::RenderOverlay(vtkViewport* viewport)
{
  vtkActor2D* band = this->Internals->BandActor;
  return band->GetVisibility() ? band->RenderOverlay(viewport) : 0;
}

//------------------------------------------------------------------------------
void vtkCageRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Cage: " << this->Cage << "\n";
  os << indent << "Palette: " << this->Palette << "\n";
  os << indent << "OccluderDepth: " << this->OccluderDepth << "\n";
  os << indent << "ApplyToCage: " << this->ApplyToCage << "\n";
  os << indent << "HandleSize: " << this->HandleSize << "\n";
  os << indent << "HandleColor: (" << this->HandleColor[0] << ", " << this->HandleColor[1] << ", "
     << this->HandleColor[2] << ")\n";
  os << indent << "HoverColor: (" << this->HoverColor[0] << ", " << this->HoverColor[1] << ", "
     << this->HoverColor[2] << ")\n";
  os << indent << "SelectedColor: (" << this->SelectedColor[0] << ", " << this->SelectedColor[1]
     << ", " << this->SelectedColor[2] << ")\n";
  os << indent << "EdgeWidth: " << this->EdgeWidth << "\n";
  os << indent << "PickTolerance: " << this->PickTolerance << "\n";
  os << indent << "OccluderTolerance: " << this->OccluderTolerance << "\n";
  os << indent << "HoverPointId: " << this->HoverPointId << "\n";
  os << indent << "PivotMode: " << this->PivotMode << "\n";
  os << indent << "PivotPoint: (" << this->PivotPoint[0] << ", " << this->PivotPoint[1] << ", "
     << this->PivotPoint[2] << ")\n";
  os << indent << "PivotBox: " << this->PivotBox << "\n";
  os << indent << "Constraint: " << this->Constraint << "\n";
  os << indent << "LatticeResolution: " << this->LatticeResolution << "\n";
  os << indent << "NumberOfSelectedPoints: " << this->GetNumberOfSelectedPoints() << "\n";
}
