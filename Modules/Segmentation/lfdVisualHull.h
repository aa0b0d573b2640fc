/**
 * @file   lfdVisualHull.h
 * @brief  The visual hull of a light field's silhouettes on a voxel grid.
 *
 * Laurentini's visual hull (1994): the voxels that project onto the object's
 * silhouette in every view. Shared by label propagation (vtkLabelPropagation)
 * and the geometric proxy (vtkLightFieldProxy). Private to the module: the
 * wrapped headers do not include it.
 */
#ifndef lfdVisualHull_h
#define lfdVisualHull_h

#include "vtkType.h" // For vtkIdType

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

class vtkCameraRig;
class vtkUnsignedCharArray;

namespace lfd
{
namespace segmentation
{

// An axis-aligned voxel grid: voxel (i, j, k) spans Origin + Size * [i, i+1).
struct VoxelGrid
{
  glm::dvec3 Origin{ 0.0 };
  double Size = 1.0;
  std::array<int, 3> Count{ 0, 0, 0 };

  VoxelGrid(const glm::dvec3& low, const glm::dvec3& high, int resolution)
  {
    const glm::dvec3 extent = high - low;
    this->Size = std::max({ extent.x, extent.y, extent.z }) / resolution;
    for (int c = 0; c < 3; ++c)
    {
      this->Count[c] = std::max(1, static_cast<int>(std::ceil(extent[c] / this->Size)));
    }
    this->Origin = low;
  }
  vtkIdType Voxels() const { return static_cast<vtkIdType>(Count[0]) * Count[1] * Count[2]; }
  glm::dvec3 Centre(vtkIdType v) const
  {
    const vtkIdType i = v % Count[0];
    const vtkIdType j = (v / Count[0]) % Count[1];
    const vtkIdType k = v / (static_cast<vtkIdType>(Count[0]) * Count[1]);
    return this->Origin + this->Size * glm::dvec3(i + 0.5, j + 0.5, k + 0.5);
  }
  // Voxel holding X, or -1 outside the grid.
  vtkIdType Find(const glm::dvec3& X) const
  {
    const glm::dvec3 g = (X - this->Origin) / this->Size;
    std::array<vtkIdType, 3> ijk;
    for (int c = 0; c < 3; ++c)
    {
      if (!(g[c] >= 0.0) || g[c] >= Count[c])
      {
        return -1;
      }
      ijk[c] = static_cast<vtkIdType>(g[c]);
    }
    return ijk[0] + Count[0] * (ijk[1] + Count[1] * ijk[2]);
  }
};

// Per view: is pixel (x, y) (OpenCV coordinates) object? `silhouettes`
// holds W x H bytes per view, VTK row order.
struct Silhouettes
{
  std::vector<unsigned char> Mask;
  std::vector<float> Distance; // to the silhouette, pixels (visual hull only)
  int Width = 0;
  int Height = 0;
  // Is the silhouette within `radius` pixels of `pixel`?
  bool Near(int view, const glm::dvec2& pixel, double radius) const
  {
    const long x = std::lround(pixel.x);
    const long y = std::lround(pixel.y);
    if (x < 0 || y < 0 || x >= Width || y >= Height)
    {
      return false;
    }
    return Distance[(static_cast<vtkIdType>(view) * Height + (Height - 1 - y)) * Width + x] <=
      radius;
  }
};

/**
 * Keeps the voxels of `grid` that overlap every silhouette: the projected
 * centre lies within the voxel's projected half-diagonal (plus `slack`
 * pixels) of it, so that parts thinner than a voxel (fins, thin columns)
 * and small calibration errors survive the carve. 1 = kept, per voxel.
 */
std::vector<unsigned char> Carve(const VoxelGrid& grid,
  vtkCameraRig* rig,
  const Silhouettes& s,
  double slack);

/// Bounds of the occupied voxels, grown by `margin` voxels; false if none.
bool OccupiedBounds(const VoxelGrid& grid,
  const std::vector<unsigned char>& occupied,
  double margin,
  glm::dvec3& low,
  glm::dvec3& high);

/// First occupied voxel along the ray from `origin` in direction `d`, or -1.
vtkIdType March(const VoxelGrid& grid,
  const std::vector<unsigned char>& occupied,
  const glm::dvec3& origin,
  const glm::dvec3& d);

/**
 * The object pixels of every view (`silhouettes`: Width and Height set, Mask
 * sized to the views' pixels) are the Coaxial pass brighter than
 * `threshold` (lfd::segmentation::ObjectMask), with their distance maps;
 * `low` and `high` bound the visual hull, carved coarsely (64 voxels) in the
 * cube the cameras surround. False when the hull is empty.
 */
bool HullBounds(vtkCameraRig* rig,
  vtkUnsignedCharArray* coaxial,
  double threshold,
  double tolerance,
  Silhouettes& silhouettes,
  glm::dvec3& low,
  glm::dvec3& high);

} // namespace segmentation
} // namespace lfd

#endif
