#include "lfdVisualHull.h"

#include "lfdLabelMorphology.h"
#include "lfdPinholeCamera.h"
#include "vtkCameraRig.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <limits>

namespace lfd
{
namespace segmentation
{

std::vector<unsigned char> Carve(const VoxelGrid& grid,
  vtkCameraRig* rig,
  const Silhouettes& s,
  double slack)
{
  std::vector<unsigned char> occupied(grid.Voxels(), 0);
  const int views = rig->GetNumberOfViews();
  vtkSMPTools::For(0,
    grid.Voxels(),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
      {
        const glm::dvec3 X = grid.Centre(v);
        bool inside = true;
        for (int view = 0; view < views && inside; ++view)
        {
          const lfd::PinholeCamera& camera = rig->GetCamera(view);
          glm::dvec2 pixel;
          inside = camera.Project(X, pixel) &&
            s.Near(view,
              pixel,
              0.866 * grid.Size * camera.K[0][0] / (camera.R * X + camera.t).z + slack);
        }
        occupied[v] = inside ? 1 : 0;
      }
    });
  return occupied;
}

bool OccupiedBounds(const VoxelGrid& grid,
  const std::vector<unsigned char>& occupied,
  double margin,
  glm::dvec3& low,
  glm::dvec3& high)
{
  low = glm::dvec3(std::numeric_limits<double>::infinity());
  high = -low;
  bool any = false;
  for (vtkIdType v = 0; v < grid.Voxels(); ++v)
  {
    if (occupied[v])
    {
      const glm::dvec3 c = grid.Centre(v);
      low = glm::min(low, c);
      high = glm::max(high, c);
      any = true;
    }
  }
  low -= (0.5 + margin) * grid.Size;
  high += (0.5 + margin) * grid.Size;
  return any;
}

vtkIdType March(const VoxelGrid& grid,
  const std::vector<unsigned char>& occupied,
  const glm::dvec3& origin,
  const glm::dvec3& d)
{
  // Slab intersection with the grid's box.
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c)
  {
    const double low = grid.Origin[c];
    const double high = grid.Origin[c] + grid.Size * grid.Count[c];
    if (std::abs(d[c]) < 1e-300)
    {
      if (origin[c] < low || origin[c] > high)
      {
        return -1;
      }
      continue;
    }
    double a = (low - origin[c]) / d[c];
    double b = (high - origin[c]) / d[c];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  const double step = 0.5 * grid.Size / glm::length(d);
  for (double t = t0 + 0.5 * step; t < t1; t += step)
  {
    const vtkIdType v = grid.Find(origin + t * d);
    if (v >= 0 && occupied[v])
    {
      return v;
    }
  }
  return -1;
}

bool HullBounds(vtkCameraRig* rig,
  vtkUnsignedCharArray* coaxial,
  double threshold,
  double tolerance,
  Silhouettes& silhouettes,
  glm::dvec3& low,
  glm::dvec3& high)
{
  const int views = rig->GetNumberOfViews();
  const int width = silhouettes.Width;
  const int height = silhouettes.Height;
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  for (int view = 0; view < views; ++view)
  {
    lfd::segmentation::ObjectMask(coaxial->GetPointer(3 * view * pixels),
      width,
      height,
      threshold,
      1,
      silhouettes.Mask.data() + view * pixels);
  }
  silhouettes.Distance.resize(silhouettes.Mask.size());
  std::vector<float> distance;
  for (int view = 0; view < views; ++view)
  {
    lfd::segmentation::DistanceToMask(
      silhouettes.Mask.data() + view * pixels, width, height, distance);
    std::copy(distance.begin(), distance.end(), silhouettes.Distance.begin() + view * pixels);
  }
  glm::dvec3 centre(0.0);
  for (int view = 0; view < views; ++view)
  {
    centre += rig->GetCamera(view).Center() / static_cast<double>(views);
  }
  double reach = 0.0;
  for (int view = 0; view < views; ++view)
  {
    reach = std::max(reach, glm::length(rig->GetCamera(view).Center() - centre));
  }
  const VoxelGrid coarse(centre - reach, centre + reach, 64);
  return OccupiedBounds(coarse, Carve(coarse, rig, silhouettes, tolerance), 1.0, low, high);
}

} // namespace segmentation
} // namespace lfd
