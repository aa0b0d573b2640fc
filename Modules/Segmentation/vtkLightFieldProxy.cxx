#include "vtkLightFieldProxy.h"

#include "lfdPinholeCamera.h"
#include "lfdVisualHull.h"
#include "vtkCameraRig.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkLightFieldProxy);

namespace
{
using lfd::segmentation::VoxelGrid;

/// The Coaxial pass as the sweep reads it: pixel (x, y) in OpenCV
/// coordinates of a view, bilinearly interpolated.
struct ViewColours
{
  const unsigned char* Rgb = nullptr;
  int Width = 0;
  int Height = 0;

  const unsigned char* Pixel(int view, int x, int y) const
  {
    return this->Rgb +
      3 *
      ((static_cast<vtkIdType>(view) * this->Height + (this->Height - 1 - y)) * this->Width + x);
  }

  /// The colour at `uv`; false when its 4 pixels are not all inside the view.
  bool Sample(int view, const glm::dvec2& uv, glm::dvec3& colour) const
  {
    const double fx = std::floor(uv.x);
    const double fy = std::floor(uv.y);
    if (!(fx >= 0.0 && fy >= 0.0 && fx + 1.0 < this->Width && fy + 1.0 < this->Height))
    {
      return false;
    }
    const int x = static_cast<int>(fx);
    const int y = static_cast<int>(fy);
    const double ax = uv.x - fx;
    const double ay = uv.y - fy;
    colour = glm::dvec3(0.0);
    for (int corner = 0; corner < 4; ++corner)
    {
      const unsigned char* rgb = this->Pixel(view, x + (corner & 1), y + (corner >> 1));
      const double w = ((corner & 1) ? ax : 1.0 - ax) * ((corner >> 1) ? ay : 1.0 - ay);
      colour += w * glm::dvec3(rgb[0], rgb[1], rgb[2]);
    }
    return true;
  }
};

/// The `count` views whose camera centres are nearest to view `view`'s
/// (near-duplicates, which see no parallax, left out).
std::vector<int> NearestViews(const std::vector<glm::dvec3>& centres,
  int view,
  int count,
  double gap)
{
  std::vector<int> order;
  for (int v = 0; v < static_cast<int>(centres.size()); ++v)
  {
    if (glm::distance(centres[v], centres[view]) > gap)
    {
      order.push_back(v);
    }
  }
  const auto nearer = [&](int a, int b)
  { return glm::distance(centres[a], centres[view]) < glm::distance(centres[b], centres[view]); };
  const std::size_t kept = std::min<std::size_t>(count, order.size());
  std::partial_sort(order.begin(), order.begin() + kept, order.end(), nearer);
  order.resize(kept);
  return order;
}

/// Per pixel of a view (VTK row order), the depth of the first hull voxel
/// its ray meets (its near side); 0 for background or no voxel.
void HullDepths(const VoxelGrid& grid,
  const std::vector<unsigned char>& occupied,
  const lfd::PinholeCamera& camera,
  const unsigned char* mask,
  int width,
  int height,
  float* depth)
{
  const lfd::PinholeCamera::Unprojection rays = camera.GetUnprojection();
  vtkSMPTools::For(0,
    height,
    [&](int first, int last)
    {
      for (int j = first; j < last; ++j)
      {
        for (int x = 0; x < width; ++x)
        {
          const vtkIdType p = static_cast<vtkIdType>(j) * width + x;
          depth[p] = 0.0f;
          if (!mask[p])
          {
            continue;
          }
          const glm::dvec2 pixel(x, height - 1.0 - j);
          const vtkIdType voxel =
            lfd::segmentation::March(grid, occupied, rays.Center, rays.Direction(pixel));
          if (voxel >= 0)
          {
            const double z = (camera.R * grid.Centre(voxel) + camera.t).z - 0.5 * grid.Size;
            depth[p] = static_cast<float>(std::max(z, 1e-6));
          }
        }
      }
    });
}

/// Sums of `values` over the (2 r + 1)^2 window around each pixel of a
/// width x height image (clipped at the borders), through an integral image.
void BoxSums(const std::vector<double>& values,
  int width,
  int height,
  int r,
  std::vector<double>& sums)
{
  std::vector<double> integral(static_cast<std::size_t>(width + 1) * (height + 1), 0.0);
  for (int j = 0; j < height; ++j)
  {
    double row = 0.0;
    for (int i = 0; i < width; ++i)
    {
      row += values[static_cast<std::size_t>(j) * width + i];
      integral[static_cast<std::size_t>(j + 1) * (width + 1) + i + 1] =
        integral[static_cast<std::size_t>(j) * (width + 1) + i + 1] + row;
    }
  }
  sums.resize(values.size());
  for (int j = 0; j < height; ++j)
  {
    const int j0 = std::max(j - r, 0), j1 = std::min(j + r + 1, height);
    for (int i = 0; i < width; ++i)
    {
      const int i0 = std::max(i - r, 0), i1 = std::min(i + r + 1, width);
      const auto at = [&](int a, int b)
      { return integral[static_cast<std::size_t>(b) * (width + 1) + a]; };
      sums[static_cast<std::size_t>(j) * width + i] =
        at(i1, j1) - at(i0, j1) - at(i1, j0) + at(i0, j0);
    }
  }
}

/// The plane sweep's settings and the light field it reads.
struct Sweep
{
  const ViewColours& Colours;
  const std::vector<lfd::PinholeCamera>& Cameras;
  int Steps;
  double Reach; ///< depth swept behind the hull (world units)
  int Window;

  /**
   * Refines the hull depths `depth` of `view` in place: the depth of least
   * aggregated photo-consistency cost against the views `neighbours`.
   */
  void Refine(int view, const std::vector<int>& neighbours, float* depth) const
  {
    const int width = this->Colours.Width;
    const int height = this->Colours.Height;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    const std::vector<float> hull(depth, depth + pixels);
    std::vector<double> cost(pixels), inside(pixels), costSums, insideSums;
    for (std::size_t p = 0; p < pixels; ++p)
    {
      inside[p] = hull[p] > 0.0f ? 1.0 : 0.0;
    }
    BoxSums(inside, width, height, this->Window, insideSums);
    std::vector<double> best(pixels, std::numeric_limits<double>::infinity());
    const lfd::PinholeCamera::Unprojection rays = this->Cameras[view].GetUnprojection();
    for (int step = 0; step < this->Steps; ++step)
    {
      const double offset = this->Steps > 1 ? this->Reach * step / (this->Steps - 1) : 0.0;
      vtkSMPTools::For(0,
        height,
        [&](int first, int last)
        {
          for (int j = first; j < last; ++j)
          {
            for (int x = 0; x < width; ++x)
            {
              const std::size_t p = static_cast<std::size_t>(j) * width + x;
              cost[p] = hull[p] > 0.0f
                ? this->Cost(view, neighbours, rays, x, height - 1 - j, hull[p] + offset)
                : 0.0;
            }
          }
        });
      BoxSums(cost, width, height, this->Window, costSums);
      for (std::size_t p = 0; p < pixels; ++p)
      {
        if (hull[p] > 0.0f && costSums[p] / insideSums[p] < best[p])
        {
          best[p] = costSums[p] / insideSums[p];
          depth[p] = static_cast<float>(hull[p] + offset);
        }
      }
    }
  }

  /// Mean absolute RGB difference between pixel (x, y) of `view` and the
  /// neighbours' colours where its point at depth `z` projects (255 where
  /// it falls outside a neighbour).
  double Cost(int view,
    const std::vector<int>& neighbours,
    const lfd::PinholeCamera::Unprojection& rays,
    int x,
    int y,
    double z) const
  {
    const unsigned char* rgb = this->Colours.Pixel(view, x, y);
    const glm::dvec3 reference(rgb[0], rgb[1], rgb[2]);
    const glm::dvec3 point = rays(glm::dvec2(x, y), z);
    double sum = 0.0;
    for (int n : neighbours)
    {
      glm::dvec2 uv;
      glm::dvec3 colour;
      if (this->Cameras[n].Project(point, uv) && this->Colours.Sample(n, uv, colour))
      {
        const glm::dvec3 difference = glm::abs(colour - reference);
        sum += (difference.x + difference.y + difference.z) / 3.0;
      }
      else
      {
        sum += 255.0;
      }
    }
    return sum / std::max<std::size_t>(neighbours.size(), 1);
  }
};
}

//------------------------------------------------------------------------------
vtkLightFieldProxy::vtkLightFieldProxy()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldProxy::~vtkLightFieldProxy() = default;

//------------------------------------------------------------------------------
void vtkLightFieldProxy::SetInputData(vtkLightField* input)
{
  this->SetInputDataObject(0, input);
}

//------------------------------------------------------------------------------
int vtkLightFieldProxy::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldProxy::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    outputVector->GetInformationObject(0)->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(),
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
      6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldProxy::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->ClearError();
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  vtkLightField* output = vtkLightField::GetData(outputVector);
  auto* coaxial =
    input ? vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL)) : nullptr;
  if (!input || input->GetNumberOfPoints() == 0 || !coaxial ||
    coaxial->GetNumberOfComponents() != 3)
  {
    this->Fail(output,
      vtkErrorCode::UnknownError,
      "vtkLightFieldProxy: the light field has no RGB Coaxial pass to find the object in");
    return 0;
  }
  output->ShallowCopy(input);
  if (input->GetPass(vtkLightField::DEPTH) && !this->ReplaceDepth)
  {
    return 1;
  }
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkCameraRig* rig = input->GetRig();

  // 1. The visual hull.
  lfd::segmentation::Silhouettes silhouettes;
  silhouettes.Width = width;
  silhouettes.Height = height;
  silhouettes.Mask.assign(pixels * views, 0);
  glm::dvec3 low, high;
  std::vector<unsigned char> occupied;
  const bool found = lfd::segmentation::HullBounds(
    rig, coaxial, this->Threshold, this->SilhouetteTolerance, silhouettes, low, high);
  const VoxelGrid grid(low, high, this->Resolution);
  if (found)
  {
    occupied = lfd::segmentation::Carve(grid, rig, silhouettes, this->SilhouetteTolerance);
  }
  if (!found || std::find(occupied.begin(), occupied.end(), 1) == occupied.end())
  {
    this->Fail(output,
      vtkErrorCode::UnknownError,
      "vtkLightFieldProxy: the visual hull is empty (no point projects inside the silhouette in "
      "every view; check Threshold and the calibration)");
    return 0;
  }
  this->UpdateProgress(0.1);

  // 2. Per view, the hull's depth refined by the plane sweep.
  std::vector<lfd::PinholeCamera> cameras(views);
  std::vector<glm::dvec3> centres(views);
  for (int v = 0; v < views; ++v)
  {
    cameras[v] = rig->GetCamera(v);
    centres[v] = cameras[v].Center();
  }
  const ViewColours colours{ coaxial->GetPointer(0), width, height };
  const Sweep sweep{
    colours, cameras, this->SweepSteps, this->SweepDepth * glm::distance(low, high), this->Window
  };
  auto* depth = vtkFloatArray::SafeDownCast(output->AllocatePass(vtkLightField::DEPTH));
  const double duplicate = 1e-6 * glm::distance(low, high);
  for (int v = 0; v < views; ++v)
  {
    float* viewDepth = depth->GetPointer(v * pixels);
    HullDepths(
      grid, occupied, cameras[v], silhouettes.Mask.data() + v * pixels, width, height, viewDepth);
    sweep.Refine(v, NearestViews(centres, v, this->Neighbours, duplicate), viewDepth);
    this->UpdateProgress(0.1 + 0.9 * (v + 1) / views);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReplaceDepth: " << (this->ReplaceDepth ? "On" : "Off") << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "SilhouetteTolerance: " << this->SilhouetteTolerance << "\n";
  os << indent << "SweepSteps: " << this->SweepSteps << "\n";
  os << indent << "SweepDepth: " << this->SweepDepth << "\n";
  os << indent << "Neighbours: " << this->Neighbours << "\n";
  os << indent << "Window: " << this->Window << "\n";
}
