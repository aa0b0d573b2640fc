#include "vtkLightFieldRenderer.h"

#include "lfdRequestGuard.h"

#include "lfdCylinderSampling.h"
#include "lfdLimits.h"
#include "lfdPinholeCamera.h"
#include "lfdRayWarp.h"
#include "lfdTrilinear.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkScanlineSplit.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkLightFieldRenderer);
vtkCxxSetObjectMacro(vtkLightFieldRenderer, Camera, vtkCamera);

namespace
{
/// A box of the cage as the renderer uses it: rest and deformed corners, the
/// label it owns and the bounds of the deformed box (to skip missed boxes).
struct CageBox
{
  lfd::Hexahedron Rest;
  lfd::Hexahedron Deformed;
  int Label = 0;
  glm::dvec3 Low{ 0.0 };
  glm::dvec3 High{ 0.0 };
  bool Moved = false;      // deformed differs from rest: it may uncover regions
  bool EyeOutside = false; // the eye is outside the deformed box (set per frame)
};

/// Slab test of the line o + t d (t >= 0) against an axis-aligned box.
bool HitsBounds(const glm::dvec3& o,
  const glm::dvec3& d,
  const glm::dvec3& low,
  const glm::dvec3& high)
{
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < low[a] || o[a] > high[a])
      {
        return false;
      }
      continue;
    }
    double near = (low[a] - o[a]) / d[a];
    double far = (high[a] - o[a]) / d[a];
    if (near > far)
    {
      std::swap(near, far);
    }
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1)
    {
      return false;
    }
  }
  return true;
}

/**
 * Distance of the box's map from the affine map through corners 0, 1, 3 and
 * 4, at the face centres and the centre: the second-order part of the
 * trilinear map, which bends the true inverse image of a straight ray.
 */
double Nonlinearity(const lfd::Hexahedron& box)
{
  const glm::dvec3& c0 = box.Corners[0];
  const glm::dmat3 affine(box.Corners[1] - c0, box.Corners[3] - c0, box.Corners[4] - c0);
  const glm::dvec3 probes[7] = { { 0.5, 0.5, 0.5 },
    { 0.0, 0.5, 0.5 },
    { 1.0, 0.5, 0.5 },
    { 0.5, 0.0, 0.5 },
    { 0.5, 1.0, 0.5 },
    { 0.5, 0.5, 0.0 },
    { 0.5, 0.5, 1.0 } };
  double deviation = 0.0;
  for (const glm::dvec3& uvw : probes)
  {
    deviation = std::max(deviation, glm::distance(lfd::TrilinearMap(box, uvw), c0 + affine * uvw));
  }
  return deviation;
}

/**
 * Tessellation (DESIGN.md 4.4): box `box` split into k x k x k sub-boxes whose
 * corners are the rest and deformed maps of the parametric sub-grid, so the
 * deformation stays the same while each warped ray becomes piecewise linear.
 */
void Subdivide(const CageBox& box, int k, std::vector<CageBox>& boxes)
{
  for (int i = 0; i < k; ++i)
  {
    for (int j = 0; j < k; ++j)
    {
      for (int l = 0; l < k; ++l)
      {
        CageBox sub;
        sub.Label = box.Label;
        sub.Moved = box.Moved;
        for (int c = 0; c < 8; ++c)
        {
          const glm::dvec3 uvw =
            glm::dvec3(
              i + lfd::HexCorner[c][0], j + lfd::HexCorner[c][1], l + lfd::HexCorner[c][2]) /
            static_cast<double>(k);
          sub.Rest.Corners[c] = lfd::TrilinearMap(box.Rest, uvw);
          sub.Deformed.Corners[c] = lfd::TrilinearMap(box.Deformed, uvw);
        }
        const lfd::AxisBounds bounds = lfd::BoxBounds(sub.Deformed);
        sub.Low = bounds.Min;
        sub.High = bounds.Max;
        boxes.push_back(sub);
      }
    }
  }
}

/// The tessellation k of a box chosen by Subdivision 0 (auto): the smallest
/// that brings the map's nonlinearity under `tolerance` x the box size (it
/// falls as 1 / k^2), up to 8.
int AutomaticSubdivision(const CageBox& box, double tolerance)
{
  const double error = std::max(Nonlinearity(box.Rest), Nonlinearity(box.Deformed)) /
    std::max(lfd::BoxSize(box.Deformed), 1e-300);
  return std::clamp(static_cast<int>(std::ceil(std::sqrt(error / tolerance))), 1, 8);
}

/// Sub-boxes of a cage whose box b is split into ks[b]^3.
long long CountSubBoxes(const std::vector<int>& ks)
{
  long long count = 0;
  for (int k : ks)
  {
    count += static_cast<long long>(k) * k * k;
  }
  return count;
}

/**
 * The boxes of a cage grid, each tessellated into subdivision^3 sub-boxes
 * (subdivision 0: AutomaticSubdivision() per box, its largest k lowered until
 * the cage fits lfd::MaximumSubBoxes). False (with an error on `self`) when
 * the grid is malformed or the tessellation is over the budget of
 * lfdLimits.h.
 */
bool CollectBoxes(vtkObject* self,
  vtkDeformationCage* cage,
  int subdivision,
  double tolerance,
  std::vector<CageBox>& boxes)
{
  const vtkIdType count = cage->GetNumberOfBoxes();
  if (subdivision < 0 || subdivision > lfd::MaximumSubdivision)
  {
    vtkErrorWithObjectMacro(self,
      "Subdivision " << subdivision << " (render.subdivision) is outside [1, "
                     << lfd::MaximumSubdivision
                     << "] (0 = auto): a ray keeps at most 64 segments, and one box at k "
                     << lfd::MaximumSubdivision << " already makes " << lfd::MaximumSubBoxes
                     << " sub-boxes.");
    return false;
  }
  std::vector<CageBox> whole(count);
  std::vector<int> ks(count, subdivision);
  for (vtkIdType b = 0; b < count; ++b)
  {
    double rest[24], deformed[24];
    if (!cage->GetRestCorners(b, rest) || !cage->GetDeformedCorners(b, deformed))
    {
      vtkErrorWithObjectMacro(
        self, "Cage cell " << b << " is not a hexahedron of 8 existing points.");
      return false;
    }
    CageBox& box = whole[b];
    box.Label = cage->GetBoxLabel(b);
    if (box.Label < 1 || box.Label > 255)
    {
      vtkErrorWithObjectMacro(
        self, "Box " << b << " has label " << box.Label << "; labels are 1..255.");
      return false;
    }
    box.Rest = lfd::HexahedronFromArray(rest);
    box.Deformed = lfd::HexahedronFromArray(deformed);
    const double size = lfd::BoxSize(box.Rest);
    for (int c = 0; c < 8; ++c)
    {
      box.Moved =
        box.Moved || glm::distance(box.Rest.Corners[c], box.Deformed.Corners[c]) > 1e-9 * size;
    }
    if (subdivision == 0)
    {
      ks[b] = AutomaticSubdivision(box, tolerance);
    }
  }
  // Auto spends the budget where the map bends most: the largest k goes
  // down first, and every box keeps at least k = 1.
  for (int cap = 8; subdivision == 0 && cap > 1 && CountSubBoxes(ks) > lfd::MaximumSubBoxes; --cap)
  {
    for (int& k : ks)
    {
      k = std::min(k, cap - 1);
    }
  }
  const long long subBoxes = CountSubBoxes(ks);
  if (subBoxes > lfd::MaximumSubBoxes)
  {
    vtkErrorWithObjectMacro(self,
      "Subdivision " << (subdivision ? std::to_string(subdivision) : std::string("auto"))
                     << " (render.subdivision) splits the cage's " << count << " boxes into "
                     << subBoxes << " sub-boxes, above the budget of " << lfd::MaximumSubBoxes
                     << " (every ray tests every sub-box): "
                     << (subdivision > 1 ? "lower it" : "use fewer boxes") << ".");
    return false;
  }
  boxes.reserve(static_cast<std::size_t>(subBoxes));
  for (vtkIdType b = 0; b < count; ++b)
  {
    Subdivide(whole[b], ks[b], boxes);
  }
  return true;
}

/// A segment of a view ray inside one deformed box.
struct BoxSegment
{
  lfd::WarpedSegment Segment;
  int Box;
};

/**
 * One ray per pixel, rows in parallel. Without a cage the ray is looked up
 * as it is. With a cage this is the paper's RENDER_VIEW (Sec. 6): the
 * segments of the view ray inside the deformed boxes, front to back, each
 * warped back to rest space (a straight warped ray through the rest images
 * of its entry and exit points) and looked up; the first segment whose
 * looked-up label is its box's label gives the pixel. Rays that match no
 * segment see the undeformed light field, but only the parts that no box
 * owns (a part that has a box is wherever its box put it).
 */
struct RenderRows
{
  const lfd::LightFieldSampler& Sampler;
  const std::vector<CageBox>& Boxes;
  const std::array<bool, 256>& Owned; // labels that have a box
  bool AllOwned;                      // every part of the light field has a box: no part stays put
  int WidenReach;                     // views tried on each side by the widened search (0: off)
  glm::dvec3 Origin;
  glm::dmat3 PixelToDirection;
  int Width;
  int Height;
  bool UseLabels;
  std::uint8_t Background[3];
  std::uint8_t* Radiance; // output, VTK row order
  std::uint8_t* Labels;
  float* Depths;
  glm::dvec3 Forward; // the camera's optical axis: d's camera z is 1

  static constexpr int MaxSegments = 64;
  static constexpr int WidenSteps = 8;

  /**
   * Label and colour seen along the view ray d (camera z component 1);
   * label -1 when nothing is seen. `depth` (camera z) approximates where:
   * the middle of the accepted segment in its box, or the focal point of a
   * ray that matched no box.
   */
  int Shade(const glm::dvec3& d, glm::dvec3& color, double& depth) const
  {
    lfd::RaySamples samples;
    BoxSegment segments[MaxSegments];
    int count = 0;
    for (std::size_t b = 0; b < this->Boxes.size() && count < MaxSegments; ++b)
    {
      const CageBox& box = this->Boxes[b];
      if (!HitsBounds(this->Origin, d, box.Low, box.High))
      {
        continue;
      }
      lfd::WarpedSegment found[lfd::MaxWarpedSegments];
      const int n = lfd::WarpRayThroughBox(box.Rest,
        box.Deformed,
        this->Origin,
        d,
        0.0,
        found,
        lfd::MaxWarpedSegments,
        box.EyeOutside);
      for (int k = 0; k < n && count < MaxSegments; ++k)
      {
        segments[count++] = { found[k], static_cast<int>(b) };
      }
    }
    std::sort(segments,
      segments + count,
      [](const BoxSegment& a, const BoxSegment& b) { return a.Segment.TEnter < b.Segment.TEnter; });
    int seen[MaxSegments];
    for (int k = 0; k < count; ++k)
    {
      seen[k] = -1;
      const lfd::WarpedSegment& segment = segments[k].Segment;
      const glm::dvec3 direction = segment.RestExit - segment.RestEnter;
      if (glm::dot(direction, direction) <= 0.0 ||
        !this->Sampler.Gather(segment.RestEnter, direction, samples))
      {
        continue;
      }
      const CageBox& box = this->Boxes[segments[k].Box];
      seen[k] = lfd::VoteLabel(samples);
      if (seen[k] == box.Label)
      {
        lfd::BlendLabel(samples, box.Label, color);
        depth = 0.5 * (segment.TEnter + segment.TExit);
        return box.Label;
      }
    }
    // No segment matched. Where the nearby cameras saw another part in a
    // moved box, that part may have hidden this one before the deformation
    // uncovered it (paper Sec. 8): look in further cameras, front to back.
    const int widen = this->WidenReach > 0 ? count : 0;
    for (int k = 0; k < widen; ++k)
    {
      const CageBox& box = this->Boxes[segments[k].Box];
      const lfd::WarpedSegment& segment = segments[k].Segment;
      if (box.Moved && seen[k] > 0 &&
        this->Sampler.Widen(
          segment.RestEnter, segment.RestExit, box.Label, WidenSteps, this->WidenReach, color))
      {
        depth = 0.5 * (segment.TEnter + segment.TExit);
        return box.Label;
      }
    }
    if (this->UseLabels && this->AllOwned)
    {
      // Every part moved with its box: what no box shows is background,
      // without looking the ray up.
      return 0;
    }
    if (!this->Sampler.Gather(this->Origin, d, samples))
    {
      return -1;
    }
    depth = glm::dot(
      lfd::FocalPoint(this->Sampler.Layout->Cyl, this->Origin, d, this->Sampler.FocalDistance) -
        this->Origin,
      this->Forward);
    if (!this->UseLabels)
    {
      lfd::BlendLabel(samples, 0, color);
      return 0;
    }
    // The heaviest label that no box owns (background included).
    for (int i = 0; i < samples.Count; ++i)
    {
      if (this->Owned[samples.Samples[i].Label])
      {
        samples.Samples[i].Weight = 0.0;
      }
    }
    const int label = lfd::VoteLabel(samples);
    if (label >= 0)
    {
      lfd::BlendLabel(samples, label, color);
    }
    return label;
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType j = begin; j < end; ++j)
    {
      const double y = static_cast<double>(this->Height - 1 - j); // OpenCV row
      for (int x = 0; x < this->Width; ++x)
      {
        const vtkIdType id = j * this->Width + x;
        std::uint8_t* rgb = this->Radiance + 3 * id;
        glm::dvec3 color;
        double depth = 0.0;
        const int label = this->Shade(this->PixelToDirection * glm::dvec3(x, y, 1.0), color, depth);
        this->Labels[id] = static_cast<std::uint8_t>(std::max(label, 0));
        if (label < 0 || (this->UseLabels && label == 0))
        {
          std::copy(this->Background, this->Background + 3, rgb);
          this->Depths[id] = 0.0f;
          continue;
        }
        this->Depths[id] = static_cast<float>(depth);
        for (int c = 0; c < 3; ++c)
        {
          rgb[c] = static_cast<std::uint8_t>(std::clamp(std::lround(color[c]), 0L, 255L));
        }
      }
    }
  }
};
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer::vtkLightFieldRenderer()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer::~vtkLightFieldRenderer()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetPinhole(const double K[9], const double R[9], const double t[3])
{
  std::copy(K, K + 9, this->PinholeK);
  std::copy(R, R + 9, this->PinholeR);
  std::copy(t, t + 3, this->PinholeT);
  this->SetCamera(nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::AddExcludedView(int view)
{
  this->ExcludedViews.push_back(view);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::RemoveAllExcludedViews()
{
  if (!this->ExcludedViews.empty())
  {
    this->ExcludedViews.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::GetNumberOfExcludedViews() const
{
  return static_cast<int>(this->ExcludedViews.size());
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldRenderer::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Camera)
  {
    mtime = std::max(mtime, this->Camera->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetCageData(vtkUnstructuredGrid* cage)
{
  this->SetInputDataInternal(1, cage);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetCageConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  if (this->Width < 1 || this->Width > lfd::MaximumRenderSize || this->Height < 1 ||
    this->Height > lfd::MaximumRenderSize)
  {
    vtkErrorMacro("Output size " << this->Width << " x " << this->Height
                                 << " is outside the render size limits: width and height in [1, "
                                 << lfd::MaximumRenderSize << "] (lfd::MaximumRenderSize).");
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Any view may be sampled: ask for the whole light field.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
    6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!input)
  {
    vtkErrorMacro("The input is not a vtkLightField.");
    return 0;
  }
  auto* radiance = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL));
  if (!radiance || radiance->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The light field has no RGB uint8 'Coaxial' pass to render from.");
    return 0;
  }
  vtkCameraRig* rig = input->GetRig();
  const int views = input->GetNumberOfViews();
  if (!rig || rig->GetNumberOfViews() != views)
  {
    vtkErrorMacro("The light field has " << views << " views but its rig has "
                                         << (rig ? rig->GetNumberOfViews() : 0) << " cameras.");
    return 0;
  }
  const lfd::RingLayout layout = rig->GetRingLayout(this->ExcludedViews);
  if (layout.Rows.empty())
  {
    vtkErrorMacro("No cylinder could be fitted to the rig, or every view is excluded.");
    return 0;
  }
  std::vector<CageBox> boxes;
  std::array<bool, 256> owned{};
  vtkLightField* lightField = input; // the input, or its one-part split
  if (vtkUnstructuredGrid* grid = vtkUnstructuredGrid::GetData(inputVector[1]))
  {
    if (!grid->GetCellData()->GetArray("Label"))
    {
      vtkErrorMacro("The cage has no cell array 'Label': every box needs the label of its part.");
      return 0;
    }
    // A plain grid (or one without rest positions: at rest) is read as a cage.
    vtkSmartPointer<vtkDeformationCage> cage = vtkDeformationCage::SafeDownCast(grid);
    if (!cage || !cage->GetRestPositions())
    {
      cage = vtkSmartPointer<vtkDeformationCage>::New();
      cage->InitializeFromGrid(grid);
    }
    if (!CollectBoxes(this, cage, this->Subdivision, this->SubdivisionTolerance, boxes))
    {
      return 0;
    }
    for (const CageBox& box : boxes)
    {
      owned[box.Label] = true;
    }
    if (this->UseLabels && !boxes.empty() && !input->GetPass(vtkLightField::LABEL))
    {
      const std::string why = cage->ValidateLabels(input);
      if (!why.empty())
      {
        vtkErrorMacro(<< why);
        return 0;
      }
      lightField = this->OnePart(input, boxes.front().Label);
      if (!lightField)
      {
        return 0;
      }
    }
  }
  std::vector<lfd::PinholeCamera> cameras(views);
  for (int v = 0; v < views; ++v)
  {
    cameras[v] = rig->GetCamera(v);
  }

  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = { radiance->GetPointer(0), input->GetWidth(), input->GetHeight(), 3 };
  auto* labels = vtkUnsignedCharArray::SafeDownCast(lightField->GetPass(vtkLightField::LABEL));
  const bool useLabels = this->UseLabels && labels;
  if (useLabels)
  {
    sampler.Labels = { labels->GetPointer(0), input->GetWidth(), input->GetHeight(), 1 };
  }
  sampler.FocalDistance = this->FocalDistance;

  double K[9], R[9], t[3];
  if (this->Camera)
  {
    vtkCameraRig::CameraToPinhole(this->Camera, this->Width, this->Height, K, R, t);
  }
  else
  {
    std::copy(this->PinholeK, this->PinholeK + 9, K);
    std::copy(this->PinholeR, this->PinholeR + 9, R);
    std::copy(this->PinholeT, this->PinholeT + 3, t);
  }
  const lfd::PinholeCamera eye = lfd::PinholeCamera::FromRowMajor(K, R, t);
  const glm::dvec3 eyeCenter = eye.Center();
  for (CageBox& box : boxes)
  {
    glm::dvec3 uvw(0.5);
    const bool inBounds = glm::all(glm::greaterThanEqual(eyeCenter, box.Low)) &&
      glm::all(glm::lessThanEqual(eyeCenter, box.High));
    box.EyeOutside = !inBounds || !lfd::Contains(box.Deformed, eyeCenter, uvw);
  }

  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkUnsignedCharArray> image;
  image->SetName("Radiance");
  image->SetNumberOfComponents(3);
  image->SetNumberOfTuples(static_cast<vtkIdType>(this->Width) * this->Height);
  vtkNew<vtkUnsignedCharArray> imageLabels;
  imageLabels->SetName("Label");
  imageLabels->SetNumberOfTuples(image->GetNumberOfTuples());
  vtkNew<vtkFloatArray> imageDepths;
  imageDepths->SetName("Depth");
  imageDepths->SetNumberOfTuples(image->GetNumberOfTuples());

  // With a cage, a ray that no box claims shows the parts without a box;
  // when every part of the light field has one, it shows background.
  bool allOwned = false;
  if (useLabels && !boxes.empty())
  {
    allOwned = true;
    for (int label = 1; label < 256; ++label)
    {
      allOwned = allOwned && (owned[label] || !lightField->HasLabel(label));
    }
  }
  RenderRows functor{ sampler,
    boxes,
    owned,
    allOwned,
    this->WidenedSearch,
    eye.Center(),
    eye.PixelToDirection(),
    this->Width,
    this->Height,
    useLabels,
    {},
    image->GetPointer(0),
    imageLabels->GetPointer(0),
    imageDepths->GetPointer(0),
    eye.Forward() };
  for (int c = 0; c < 3; ++c)
  {
    functor.Background[c] =
      static_cast<std::uint8_t>(std::clamp(std::lround(255.0 * this->Background[c]), 0L, 255L));
  }
  vtkSMPTools::For(0, this->Height, functor);

  output->GetPointData()->SetScalars(image);
  output->GetPointData()->AddArray(imageLabels);
  output->GetPointData()->AddArray(imageDepths);
  return 1;
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldRenderer::OnePart(vtkLightField* input, int label)
{
  if (this->Parts && this->PartsInput == input && input->GetMTime() <= this->PartsTime &&
    this->PartsLabel == label && this->PartsThreshold == this->ObjectThreshold)
  {
    return this->Parts;
  }
  // A scan-line split without boundaries is one band: every object pixel
  // gets band 0's label. It runs on a shallow copy, so the input's pipeline
  // and arrays stay as they are.
  vtkNew<vtkLightField> copy;
  copy->ShallowCopy(input);
  vtkNew<vtkScanlineSplit> split;
  split->SetInputData(copy);
  split->SetBandLabel(0, label);
  split->SetThreshold(this->ObjectThreshold);
  split->Update();
  if (split->GetErrorCode() != 0)
  {
    vtkErrorMacro(<< split->GetErrorMessage());
    this->Parts = nullptr;
    return nullptr;
  }
  this->Parts = split->GetOutput();
  this->PartsInput = input;
  this->PartsLabel = label;
  this->PartsThreshold = this->ObjectThreshold;
  this->PartsTime.Modified();
  return this->Parts;
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  if (!this->Camera)
  {
    os << indent << "Pinhole K:";
    for (double k : this->PinholeK)
    {
      os << " " << k;
    }
    os << "\n" << indent << "Pinhole R:";
    for (double r : this->PinholeR)
    {
      os << " " << r;
    }
    os << "\n"
       << indent << "Pinhole t: " << this->PinholeT[0] << " " << this->PinholeT[1] << " "
       << this->PinholeT[2] << "\n";
  }
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "Background: " << this->Background[0] << " " << this->Background[1] << " "
     << this->Background[2] << "\n";
  os << indent << "UseLabels: " << this->UseLabels << "\n";
  os << indent << "Subdivision: " << this->Subdivision << (this->Subdivision ? "" : " (auto)")
     << "\n";
  os << indent << "SubdivisionTolerance: " << this->SubdivisionTolerance << "\n";
  os << indent << "WidenedSearch: " << this->WidenedSearch << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "ExcludedViews:";
  for (int v : this->ExcludedViews)
  {
    os << " " << v;
  }
  os << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkLightFieldRenderer);
