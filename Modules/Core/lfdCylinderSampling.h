/**
 * @file   lfdCylinderSampling.h
 * @brief  Cylindrical light-field sampling (Chen, Ofek, Shum and Levoy 2005, Sec. 6.2).
 *
 * A ray is looked up in a light field captured from a ring (or a stack of
 * rings) of cameras: the ray's line is intersected with the rig cylinder on
 * the camera side (the entry point, upstream of the object), which gives an
 * azimuth and a height; the two views around that azimuth in the one or two
 * rows around that height are chosen (four cameras, two for a single ring);
 * the ray meets the focal plane at a point that is projected into each
 * chosen camera with its *real* calibration and bilinearly interpolated.
 * That is 16 weighted rays, quadrilinear weights. The real calibration
 * includes a view's lens distortion (PinholeCamera::Project applies it): a
 * distorted photograph is sampled at the distorted pixel that saw the point.
 *
 * Labels are categorical and never averaged: the label of a ray is the
 * weighted vote of its samples and the colour is the weighted mean of the
 * samples whose label matches (weights renormalised), which keeps parts from
 * bleeding into each other (DESIGN.md section 4.1, an improvement on the
 * paper).
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdCylinderSampling_h
#define lfdCylinderSampling_h

#include "lfdPinholeCamera.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace lfd
{

constexpr double TwoPi = 6.283185307179586476925286766559;

struct Cylinder
{
  glm::dvec3 Center{ 0.0 };
  glm::dvec3 Axis{ 0.0, 1.0, 0.0 }; // unit
  double Radius = 1.0;
};

/**
 * Parameter `s` where the line `o + s d` enters the cylinder (the smaller
 * root of |perp(o + s d - c)|^2 = r^2). Returns false when the line misses
 * the cylinder or runs parallel to its axis. Uses the cancellation-free form
 * of the quadratic roots.
 */
inline bool IntersectCylinderEntry(const Cylinder& cylinder,
  const glm::dvec3& o,
  const glm::dvec3& d,
  double& s)
{
  const glm::dvec3& a = cylinder.Axis;
  const glm::dvec3 oc = o - cylinder.Center;
  const glm::dvec3 dp = d - glm::dot(d, a) * a;
  const glm::dvec3 op = oc - glm::dot(oc, a) * a;
  const double qa = glm::dot(dp, dp);
  const double qb = glm::dot(dp, op); // half of the linear coefficient
  const double qc = glm::dot(op, op) - cylinder.Radius * cylinder.Radius;
  if (qa <= 1e-12 * glm::dot(d, d))
  {
    return false;
  }
  const double disc = qb * qb - qa * qc;
  if (disc < 0.0)
  {
    return false;
  }
  const double q = -(qb + std::copysign(std::sqrt(disc), qb));
  double s0 = q / qa;
  double s1 = q != 0.0 ? qc / q : s0;
  s = std::min(s0, s1);
  return true;
}

/**
 * Point of the focal plane hit by the ray: the plane is orthogonal to the
 * ray and lies `focalDistance` in front of (towards the viewer from) the
 * point where the ray passes closest to the rig axis. focalDistance = 0 puts
 * the focal plane through the axis.
 */
inline glm::dvec3 FocalPoint(const Cylinder& cylinder,
  const glm::dvec3& o,
  const glm::dvec3& d,
  double focalDistance)
{
  // Closest approach of the lines o + s d and c + u a.
  const glm::dvec3& a = cylinder.Axis;
  const glm::dvec3 w = o - cylinder.Center;
  const double dd = glm::dot(d, d);
  const double da = glm::dot(d, a);
  const double denom = dd - da * da; // |a| = 1
  double s = 0.0;
  if (denom > 1e-12 * dd)
  {
    s = (da * glm::dot(w, a) - glm::dot(w, d)) / denom;
  }
  return o + (s - focalDistance / std::sqrt(dd)) * d;
}

/// One row (ring) of views, sorted by azimuth in [0, 2 pi).
struct RingRow
{
  double Height = 0.0;
  std::vector<double> Azimuth;
  std::vector<int> View;
};

/**
 * The neighbour structure of a cylindrical rig: the cylinder, the azimuth
 * reference frame and the rows sorted by height. Built by vtkCameraRig from
 * the views that are enabled (leave-one-out disables one and its duplicates).
 */
struct RingLayout
{
  Cylinder Cyl;
  glm::dvec3 RefX{ 1.0, 0.0, 0.0 }; // azimuth 0, orthogonal to the axis
  glm::dvec3 RefY{ 0.0, 0.0, 1.0 }; // azimuth pi/2 = Axis x RefX
  std::vector<RingRow> Rows;

  /// Azimuth in [0, 2 pi) and height along the axis of a point.
  void Locate(const glm::dvec3& p, double& azimuth, double& height) const
  {
    const glm::dvec3 v = p - this->Cyl.Center;
    height = glm::dot(v, this->Cyl.Axis);
    azimuth = std::atan2(glm::dot(v, this->RefY), glm::dot(v, this->RefX));
    if (azimuth < 0.0)
    {
      azimuth += TwoPi;
      if (azimuth >= TwoPi) // -0.0 and tiny negative angles round up to 2 pi
      {
        azimuth = 0.0;
      }
    }
  }
};

/// A camera chosen for a ray and its weight (azimuth x height).
struct WeightedView
{
  int View = -1;
  double Weight = 0.0;
};

/**
 * The two views of a row around `azimuth`, linearly weighted by angular
 * distance (the row wraps around). Returns how many were written (0..2).
 */
inline int BracketAzimuth(const RingRow& row, double azimuth, double rowWeight, WeightedView out[2])
{
  const std::size_t n = row.Azimuth.size();
  if (n == 0)
  {
    return 0;
  }
  if (n == 1)
  {
    out[0] = { row.View[0], rowWeight };
    return 1;
  }
  // First view with an azimuth greater than the query; the one before it
  // (cyclically) is the lower neighbour.
  const std::size_t upper =
    std::upper_bound(row.Azimuth.begin(), row.Azimuth.end(), azimuth) - row.Azimuth.begin();
  const std::size_t hi = upper % n;
  const std::size_t lo = (upper + n - 1) % n;
  double span = row.Azimuth[hi] - row.Azimuth[lo];
  double offset = azimuth - row.Azimuth[lo];
  if (span <= 0.0)
  {
    span += TwoPi;
  }
  if (offset < 0.0)
  {
    offset += TwoPi;
  }
  const double f = std::clamp(offset / span, 0.0, 1.0);
  out[0] = { row.View[lo], rowWeight * (1.0 - f) };
  out[1] = { row.View[hi], rowWeight * f };
  return 2;
}

/**
 * The (up to) four cameras around an azimuth and height: two per row in the
 * one or two rows around the height (clamped to the outermost row).
 */
inline int ChooseViews(const RingLayout& layout, double azimuth, double height, WeightedView out[4])
{
  const std::size_t rows = layout.Rows.size();
  if (rows == 0)
  {
    return 0;
  }
  std::size_t r0 = 0;
  while (r0 + 1 < rows && layout.Rows[r0 + 1].Height <= height)
  {
    ++r0;
  }
  if (r0 + 1 == rows || height <= layout.Rows[0].Height)
  {
    const std::size_t r = height <= layout.Rows[0].Height ? 0 : r0;
    return BracketAzimuth(layout.Rows[r], azimuth, 1.0, out);
  }
  const double h0 = layout.Rows[r0].Height;
  const double h1 = layout.Rows[r0 + 1].Height;
  const double f = (height - h0) / (h1 - h0);
  int n = BracketAzimuth(layout.Rows[r0], azimuth, 1.0 - f, out);
  n += BracketAzimuth(layout.Rows[r0 + 1], azimuth, f, out + n);
  return n;
}

/**
 * Pixels of all views of one pass, stacked view after view. Rows are stored
 * in VTK order (bottom image row first), as vtkLightField stores them.
 */
template<typename T>
struct ViewStack
{
  const T* Data = nullptr;
  int Width = 0;
  int Height = 0;
  int Components = 1;

  /// Pointer to the pixel at OpenCV coordinates (x, y) (top-left origin).
  const T* Pixel(int view, int x, int y) const
  {
    const std::size_t row = static_cast<std::size_t>(view) * this->Height + (this->Height - 1 - y);
    return this->Data + (row * this->Width + x) * this->Components;
  }
};

/// One of the (up to) 16 rays a light-field ray is interpolated from.
struct RaySample
{
  glm::dvec3 Color;
  double Weight;
  int Label;
};

/**
 * The samples of one light-field ray. Only the first Count are meaningful:
 * a lookup writes every field of each sample it adds, so the array is left
 * uninitialised (zeroing 16 samples per ray cost about 15% of an undeformed
 * frame).
 */
struct RaySamples
{
  // User-provided, so that value-initialisation (std::optional::emplace())
  // does not zero the array either.
  RaySamples() noexcept {}
  RaySample Samples[16];
  int Count = 0;
};

/**
 * The light field as the sampler sees it: the rig layout, one camera per
 * view, the radiance pass and (optionally) the label pass.
 */
struct LightFieldSampler
{
  const RingLayout* Layout = nullptr;
  const PinholeCamera* Cameras = nullptr; // indexed by view
  ViewStack<std::uint8_t> Radiance;       // 3 components
  ViewStack<std::uint8_t> Labels;         // 1 component, Data may be null
  double FocalDistance = 0.0;

  /**
   * Sec. 6.2: gathers the weighted samples of the ray `o + s d` (d need not
   * be unit). Pixels projecting outside a view contribute nothing.
   * Returns false when the ray misses the rig cylinder.
   */
  bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const
  {
    out.Count = 0;
    double s;
    if (!IntersectCylinderEntry(this->Layout->Cyl, o, d, s))
    {
      return false;
    }
    double azimuth, height;
    this->Layout->Locate(o + s * d, azimuth, height);
    WeightedView views[4];
    const int nviews = ChooseViews(*this->Layout, azimuth, height, views);
    const glm::dvec3 x = FocalPoint(this->Layout->Cyl, o, d, this->FocalDistance);
    const int w = this->Radiance.Width;
    const int h = this->Radiance.Height;
    for (int i = 0; i < nviews; ++i)
    {
      if (views[i].Weight <= 0.0)
      {
        continue;
      }
      glm::dvec2 uv;
      if (!this->Cameras[views[i].View].Project(x, uv))
      {
        continue;
      }
      const double fx = std::floor(uv.x);
      const double fy = std::floor(uv.y);
      const double ax = uv.x - fx;
      const double ay = uv.y - fy;
      const int x0 = static_cast<int>(fx);
      const int y0 = static_cast<int>(fy);
      if (x0 < -1 || y0 < -1 || x0 >= w || y0 >= h)
      {
        continue;
      }
      for (int corner = 0; corner < 4; ++corner)
      {
        const int px = x0 + (corner & 1);
        const int py = y0 + (corner >> 1);
        const double bw = ((corner & 1) ? ax : 1.0 - ax) * ((corner >> 1) ? ay : 1.0 - ay);
        if (px < 0 || py < 0 || px >= w || py >= h || bw <= 0.0)
        {
          continue;
        }
        RaySample& sample = out.Samples[out.Count++];
        const std::uint8_t* rgb = this->Radiance.Pixel(views[i].View, px, py);
        sample.Color = glm::dvec3(rgb[0], rgb[1], rgb[2]);
        sample.Weight = views[i].Weight * bw;
        sample.Label = this->Labels.Data ? *this->Labels.Pixel(views[i].View, px, py) : 0;
      }
    }
    return out.Count > 0;
  }

  /**
   * Sec. 8 of the paper, the widened camera search for a region that a
   * deformation uncovers: the nearby cameras of a warped ray see another
   * part where the ray's own part should be (it was hidden behind that part
   * before the deformation). Points p along the rest-space segment [a, b],
   * front to back (`steps` of them), are tried in the `reach` views on each
   * side of the ray's azimuth, stepping outwards, in the row nearest the
   * height where the segment's line enters the rig cylinder. Each view tells what p projects onto:
   * `label` (a vote), another part (p is hidden from that view: no say) or background (p is in the
   * air: p is refused, as a visual hull carves it). Of the points with two
   * votes or more and no refusal, the most photo-consistent (most votes,
   * then the smallest spread of the voting colours) gives the pixel: the
   * mean colour of the voting views at its projection, weighted by angular
   * nearness. Returns false when no point qualifies.
   */
  bool Widen(const glm::dvec3& a,
    const glm::dvec3& b,
    int label,
    int steps,
    int reach,
    glm::dvec3& color) const
  {
    const glm::dvec3 d = b - a;
    double s;
    if (!this->Labels.Data || !IntersectCylinderEntry(this->Layout->Cyl, a, d, s))
    {
      return false;
    }
    double azimuth, height;
    this->Layout->Locate(a + s * d, azimuth, height);
    const RingRow* row = &this->Layout->Rows[0];
    for (const RingRow& candidate : this->Layout->Rows)
    {
      row = std::abs(candidate.Height - height) < std::abs(row->Height - height) ? &candidate : row;
    }
    const int n = static_cast<int>(row->Azimuth.size());
    if (n < 2)
    {
      return false;
    }
    const int upper = static_cast<int>(
      std::upper_bound(row->Azimuth.begin(), row->Azimuth.end(), azimuth) - row->Azimuth.begin());
    const int w = this->Radiance.Width;
    const int h = this->Radiance.Height;
    // The most photo-consistent point: most votes, then the least spread of
    // the voting colours.
    int bestVotes = 1;
    double bestSpread = std::numeric_limits<double>::infinity();
    for (int step = 0; step < steps; ++step)
    {
      const glm::dvec3 p = a + ((step + 0.5) / steps) * d;
      glm::dvec3 sum(0.0), squares(0.0);
      double total = 0.0;
      int votes = 0;
      bool refused = false;
      for (int k = 0; k < 2 * std::min(reach, n / 2) && !refused; ++k)
      {
        // Alternate sides, nearest first: upper, lower, upper + 1, ...
        const int offset = k / 2;
        const int index = (k % 2 == 0) ? (upper + offset) % n : ((upper - 1 - offset) % n + n) % n;
        glm::dvec2 uv;
        if (!this->Cameras[row->View[index]].Project(p, uv))
        {
          continue;
        }
        const int px = static_cast<int>(std::lround(uv.x));
        const int py = static_cast<int>(std::lround(uv.y));
        if (px < 0 || py < 0 || px >= w || py >= h)
        {
          continue;
        }
        const int seen = *this->Labels.Pixel(row->View[index], px, py);
        if (seen == 0)
        {
          refused = true;
        }
        else if (seen == label)
        {
          const std::uint8_t* rgb = this->Radiance.Pixel(row->View[index], px, py);
          const glm::dvec3 sample(rgb[0], rgb[1], rgb[2]);
          const double weight = 1.0 / (1.0 + offset);
          sum += weight * sample;
          squares += weight * sample * sample;
          total += weight;
          ++votes;
        }
      }
      if (refused || votes < 2)
      {
        continue;
      }
      const glm::dvec3 mean = sum / total;
      const glm::dvec3 variance = squares / total - mean * mean;
      const double spread = variance.x + variance.y + variance.z;
      if (votes > bestVotes || (votes == bestVotes && spread < bestSpread))
      {
        bestVotes = votes;
        bestSpread = spread;
        color = mean;
      }
    }
    return bestVotes >= 2;
  }
};

/// Weighted vote of the samples' labels; -1 when there is no sample.
inline int VoteLabel(const RaySamples& samples)
{
  // The distinct labels in order of first appearance and their weights
  // (at most 16), then the heaviest; ties go to the first seen.
  int labels[16];
  double weights[16];
  int distinct = 0;
  for (int i = 0; i < samples.Count; ++i)
  {
    int k = 0;
    while (k < distinct && labels[k] != samples.Samples[i].Label)
    {
      ++k;
    }
    if (k == distinct)
    {
      labels[distinct] = samples.Samples[i].Label;
      weights[distinct++] = 0.0;
    }
    weights[k] += samples.Samples[i].Weight;
  }
  int best = -1;
  double bestWeight = 0.0;
  for (int k = 0; k < distinct; ++k)
  {
    if (weights[k] > bestWeight)
    {
      best = labels[k];
      bestWeight = weights[k];
    }
  }
  return best;
}

/**
 * Weighted mean colour of the samples carrying `label`, weights renormalised.
 * Returns the total weight of those samples (0: no sample has the label).
 */
inline double BlendLabel(const RaySamples& samples, int label, glm::dvec3& color)
{
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (int i = 0; i < samples.Count; ++i)
  {
    if (samples.Samples[i].Label == label)
    {
      sum += samples.Samples[i].Weight * samples.Samples[i].Color;
      total += samples.Samples[i].Weight;
    }
  }
  if (total > 0.0)
  {
    color = sum / total;
  }
  return total;
}

} // namespace lfd

#endif
