/**
 * @file   lfdTwoPlaneSampling.h
 * @brief  Two-plane light-field sampling (Levoy and Hanrahan, "Light Field Rendering",
 *         SIGGRAPH 1996), with a variable focal plane and a synthetic aperture.
 *
 * A two-plane light field is captured by a grid of cameras on a plane (the
 * camera plane, uv of the paper) that all look the same way, orthogonally to
 * it. A ray is looked up where its line crosses the camera plane (u, v) and
 * where it crosses the focal plane (st), parallel to the camera plane at a
 * depth FocalDepth in front of it: the cameras around (u, v) are chosen and
 * the focal point is projected into each with its *real* calibration (lens
 * distortion included, PinholeCamera::Project), bilinearly interpolated over
 * 4 pixels. With the 4 cameras around (u, v), bilinearly weighted, that is
 * the paper's quadrilinear interpolation over 16 rays.
 *
 * Refocusing and the synthetic aperture are the dynamically reparameterised
 * light field of Isaksen, McMillan and Gortler (SIGGRAPH 2000): moving the
 * focal plane changes which point the cameras' rays agree on, and widening
 * the camera weights beyond the nearest 4 blurs whatever lies off the focal
 * plane. Each camera's weight is a separable tent over the camera plane,
 * (1 - |du| / a_u)(1 - |dv| / a_v): up to the spacing of the grid lines
 * around (u, v), the two lines around it with a = that spacing, which is
 * exactly the bilinear weighting of the paper (Aperture 0); a larger
 * Aperture a (world units on the camera plane) brings in every camera closer
 * than it along both axes. A
 * point at depth z then spreads, in a view on the camera plane with focal
 * length f (pixels), over copies displaced by f |du| |1/z - 1/FocalDepth|
 * pixels for the cameras du away, weighted by the tent.
 *
 * Labels are categorical and never averaged (DESIGN.md section 4.1): the
 * samples are merged per label (the weight of each label and the weighted
 * mean colour of its rays), which is all that VoteLabel and BlendLabel read,
 * so a wide aperture over many cameras still fits in RaySamples.
 *
 * The lookup is the one RENDER_VIEW takes (lfdRenderView.h: Gather, Widen,
 * FocalDepth), so a two-plane light field is split and deformed like a ring.
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdTwoPlaneSampling_h
#define lfdTwoPlaneSampling_h

#include "lfdCylinderSampling.h" // RaySamples, ViewStack
#include "lfdPinholeCamera.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace lfd
{

/**
 * The camera plane of a two-plane rig and its grid: the views sorted into
 * columns (along U, the views' image x) and rows (along V, their image y).
 */
struct TwoPlaneLayout
{
  glm::dvec3 Origin{ 0.0 };           ///< a point of the camera plane (the centres' mean)
  glm::dvec3 U{ 1.0, 0.0, 0.0 };      ///< unit, in the plane: the views' image x
  glm::dvec3 V{ 0.0, 1.0, 0.0 };      ///< unit, in the plane: the views' image y (Normal x U)
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 }; ///< unit: the views' common optical axis
  std::vector<double> Columns;        ///< u of the grid columns, increasing
  std::vector<double> Rows;           ///< v of the grid rows, increasing
  std::vector<int> View;              ///< Rows x Columns, row-major; -1: no view there

  bool Empty() const { return this->View.empty(); }

  /// The view at grid (row, column), -1 for none.
  int At(int row, int column) const
  {
    return this->View[static_cast<std::size_t>(row) * this->Columns.size() + column];
  }

  /// (u, v) of a point, projected onto the camera plane.
  glm::dvec2 Locate(const glm::dvec3& p) const
  {
    return { glm::dot(p - this->Origin, this->U), glm::dot(p - this->Origin, this->V) };
  }
};

/// Largest angle (radians) between two views' optical axes on a camera plane.
constexpr double TwoPlaneAxisTolerance = 1e-3;

/// Largest distance of a camera centre from the camera plane, and smallest
/// gap between two grid lines, as a fraction of the grid's extent.
constexpr double TwoPlaneGridTolerance = 1e-3;

namespace detail
{
/// Sorts `values` into clusters no wider than `tolerance` between
/// neighbours: their means (increasing) and each value's cluster.
inline void ClusterCoordinates(const std::vector<double>& values,
  double tolerance,
  std::vector<double>& means,
  std::vector<int>& cluster)
{
  std::vector<int> order(values.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    order[i] = static_cast<int>(i);
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
  means.clear();
  cluster.assign(values.size(), -1);
  std::vector<int> counts;
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    const int i = order[k];
    if (k == 0 || values[i] - values[order[k - 1]] > tolerance)
    {
      means.push_back(0.0);
      counts.push_back(0);
    }
    means.back() += values[i];
    ++counts.back();
    cluster[i] = static_cast<int>(means.size()) - 1;
  }
  for (std::size_t c = 0; c < means.size(); ++c)
  {
    means[c] /= counts[c];
  }
}
} // namespace detail

/**
 * The two-plane layout of `count` cameras, or false with the reason in
 * `problem` when they are not a two-plane rig: every optical axis within
 * TwoPlaneAxisTolerance of their mean, every centre within
 * TwoPlaneGridTolerance x the extent of the centres from the plane through
 * their mean orthogonal to it. Centres are sorted into grid columns and rows
 * (coordinates closer than TwoPlaneGridTolerance x the extent are one line);
 * a cell that several views fall in keeps the first (by index), and a
 * cell with an `excluded` view (leave-one-out) is left empty.
 */
inline bool BuildTwoPlaneLayout(const PinholeCamera* cameras,
  int count,
  const std::vector<int>& excluded,
  TwoPlaneLayout& layout,
  std::string& problem)
{
  layout = TwoPlaneLayout();
  if (count < 1)
  {
    problem = "the rig has no view";
    return false;
  }
  glm::dvec3 axis(0.0), origin(0.0);
  for (int i = 0; i < count; ++i)
  {
    axis += cameras[i].Forward();
    origin += cameras[i].Center();
  }
  axis = glm::normalize(axis);
  origin /= static_cast<double>(count);
  for (int i = 0; i < count; ++i)
  {
    if (!(glm::dot(cameras[i].Forward(), axis) >= std::cos(TwoPlaneAxisTolerance)))
    {
      problem = "the optical axis of view " + std::to_string(i) + " is not parallel to the others";
      layout = TwoPlaneLayout();
      return false;
    }
  }
  // The first view's image x (the first row of R) fixes U.
  const glm::dvec3 x(cameras[0].R[0][0], cameras[0].R[1][0], cameras[0].R[2][0]);
  layout.Origin = origin;
  layout.Normal = axis;
  layout.U = glm::normalize(x - glm::dot(x, axis) * axis);
  layout.V = glm::cross(axis, layout.U);
  std::vector<double> u(count), v(count);
  double extent = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const glm::dvec3 c = cameras[i].Center();
    extent = std::max(extent, glm::distance(c, origin));
    u[i] = glm::dot(c - origin, layout.U);
    v[i] = glm::dot(c - origin, layout.V);
  }
  const double tolerance = TwoPlaneGridTolerance * extent;
  for (int i = 0; i < count; ++i)
  {
    if (std::abs(glm::dot(cameras[i].Center() - origin, axis)) > tolerance)
    {
      problem = "the centre of view " + std::to_string(i) + " is off the camera plane";
      layout = TwoPlaneLayout();
      return false;
    }
  }
  std::vector<int> column, row;
  detail::ClusterCoordinates(u, tolerance, layout.Columns, column);
  detail::ClusterCoordinates(v, tolerance, layout.Rows, row);
  layout.View.assign(layout.Rows.size() * layout.Columns.size(), -1);
  for (int i = 0; i < count; ++i)
  {
    int& cell = layout.View[static_cast<std::size_t>(row[i]) * layout.Columns.size() + column[i]];
    cell = cell < 0 ? i : cell;
  }
  // An excluded view takes the views it duplicates with it, as on a ring.
  for (int e : excluded)
  {
    if (e >= 0 && e < count)
    {
      layout.View[static_cast<std::size_t>(row[e]) * layout.Columns.size() + column[e]] = -1;
    }
  }
  return true;
}

namespace detail
{
/// Weight of a camera `delta` away from the ray along one axis: a tent of
/// half-width `half` (0: only the camera at delta 0).
inline double TentWeight(double delta, double half)
{
  if (half <= 0.0)
  {
    return delta == 0.0 ? 1.0 : 0.0;
  }
  return std::max(0.0, 1.0 - std::abs(delta) / half);
}

/**
 * The half-width of the tent along one axis of the grid at `x` (clamped
 * into the grid), and the lines [first, last) it weighs: the two lines
 * around x and the gap between them when the aperture is no wider (the
 * bilinear weights), else every line closer than the aperture.
 */
inline double TentSpan(const std::vector<double>& lines,
  double& x,
  double aperture,
  std::size_t& first,
  std::size_t& last)
{
  x = std::clamp(x, lines.front(), lines.back());
  const std::size_t upper = std::upper_bound(lines.begin(), lines.end(), x) - lines.begin();
  const std::size_t hi = std::min(upper, lines.size() - 1);
  const std::size_t lo = upper == 0 ? 0 : upper - 1;
  const double gap = lines[hi] - lines[lo];
  if (aperture <= gap)
  {
    // The two lines around x, bilinearly, however the grid is spaced.
    first = lo;
    last = hi + 1;
    return gap;
  }
  first = std::lower_bound(lines.begin(), lines.end(), x - aperture) - lines.begin();
  last = std::upper_bound(lines.begin(), lines.end(), x + aperture) - lines.begin();
  return aperture;
}

/// Adds a ray of `label` to the per-label sums of `out` (colours summed
/// weighted, not yet divided); a 17th distinct label is dropped.
inline void AddToLabel(RaySamples& out, const glm::dvec3& color, double weight, int label)
{
  for (int i = 0; i < out.Count; ++i)
  {
    if (out.Samples[i].Label == label)
    {
      out.Samples[i].Color += weight * color;
      out.Samples[i].Weight += weight;
      return;
    }
  }
  if (out.Count < 16)
  {
    out.Samples[out.Count++] = { weight * color, weight, label };
  }
}
} // namespace detail

/**
 * A two-plane light field as the sampler sees it: the layout, one camera per
 * view, the radiance pass and (optionally) the label pass, the focal plane
 * and the aperture.
 */
struct TwoPlaneSampler
{
  const TwoPlaneLayout* Layout = nullptr;
  const PinholeCamera* Cameras = nullptr; // indexed by view
  ViewStack<std::uint8_t> Radiance;       // 3 components
  ViewStack<std::uint8_t> Labels;         // 1 component, may be absent (Present())
  /// Depth of the focal plane in front of the camera plane (along Normal);
  /// 0 or less: at infinity, where every camera sees the ray's direction
  /// (the zero-disparity plane of views that share one K).
  double FocalDepth = 0.0;
  /// Half-width (world units on the camera plane) of the cameras' tent
  /// weights; below the grid spacing, the 4 nearest cameras, bilinearly.
  double Aperture = 0.0;

  /// The ray parameter s of the point where the line o + s d meets the focal
  /// plane (false: at infinity, or the ray does not head into the scene).
  bool FocalParameter(const glm::dvec3& o, const glm::dvec3& d, double& s) const
  {
    const double along = glm::dot(this->Layout->Normal, d);
    if (this->FocalDepth <= 0.0 || !(along > 1e-12 * glm::length(d)))
    {
      return false;
    }
    s = (glm::dot(this->Layout->Normal, this->Layout->Origin - o) + this->FocalDepth) / along;
    return true;
  }

  /**
   * Gathers the samples of the ray `o + s d` (d need not be unit), merged
   * per label (see above). Returns false when the ray does not head away
   * from the camera plane into the scene (Normal . d <= 0: the cameras saw
   * no light travelling along it) or no camera sees its focal point.
   */
  bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const
  {
    out.Count = 0;
    const TwoPlaneLayout& layout = *this->Layout;
    const double along = glm::dot(layout.Normal, d);
    if (!(along > 1e-12 * glm::length(d)) || layout.Empty())
    {
      return false;
    }
    // (u, v): where the line crosses the camera plane.
    glm::dvec2 uv = layout.Locate(o + (glm::dot(layout.Normal, layout.Origin - o) / along) * d);
    std::size_t c0, c1, r0, r1;
    const double halfU = detail::TentSpan(layout.Columns, uv.x, this->Aperture, c0, c1);
    const double halfV = detail::TentSpan(layout.Rows, uv.y, this->Aperture, r0, r1);
    double s = 0.0;
    const bool finite = this->FocalParameter(o, d, s);
    for (std::size_t r = r0; r < r1; ++r)
    {
      const double wv = detail::TentWeight(layout.Rows[r] - uv.y, halfV);
      for (std::size_t c = c0; c < c1 && wv > 0.0; ++c)
      {
        const int view = layout.At(static_cast<int>(r), static_cast<int>(c));
        const double weight = wv * detail::TentWeight(layout.Columns[c] - uv.x, halfU);
        if (view >= 0 && weight > 0.0)
        {
          // At infinity, every point of the view's own ray along d projects
          // to the pixel that saw direction d.
          const glm::dvec3 x = finite ? o + s * d : this->Cameras[view].Center() + d;
          this->SampleView(view, x, weight, out);
        }
      }
    }
    for (int i = 0; i < out.Count; ++i)
    {
      out.Samples[i].Color /= out.Samples[i].Weight;
    }
    return out.Count > 0;
  }

  /// Adds the 4 pixels of view `view` around the projection of `x`, weighted
  /// `weight` x bilinear; pixels outside the image add nothing.
  void SampleView(int view, const glm::dvec3& x, double weight, RaySamples& out) const
  {
    glm::dvec2 pixel;
    if (!this->Cameras[view].Project(x, pixel))
    {
      return;
    }
    ForEachBilinearPixel(pixel,
      this->Radiance.Width,
      this->Radiance.Height,
      [&](int px, int py, double bw)
      {
        const std::uint8_t* rgb = this->Radiance.Pixel(view, px, py);
        detail::AddToLabel(out,
          glm::dvec3(rgb[0], rgb[1], rgb[2]),
          weight * bw,
          this->Labels.Present() ? *this->Labels.Pixel(view, px, py) : 0);
      });
  }
};

/// The Lookup of RENDER_VIEW (lfdRenderView.h) over a TwoPlaneSampler.
struct TwoPlaneLookup
{
  const TwoPlaneSampler& Sampler;
  glm::dvec3 Forward; ///< the eye's optical axis (unit)

  bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const
  {
    return this->Sampler.Gather(o, d, out);
  }

  /// The widened camera search of Chen et al. Sec. 8 follows the ring's
  /// azimuths (LightFieldSampler::Widen); a grid has no such search: a
  /// region that a deformation uncovers and the nearby cameras did not see
  /// stays unmatched.
  bool Widen(const glm::dvec3&, const glm::dvec3&, int, glm::dvec3&) const { return false; }

  /// Depth (along Forward) of the ray's focal point; 0 at infinity.
  double FocalDepth(const glm::dvec3& o, const glm::dvec3& d) const
  {
    double s = 0.0;
    return this->Sampler.FocalParameter(o, d, s) ? s * glm::dot(d, this->Forward) : 0.0;
  }

  /// The s of the ray's point on the focal plane (RENDER_VIEW's contract);
  /// focused at infinity, +infinity.
  double FocalParameter(const glm::dvec3& o, const glm::dvec3& d) const
  {
    double s = 0.0;
    return this->Sampler.FocalParameter(o, d, s) ? s : std::numeric_limits<double>::infinity();
  }
};

} // namespace lfd

#endif
