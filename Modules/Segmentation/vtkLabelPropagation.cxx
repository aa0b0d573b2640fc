#include "vtkLabelPropagation.h"

#include "lfdLabelMorphology.h"
#include "lfdPinholeCamera.h"
#include "lfdVisualHull.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLabelPropagation);

namespace
{
using lfd::segmentation::Carve;
using lfd::segmentation::HullBounds;
using lfd::segmentation::March;
using lfd::segmentation::Silhouettes;
using lfd::segmentation::VoxelGrid;

using PaintedViews = std::map<int, vtkSmartPointer<vtkImageData>>;

// The painted label images must be of existing views, of the views' size,
// one component. Returns the problem in words, empty when they are.
std::string CheckPaintedViews(const PaintedViews& paintedViews, int width, int height, int views)
{
  for (const auto& painted : paintedViews)
  {
    const int* dims = painted.second->GetDimensions();
    vtkDataArray* scalars = painted.second->GetPointData()->GetScalars();
    if (painted.first < 0 || painted.first >= views)
    {
      return "vtkLabelPropagation: painted view " + std::to_string(painted.first) +
        " does not exist (the light field has views 0.." + std::to_string(views - 1) + ")";
    }
    if (dims[0] != width || dims[1] != height || dims[2] != 1 || !scalars ||
      scalars->GetNumberOfComponents() != 1)
    {
      return "vtkLabelPropagation: the label image of view " + std::to_string(painted.first) +
        " is " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
        (scalars ? " with " + std::to_string(scalars->GetNumberOfComponents()) + " components"
                 : std::string(" without scalars")) +
        "; the views are " + std::to_string(width) + "x" + std::to_string(height) +
        " and labels have 1 component";
    }
  }
  return std::string();
}

// The rays of the light field's pixels: per view, the camera centre and the
// pixel-to-direction map (R^T K^-1, lens distortion removed), and the Depth
// pass when there is one.
struct PixelRays
{
  int Width = 0;
  int Height = 0;
  int Views = 0;
  vtkIdType Pixels = 0;
  std::vector<lfd::PinholeCamera::Unprojection> Cameras;
  vtkFloatArray* Depth = nullptr;

  PixelRays(vtkLightField* input, vtkFloatArray* depth)
    : Width(input->GetWidth())
    , Height(input->GetHeight())
    , Views(input->GetNumberOfViews())
    , Pixels(static_cast<vtkIdType>(Width) * Height)
    , Cameras(Views)
    , Depth(depth)
  {
    for (int view = 0; view < this->Views; ++view)
    {
      this->Cameras[view] = input->GetRig()->GetCamera(view).GetUnprojection();
    }
  }
  // OpenCV coordinates of pixel `p` of a view (VTK row order).
  glm::dvec2 PixelOf(vtkIdType p) const
  {
    return glm::dvec2(static_cast<double>(p % this->Width), this->Height - 1.0 - p / this->Width);
  }
  glm::dvec3 DirectionOf(int view, vtkIdType p) const
  {
    return this->Cameras[view].Direction(this->PixelOf(p));
  }
  // The surface point pixel `p` of `view` sees, from the Depth pass.
  glm::dvec3 PointOf(int view, vtkIdType p) const
  {
    return this->Cameras[view](
      this->PixelOf(p), static_cast<double>(this->Depth->GetValue(view * this->Pixels + p)));
  }
};

// With depth: the object pixels are those with a depth, the proxy's bounds
// those of their surface points (padded). False when no view sees a surface.
bool DepthBounds(const PixelRays& rays, Silhouettes& silhouettes, glm::dvec3& low, glm::dvec3& high)
{
  low = glm::dvec3(std::numeric_limits<double>::infinity());
  high = -low;
  for (int view = 0; view < rays.Views; ++view)
  {
    for (vtkIdType p = 0; p < rays.Pixels; ++p)
    {
      if (rays.Depth->GetValue(view * rays.Pixels + p) > 0.0f)
      {
        silhouettes.Mask[view * rays.Pixels + p] = 1;
        const glm::dvec3 X = rays.PointOf(view, p);
        low = glm::min(low, X);
        high = glm::max(high, X);
      }
    }
  }
  if (!(low.x <= high.x))
  {
    return false;
  }
  const glm::dvec3 pad = 1e-3 * (high - low) + 1e-9;
  low -= pad;
  high += pad;
  return true;
}

// The voxel each object pixel sees: with `march`, the first occupied one
// along its ray (visibility of a carved hull); otherwise the one holding
// its surface point from the depth.
void FindSeen(const VoxelGrid& grid,
  const PixelRays& rays,
  const Silhouettes& silhouettes,
  bool march,
  const std::vector<unsigned char>& occupied,
  std::vector<vtkIdType>& seen)
{
  vtkSMPTools::For(0,
    rays.Views,
    [&](int first, int last)
    {
      for (int view = first; view < last; ++view)
      {
        for (vtkIdType p = 0; p < rays.Pixels; ++p)
        {
          const vtkIdType index = view * rays.Pixels + p;
          if (silhouettes.Mask[index])
          {
            seen[index] = march
              ? March(grid, occupied, rays.Cameras[view].Center, rays.DirectionOf(view, p))
              : grid.Find(rays.PointOf(view, p));
          }
        }
      }
    });
}

// The label of every voxel a painted pixel sees (the majority of the
// pixels that see it); 0 elsewhere. False when no painted pixel lands on
// the proxy.
bool VoteVoxels(const PaintedViews& paintedViews,
  const std::vector<vtkIdType>& seen,
  vtkIdType pixels,
  std::vector<unsigned char>& voxelLabel)
{
  std::vector<std::array<int, 256>> votes;
  std::vector<int> voteOf(voxelLabel.size(), -1);
  for (const auto& painted : paintedViews)
  {
    vtkDataArray* scalars = painted.second->GetPointData()->GetScalars();
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const int label = static_cast<int>(scalars->GetComponent(p, 0));
      const vtkIdType v = seen[painted.first * pixels + p];
      if (label <= 0 || label > 255 || v < 0)
      {
        continue;
      }
      if (voteOf[v] < 0)
      {
        voteOf[v] = static_cast<int>(votes.size());
        votes.emplace_back();
        votes.back().fill(0);
      }
      ++votes[voteOf[v]][label];
    }
  }
  for (std::size_t v = 0; v < voxelLabel.size(); ++v)
  {
    if (voteOf[v] >= 0)
    {
      const auto& count = votes[voteOf[v]];
      voxelLabel[v] =
        static_cast<unsigned char>(std::max_element(count.begin(), count.end()) - count.begin());
    }
  }
  return !votes.empty();
}

// Gives every unlabelled voxel the label of the nearest labelled one
// (breadth first over the 26 neighbours, from the voted voxels in order).
void GrowLabels(const VoxelGrid& grid, std::vector<unsigned char>& voxelLabel)
{
  std::deque<vtkIdType> front;
  for (vtkIdType v = 0; v < grid.Voxels(); ++v)
  {
    if (voxelLabel[v])
    {
      front.push_back(v);
    }
  }
  const vtkIdType nx = grid.Count[0], ny = grid.Count[1], nz = grid.Count[2];
  while (!front.empty())
  {
    const vtkIdType v = front.front();
    front.pop_front();
    const vtkIdType i = v % nx, j = (v / nx) % ny, k = v / (nx * ny);
    for (int dk = -1; dk <= 1; ++dk)
    {
      for (int dj = -1; dj <= 1; ++dj)
      {
        for (int di = -1; di <= 1; ++di)
        {
          const vtkIdType a = i + di, b = j + dj, c = k + dk;
          if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz)
          {
            continue;
          }
          const vtkIdType u = a + nx * (b + ny * c);
          if (!voxelLabel[u])
          {
            voxelLabel[u] = voxelLabel[v];
            front.push_back(u);
          }
        }
      }
    }
  }
}

// The voxels some pixel sees as vertices at their centres, labelled
// (GetProxyVoxels()).
void FillProxy(const VoxelGrid& grid,
  const std::vector<unsigned char>& visible,
  const std::vector<unsigned char>& voxelLabel,
  vtkPolyData* proxy)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkUnsignedCharArray> labels;
  labels->SetName("Label");
  for (vtkIdType v = 0; v < grid.Voxels(); ++v)
  {
    if (visible[v])
    {
      const glm::dvec3 centre = grid.Centre(v);
      const vtkIdType id = points->InsertNextPoint(centre.x, centre.y, centre.z);
      vertices->InsertNextCell(1, &id);
      labels->InsertNextValue(voxelLabel[v]);
    }
  }
  proxy->SetPoints(points);
  proxy->SetVerts(vertices);
  proxy->GetCellData()->AddArray(labels);
}
}

//------------------------------------------------------------------------------
vtkLabelPropagation::vtkLabelPropagation()
  : ProxyVoxels(vtkSmartPointer<vtkPolyData>::New())
{
}

//------------------------------------------------------------------------------
vtkLabelPropagation::~vtkLabelPropagation() = default;

//------------------------------------------------------------------------------
vtkPolyData* vtkLabelPropagation::GetProxyVoxels()
{
  return this->ProxyVoxels;
}

//------------------------------------------------------------------------------
void vtkLabelPropagation::SetPaintedView(int view, vtkImageData* labels)
{
  if (labels)
  {
    this->Painted[view] = labels;
  }
  else
  {
    this->Painted.erase(view);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLabelPropagation::SetPaintedViews(vtkDataArray* labels, int width, int height)
{
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  this->Painted.clear();
  for (int view = 0; labels && pixels > 0 && (view + 1) * pixels <= labels->GetNumberOfTuples();
       ++view)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(width, height, 1);
    vtkNew<vtkUnsignedCharArray> painted;
    painted->SetNumberOfTuples(pixels);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      painted->SetValue(p, static_cast<unsigned char>(labels->GetComponent(view * pixels + p, 0)));
    }
    image->GetPointData()->SetScalars(painted);
    this->Painted[view] = image;
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLabelPropagation::RemoveAllPaintedViews()
{
  this->Painted.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkLabelPropagation::Split(vtkLightField* input, vtkLightField* output, std::string& error)
{
  this->ProxyVoxels->Initialize();
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkCameraRig* rig = input->GetRig();
  if (this->Painted.empty())
  {
    error = "vtkLabelPropagation: no painted view (SetPaintedView)";
    return false;
  }
  error = CheckPaintedViews(this->Painted, width, height, views);
  if (!error.empty())
  {
    return false;
  }
  auto* depth = vtkFloatArray::SafeDownCast(input->GetPass(vtkLightField::DEPTH));
  const bool useDepth = this->Proxy == DEPTH || (this->Proxy == AUTOMATIC && depth);
  if (useDepth && !depth)
  {
    error = "vtkLabelPropagation: the DEPTH proxy needs a Depth pass";
    return false;
  }
  auto* coaxial = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL));
  if (!useDepth && !coaxial)
  {
    error = "vtkLabelPropagation: the visual hull needs a Coaxial pass to find the silhouettes in";
    return false;
  }

  // The object pixels of every view, and the proxy grid.
  const PixelRays rays(input, depth);
  Silhouettes silhouettes;
  silhouettes.Width = width;
  silhouettes.Height = height;
  silhouettes.Mask.assign(pixels * views, 0);
  glm::dvec3 low, high;
  if (useDepth && !DepthBounds(rays, silhouettes, low, high))
  {
    error = "vtkLabelPropagation: the Depth pass sees no surface in any view";
    return false;
  }
  if (!useDepth &&
    !HullBounds(rig, coaxial, this->Threshold, this->SilhouetteTolerance, silhouettes, low, high))
  {
    error = "vtkLabelPropagation: the visual hull is empty (no point projects inside the "
            "silhouette in every view; check Threshold and the calibration)";
    return false;
  }
  this->UpdateProgress(0.1);
  const VoxelGrid grid(low, high, this->Resolution);
  // With depth, the voxels holding the surface points are the proxy; a hull
  // is carved at full resolution, then each pixel sees its first voxel.
  std::vector<vtkIdType> seen(pixels * views, -1);
  std::vector<unsigned char> occupied;
  if (useDepth)
  {
    FindSeen(grid, rays, silhouettes, false, occupied, seen);
    occupied.assign(grid.Voxels(), 0);
    for (vtkIdType v : seen)
    {
      if (v >= 0)
      {
        occupied[v] = 1;
      }
    }
  }
  else
  {
    occupied = Carve(grid, rig, silhouettes, this->SilhouetteTolerance);
  }
  this->NumberOfProxyVoxels = std::count(occupied.begin(), occupied.end(), 1);
  if (this->NumberOfProxyVoxels == 0)
  {
    error = "vtkLabelPropagation: the proxy has no voxel";
    return false;
  }
  this->UpdateProgress(0.3);
  if (!useDepth)
  {
    FindSeen(grid, rays, silhouettes, true, occupied, seen);
  }
  this->UpdateProgress(0.6);

  // Votes of the painted pixels, then the nearest voted voxel for all.
  std::vector<unsigned char> voxelLabel(grid.Voxels(), 0);
  if (!VoteVoxels(this->Painted, seen, pixels, voxelLabel))
  {
    error = "vtkLabelPropagation: no painted pixel lands on the proxy (are the label images "
            "empty, or of other views?)";
    return false;
  }
  GrowLabels(grid, voxelLabel);
  std::vector<unsigned char> visible(grid.Voxels(), 0);
  for (vtkIdType v : seen)
  {
    if (v >= 0)
    {
      visible[v] = 1;
    }
  }
  FillProxy(grid, visible, voxelLabel, this->ProxyVoxels);
  this->UpdateProgress(0.8);

  unsigned char* label =
    static_cast<unsigned char*>(output->AllocatePass(vtkLightField::LABEL)->GetVoidPointer(0));
  for (vtkIdType index = 0; index < pixels * views; ++index)
  {
    label[index] = seen[index] >= 0 ? voxelLabel[seen[index]] : 0;
  }
  for (const auto& painted : this->Painted)
  {
    vtkDataArray* scalars = painted.second->GetPointData()->GetScalars();
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const double value = scalars->GetComponent(p, 0);
      if (value > 0.0 && value <= 255.0)
      {
        label[painted.first * pixels + p] = static_cast<unsigned char>(value);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLabelPropagation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PaintedViews:";
  for (const auto& painted : this->Painted)
  {
    os << " " << painted.first;
  }
  os << "\n";
  os << indent << "Proxy: " << this->Proxy << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "SilhouetteTolerance: " << this->SilhouetteTolerance << "\n";
  os << indent << "NumberOfProxyVoxels: " << this->NumberOfProxyVoxels << "\n";
  os << indent << "Proxy vertices: " << this->ProxyVoxels->GetNumberOfPoints() << "\n";
}
