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
 * Beyond the paper, a per-view depth map stack (the light field's Depth
 * pass) can stand for a geometric proxy: LightFieldSampler::GatherOnSurface
 * focuses a ray on the surface it meets (Gortler et al. 1996's depth
 * correction) and blends the views nearest to it in angle that see that
 * point (Buehler et al. 2001, Unstructured Lumigraph Rendering). Without a
 * depth stack the plane path above is used, unchanged.
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
#include "lfdTexelSource.h"
#include "lfdTrilinear.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

/// Whether LightFieldSampler::AimBatch has a version for AVX2 (GCC and
/// Clang on x86, where the processor is asked at run time).
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define LFD_AIM_AVX2 1
#else
#define LFD_AIM_AVX2 0
#endif

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
 * root of |perp(o + s d - c)|^2 = r^2). Returns false (`s` meaningless)
 * when the line misses the cylinder or runs parallel to its axis. Uses the
 * cancellation-free form of the quadratic roots. Branch-free (each division
 * and root taken, of a harmless operand where its result is not used), so
 * that a loop over rays vectorises (LightFieldSampler::AimBatch).
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
  const double disc = qb * qb - qa * qc;
  const bool hit = !(qa <= 1e-12 * glm::dot(d, d)) & !(disc < 0.0);
  const double q = -(qb + std::copysign(std::sqrt(hit ? disc : 0.0), qb));
  const double s0 = q / (hit ? qa : 1.0);
  const double s1 = qc / (q != 0.0 ? q : 1.0);
  s = std::min(s0, q != 0.0 ? s1 : s0);
  return hit;
}

/**
 * Where the ray o + s d meets its focal plane (FocalPoint()): the parameter s.
 * (Always inlined: FocalPoint and the walk's focal test call it.)
 */
__attribute__((always_inline)) inline double FocalParameter(const Cylinder& cylinder,
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
  // Branch-free (LightFieldSampler::AimBatch vectorises it): the division
  // by 1 where the lines are parallel.
  const bool crossing = denom > 1e-12 * dd;
  const double t = (da * glm::dot(w, a) - glm::dot(w, d)) / (crossing ? denom : 1.0);
  const double s = crossing ? t : 0.0;
  // (The plane through the axis, the default, needs no square root.)
  return focalDistance != 0.0 ? s - focalDistance / std::sqrt(dd) : s;
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
  return o + FocalParameter(cylinder, o, d, focalDistance) * d;
}

/**
 * std::lround(v) (halves away from zero) for |v| < 2^31, without its library
 * call: the truncation, moved by the fraction (exact: v minus its integer
 * part).
 */
inline int RoundHalfAway(double v)
{
  const int t = static_cast<int>(v);
  const double f = v - t;
  return t + (f >= 0.5) - (f <= -0.5);
}

/**
 * The index of the first of the largest of `values[0, Count)` (`values`
 * 16-byte aligned), the one a scan for a strictly
 * larger value keeps; -1 when none is larger than -infinity. NaN is never
 * chosen. With SSE2, two values a vector and without a branch per value
 * (a scan's branches, taken as the data fall, are mispredicted often): the
 * maximum, then the first lane equal to it.
 */
template<int Count>
inline int FirstLargest(const double* values)
{
  static_assert(Count % 2 == 0 && Count <= 32, "pairs, and a bit per value in an int");
  constexpr double none = -std::numeric_limits<double>::infinity();
#if defined(__SSE2__)
  // Two maxima in turn (two chains), then the first lane equal to the
  // largest. maxpd returns its second operand where either is NaN: NaN
  // never enters.
  __m128d even = _mm_set1_pd(none);
  __m128d odd = even;
  for (int i = 0; i < Count; i += 4)
  {
    even = _mm_max_pd(_mm_load_pd(values + i), even);
    odd = i + 2 < Count ? _mm_max_pd(_mm_load_pd(values + i + 2), odd) : odd;
  }
  __m128d largest = _mm_max_pd(even, odd);
  largest = _mm_max_pd(largest, _mm_unpackhi_pd(largest, largest));
  if (!(_mm_cvtsd_f64(largest) > none))
  {
    return -1;
  }
  largest = _mm_unpacklo_pd(largest, largest);
  int equal = 0;
  for (int i = 0; i < Count; i += 2)
  {
    equal |= _mm_movemask_pd(_mm_cmpeq_pd(_mm_load_pd(values + i), largest)) << i;
  }
  return __builtin_ctz(equal);
#else
  int first = -1;
  double largest = none;
  for (int i = 0; i < Count; ++i)
  {
    const bool larger = values[i] > largest;
    first = larger ? i : first;
    largest = larger ? values[i] : largest;
  }
  return first;
#endif
}

/**
 * The bilinear footprint of the continuous position `uv` (pixel centres at
 * integers) in a width x height image: its top-left pixel (x0, y0), which
 * may lie outside the image by one, and the fraction uv - (x0, y0). False
 * when no pixel of the footprint is inside the image.
 */
inline bool BilinearFootprint(const glm::dvec2& uv,
  int width,
  int height,
  int& x0,
  int& y0,
  glm::dvec2& fraction)
{
  // floor(u) >= -1 and floor(u) < width hold exactly when u does (width is
  // an integer); inside that range the floor is the truncation, one lower
  // for a negative fraction: without SSE4.1 (the baseline x86-64 build)
  // std::floor is a software sequence that cost a tenth of a lookup.
#if defined(__SSE2__)
  // Both coordinates at once, lane by lane the scalar path's operations.
  const __m128d p = _mm_set_pd(uv.y, uv.x);
  const __m128d inside = _mm_and_pd(_mm_cmpge_pd(p, _mm_set1_pd(-1.0)),
    _mm_cmplt_pd(p, _mm_cvtepi32_pd(_mm_set_epi32(0, 0, height, width))));
  if (_mm_movemask_pd(inside) != 3)
  {
    return false;
  }
  const __m128i truncated = _mm_cvttpd_epi32(p);
  // The comparison's all-ones 64-bit lanes, as 32-bit -1s, lower the
  // truncation of a negative fraction.
  const __m128i lower = _mm_shuffle_epi32(
    _mm_castpd_si128(_mm_cmplt_pd(p, _mm_cvtepi32_pd(truncated))), _MM_SHUFFLE(3, 3, 2, 0));
  const __m128i floor = _mm_add_epi32(truncated, lower);
  x0 = _mm_cvtsi128_si32(floor);
  y0 = _mm_cvtsi128_si32(_mm_srli_si128(floor, 4));
  const __m128d f = _mm_sub_pd(p, _mm_cvtepi32_pd(floor));
  fraction = glm::dvec2(_mm_cvtsd_f64(f), _mm_cvtsd_f64(_mm_unpackhi_pd(f, f)));
#else
  if (!(uv.x >= -1.0 && uv.y >= -1.0 && uv.x < width && uv.y < height))
  {
    return false;
  }
  x0 = static_cast<int>(uv.x) - (uv.x < static_cast<int>(uv.x) ? 1 : 0);
  y0 = static_cast<int>(uv.y) - (uv.y < static_cast<int>(uv.y) ? 1 : 0);
  fraction = glm::dvec2(uv.x - x0, uv.y - y0);
#endif
  return true;
}

/**
 * The bilinear weights of the pixels (x0, y0), (x0 + 1, y0), (x0, y0 + 1)
 * and (x0 + 1, y0 + 1) of a footprint (BilinearFootprint()) whose fraction
 * is (ax, ay).
 */
inline void BilinearWeights(const glm::dvec2& fraction, double weights[4])
{
  const double ax = fraction.x;
  const double ay = fraction.y;
  weights[0] = (1.0 - ax) * (1.0 - ay);
  weights[1] = ax * (1.0 - ay);
  weights[2] = (1.0 - ax) * ay;
  weights[3] = ax * ay;
}

#if defined(__SSE2__)
namespace detail
{
/// The two RGB texels at p[0..2] and p[3..5] as doubles, two lanes per
/// register: (R, G) and (B, unused) of each. Reads those 6 bytes only.
inline void LoadTexelPair(const std::uint8_t* p,
  __m128d& rg0,
  __m128d& b0,
  __m128d& rg1,
  __m128d& b1)
{
  std::uint32_t head;
  std::uint16_t tail;
  std::memcpy(&head, p, sizeof(head));
  std::memcpy(&tail, p + sizeof(head), sizeof(tail));
  const __m128i zero = _mm_setzero_si128();
  // Bytes to 16 bits (R0 G0 B0 R1 G1 B1 0 0), then each texel to 32 bits.
  const __m128i words = _mm_unpacklo_epi8(_mm_insert_epi16(_mm_cvtsi32_si128(head), tail, 2), zero);
  const __m128i texel0 = _mm_unpacklo_epi16(words, zero);
  const __m128i texel1 = _mm_unpacklo_epi16(_mm_srli_si128(words, 6), zero);
  rg0 = _mm_cvtepi32_pd(texel0);
  b0 = _mm_cvtepi32_pd(_mm_unpackhi_epi64(texel0, texel0));
  rg1 = _mm_cvtepi32_pd(texel1);
  b1 = _mm_cvtepi32_pd(_mm_unpackhi_epi64(texel1, texel1));
}
} // namespace detail
#endif

/**
 * The bilinear blend of a footprint's 4 RGB texels at the fraction (ax, ay)
 * (BilinearFootprint()), in lerp form, which keeps a flat colour exact: the
 * texels (x0, y0) and (x0 + 1, y0) at top[0..2] and top[3..5], (x0, y0 + 1)
 * and (x0 + 1, y0 + 1) at bottom[0..2] and bottom[3..5]. With SSE2 (the
 * x86-64 baseline) the channels are converted and blended two at a time;
 * each lane does the scalar path's operations in its order, so both give
 * the same bits where neither is contracted into fused multiply-adds (the
 * baseline has none; GCC contracts C++ by default where they exist).
 * Always inlined: the lookup loops it sits in are large enough that GCC's
 * growth limits would otherwise leave it a call per sample.
 */
__attribute__((always_inline)) inline void BlendTexels(const std::uint8_t* top,
  const std::uint8_t* bottom,
  double ax,
  double ay,
  double color[3])
{
#if defined(__SSE2__)
  __m128d rg0, b0, rg1, b1, rg2, b2, rg3, b3;
  detail::LoadTexelPair(top, rg0, b0, rg1, b1);
  detail::LoadTexelPair(bottom, rg2, b2, rg3, b3);
  const __m128d x = _mm_set1_pd(ax);
  const __m128d y = _mm_set1_pd(ay);
  const __m128d rgTop = _mm_add_pd(rg0, _mm_mul_pd(x, _mm_sub_pd(rg1, rg0)));
  const __m128d bTop = _mm_add_pd(b0, _mm_mul_pd(x, _mm_sub_pd(b1, b0)));
  const __m128d rgBottom = _mm_add_pd(rg2, _mm_mul_pd(x, _mm_sub_pd(rg3, rg2)));
  const __m128d bBottom = _mm_add_pd(b2, _mm_mul_pd(x, _mm_sub_pd(b3, b2)));
  _mm_storeu_pd(color, _mm_add_pd(rgTop, _mm_mul_pd(y, _mm_sub_pd(rgBottom, rgTop))));
  _mm_store_sd(color + 2, _mm_add_pd(bTop, _mm_mul_pd(y, _mm_sub_pd(bBottom, bTop))));
#else
  for (int c = 0; c < 3; ++c)
  {
    const double upper = top[c] + ax * (top[3 + c] - top[c]);
    const double lower = bottom[c] + ax * (bottom[3 + c] - bottom[c]);
    color[c] = upper + ay * (lower - upper);
  }
#endif
}

/**
 * Calls add(px, py, weight) for the (up to) 4 pixels of the bilinear
 * footprint at (x0, y0) with the fraction `fraction` (BilinearFootprint())
 * in a width x height image, with their bilinear weights; pixels outside the
 * image and zero weights are skipped.
 */
template<typename Add>
inline void ForEachFootprintPixel(int x0,
  int y0,
  const glm::dvec2& fraction,
  int width,
  int height,
  Add&& add)
{
  double weights[4];
  BilinearWeights(fraction, weights);
  for (int corner = 0; corner < 4; ++corner)
  {
    const int px = x0 + (corner & 1);
    const int py = y0 + (corner >> 1);
    if (px >= 0 && py >= 0 && px < width && py < height && weights[corner] > 0.0)
    {
      add(px, py, weights[corner]);
    }
  }
}

/**
 * Calls add(px, py, weight) for the (up to) 4 pixels of a width x height
 * image around the continuous position `uv` (pixel centres at integers),
 * with their bilinear weights; pixels outside the image and zero weights are
 * skipped. One bilinear lookup for every sampler (ring and two-plane).
 */
template<typename Add>
inline void ForEachBilinearPixel(const glm::dvec2& uv, int width, int height, Add&& add)
{
  int x0, y0;
  glm::dvec2 fraction;
  if (BilinearFootprint(uv, width, height, x0, y0, fraction))
  {
    ForEachFootprintPixel(x0, y0, fraction, width, height, std::forward<Add>(add));
  }
}

/**
 * The angle of the vector (x, y) in [0, 2 pi): std::atan2 shifted into that
 * range, within 2e-10 radian of it at a fraction of its cost (glibc's atan2
 * took a tenth of an undeformed frame). With a = min and b = max of |x|,
 * |y|, atan(a / b) is reduced below tan(pi / 8) by atan(a / b) = pi / 4 +
 * atan((a - b) / (a + b)) (one division either way), where an odd
 * polynomial of degree 11 stands for atan: least squares on 4000 Chebyshev
 * nodes of [-tan(pi / 8), tan(pi / 8)], largest error 1.3e-10.
 */
inline double Azimuth(double y, double x)
{
  constexpr double Pi = 0.5 * TwoPi;
  const double ax = std::abs(x);
  const double ay = std::abs(y);
  const double low = std::min(ax, ay);
  const double high = std::max(ax, ay);
  const bool reduced = low > 0.41421356237309503 * high; // tan(pi / 8)
  const double denominator = reduced ? low + high : high;
  // (Branch-free, for LightFieldSampler::AimBatch: the division by 1 at the origin.)
  const double ratio = (reduced ? low - high : low) / (denominator > 0.0 ? denominator : 1.0);
  const double u = denominator > 0.0 ? ratio : 0.0;
  const double u2 = u * u;
  const double series = 0.99999999701802489 +
    u2 *
      (-0.33333278009378303 +
        u2 *
          (0.19997219935851313 +
            u2 * (-0.14226554657594762 + u2 * (0.10493657285601736 + u2 * -0.058641128553379503))));
  double angle = u * series + (reduced ? 0.25 * Pi : 0.0);
  angle = ay > ax ? 0.5 * Pi - angle : angle;
  angle = x < 0.0 ? Pi - angle : angle;
  angle = y < 0.0 ? TwoPi - angle : angle;
  return angle < TwoPi ? angle : 0.0; // -0.0 and tiny negative y round up to 2 pi
}

/// One row (ring) of views, sorted by azimuth in [0, 2 pi).
struct RingRow
{
  double Height = 0.0;
  std::vector<double> Azimuth;
  std::vector<int> View;
  /// Per bucket k of [0, 2 pi) cut in Buckets.size() equal parts, the
  /// number of views whose azimuth is at most the bucket's start (Index()).
  std::vector<int> Buckets;
  double BucketsPerRadian = 0.0;

  /// Fills Buckets, 4 per view, once Azimuth holds the row's views.
  void Index()
  {
    this->Buckets.resize(4 * this->Azimuth.size());
    this->BucketsPerRadian = this->Buckets.size() / TwoPi;
    for (std::size_t k = 0; k < this->Buckets.size(); ++k)
    {
      this->Buckets[k] = static_cast<int>(
        std::upper_bound(this->Azimuth.begin(), this->Azimuth.end(), k / this->BucketsPerRadian) -
        this->Azimuth.begin());
    }
  }

  /// The number of views whose azimuth is at most `azimuth`
  /// (std::upper_bound's index).
  /// Always inlined, as BracketAzimuth() and ChooseViews(): AimBatch's
  /// stages are one large function, where GCC's growth limits otherwise
  /// leave one of the three a call per ray, whichever changes elsewhere tip.
  __attribute__((always_inline)) std::size_t Upper(double azimuth) const
  {
    // From the azimuth's bucket (without Index(), from the first view):
    // with 4 buckets per view, most rays' answer is their bucket's, the
    // others' one view on; the walks make it exact however the bucket
    // rounds. A chain of a multiplication and a load or two, where a search
    // by halves is 7 dependent loads (120 views).
    const std::size_t n = this->Azimuth.size();
    const int last = static_cast<int>(this->Buckets.size()) - 1;
    std::size_t upper = last < 0
      ? 0
      : this->Buckets[std::clamp(static_cast<int>(azimuth * this->BucketsPerRadian), 0, last)];
    while (upper > 0 && this->Azimuth[upper - 1] > azimuth)
    {
      --upper;
    }
    while (upper < n && this->Azimuth[upper] <= azimuth)
    {
      ++upper;
    }
    return upper;
  }
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
    azimuth = Azimuth(glm::dot(v, this->RefY), glm::dot(v, this->RefX));
  }
};

/// A camera chosen for a ray and its weight (azimuth x height).
struct WeightedView
{
  int View;
  double Weight;
};

/**
 * The two views of a row around `azimuth`, linearly weighted by angular
 * distance (the row wraps around). Returns how many were written (0..2).
 */
__attribute__((always_inline)) inline int BracketAzimuth(const RingRow& row,
  double azimuth,
  double rowWeight,
  WeightedView out[2])
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
  // First view with an azimuth greater than the query (std::upper_bound's
  // answer), the one before it (cyclically) the lower neighbour.
  const std::size_t upper = row.Upper(azimuth);
  // upper is in [0, n]: the neighbours wrap without a division.
  const std::size_t hi = upper == n ? 0 : upper;
  const std::size_t lo = upper == 0 ? n - 1 : upper - 1;
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
__attribute__((always_inline)) inline int ChooseViews(const RingLayout& layout,
  double azimuth,
  double height,
  WeightedView out[4])
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
 * in VTK order (bottom image row first), as vtkLightField stores them. A
 * pass larger than memory has no Data but a Source its texels are read
 * through (a light field backed by an image cache).
 */
template<typename T>
struct ViewStack
{
  const T* Data = nullptr;
  int Width = 0;
  int Height = 0;
  int Components = 1;
  const TexelSource* Source = nullptr;

  /// Whether the stack holds a pass (in memory or through Source).
  bool Present() const { return this->Data || this->Source; }

  /// Pointer to the pixel at OpenCV coordinates (x, y) (top-left origin);
  /// read it before the next Pixel() call (Source's tiles are recycled).
  const T* Pixel(int view, int x, int y) const
  {
    if (this->Source)
    {
      return static_cast<const T*>(this->Source->Texel(view, x, y));
    }
    return this->Data + this->Index(view, x, y) * this->Components;
  }

  /// Index of the pixel at OpenCV coordinates (x, y) of `view` in Data
  /// (in pixels: times Components for its first value).
  std::size_t Index(int view, int x, int y) const
  {
    const std::size_t row = static_cast<std::size_t>(view) * this->Height + (this->Height - 1 - y);
    return row * this->Width + x;
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
  /// Parameter s of the proxy surface point the samples are focused on,
  /// along the looked-up line o + s d; NaN when they are focused on the
  /// focal plane (no proxy, or the ray meets no surface).
  double Surface = std::numeric_limits<double>::quiet_NaN();

  /// No sample (a lookup that found none, or before one).
  void Clear()
  {
    this->Count = 0;
    this->Surface = std::numeric_limits<double>::quiet_NaN();
  }
};

/**
 * Runs `body(begin, end)` over the ranges of [0, n) it chooses, for a loop
 * whose iterations are independent (the views of a depth stack, the boxes
 * of a FrameCage): SerialLoop runs the one range; vtkLightFieldRenderer
 * hands vtkSMPTools::For, so that the loop runs on every thread, with the
 * same results.
 */
using RangeLoop = std::function<void(std::size_t n,
  const std::function<void(std::size_t begin, std::size_t end)>& body)>;
inline void SerialLoop(std::size_t n,
  const std::function<void(std::size_t begin, std::size_t end)>& body)
{
  body(0, n);
}

/**
 * Per view v of a depth stack, the smallest and largest positive depth at
 * 2 v and 2 v + 1 (0 and 0 for a view that sees no surface): the stretch of
 * a ray that LightFieldSampler::IntersectDepthMap walks. The views are run
 * by `loop`.
 */
inline std::vector<double> DepthRanges(const ViewStack<float>& depth,
  int views,
  const RangeLoop& loop = SerialLoop)
{
  std::vector<double> ranges(2 * static_cast<std::size_t>(views), 0.0);
  loop(static_cast<std::size_t>(views),
    [&](std::size_t begin, std::size_t end)
    {
      for (int v = static_cast<int>(begin); v < static_cast<int>(end); ++v)
      {
        double low = std::numeric_limits<double>::infinity();
        double high = 0.0;
        // Texel by texel (ViewStack::Pixel): the stack may be out of core.
        for (int y = 0; y < depth.Height; ++y)
        {
          for (int x = 0; x < depth.Width; ++x)
          {
            const double z = *depth.Pixel(v, x, y);
            if (z > 0.0)
            {
              low = std::min(low, z);
              high = std::max(high, z);
            }
          }
        }
        if (high > 0.0)
        {
          ranges[2 * v] = low;
          ranges[2 * v + 1] = high;
        }
      }
    });
  return ranges;
}

/**
 * The axis-aligned bounds, `low` and `high`, of the surface points of a
 * depth stack (every pixel with a depth, back-projected through its view's
 * camera): no ray that misses them meets the proxy. False when no view sees
 * a surface. The views are run by `loop`.
 */
inline bool DepthBounds(const ViewStack<float>& depth,
  const PinholeCamera* cameras,
  int views,
  glm::dvec3& low,
  glm::dvec3& high,
  const RangeLoop& loop = SerialLoop)
{
  // Each view's bounds (in `loop`), then theirs: minima and maxima are exact,
  // so the same bounds however the views are split.
  const glm::dvec3 none(std::numeric_limits<double>::infinity());
  std::vector<glm::dvec3> lows(static_cast<std::size_t>(views), none);
  std::vector<glm::dvec3> highs(static_cast<std::size_t>(views), -none);
  loop(static_cast<std::size_t>(views),
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t v = begin; v < end; ++v)
      {
        const PinholeCamera::Unprojection rays = cameras[v].GetUnprojection();
        for (int y = 0; y < depth.Height; ++y)
        {
          for (int x = 0; x < depth.Width; ++x)
          {
            const double z = *depth.Pixel(static_cast<int>(v), x, y);
            if (z > 0.0)
            {
              const glm::dvec3 point = rays(glm::dvec2(x, y), z);
              lows[v] = glm::min(lows[v], point);
              highs[v] = glm::max(highs[v], point);
            }
          }
        }
      }
    });
  low = none;
  high = -none;
  for (int v = 0; v < views; ++v)
  {
    low = glm::min(low, lows[v]);
    high = glm::max(high, highs[v]);
  }
  return low.x <= high.x;
}

/**
 * Per view, the Size x Size pixel blocks of its label image that hold a
 * labelled (non-zero) pixel: LabelHull tests a voxel against them as well
 * as against the view's label rectangle. The rectangle of a part seen
 * obliquely (a fish seen from its side, a diagonal limb) is mostly
 * background: of the swimming fish's lookups that passed the rectangles'
 * hull, half had no labelled sample.
 */
struct LabelBlocks
{
  static constexpr int Size = 4;
  int Columns = 0;
  int Rows = 0;
  /// Per view, Rows x Columns flags (1: a labelled pixel), top block row first.
  std::vector<std::uint8_t> Labelled;

  /// Whether view `view` has a labelled pixel in the pixel rectangle
  /// [x0, x1] x [y0, y1] (OpenCV pixel indices, inclusive; clipped to the image).
  bool Any(int view, int x0, int y0, int x1, int y1) const
  {
    const int bx0 = std::max(x0, 0) / Size;
    const int by0 = std::max(y0, 0) / Size;
    const int bx1 = std::min(x1 / Size, this->Columns - 1);
    const int by1 = std::min(y1 / Size, this->Rows - 1);
    const std::uint8_t* blocks =
      this->Labelled.data() + static_cast<std::size_t>(view) * this->Rows * this->Columns;
    for (int by = by0; by <= by1; ++by)
    {
      for (int bx = bx0; bx <= bx1; ++bx)
      {
        if (blocks[by * this->Columns + bx])
        {
          return true;
        }
      }
    }
    return false;
  }
};

/**
 * Where a focal-plane lookup can meet a part: per azimuth sector of the rig,
 * a voxel grid (in the rig's frame: RefX, RefY, Axis) marking every voxel
 * that the label cone of a view that may be chosen in the sector touches
 * (the cone from the view's centre through the bounding rectangle of its
 * labelled pixels, widened by the bilinear footprint; with LabelBlocks,
 * through its blocks of 4 x 4 pixels that hold a labelled pixel). A ray whose entry
 * azimuth lies in a sector and whose focal point falls in an unmarked voxel
 * of that sector's grid has no labelled sample among its 16: with labels it
 * is background, exactly, and LightFieldSampler::Gather skips its texels.
 * The marking is conservative (each voxel is tested as its bounding sphere,
 * with a rigorous bound of the sphere's projection), and a focal point
 * outside the grid is always looked up, so skipping never changes a pixel.
 * Built once per light field; a rig with lens distortion (whose projection
 * of a sphere this bound does not hold for) gets no grid. Through a proxy,
 * the voxels a ray's stretch inside the proxy's bounds crosses are tested
 * as well (MaySeePart(); why that is exact: LightFieldSampler::Gather).
 */
struct LabelHull
{
  static constexpr int Sectors = 32;
  static constexpr int Cells = 32; ///< per axis of a sector's grid

  glm::dvec3 Low{ 0.0 };      ///< grid corner in the rig frame
  glm::dvec3 CellSize{ 1.0 }; ///< per axis
  /// 1 / CellSize: Cell() multiplies (a division per axis cost every looked-up ray).
  glm::dvec3 InverseCellSize{ 1.0 };
  /// Per sector, Cells^3 flags (1: a label cone touches the voxel); empty: no grid.
  std::vector<std::uint8_t> Marks;
  /// Per voxel (Cells^3), the sectors that mark it (Unite(); bit k: sector
  /// k), non-zero for the union of the sectors' marks: a focal point in a
  /// voxel unmarked in every sector, or in each of the sectors its ray may
  /// enter the rig in (LightFieldSampler::EntrySectors()), is skipped before
  /// the ray's azimuth is known.
  std::vector<std::uint32_t> Union;
  /// Per sector, its marks united with its two neighbours' (Unite()): the
  /// proxy's candidate cameras (LightFieldSampler::FindProxyCandidates, 4 per
  /// row around the azimuth) use up the margin of one view that MarkSector
  /// leaves on each side for rounding, so the proxy's test takes it from the
  /// neighbouring sectors instead (see MaySeePart()).
  std::vector<std::uint8_t> Wide;

  /**
   * Sizes the grid around the rig's axis: radially the half-width that the
   * views image at the axis, along it the rows' heights widened by as much.
   * Returns false (no grid) when a camera has lens distortion.
   */
  bool Initialize(const RingLayout& layout, const PinholeCamera* cameras, int width, int height)
  {
    this->Marks.clear();
    double reach = 0.0;
    for (const RingRow& row : layout.Rows)
    {
      for (int view : row.View)
      {
        const PinholeCamera& camera = cameras[view];
        if (camera.Lens.Active)
        {
          return false;
        }
        const double focal = std::min(std::abs(camera.K[0][0]), std::abs(camera.K[1][1]));
        reach = std::max(reach,
          glm::distance(camera.Center(), layout.Cyl.Center) * 0.5 * std::max(width, height) /
            focal);
      }
    }
    if (layout.Rows.empty() || !(reach > 0.0))
    {
      return false;
    }
    this->Low = glm::dvec3(-reach, -reach, layout.Rows.front().Height - reach);
    const glm::dvec3 high(reach, reach, layout.Rows.back().Height + reach);
    this->CellSize = (high - this->Low) / double(Cells);
    this->InverseCellSize = 1.0 / this->CellSize;
    this->Marks.assign(static_cast<std::size_t>(Sectors) * Cells * Cells * Cells, 0);
    return true;
  }

  /**
   * Marks sector `sector`'s grid from `rects`: per view, the OpenCV pixel
   * bounds (x0, y0, x1, y1) of its labelled pixels (x1 < x0: none).
   * Sectors are independent: they may be marked in parallel.
   */
  void MarkSector(int sector,
    const RingLayout& layout,
    const PinholeCamera* cameras,
    const std::vector<glm::ivec4>& rects,
    const LabelBlocks* blocks = nullptr)
  {
    std::uint8_t* marks =
      this->Marks.data() + static_cast<std::size_t>(sector) * Cells * Cells * Cells;
    const double a0 = TwoPi * sector / Sectors;
    const double a1 = TwoPi * (sector + 1) / Sectors;
    const double radius = 0.5 * glm::length(this->CellSize);
    for (const RingRow& row : layout.Rows)
    {
      const int n = static_cast<int>(row.Azimuth.size());
      if (n == 0)
      {
        continue;
      }
      // The views BracketAzimuth may pick for an azimuth in [a0, a1], and one
      // more on each side for the rounding of the sector's bounds.
      const int first =
        static_cast<int>(
          std::upper_bound(row.Azimuth.begin(), row.Azimuth.end(), a0) - row.Azimuth.begin()) -
        2;
      const int last =
        static_cast<int>(
          std::upper_bound(row.Azimuth.begin(), row.Azimuth.end(), a1) - row.Azimuth.begin()) +
        1;
      for (int i = first; i <= std::min(last, first + n - 1); ++i)
      {
        const int view = row.View[((i % n) + n) % n];
        const glm::ivec4& rect = rects[view];
        if (rect.z >= rect.x)
        {
          this->MarkCone(cameras[view], rect, blocks, view, radius, marks, layout);
        }
      }
    }
  }

  static_assert(Sectors <= 32, "a voxel's sectors are the bits of a 32-bit Union entry");

  /**
   * Fills Union from the sectors' marks; call once every sector is marked
   * (until then, and without a grid, Union is empty and unused).
   */
  void Unite()
  {
    const std::size_t cells = static_cast<std::size_t>(Cells) * Cells * Cells;
    this->Union.assign(this->Marks.empty() ? 0 : cells, 0);
    this->Wide.assign(this->Marks.size(), 0);
    for (std::size_t i = 0; i < this->Marks.size(); ++i)
    {
      const std::size_t sector = i / cells;
      this->Union[i % cells] |= static_cast<std::uint32_t>(this->Marks[i]) << sector;
      for (std::size_t next : { sector + Sectors - 1, sector, sector + 1 })
      {
        this->Wide[next % Sectors * cells + i % cells] |= this->Marks[i];
      }
    }
  }

  /**
   * Index of the voxel (within one sector's grid) holding the focal point
   * `x`; -1 outside the grid, where every ray may meet a part.
   */
  int Cell(const glm::dvec3& x, const RingLayout& layout) const
  {
    return CellAt(this->GridPosition(x, layout));
  }

  /**
   * The grid coordinates (in voxels from Low) of the world point `x`:
   * Cell()'s arithmetic, which LightFieldSampler::AimBatch runs over a
   * batch of focal points as one vectorised loop.
   */
  glm::dvec3 GridPosition(const glm::dvec3& x, const RingLayout& layout) const
  {
    const glm::dvec3 v = x - layout.Cyl.Center;
    return (glm::dvec3(
              glm::dot(v, layout.RefX), glm::dot(v, layout.RefY), glm::dot(v, layout.Cyl.Axis)) -
             this->Low) *
      this->InverseCellSize;
  }

  /// Index of the voxel at grid coordinates `q` (GridPosition()); -1 outside the grid.
  static int CellAt(const glm::dvec3& q)
  {
    if (!(q.x >= 0.0 && q.y >= 0.0 && q.z >= 0.0 && q.x < Cells && q.y < Cells && q.z < Cells))
    {
      return -1;
    }
    return (static_cast<int>(q.z) * Cells + static_cast<int>(q.y)) * Cells + static_cast<int>(q.x);
  }

  /**
   * False when the ray entering the rig at `azimuth`, focused in voxel
   * `cell` (Cell()), has no labelled sample for sure; true when it may have
   * one.
   */
  bool MayMeetPart(double azimuth, long cell) const
  {
    if (cell < 0)
    {
      return true;
    }
    return this->Marks[Sector(azimuth) * Cells * Cells * Cells + static_cast<std::size_t>(cell)] !=
      0;
  }

  /**
   * The sectors (bit k: sector k, as in Union) of the azimuths on the arc
   * of `length` radians from `from` (in [-2 pi, 2 pi)) counter-clockwise;
   * every sector for an arc of 2 pi or more.
   */
  static std::uint32_t SectorsOnArc(double from, double length)
  {
    constexpr std::uint32_t all = Sectors == 32 ? ~0u : (1u << Sectors) - 1;
    if (!(length < TwoPi))
    {
      return all;
    }
    from = from < 0.0 ? from + TwoPi : from;
    double to = from + length;
    to = to >= TwoPi ? to - TwoPi : to;
    const std::size_t first = Sector(from);
    const std::size_t last = Sector(to);
    // An arc across azimuth 0 that comes back into its first sector holds them all.
    if (to < from && last >= first)
    {
      return all;
    }
    const std::size_t count = (last + Sectors - first) % Sectors + 1;
    const std::uint32_t run = count == 32 ? ~0u : (1u << count) - 1;
    return ((run << first) | (first == 0 ? 0u : run >> (Sectors - first))) & all;
  }

  /**
   * False when no point of the segment [a, b] (world points) can have a
   * labelled sample in any camera that GatherOnSurface may blend for a ray
   * entering the rig at `azimuth`: the segment lies inside the grid and
   * crosses only voxels unmarked in the sector's Wide marks. True when it
   * may. The voxels crossed are found slab by slab along the axis in which
   * the segment runs longest, each slab's stretch of the other two
   * coordinates widened by 1e-6 voxel for rounding (of [a, b] and of the
   * walk's points on it, whose errors are some 1e-13 voxel).
   */
  bool MaySeePart(double azimuth,
    const glm::dvec3& a,
    const glm::dvec3& b,
    const RingLayout& layout) const
  {
    constexpr double margin = 1e-6;
    const glm::dvec3 q0 = (ToRig(layout, a - layout.Cyl.Center) - this->Low) / this->CellSize;
    const glm::dvec3 q1 = (ToRig(layout, b - layout.Cyl.Center) - this->Low) / this->CellSize;
    const glm::dvec3 low = glm::min(q0, q1) - margin;
    const glm::dvec3 high = glm::max(q0, q1) + margin;
    // Both ends inside the grid: the whole segment is (the grid is convex).
    if (!(low.x >= 0.0 && low.y >= 0.0 && low.z >= 0.0 && high.x < Cells && high.y < Cells &&
          high.z < Cells))
    {
      return true;
    }
    const std::uint8_t* marks = this->Wide.data() + Sector(azimuth) * Cells * Cells * Cells;
    const glm::dvec3 span = q1 - q0;
    const glm::dvec3 length = glm::abs(span);
    const int m = length.x >= length.y && length.x >= length.z ? 0 : (length.y >= length.z ? 1 : 2);
    const int u = (m + 1) % 3;
    const int v = (m + 2) % 3;
    const int stride[3] = { 1, Cells, Cells * Cells };
    for (int i = static_cast<int>(low[m]); i <= static_cast<int>(high[m]); ++i)
    {
      // The stretch of the segment (f in [0, 1]) within slab i, widened.
      double f0 = 0.0, f1 = 1.0;
      if (length[m] > 0.0)
      {
        const double e0 = (i - margin - q0[m]) / span[m];
        const double e1 = (i + 1 + margin - q0[m]) / span[m];
        f0 = std::max(std::min(e0, e1), 0.0);
        f1 = std::min(std::max(e0, e1), 1.0);
      }
      const double u0 = q0[u] + f0 * span[u], u1 = q0[u] + f1 * span[u];
      const double v0 = q0[v] + f0 * span[v], v1 = q0[v] + f1 * span[v];
      const int ua = static_cast<int>(std::max(std::min(u0, u1) - margin, 0.0));
      const int ub = static_cast<int>(std::min(std::max(u0, u1) + margin, Cells - 1.0));
      const int va = static_cast<int>(std::max(std::min(v0, v1) - margin, 0.0));
      const int vb = static_cast<int>(std::min(std::max(v0, v1) + margin, Cells - 1.0));
      for (int j = ua; j <= ub; ++j)
      {
        for (int k = va; k <= vb; ++k)
        {
          if (marks[i * stride[m] + j * stride[u] + k * stride[v]])
          {
            return true;
          }
        }
      }
    }
    return false;
  }

  /**
   * The screen-tile mask of a frame: per tile of `tileSize` x `tileSize`
   * pixels of a width x height frame (row-major, top tile row first), whose
   * ray through pixel (x, y) (OpenCV) is eye + t pixelToDirection (x, y, 1),
   * 0 when the focal point (FocalPoint(), `focalDistance`) of every ray of
   * the tile falls in a voxel unmarked in Union: Gather skips every one of
   * them, so with labels the whole tile is background and its rays need not
   * be generated. 1 when a ray of the tile may be looked up. Empty without
   * Union. The bound is rigorous (FocalBox()), so a 0 never hides a pixel.
   *
   * With a proxy whose surface points lie in the world box [surfaceLow,
   * surfaceHigh] (LightFieldSampler::SurfaceLow, SurfaceHigh; empty by
   * default: no proxy), a tile is 0 only when, besides, the stretches of its
   * rays inside the box (SurfaceStretch()) meet no voxel marked in Union
   * (SurfaceUnmarked()), so that Gather skips each of them there too.
   */
  std::vector<std::uint8_t> ScreenTiles(const RingLayout& layout,
    const glm::dvec3& eye,
    const glm::dmat3& pixelToDirection,
    int width,
    int height,
    double focalDistance,
    int tileSize,
    const glm::dvec3& surfaceLow = glm::dvec3(std::numeric_limits<double>::infinity()),
    const glm::dvec3& surfaceHigh = glm::dvec3(-std::numeric_limits<double>::infinity())) const
  {
    if (this->Union.empty())
    {
      return {};
    }
    const int columns = (width + tileSize - 1) / tileSize;
    const int rows = (height + tileSize - 1) / tileSize;
    std::vector<std::uint8_t> tiles(static_cast<std::size_t>(columns) * rows, 1);
    for (int ty = 0; ty < rows; ++ty)
    {
      for (int tx = 0; tx < columns; ++tx)
      {
        const double x0 = tx * tileSize;
        const double y0 = ty * tileSize;
        const double x1 = std::min(x0 + tileSize - 1, width - 1.0);
        const double y1 = std::min(y0 + tileSize - 1, height - 1.0);
        // Corners in order around the pixel rectangle.
        const glm::dvec3 corners[4] = { pixelToDirection * glm::dvec3(x0, y0, 1.0),
          pixelToDirection * glm::dvec3(x1, y0, 1.0),
          pixelToDirection * glm::dvec3(x1, y1, 1.0),
          pixelToDirection * glm::dvec3(x0, y1, 1.0) };
        glm::dvec3 low, high;
        tiles[static_cast<std::size_t>(ty) * columns + tx] =
          !(this->FocalBox(layout, eye, corners, focalDistance, low, high) &&
            this->Unmarked(low, high) &&
            this->SurfaceUnmarked(layout,
              eye,
              pixelToDirection,
              glm::dvec4(x0, y0, x1, y1),
              corners,
              surfaceLow,
              surfaceHigh));
      }
    }
    return tiles;
  }

private:
  /// Side, in voxels, of the blocks MarkCone tests first.
  static constexpr int Block = 4;

  /// The sector of an azimuth in [0, 2 pi).
  static std::size_t Sector(double azimuth)
  {
    return static_cast<std::size_t>(
      std::min(static_cast<int>(azimuth * (Sectors / TwoPi)), Sectors - 1));
  }

  /// The camera `camera` seen from the rig frame: c = Origin + ToCamera q.
  struct ConeView
  {
    const PinholeCamera& Camera;
    glm::dmat3 ToCamera;
    glm::dvec3 Origin;
    glm::ivec4 Rect;
    const LabelBlocks* Blocks; ///< null: the rectangle alone
    int View;                  ///< the camera's view (Blocks)
  };

  /// The rig-frame coordinates (RefX, RefY, Axis) of the vector `v`.
  static glm::dvec3 ToRig(const RingLayout& layout, const glm::dvec3& v)
  {
    return glm::dvec3(
      glm::dot(v, layout.RefX), glm::dot(v, layout.RefY), glm::dot(v, layout.Cyl.Axis));
  }

  /**
   * Rig-frame bounds [low, high] of the focal points of the rays eye + s d,
   * d in the parallelogram of directions spanned by `corners` (the affine
   * image of a pixel rectangle, corners in order around it). In the rig
   * frame the focal point is w + t r (w: the eye, r: the direction), with
   * t = s - f / |r| and s = N / D, N = -(w_xy . r_xy) affine in the pixel
   * (extremes at corners), D = |r_xy|^2 convex (maximum at a corner, minimum
   * the squared distance of the origin to the parallelogram of the r_xy), and
   * sqrt(D) <= |r| <= the largest corner's. Every point w + t r, t in
   * [t0, t1], is a convex combination of w + t0 r and w + t1 r, so the
   * corners at t0 and t1 bound them all. False for rays too near the axis's
   * direction (no bounded focal point, and FocalPoint's rounding grows).
   */
  bool FocalBox(const RingLayout& layout,
    const glm::dvec3& eye,
    const glm::dvec3 corners[4],
    double focalDistance,
    glm::dvec3& low,
    glm::dvec3& high) const
  {
    const glm::dvec3 w = ToRig(layout, eye - layout.Cyl.Center);
    glm::dvec3 r[4];
    double nLow = std::numeric_limits<double>::infinity(), nHigh = -nLow;
    double dHigh = 0.0, lengthHigh = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      r[k] = ToRig(layout, corners[k]);
      const double n = -(w.x * r[k].x + w.y * r[k].y);
      nLow = std::min(nLow, n);
      nHigh = std::max(nHigh, n);
      dHigh = std::max(dHigh, r[k].x * r[k].x + r[k].y * r[k].y);
      lengthHigh = std::max(lengthHigh, glm::dot(r[k], r[k]));
    }
    // The squared distance of the origin to the parallelogram of the r_xy:
    // 0 inside it, else the nearest of its edges.
    double dLow = std::numeric_limits<double>::infinity();
    int positive = 0;
    for (int k = 0; k < 4; ++k)
    {
      const glm::dvec2 a(r[k]);
      const glm::dvec2 edge = glm::dvec2(r[(k + 1) % 4]) - a;
      positive += edge.x * -a.y - edge.y * -a.x > 0.0 ? 1 : 0;
      const double along = glm::dot(edge, edge) > 0.0
        ? std::clamp(-glm::dot(a, edge) / glm::dot(edge, edge), 0.0, 1.0)
        : 0.0;
      const glm::dvec2 nearest = a + along * edge;
      dLow = std::min(dLow, glm::dot(nearest, nearest));
    }
    if (positive == 0 || positive == 4 || !(dLow > 1e-3 * lengthHigh))
    {
      return false;
    }
    double sLow = std::numeric_limits<double>::infinity(), sHigh = -sLow;
    for (double n : { nLow, nHigh })
    {
      for (double d : { dLow, dHigh })
      {
        sLow = std::min(sLow, n / d);
        sHigh = std::max(sHigh, n / d);
      }
    }
    const double g0 = focalDistance / std::sqrt(lengthHigh);
    const double g1 = focalDistance / std::sqrt(dLow);
    const double t0 = sLow - std::max(g0, g1);
    const double t1 = sHigh - std::min(g0, g1);
    low = glm::dvec3(std::numeric_limits<double>::infinity());
    high = -low;
    for (int k = 0; k < 4; ++k)
    {
      for (double t : { t0, t1 })
      {
        low = glm::min(low, w + t * r[k]);
        high = glm::max(high, w + t * r[k]);
      }
    }
    // Margin for the rounding of FocalPoint() and Cell().
    const glm::dvec3 margin =
      1e-6 * this->CellSize + 1e-9 * (glm::length(w) + std::max(std::abs(t0), std::abs(t1)));
    low -= margin;
    high += margin;
    return true;
  }

  /**
   * Whether the rays eye + t r, r in the parallelogram of directions spanned
   * by `corners` (pixels `tile`: x0, y0, x1, y1), meet no voxel marked in
   * Union inside the world box [surfaceLow, surfaceHigh] (true for an empty
   * box). A ray's direction has camera z 1 (pixelToDirection), so t is the
   * camera z of its point: with every box corner in front of the eye, a
   * ray whose pixel lies outside the bounding rectangle of the corners'
   * projections misses the box, and the points of the others inside it
   * have t between the corners' least and greatest camera z, t0 and t1.
   * Those points lie in the convex hull of the 8 points eye + t r_k (t0 and
   * t1, the 4 corners r_k), whose bounds, cut to the box, are tested
   * (Unmarked()). False where a box corner is not in front of the eye.
   */
  bool SurfaceUnmarked(const RingLayout& layout,
    const glm::dvec3& eye,
    const glm::dmat3& pixelToDirection,
    const glm::dvec4& tile,
    const glm::dvec3 corners[4],
    const glm::dvec3& surfaceLow,
    const glm::dvec3& surfaceHigh) const
  {
    if (!(surfaceLow.x <= surfaceHigh.x && surfaceLow.y <= surfaceHigh.y &&
          surfaceLow.z <= surfaceHigh.z))
    {
      return true;
    }
    const glm::dmat3 toCamera = glm::inverse(pixelToDirection);
    glm::dvec2 low(std::numeric_limits<double>::infinity());
    glm::dvec2 high = -low;
    double t0 = std::numeric_limits<double>::infinity(), t1 = 0.0;
    for (int k = 0; k < 8; ++k)
    {
      const glm::dvec3 corner = BoundsCorner(AxisBounds{ surfaceLow, surfaceHigh }, k);
      const glm::dvec3 c = toCamera * (corner - eye);
      if (!(c.z > 1e-9 * glm::length(corner - eye)))
      {
        return false;
      }
      low = glm::min(low, glm::dvec2(c) / c.z);
      high = glm::max(high, glm::dvec2(c) / c.z);
      t0 = std::min(t0, c.z);
      t1 = std::max(t1, c.z);
    }
    // A margin of 1e-3 pixel for the rounding of the projection and of the
    // rays' stretches.
    if (tile.z < low.x - 1e-3 || tile.x > high.x + 1e-3 || tile.w < low.y - 1e-3 ||
      tile.y > high.y + 1e-3)
    {
      return true;
    }
    glm::dvec3 hullLow(std::numeric_limits<double>::infinity());
    glm::dvec3 hullHigh = -hullLow;
    for (int k = 0; k < 4; ++k)
    {
      for (double t : { t0, t1 })
      {
        hullLow = glm::min(hullLow, eye + t * corners[k]);
        hullHigh = glm::max(hullHigh, eye + t * corners[k]);
      }
    }
    hullLow = glm::max(hullLow, surfaceLow);
    hullHigh = glm::min(hullHigh, surfaceHigh);
    // The rig-frame bounds of that world box, widened for rounding as FocalBox's.
    glm::dvec3 low3(std::numeric_limits<double>::infinity());
    glm::dvec3 high3 = -low3;
    for (int k = 0; k < 8; ++k)
    {
      const glm::dvec3 corner = BoundsCorner(AxisBounds{ hullLow, hullHigh }, k);
      const glm::dvec3 q = ToRig(layout, corner - layout.Cyl.Center);
      low3 = glm::min(low3, q);
      high3 = glm::max(high3, q);
    }
    const glm::dvec3 margin = 1e-6 * this->CellSize + 1e-9 * glm::length(eye - layout.Cyl.Center);
    return this->Unmarked(low3 - margin, high3 + margin);
  }

  /**
   * Whether the rig-frame box [low, high] lies inside the grid and meets
   * only voxels unmarked in Union (false, too, for a box over more than
   * 4096 voxels: not worth reading).
   */
  bool Unmarked(const glm::dvec3& low, const glm::dvec3& high) const
  {
    const glm::dvec3 q0 = (low - this->Low) / this->CellSize;
    const glm::dvec3 q1 = (high - this->Low) / this->CellSize;
    if (!(q0.x >= 0.0 && q0.y >= 0.0 && q0.z >= 0.0 && q1.x < Cells && q1.y < Cells &&
          q1.z < Cells))
    {
      return false;
    }
    const glm::ivec3 c0(q0);
    const glm::ivec3 c1(q1);
    const glm::ivec3 span = c1 - c0 + 1;
    if (span.x * span.y * span.z > 4096)
    {
      return false;
    }
    for (int z = c0.z; z <= c1.z; ++z)
    {
      for (int y = c0.y; y <= c1.y; ++y)
      {
        for (int x = c0.x; x <= c1.x; ++x)
        {
          if (this->Union[(static_cast<std::size_t>(z) * Cells + y) * Cells + x])
          {
            return false;
          }
        }
      }
    }
    return true;
  }

  /**
   * Whether the sphere of radius `radius` around the rig-frame point `q` may
   * project within one pixel of the view's label rectangle (a bilinear
   * lookup reads the pixels within 1 of its position) and, with label
   * blocks, of a labelled pixel: one of the pixels whose index lies within
   * 1 of the projection's bounds.
   */
  static bool SphereMayTouch(const ConeView& view, const glm::dvec3& q, double radius)
  {
    const glm::dvec3 c = view.Origin + view.ToCamera * q;
    if (!(c.z > 2.0 * radius))
    {
      return true; // the sphere nears the camera plane: no bounded projection
    }
    // For |e| <= radius: |(c.x + e.x)/(c.z + e.z) - c.x/c.z| <=
    // radius (c.z + |c.x|) / (c.z (c.z - radius)), likewise for y.
    const double scale = radius / (c.z * (c.z - radius));
    const double dx = scale * (c.z + std::abs(c.x));
    const double dy = scale * (c.z + std::abs(c.y));
    const double nx = c.x / c.z;
    const double ny = c.y / c.z;
    const glm::dmat3& K = view.Camera.K;
    const double u = K[0][0] * nx + K[1][0] * ny + K[2][0];
    const double w = K[0][1] * nx + K[1][1] * ny + K[2][1];
    const double du = std::abs(K[0][0]) * dx + std::abs(K[1][0]) * dy;
    const double dv = std::abs(K[0][1]) * dx + std::abs(K[1][1]) * dy;
    const glm::ivec4& rect = view.Rect;
    if (!(u + du > rect.x - 1.0 - 1e-6 && u - du < rect.z + 1.0 + 1e-6 &&
          w + dv > rect.y - 1.0 - 1e-6 && w - dv < rect.w + 1.0 + 1e-6))
    {
      return false;
    }
    // The pixels p with u - du - 1 < p < u + du + 1 (and 1e-6 more for
    // rounding), within the rectangle (the conditions above; clamped to it
    // before the conversion to int, which the far side may overflow).
    const auto first = [](double from, int low)
    { return static_cast<int>(std::floor(std::max(from, double(low)))); };
    const auto last = [](double to, int high)
    { return static_cast<int>(std::ceil(std::min(to, double(high)))); };
    return !view.Blocks ||
      view.Blocks->Any(view.View,
        first(u - du - 1.0 - 1e-6, rect.x),
        first(w - dv - 1.0 - 1e-6, rect.y),
        last(u + du + 1.0 + 1e-6, rect.z),
        last(w + dv + 1.0 + 1e-6, rect.w));
  }

  /**
   * Marks the voxels whose bounding sphere (radius `radius`) may project
   * within one pixel of `rect` in `camera` (and of a labelled pixel of
   * `labelled`, view `view`, unless null): blocks of Block^3 voxels are
   * tested first (their own bounding sphere), so that the voxels of the
   * many blocks far from the cone are never tested one by one.
   */
  void MarkCone(const PinholeCamera& camera,
    const glm::ivec4& rect,
    const LabelBlocks* labelled,
    int view,
    double radius,
    std::uint8_t* marks,
    const RingLayout& layout) const
  {
    // World position of a rig-frame point: Center + RefX q.x + RefY q.y + Axis q.z.
    const glm::dmat3 frame(layout.RefX, layout.RefY, layout.Cyl.Axis);
    const ConeView cone{
      camera, camera.R * frame, camera.R * layout.Cyl.Center + camera.t, rect, labelled, view
    };
    const int blocks = Cells / Block;
    for (int b = 0; b < blocks * blocks * blocks; ++b)
    {
      const glm::ivec3 corner =
        Block * glm::ivec3(b % blocks, b / blocks % blocks, b / blocks / blocks);
      const glm::dvec3 centre = this->Low + (glm::dvec3(corner) + 0.5 * Block) * this->CellSize;
      if (!SphereMayTouch(cone, centre, Block * radius))
      {
        continue;
      }
      for (int v = 0; v < Block * Block * Block; ++v)
      {
        const glm::ivec3 cell =
          corner + glm::ivec3(v % Block, v / Block % Block, v / Block / Block);
        std::uint8_t& mark =
          marks[(static_cast<std::size_t>(cell.z) * Cells + cell.y) * Cells + cell.x];
        if (!mark)
        {
          mark =
            SphereMayTouch(cone, this->Low + (glm::dvec3(cell) + 0.5) * this->CellSize, radius);
        }
      }
    }
  }
};

/**
 * The OpenCV pixel bounds (x0, y0, x1, y1) of the labelled (non-zero) pixels
 * of each view of a label stack; x1 < x0 for a view without any; and, into
 * `blocks` (unless null), the blocks that hold one. Reads texel by texel
 * through ViewStack::Pixel, row by row, so that labels served by an image
 * cache (tile by tile) are read in order.
 */
inline std::vector<glm::ivec4> LabelRectangles(const ViewStack<std::uint8_t>& labels,
  int views,
  LabelBlocks* blocks = nullptr)
{
  std::vector<glm::ivec4> rects(views, glm::ivec4(labels.Width, labels.Height, -1, -1));
  if (blocks)
  {
    blocks->Columns = (labels.Width + LabelBlocks::Size - 1) / LabelBlocks::Size;
    blocks->Rows = (labels.Height + LabelBlocks::Size - 1) / LabelBlocks::Size;
    blocks->Labelled.assign(static_cast<std::size_t>(views) * blocks->Rows * blocks->Columns, 0);
  }
  for (int v = 0; v < views; ++v)
  {
    glm::ivec4& rect = rects[v];
    std::uint8_t* labelled = blocks
      ? blocks->Labelled.data() + static_cast<std::size_t>(v) * blocks->Rows * blocks->Columns
      : nullptr;
    for (int y = 0; y < labels.Height; ++y)
    {
      int x0 = 0;
      while (x0 < labels.Width && !*labels.Pixel(v, x0, y))
      {
        ++x0;
      }
      if (x0 == labels.Width)
      {
        continue;
      }
      int x1 = labels.Width - 1;
      while (!*labels.Pixel(v, x1, y))
      {
        --x1;
      }
      rect = glm::ivec4(std::min(rect.x, x0), std::min(rect.y, y), std::max(rect.z, x1), y);
      if (labelled)
      {
        // (The pixels between the row's first and last labelled ones.)
        std::uint8_t* row = labelled + (y / LabelBlocks::Size) * blocks->Columns;
        for (int x = x0; x <= x1; ++x)
        {
          row[x / LabelBlocks::Size] |= *labels.Pixel(v, x, y) != 0;
        }
      }
    }
  }
  return rects;
}

/**
 * The coarse level of a depth stack, for the coarse-then-fine walk of
 * LightFieldSampler::IntersectDepthMap: per view, the nearest depth of each
 * Size x Size tile of its map (infinity for a tile that sees no surface).
 * A stretch of a ray whose camera z stays nearer than the nearest depth of
 * every tile its projection crosses cannot go behind the map there, so the
 * walk skips it without reading its pixels (the idea of a min-depth
 * hierarchy in relief mapping and screen-space ray marching, one level).
 * Built once per depth stack, like DepthRanges().
 */
struct NearestDepthTiles
{
  static constexpr int Size = 8;
  int Width = 0; // of the depth maps
  int Height = 0;
  int Columns = 0;
  int Rows = 0;
  std::vector<float> Depth; // per view, Rows x Columns, top tile row first

  /// The tiles of the `views` views of `depth`, the views run by `loop`.
  void Build(const ViewStack<float>& depth, int views, const RangeLoop& loop = SerialLoop)
  {
    this->Width = depth.Width;
    this->Height = depth.Height;
    this->Columns = (depth.Width + Size - 1) / Size;
    this->Rows = (depth.Height + Size - 1) / Size;
    const std::size_t tiles = static_cast<std::size_t>(this->Columns) * this->Rows;
    this->Depth.assign(tiles * views, std::numeric_limits<float>::infinity());
    loop(static_cast<std::size_t>(views),
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t v = begin; v < end; ++v)
        {
          float* nearest = this->Depth.data() + v * tiles;
          for (int y = 0; y < depth.Height; ++y)
          {
            for (int x = 0; x < depth.Width; ++x)
            {
              // Texel by texel: an out-of-core stack's pointer is one texel's.
              const float z = *depth.Pixel(static_cast<int>(v), x, y);
              float& tile = nearest[(y / Size) * this->Columns + x / Size];
              tile = z > 0.0f ? std::min(tile, z) : tile;
            }
          }
        }
      });
  }

  /**
   * The nearest depth of `view` over the tiles that hold a pixel of the box
   * [low, high] (pixel coordinates, clamped to the image); infinity when
   * the box lies outside the image.
   */
  double Nearest(int view, const glm::dvec2& low, const glm::dvec2& high) const
  {
    if (!(high.x >= 0.0 && high.y >= 0.0 && low.x < this->Width && low.y < this->Height))
    {
      return std::numeric_limits<double>::infinity();
    }
    const int x0 = static_cast<int>(std::max(low.x, 0.0)) / Size;
    const int y0 = static_cast<int>(std::max(low.y, 0.0)) / Size;
    const int x1 = static_cast<int>(std::min(high.x, this->Width - 1.0)) / Size;
    const int y1 = static_cast<int>(std::min(high.y, this->Height - 1.0)) / Size;
    const float* tiles =
      this->Depth.data() + static_cast<std::size_t>(view) * this->Columns * this->Rows;
    if (x1 - x0 <= 1 && y1 - y0 <= 1)
    {
      // Most boxes (a walk of a step or two, and its margin) hold 2 x 2
      // tiles or fewer: their 4 corner tiles, a tile counted twice where
      // the box spans one, without the loops' branches.
      return std::min(std::min(tiles[y0 * this->Columns + x0], tiles[y0 * this->Columns + x1]),
        std::min(tiles[y1 * this->Columns + x0], tiles[y1 * this->Columns + x1]));
    }
    float nearest = std::numeric_limits<float>::infinity();
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        nearest = std::min(nearest, tiles[y * this->Columns + x]);
      }
    }
    return nearest;
  }

  /// The nearest depth of the tile of `view` that holds pixel (x, y).
  float At(int view, int x, int y) const
  {
    return this
      ->Depth[(static_cast<std::size_t>(view) * this->Rows + y / Size) * this->Columns + x / Size];
  }
};

/// Weighted vote of the samples' labels; -1 when there is no sample.
inline int VoteLabel(const RaySamples& samples);

/// A bilinear footprint (BilinearFootprint()): its top-left pixel and the
/// fraction of the position from it.
struct TexelFootprint
{
  int X0, Y0;
  glm::dvec2 Fraction;
};

/// The focal point's bilinear footprints in a ray's views
/// (LightFieldSampler::ProjectViews()).
struct ViewFootprints
{
  TexelFootprint Views[4]; ///< per view, its footprint
  /// Per view, whether it is looked up: positive weight, the point in front
  /// and its footprint inside the view by a pixel at least.
  bool Looked[4];
};

/**
 * Where LightFieldSampler::Gather samples a ray, from its first stage
 * (LightFieldSampler::Aim()): the focal point, the proxy's stretch and the
 * views around the ray's entry into the rig. (No member initialisers, nor
 * in WeightedView: the batches' arrays of 16 aims, RenderWalks() one per
 * tile row, were initialised for each batch, about 0.7 M instructions of
 * the 3-box swim's frame; Views is read up to Count, Enter and Leave with
 * Stretch only.)
 */
struct RayAim
{
  glm::dvec3 Focal; ///< the focal point (FocalPoint()), where the views are sampled
  /// With a proxy, the stretch [Enter, Leave] of the ray its walk may focus
  /// on (LightFieldSampler::SurfaceStretch()); Stretch: there is one (else
  /// Enter and Leave are not set).
  bool Stretch;
  double Enter;
  double Leave;
  double Azimuth; ///< of the ray's entry into the rig cylinder
  double Height;  ///< of the ray's entry along the rig axis
  WeightedView Views[4];
  int Count; ///< views in Views (ChooseViews())
  /// Whether Footprints holds the focal point's footprints in the Views
  /// (LightFieldSampler::ProjectViews(), which AimBatch() runs for the rays
  /// it aims that have no proxy stretch); else Sample() projects. (Set by
  /// Aim() and AimBatch(), like every member Sample() reads.)
  bool Projected;
  ViewFootprints Footprints;
};

/**
 * The light field as the sampler sees it: the rig layout, one camera per
 * view, the radiance pass and (optionally) the label pass.
 */
struct LightFieldSampler
{
  const RingLayout* Layout = nullptr;
  const PinholeCamera* Cameras = nullptr; // indexed by view
  /// The cameras' projection matrices, indexed by view, for the lookup's
  /// projections (AddBilinear); null: Cameras[view].Project (which a rig
  /// with lens distortion needs).
  const ProjectionMatrix* Projections = nullptr;
  ViewStack<std::uint8_t> Radiance; // 3 components
  ViewStack<std::uint8_t> Labels;   // 1 component, may be absent (Present())
  double FocalDistance = 0.0;
  /// The proxy: per-view depth maps (camera z, 0 = no surface), 1 component;
  /// not Present() = the paper's focal plane at FocalDistance.
  ViewStack<float> Depth;
  /// Per view v, the smallest and largest depth of its map at 2 v and
  /// 2 v + 1 (DepthRanges()).
  const double* DepthRange = nullptr;
  /// The coarse level of the walk (NearestDepthTiles of Depth); null: every
  /// step of the walk reads its pixel.
  const NearestDepthTiles* DepthTiles = nullptr;
  /// Bounds of the proxy's surface points (DepthBounds()): rays that miss
  /// them meet no surface. Unbounded by default.
  glm::dvec3 SurfaceLow{ -std::numeric_limits<double>::infinity() };
  glm::dvec3 SurfaceHigh{ std::numeric_limits<double>::infinity() };
  /// Where rays may meet a part (LabelHull); null or empty: no ray is
  /// skipped. Only meaningful with labels (Gather).
  const LabelHull* Hull = nullptr;
  /// Per view, its camera's Center() (FindProxyCandidates computes each
  /// candidate's angle from it, for every ray); null: computed per ray.
  const glm::dvec3* CameraCenters = nullptr;
  /// Views blended on the proxy surface (k of GatherOnSurface, 1..4).
  int ProxyViews = 3;
  /// Relative depth by which a camera's own depth map may be nearer than a
  /// surface point before the camera counts as not seeing it.
  double OcclusionTolerance = 0.02;

  /// The most rays AimBatch() aims at once, as one batch.
  static constexpr int MaximumBatch = 16;

  /// Steps of the walk along a ray's projection into a depth map.
  static constexpr int MaximumDepthSteps = 256;
  /// Steps of the walk tested at once against DepthTiles.
  static constexpr int CoarseDepthSteps = 8;

  /**
   * Sec. 6.2: gathers the weighted samples of the ray `o + s d` (d need not
   * be unit). Pixels projecting outside a view contribute nothing.
   * Returns false when the ray misses the rig cylinder.
   *
   * With a proxy (Depth.Present()) the ray is focused on the surface it meets
   * first (s >= 0) and blended from the nearest views by angle
   * (GatherOnSurface); a ray that meets no surface, or whose focused samples
   * see background, falls back to the focal plane, as without a proxy.
   *
   * A ray that the Hull proves to have no labelled sample returns false at
   * once: with labels it is background either way (a Hull is only given
   * with labels: without them, or for an unlabelled light field, label 0
   * is no background and nothing is skipped).
   *
   * With a proxy the skip stays exact, though the views are chosen per
   * crossing rather than per sector: the ray's samples are either (a) those
   * of GatherOnSurface, bilinear lookups at a point X = o + s d with s in
   * the stretch [enter, leave] (SurfaceStretch(); IntersectDepthMap only
   * walks, and interpolates its crossing, within it), in cameras among
   * FindProxyCandidates (the 4 views around the azimuth in each of the rows
   * searched), or (b) the plane fallback's, at the focal point x in the
   * views of ChooseViews. The Hull marks a voxel of a sector's grid when the
   * label cone of any view that may be chosen for an azimuth in the sector,
   * in any row, comes within a bilinear footprint of it (a conservative
   * bound of the voxel's bounding sphere); a sector's Wide marks add its
   * neighbours', which holds every FindProxyCandidates view however the
   * sector's bounds round. So a labelled sample at X needs X in a voxel
   * marked in Wide (MaySeePart() walks every voxel the stretch crosses,
   * with a margin for rounding), and one at x needs x's voxel marked
   * (MayMeetPart(), as without a proxy); the walk's result is kept only
   * when its samples vote for a part (a labelled sample), else the ray falls
   * back to (b). Points outside the grid are never skipped. Labels read out
   * of core give the same rectangles (LabelRectangles reads them texel by
   * texel), and a rig with lens distortion gets no Hull.
   */
  bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const
  {
    RayAim aim;
    if (!this->Aim(o, d, aim))
    {
      out.Clear();
      return false;
    }
    return this->Sample(o, d, aim, out);
  }

  /**
   * The first stage of Gather(): the ray's geometry up to its views (focal
   * point, the Hull's tests, cylinder entry, azimuth and height, the views
   * around them), no texel read. False when the ray has no sample for sure
   * (Gather's false before any lookup). A batch of rays runs this stage for
   * every ray before Sample() for any (see RenderPlainViews): each ray's
   * stage is a long dependent chain of divisions and square roots, and the
   * chains of neighbouring rays then overlap in the processor.
   */
  bool Aim(const glm::dvec3& origin,
    const glm::dvec3& direction,
    RayAim& __restrict aim,
    std::uint32_t sectors = ~std::uint32_t(0)) const
  {
    // The ray in locals and `aim` declared unaliased: otherwise each store
    // into `aim` (its doubles might be the ray's, or the layout's) has the
    // compiler load them again and redo the products that FocalPoint() and
    // Entry() share (o - Center, d . Axis, ...): -23 instructions a ray.
    const glm::dvec3 o = origin;
    const glm::dvec3 d = direction;
    aim.Focal = FocalPoint(this->Layout->Cyl, o, d, this->FocalDistance);
    const bool hull = this->Hull && !this->Hull->Marks.empty();
    const int cell = hull ? this->Hull->Cell(aim.Focal, *this->Layout) : -1;
    // With a proxy, the stretch [enter, leave] of the ray that its walk may
    // focus on; the ray is skipped when neither it nor the focal point can
    // have a labelled sample (see Gather()).
    aim.Stretch = this->Depth.Present() && this->SurfaceStretch(o, d, aim.Enter, aim.Leave);
    // Most skipped rays are unmarked in every sector, or in every sector
    // they may enter the rig in (`sectors`): they skip the cylinder entry
    // and the atan2 of the azimuth too (MayMeetPart() would be false for
    // them; a ray that misses the cylinder returns false as well).
    if (this->SkippedBeforeEntry(cell, sectors, aim.Stretch))
    {
      return false;
    }
    double s;
    if (!this->Entry(o, d, s, aim.Azimuth, aim.Height))
    {
      return false;
    }
    if (hull && this->SkippedAtEntry(o, d, aim.Azimuth, cell, aim))
    {
      return false;
    }
    aim.Count = ChooseViews(*this->Layout, aim.Azimuth, aim.Height, aim.Views);
    aim.Projected = false;
    return true;
  }

  /**
   * Aim() for the rays o + s d[i], i < count, into aims[i] (aimed[i]: its
   * result), with the hull's sectors bounded for all of them at once
   * (EntrySectors()): the same results as ray by ray, the rays whose focal
   * voxel no sector of the bound marks skipped before their cylinder entry.
   * The d[i] are the directions through pixels of one image row, in order.
   * On an x86 processor with AVX2, AimBatchAvx2() (4 doubles a vector where
   * SSE2, the x86-64 baseline, has 2).
   */
  void AimBatch(const glm::dvec3& o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    this->AimBatch<0>(&o, d, count, aims, aimed);
  }

  /**
   * Aim() for the rays o[i] + s d[i], i < count, each from its own origin
   * (the warped rays of several view rays: RenderWalks), into aims[i]: the
   * same results as ray by ray, as AimBatch() over one origin, but every
   * sector tried (no bound: the rays share no origin).
   */
  void AimBatch(const glm::dvec3* o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    this->AimBatch<1>(o, d, count, aims, aimed);
  }

  /// AimBatch() from origin o[OriginStep * i] (0: one origin for all rays, 1: one each).
  template<int OriginStep>
  void AimBatch(const glm::dvec3* o, const glm::dvec3* d, int count, RayAim* aims, bool* aimed)
    const
  {
#if LFD_AIM_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2)
    {
      this->AimBatchAvx2<OriginStep>(o, d, count, aims, aimed);
      return;
    }
#endif
    this->AimStages<OriginStep>(o, d, count, aims, aimed);
  }

#if LFD_AIM_AVX2
  /**
   * AimBatch() compiled for AVX2 (the processor must have it): the same
   * results as with SSE2 (no instruction of AVX2 rounds differently, and it
   * has no fused multiply-add to contract the stages' products into).
   */
  template<int OriginStep>
  __attribute__((target("avx2"))) void AimBatchAvx2(const glm::dvec3* o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    this->AimStages<OriginStep>(o, d, count, aims, aimed);
  }
#endif

  /// AimBatch()'s body, inlined into each of its instruction sets' versions.
  template<int OriginStep>
  __attribute__((always_inline)) inline void AimStages(const glm::dvec3* o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    const std::uint32_t sectors =
      OriginStep == 0 ? this->EntrySectors(*o, d, count) : ~std::uint32_t(0);
    if (count > MaximumBatch)
    {
      for (int i = 0; i < count; ++i)
      {
        aimed[i] = this->Aim(o[OriginStep * i], d[i], aims[i], sectors);
      }
      return;
    }
    // Aim()'s stages, each over the batch as one loop over arrays of
    // coordinates, which the compiler vectorises (the stage functions are
    // branch-free), and between them the table look-ups, ray by ray.
    const bool hull = this->Hull && !this->Hull->Marks.empty();
    double x[MaximumBatch], y[MaximumBatch], z[MaximumBatch];    // the focal points
    double qx[MaximumBatch], qy[MaximumBatch], qz[MaximumBatch]; // LabelHull::GridPosition()
    int cells[MaximumBatch];
    for (int i = 0; i < count; ++i)
    {
      const glm::dvec3 focal =
        FocalPoint(this->Layout->Cyl, o[OriginStep * i], d[i], this->FocalDistance);
      x[i] = focal.x;
      y[i] = focal.y;
      z[i] = focal.z;
    }
    if (hull)
    {
      for (int i = 0; i < count; ++i)
      {
        const glm::dvec3 q = this->Hull->GridPosition(glm::dvec3(x[i], y[i], z[i]), *this->Layout);
        qx[i] = q.x;
        qy[i] = q.y;
        qz[i] = q.z;
      }
    }
    // With a proxy, each ray's stretch that its walk may focus on, ray by
    // ray: a ray with one escapes the skips below as in Aim().
    const bool proxy = this->Depth.Present();
    for (int i = 0; i < count; ++i)
    {
      aims[i].Stretch =
        proxy && this->SurfaceStretch(o[OriginStep * i], d[i], aims[i].Enter, aims[i].Leave);
    }
    // The rays the hull does not skip before their entry (as Aim()), their
    // directions gathered.
    // (With one origin each, the origins too.)
    double ox[MaximumBatch], oy[MaximumBatch], oz[MaximumBatch];
    double dx[MaximumBatch], dy[MaximumBatch], dz[MaximumBatch];
    int kept[MaximumBatch];
    int n = 0;
    for (int i = 0; i < count; ++i)
    {
      aimed[i] = false;
      cells[i] = hull ? LabelHull::CellAt(glm::dvec3(qx[i], qy[i], qz[i])) : -1;
      aims[i].Focal = glm::dvec3(x[i], y[i], z[i]);
      if (!this->SkippedBeforeEntry(cells[i], sectors, aims[i].Stretch))
      {
        if constexpr (OriginStep != 0)
        {
          ox[n] = o[i].x;
          oy[n] = o[i].y;
          oz[n] = o[i].z;
        }
        dx[n] = d[i].x;
        dy[n] = d[i].y;
        dz[n] = d[i].z;
        kept[n++] = i;
      }
    }
    // The entries; a ray that misses the cylinder gets azimuth -1.
    double azimuths[MaximumBatch], heights[MaximumBatch];
    for (int k = 0; k < n; ++k)
    {
      double s, azimuth;
      const bool hit = this->Entry(OriginStep == 0 ? *o : glm::dvec3(ox[k], oy[k], oz[k]),
        glm::dvec3(dx[k], dy[k], dz[k]),
        s,
        azimuth,
        heights[k]);
      azimuths[k] = hit ? azimuth : -1.0;
    }
    for (int k = 0; k < n; ++k)
    {
      const int i = kept[k];
      if (azimuths[k] >= 0.0 &&
        !(hull && this->SkippedAtEntry(o[OriginStep * i], d[i], azimuths[k], cells[i], aims[i])))
      {
        aims[i].Azimuth = azimuths[k];
        aims[i].Height = heights[k];
        aims[i].Count = ChooseViews(*this->Layout, azimuths[k], heights[k], aims[i].Views);
        aims[i].Projected = false;
        aimed[i] = true;
      }
    }
    // Sample()'s projections of the focal points, for the rays it will look
    // up in the Views (those with a stretch walk the proxy first).
    if (this->Projections)
    {
      for (int k = 0; k < n; ++k)
      {
        const int i = kept[k];
        if (aimed[i] && !aims[i].Stretch)
        {
          this->ProjectViews(aims[i], aims[i].Footprints);
          aims[i].Projected = true;
        }
      }
    }
  }

  /**
   * Aim()'s first skip: a ray whose focal point lies in hull voxel `cell`
   * (-1: outside the grid, or no hull) unmarked in every sector of
   * `sectors` (EntrySectors()) has no labelled sample, unless it has a
   * proxy stretch (`stretch`) to walk.
   */
  bool SkippedBeforeEntry(int cell, std::uint32_t sectors, bool stretch) const
  {
    return cell >= 0 && !this->Hull->Union.empty() && !(this->Hull->Union[cell] & sectors) &&
      !stretch;
  }

  /**
   * Aim()'s second skip, once the ray o + s d is known to enter the rig at
   * `azimuth` (needs a Hull with marks): its focal voxel `cell` is unmarked
   * in the azimuth's sector and its stretch, if `aim` has one, can see no
   * part.
   */
  bool SkippedAtEntry(const glm::dvec3& o,
    const glm::dvec3& d,
    double azimuth,
    int cell,
    const RayAim& aim) const
  {
    return !this->Hull->MayMeetPart(azimuth, cell) &&
      !(aim.Stretch &&
        this->Hull->MaySeePart(azimuth, o + aim.Enter * d, o + aim.Leave * d, *this->Layout));
  }

  /**
   * The parameter `s` (IntersectCylinderEntry()), azimuth and height
   * (RingLayout::Locate()) of where the line o + s d enters the rig
   * cylinder; false when it misses (azimuth and height meaningless then).
   */
  bool Entry(const glm::dvec3& o,
    const glm::dvec3& d,
    double& s,
    double& azimuth,
    double& height) const
  {
    // Branch-free (AimBatch vectorises it): located also when it misses.
    const bool hit = IntersectCylinderEntry(this->Layout->Cyl, o, d, s);
    this->Layout->Locate(o + s * d, azimuth, height);
    return hit;
  }

  /**
   * The hull sectors (LabelHull::Union's bits) that the entry azimuths
   * (Entry()) of the lines o + s d[i], i < count, lie in, when every d[i]
   * lies on the segment from d[0] to d[count - 1] (directions through the
   * pixels of one image row, in order: affine in the column); every sector
   * when the bound does not hold or does not pay (no hull, few rays).
   *
   * Why it holds: the parts of the d[i] across the axis lie on a segment,
   * so when its ends make an angle below pi / 2 the lines' directions
   * sweep that angle once, monotonically. Where every line of the sweep
   * meets the cylinder, its entry moves continuously with the direction,
   * and one-to-one (two lines through o share no other point, and o is not
   * on the cylinder: its entries lie on one side of it), so the entries
   * fill one of the two arcs between the ends' entries: the one that holds
   * the middle line's. Every line meets the cylinder when both ends enter
   * on the same side of o: from inside, every line does; from outside, the
   * lines that enter ahead of o (or behind it) form a convex cone, which
   * holds the sweep between two of them. Rounding (of the directions; of
   * an entry, some 1e-8 radian next to tangency, where the square root of
   * the discriminant amplifies it; of Azimuth(), 2e-10) stays far below
   * the margin of 1e-6 radian the arc is widened by on each side; a middle
   * entry within the margin of an end gives no bound.
   */
  std::uint32_t EntrySectors(const glm::dvec3& o, const glm::dvec3* d, int count) const
  {
    constexpr std::uint32_t all = ~std::uint32_t(0);
    constexpr double margin = 1e-6;
    // Three entries bound the batch: with fewer rays they would not pay.
    if (count < 4 || !this->Hull || this->Hull->Union.empty())
    {
      return all;
    }
    const glm::dvec3& a = this->Layout->Cyl.Axis;
    const glm::dvec3 first = d[0] - glm::dot(d[0], a) * a;
    const glm::dvec3 last = d[count - 1] - glm::dot(d[count - 1], a) * a;
    double s[3], azimuth[3], height;
    if (!(glm::dot(first, last) > 0.0) || !this->Entry(o, d[0], s[0], azimuth[0], height) ||
      !this->Entry(o, d[count - 1], s[1], azimuth[1], height) ||
      !((s[0] > 0.0 && s[1] > 0.0) || (s[0] < 0.0 && s[1] < 0.0)) ||
      !this->Entry(o, d[count / 2], s[2], azimuth[2], height))
    {
      return all;
    }
    // Counter-clockwise from the first end: the span to the last, the middle.
    const auto ccw = [](double from, double to)
    { return to >= from ? to - from : to - from + TwoPi; };
    const double span = ccw(azimuth[0], azimuth[1]);
    const double middle = ccw(azimuth[0], azimuth[2]);
    if (middle > margin && middle < span - margin)
    {
      return LabelHull::SectorsOnArc(azimuth[0] - margin, span + 2.0 * margin);
    }
    if (middle > span + margin && middle < TwoPi - margin)
    {
      return LabelHull::SectorsOnArc(azimuth[1] - margin, TwoPi - span + 2.0 * margin);
    }
    return all;
  }

  /**
   * The second stage of Gather(): the samples of the ray `o + s d` that
   * Aim() aimed (true), into `out`; Gather()'s result.
   */
  bool Sample(const glm::dvec3& o, const glm::dvec3& d, const RayAim& aim, RaySamples& out) const
  {
    out.Clear();
    if (aim.Stretch &&
      this->GatherOnSurface(
        o, d, aim.Enter, aim.Leave, aim.Azimuth, aim.Height, aim.Views, aim.Count, out))
    {
      return true;
    }
    if (this->Projections)
    {
      // (Projected by AimBatch() ahead of the texels, or here.)
      ViewFootprints projected;
      if (!aim.Projected)
      {
        this->ProjectViews(aim, projected);
      }
      const ViewFootprints& footprints = aim.Projected ? aim.Footprints : projected;
      for (int i = 0; i < aim.Count; ++i)
      {
        if (footprints.Looked[i])
        {
          this->AddFootprintAt(aim.Views[i].View, aim.Views[i].Weight, footprints.Views[i], out);
        }
      }
      return out.Count > 0;
    }
    for (int i = 0; i < aim.Count; ++i)
    {
      if (aim.Views[i].Weight > 0.0)
      {
        this->AddBilinear(aim.Views[i].View, aim.Views[i].Weight, aim.Focal, out);
      }
    }
    return out.Count > 0;
  }

  /**
   * The first step of Sample()'s lookups at the focal point (AddBilinear()
   * in each view of positive weight) through the views' projection matrices
   * (Projections): the focal point's bilinear footprint in each of `aim`'s
   * Views, into `footprints`. The camera z of two views is one
   * vector and their reciprocals one division (SSE2, each lane the scalar
   * operations of ProjectionMatrix::Project()). AimBatch() runs it for a
   * batch of rays before any is sampled: a view's lookup is a chain of some
   * 150 dependent instructions from the division to the sample, so taken
   * ray by ray the lookups hardly overlap, while the projections of
   * neighbouring rays do; the samples then start from their texels.
   */
  void ProjectViews(const RayAim& aim, ViewFootprints& footprints) const
  {
    const int count = aim.Count;
    const glm::dvec3 x = aim.Focal;
    alignas(16) double z[4];
    alignas(16) double inverse[4];
#if defined(__SSE2__)
    // The pairs built in registers (stored one by one and loaded as a pair,
    // the z would wait for a failed store forwarding). A pair without its
    // second view repeats the first.
    const __m128d one = _mm_set1_pd(1.0);
    for (int i = 0; i < count; i += 2)
    {
      const __m128d pair = ProjectionMatrix::CameraZPair(this->Projections[aim.Views[i].View],
        this->Projections[aim.Views[i + 1 < count ? i + 1 : i].View],
        x);
      _mm_store_pd(z + i, pair);
      _mm_store_pd(inverse + i, _mm_div_pd(one, pair));
    }
#else
    for (int i = 0; i < count; ++i)
    {
      z[i] = this->Projections[aim.Views[i].View].CameraZ(x);
      inverse[i] = 1.0 / z[i];
    }
#endif
    for (int i = 0; i < count; ++i)
    {
      // (Project()'s test: a point not in front of the view has no sample.)
      footprints.Looked[i] = aim.Views[i].Weight > 0.0 && z[i] > 0.0 &&
        BilinearFootprint(this->Projections[aim.Views[i].View].PixelAt(x, inverse[i]),
          this->Radiance.Width,
          this->Radiance.Height,
          footprints.Views[i].X0,
          footprints.Views[i].Y0,
          footprints.Views[i].Fraction);
    }
  }

  /**
   * Projects the world point `x` into `view` (PinholeCamera::Project): with
   * the view's 3x4 matrix when the sampler has them (Projections), one
   * division instead of two, else with its camera. False when `x` is not in
   * front of the view.
   */
  bool Project(int view, const glm::dvec3& x, glm::dvec2& uv) const
  {
    double z;
    return this->Project(view, x, uv, z);
  }

  /// Project() that also gives the camera z of `x` (the projection's
  /// homogeneous w, set even when false).
  bool Project(int view, const glm::dvec3& x, glm::dvec2& uv, double& z) const
  {
    return this->Projections ? this->Projections[view].Project(x, uv, z)
                             : this->Cameras[view].Project(x, uv, z);
  }

  /**
   * Appends the bilinear samples of `view` around the projection of `x`,
   * weighted `weight` x the bilinear weight; nothing when `x` projects
   * outside the view. The 4 texels of a footprint inside the view that
   * carry one label (most do) are one sample: their bilinear interpolation,
   * weighing `weight` (the bilinear weights sum to 1), as the two-plane sampler
   * merges its samples per label. A label's vote, blend and coverage are
   * those of the 4 samples up to rounding, and a ray has about 4 samples
   * instead of 16 to store, vote on and blend. The other footprints give a
   * sample per texel inside the view.
   */
  void AddBilinear(int view, double weight, const glm::dvec3& x, RaySamples& out) const
  {
    glm::dvec2 uv;
    if (this->Project(view, x, uv))
    {
      this->AddBilinearAt(view, weight, uv, out);
    }
  }

  /// AddBilinear() at `uv`, the projection of its point into `view`
  /// (Project()), for a caller that has projected it already.
  __attribute__((always_inline)) void AddBilinearAt(int view,
    double weight,
    const glm::dvec2& uv,
    RaySamples& out) const
  {
    TexelFootprint footprint;
    if (BilinearFootprint(uv,
          this->Radiance.Width,
          this->Radiance.Height,
          footprint.X0,
          footprint.Y0,
          footprint.Fraction))
    {
      this->AddFootprintAt(view, weight, footprint, out);
    }
  }

  /// AddBilinearAt() from the footprint of its point in `view`, for a
  /// caller that has found it already (ProjectViews()).
  __attribute__((always_inline)) void AddFootprintAt(int view,
    double weight,
    const TexelFootprint& footprint,
    RaySamples& out) const
  {
    const int width = this->Radiance.Width;
    const int x0 = footprint.X0;
    const int y0 = footprint.Y0;
    const glm::dvec2& a = footprint.Fraction;
    // Most footprints lie inside the view, in memory, with one label: their
    // sample is taken here, and the others in AddFootprint(), out of line,
    // so that this path saves no registers and stores no label.
    if (x0 >= 0 && y0 >= 0 && x0 + 1 < width && y0 + 1 < this->Radiance.Height &&
      this->Radiance.Data && (this->Labels.Data || !this->Labels.Present()))
    {
      // Rows in VTK order: y0 + 1 is the row before y0's.
      const std::size_t first = this->Radiance.Index(view, x0, y0);
      const std::size_t below = first - width;
      const std::uint8_t* labels = this->Labels.Data;
      const int label = labels ? labels[first] : 0;
      if (!labels ||
        (labels[first + 1] == label && labels[below] == label && labels[below + 1] == label))
      {
        AddBlended(
          this->Radiance.Data + 3 * first, this->Radiance.Data + 3 * below, a, weight, label, out);
        return;
      }
    }
    this->AddFootprint(view, weight, x0, y0, a, out);
  }

  /**
   * AddFootprintAt()'s samples of the footprint at (x0, y0) with the
   * fraction `a` (BilinearFootprint()) that its inline path does not take:
   * footprints across the view's edge (a sample per texel inside it),
   * with several labels (a sample per texel) or read out of core.
   */
  __attribute__((noinline)) void AddFootprint(int view,
    double weight,
    int x0,
    int y0,
    const glm::dvec2& a,
    RaySamples& out) const
  {
    const int width = this->Radiance.Width;
    const int height = this->Radiance.Height;
    if (x0 >= 0 && y0 >= 0 && x0 + 1 < width && y0 + 1 < height)
    {
      std::uint8_t copies[2][6];
      const std::uint8_t* rows[2];
      int labels[4];
      this->Footprint(view, x0, y0, copies, rows, labels);
      if (labels[0] == labels[1] && labels[0] == labels[2] && labels[0] == labels[3])
      {
        AddBlended(rows[0], rows[1], a, weight, labels[0], out);
        return;
      }
      double weights[4];
      BilinearWeights(a, weights);
      for (int corner = 0; corner < 4; ++corner)
      {
        if (weights[corner] > 0.0)
        {
          const std::uint8_t* rgb = rows[corner >> 1] + 3 * (corner & 1);
          out.Samples[out.Count++] = {
            glm::dvec3(rgb[0], rgb[1], rgb[2]), weight * weights[corner], labels[corner]
          };
        }
      }
      return;
    }
    ForEachFootprintPixel(x0,
      y0,
      a,
      width,
      height,
      [&](int px, int py, double bw)
      {
        RaySample& sample = out.Samples[out.Count++];
        const std::uint8_t* rgb = this->Radiance.Pixel(view, px, py);
        sample.Color = glm::dvec3(rgb[0], rgb[1], rgb[2]);
        sample.Weight = weight * bw;
        sample.Label = this->Labels.Present() ? *this->Labels.Pixel(view, px, py) : 0;
      });
  }

  /**
   * Appends the one sample of a footprint whose 4 texels carry `label`:
   * their bilinear blend at the fraction `a` (BlendTexels(), texels at
   * top[0..5] and bottom[0..5]), weighing `weight`. Always inlined, as
   * BlendTexels().
   */
  __attribute__((always_inline)) static void AddBlended(const std::uint8_t* top,
    const std::uint8_t* bottom,
    const glm::dvec2& a,
    double weight,
    int label,
    RaySamples& out)
  {
    RaySample& sample = out.Samples[out.Count++];
    BlendTexels(top, bottom, a.x, a.y, &sample.Color.x);
    sample.Weight = weight;
    sample.Label = label;
  }

  /**
   * The texels (x0, y0), (x0 + 1, y0), (x0, y0 + 1) and (x0 + 1, y0 + 1) of
   * `view`, all inside it, as BlendTexels() reads them: rows[0] points at
   * the RGB of the first two, rows[1] at those of the last two, 6 bytes
   * each; their labels (0 without a Label pass) in `labels`. In memory the
   * rows point into the pass (a row's two texels are neighbours there); out
   * of core the texels are copied into `copies`: the same values either way.
   */
  void Footprint(int view,
    int x0,
    int y0,
    std::uint8_t copies[2][6],
    const std::uint8_t* rows[2],
    int labels[4]) const
  {
    if (this->Radiance.Data && (this->Labels.Data || !this->Labels.Present()))
    {
      // In memory: the 4 texels from the first one's index (rows in VTK
      // order: y0 + 1 is the row before y0's), without Pixel()'s test of
      // Source per texel.
      const std::size_t first = this->Radiance.Index(view, x0, y0);
      const std::size_t below = first - this->Radiance.Width;
      rows[0] = this->Radiance.Data + 3 * first;
      rows[1] = this->Radiance.Data + 3 * below;
      const std::uint8_t* label = this->Labels.Data;
      labels[0] = label ? label[first] : 0;
      labels[1] = label ? label[first + 1] : 0;
      labels[2] = label ? label[below] : 0;
      labels[3] = label ? label[below + 1] : 0;
      return;
    }
    for (int corner = 0; corner < 4; ++corner)
    {
      const int px = x0 + (corner & 1);
      const int py = y0 + (corner >> 1);
      std::memcpy(copies[corner >> 1] + 3 * (corner & 1), this->Radiance.Pixel(view, px, py), 3);
      labels[corner] = this->Labels.Present() ? *this->Labels.Pixel(view, px, py) : 0;
    }
    rows[0] = copies[0];
    rows[1] = copies[1];
  }

  /**
   * The proxy's depth (camera z, 0: no surface) of `view` at the pixel
   * nearest to `uv`; 0 outside the view.
   */
  double DepthAt(int view, const glm::dvec2& uv) const
  {
    int x, y;
    return this->DepthPixel(uv, x, y) ? *this->Depth.Pixel(view, x, y) : 0.0;
  }

  /**
   * The depth maps' pixel (x, y) nearest to `uv`, std::lround's (halves away
   * from zero) without its library call, which the walk would pay at every
   * step; false outside the maps.
   */
  bool DepthPixel(const glm::dvec2& uv, int& x, int& y) const
  {
    // A coordinate rounds (halves away from zero) into [0, n) exactly when
    // it lies in (-0.5, n - 0.5): one test instead of one before and one
    // after the rounding. It also keeps NaN and far points from the
    // conversions below.
    if (!(uv.x > -0.5 && uv.y > -0.5 && uv.x < this->Depth.Width - 0.5 &&
          uv.y < this->Depth.Height - 0.5))
    {
      return false;
    }
    x = RoundHalfAway(uv.x);
    y = RoundHalfAway(uv.y);
    return true;
  }

  /**
   * Where the ray o + s d (start <= s <= end) first goes behind the depth map of `view`
   * (Gortler et al. 1996's depth correction, Lumigraph Sec. 3.6): the ray is
   * walked over the stretch whose camera z lies in the view's depth range,
   * one step per pixel of its projection (at most MaximumDepthSteps), and
   * the crossing is interpolated between the last step in front of the
   * surface and the first behind it. Where the view does not see the ray's
   * surface (another part hides it), the crossing comes earlier than the
   * surface, never later: the latest crossing of several views is the best
   * estimate. False when the ray stays in front of the map.
   *
   * Coarse then fine: with DepthTiles, each run of CoarseDepthSteps steps
   * whose camera z stays nearer than the tiles around its projection is
   * skipped unread; the others are walked step by step. The steps, and so
   * the crossing, are those of the plain walk, bit for bit.
   */
  bool IntersectDepthMap(int view,
    const glm::dvec3& o,
    const glm::dvec3& d,
    double start,
    double end,
    double& hit) const
  {
    const PinholeCamera& camera = this->Cameras[view];
    // 1% of margin around the range keeps the first and last surface pixels.
    const double zLow = 0.99 * this->DepthRange[2 * view];
    const double zHigh = 1.01 * this->DepthRange[2 * view + 1];
    if (!(zHigh > 0.0))
    {
      return false;
    }
    const glm::dvec3 forward = camera.Forward();
    const double co = glm::dot(forward, o) + camera.t.z; // camera z along the ray
    const double cd = glm::dot(forward, d);
    if (!(cd * cd > 1e-24 * glm::dot(d, d)))
    {
      return false; // parallel to the image plane: no bounded stretch
    }
    double s0 = (zLow - co) / cd;
    double s1 = (zHigh - co) / cd;
    if (s0 > s1)
    {
      std::swap(s0, s1);
    }
    s0 = std::max(s0, start);
    s1 = std::min(s1, end);
    glm::dvec2 uv0, uv1;
    if (!(s0 < s1) || !this->Project(view, o + s0 * d, uv0) ||
      !this->Project(view, o + s1 * d, uv1))
    {
      return false;
    }
    // One step per pixel of the projection's length, at least one: a walk
    // of a pixel or less (most are) needs no square root, as sqrt(q) <= 1
    // exactly when q <= 1.
    const glm::dvec2 span = uv1 - uv0;
    const double squared = glm::dot(span, span);
    const int steps = squared <= 1.0
      ? 1
      : static_cast<int>(std::clamp(std::ceil(std::sqrt(squared)), 1.0, double(MaximumDepthSteps)));
    double previousS = s0;
    double previousGap = std::numeric_limits<double>::quiet_NaN(); // NaN: no surface there
    // Steps first to last of the current run; previousGap is step first's
    // when `walked` (the run before was walked), else that step is unread.
    int first = 0;
    bool walked = false;
    glm::dvec2 uvFirst = uv0;
    bool firstProjected = true; // uvFirst is step first's projection
    while (first < steps)
    {
      const int last = std::min(first + CoarseDepthSteps, steps);
      // (s1 - s0) * 1 / 1 is s1 - s0 exactly: a walk of one step (most
      // are) skips the division.
      const double sLast = s0 + (steps == 1 ? s1 - s0 : (s1 - s0) * last / steps);
      glm::dvec2 uvLast;
      // The walk's end is projected already (most walks are one run).
      const bool lastProjected = this->DepthTiles &&
        (sLast == s1 ? (uvLast = uv1, true) : this->Project(view, o + sLast * d, uvLast));
      // A projection bends (lens distortion) far less than the margin of
      // one pixel over a run, and each step reads its nearest pixel.
      if (firstProjected && lastProjected &&
        this->DepthTiles->Nearest(view,
          glm::min(uvFirst, uvLast) - 1.0,
          glm::max(uvFirst, uvLast) + 1.0) > std::max(co + previousS * cd, co + sLast * cd))
      {
        walked = false;
      }
      else
      {
        for (int i = walked ? first + 1 : first; i <= last; ++i)
        {
          // The run's ends are stepped and projected already (the same s,
          // so the same pixel): most walks are a step or two long (the
          // views nearest in angle see the ray nearly end on). Step first's
          // s is previousS (s0 + 0 at step 0).
          const double s =
            i == first ? previousS : (i == last ? sLast : s0 + (s1 - s0) * i / steps);
          glm::dvec2 uv = i == last ? uvLast : uvFirst;
          const bool projected = (i == last && lastProjected) || (i == first && firstProjected);
          const double surface =
            projected || this->Project(view, o + s * d, uv) ? this->DepthAt(view, uv) : 0.0;
          const double gap =
            surface > 0.0 ? co + s * cd - surface : std::numeric_limits<double>::quiet_NaN();
          if (gap >= 0.0)
          {
            hit = previousGap < 0.0
              ? previousS + (s - previousS) * previousGap / (previousGap - gap)
              : s;
            return true;
          }
          previousS = s;
          previousGap = gap;
        }
        walked = true;
      }
      first = last;
      uvFirst = uvLast;
      firstProjected = lastProjected;
      previousS = sLast;
    }
    return false;
  }

  /**
   * Beyond the paper: the samples of the ray o + s d focused on the proxy
   * surface (Buehler et al. 2001, Unstructured Lumigraph Rendering). The
   * surface point X is the latest crossing of the ray with the depth maps of
   * its two heaviest ring neighbours (IntersectDepthMap). The candidate
   * cameras are the 4 views around the ray's azimuth in the rows around its
   * height (one row more above and below); of those that see X (their depth
   * at X's projection is not nearer than X's by more than
   * OcclusionTolerance), the ProxyViews nearest in angle to the ray at X
   * are blended with ULR's weights (1 - p / p_k+1) / p, p the angular
   * penalty (chord between the unit directions to the eye and to the
   * camera), p_k+1 that of the next candidate. False (out.Count 0) when the
   * ray meets no surface, and where the focused samples vote for background
   * (near a silhouette, where one depth per pixel is least certain): such
   * rays are looked up through the plane, as without a proxy (fish at rest:
   * IoU 0.985 -> 0.992, 28.86 -> 30.29 dB).
   */
  bool GatherOnSurface(const glm::dvec3& o,
    const glm::dvec3& d,
    double enter,
    double leave,
    double azimuth,
    double height,
    const WeightedView* neighbours,
    int count,
    RaySamples& out) const
  {
    // The two heaviest ring neighbours.
    int first = -1, second = -1;
    for (int i = 0; i < count; ++i)
    {
      if (first < 0 || neighbours[i].Weight > neighbours[first].Weight)
      {
        second = first;
        first = i;
      }
      else if (second < 0 || neighbours[i].Weight > neighbours[second].Weight)
      {
        second = i;
      }
    }
    // The latest crossing is the estimate, so the second walk starts where
    // the first one crossed: nothing before it can matter.
    double surface = -1.0;
    for (int i : { first, second })
    {
      double hit;
      if (i >= 0 &&
        this->IntersectDepthMap(neighbours[i].View, o, d, std::max(surface, enter), leave, hit))
      {
        surface = hit;
      }
    }
    if (!(surface >= 0.0))
    {
      return false;
    }
    const glm::dvec3 x = o + surface * d;
    const glm::dvec3 toEye = -glm::normalize(d);
    ProxyCandidates candidates;
    this->FindProxyCandidates(azimuth, height, x, toEye, candidates);
    // The visible candidates, nearest first (ties in the order of
    // FindProxyCandidates), up to one more than blended. Each is the nearest
    // of those not examined yet, picked when it is needed: a ray examines
    // about 4 of its 12 candidates, so neither sorting them all nor the
    // penalties of the others pay. A chosen one keeps its projection for
    // AddBilinearAt().
    const int k = std::clamp(this->ProxyViews, 1, 4);
    struct Chosen
    {
      double Penalty;
      int View;
      glm::dvec2 Pixel;
    };
    Chosen chosen[5];
    int visible = 0;
    while (visible <= k)
    {
      const int nearest = FirstLargest<ProxyCandidates::Maximum>(candidates.Nearness);
      if (nearest < 0)
      {
        break;
      }
      candidates.Nearness[nearest] = -std::numeric_limits<double>::infinity(); // examined
      const int view = candidates.View[nearest];
      glm::dvec2 uv;
      double z; // X's camera z, for the visibility test
      if (!this->Project(view, x, uv, z))
      {
        continue;
      }
      int px, py;
      if (this->DepthPixel(uv, px, py))
      {
        // The nearest depth of the pixel's tile bounds the pixel's from
        // below: a point no deeper than it (with the tolerance) is seen, and
        // the small tiles spare most reads of the large depth maps, whose
        // misses cost the proxy path more than its arithmetic.
        const double tolerance = 1.0 + this->OcclusionTolerance;
        if (!(this->DepthTiles && z <= this->DepthTiles->At(view, px, py) * tolerance))
        {
          const double seen = *this->Depth.Pixel(view, px, py);
          if (seen > 0.0 && z > seen * tolerance)
          {
            continue;
          }
        }
      }
      // ULR's angular penalty: the chord between the unit directions.
      chosen[visible++] = {
        glm::distance(glm::normalize(candidates.ToCamera[nearest]), toEye), view, uv
      };
    }
    if (visible == 0)
    {
      return false;
    }
    const int blended = std::min(visible, k);
    const double threshold =
      visible > k ? chosen[k].Penalty : 2.0 * chosen[blended - 1].Penalty + 1e-9;
    double weights[4];
    double total = 0.0;
    for (int i = 0; i < blended; ++i)
    {
      const double p = std::max(chosen[i].Penalty, 1e-9);
      weights[i] = std::max(1.0 - p / threshold, 0.0) / p;
      total += weights[i];
    }
    if (!(total > 0.0))
    {
      return false;
    }
    for (int i = 0; i < blended; ++i)
    {
      this->AddBilinearAt(chosen[i].View, weights[i] / total, chosen[i].Pixel, out);
    }
    // Near a silhouette the depth maps are least certain (one depth per
    // pixel, nearest pixel): where the focused samples vote for background,
    // the ray is looked up as without a proxy, through the plane. Only
    // samples with a background one can (fish at rest: 6% of them), so the
    // others skip the vote, whose sums cost more than this scan.
    bool background = false;
    for (int i = 0; i < out.Count; ++i)
    {
      background |= out.Samples[i].Label == 0;
    }
    if (out.Count == 0 || (this->Labels.Present() && background && VoteLabel(out) == 0))
    {
      out.Count = 0;
      return false;
    }
    out.Surface = surface;
    return true;
  }

  /**
   * The stretch [enter, leave] of the ray o + s d (s >= 0) inside the
   * surface's bounds (SurfaceLow, SurfaceHigh): the only part of it that
   * IntersectDepthMap walks. False when the ray misses them.
   */
  bool SurfaceStretch(const glm::dvec3& o, const glm::dvec3& d, double& enter, double& leave) const
  {
    return RayStretchInBounds(
      o, d, AxisBounds{ this->SurfaceLow, this->SurfaceHigh }, enter, leave);
  }

  /**
   * The candidate cameras of GatherOnSurface (FindProxyCandidates()), as arrays
   * so that the search for the nearest runs two candidates a vector
   * (FirstLargest()).
   */
  struct ProxyCandidates
  {
    static constexpr int Maximum = 16;
    /// The squared cosine, with its sign, of the angle at the surface point
    /// between the directions to the camera and to the eye: the larger, the
    /// smaller ULR's angular penalty (the chord 2 sin(angle / 2)), without
    /// the penalty's square roots. (NaN, at a camera's centre: never
    /// chosen.) -infinity beyond Count: FirstLargest() reads all Maximum.
    alignas(16) double Nearness[Maximum];
    int View[Maximum];
    /// From the surface point to the camera's centre, for the penalty.
    glm::dvec3 ToCamera[Maximum];
    int Count = 0;
  };

  /**
   * The candidate cameras of GatherOnSurface: in each row from the one below
   * `height` minus one to the one above plus one, the 4 views around
   * `azimuth` (all of a row of fewer), each with its nearness in angle at
   * `x` to the unit direction `toEye`, into `out`.
   */
  void FindProxyCandidates(double azimuth,
    double height,
    const glm::dvec3& x,
    const glm::dvec3& toEye,
    ProxyCandidates& out) const
  {
    const int rows = static_cast<int>(this->Layout->Rows.size());
    int below = 0;
    while (below + 1 < rows && this->Layout->Rows[below + 1].Height <= height)
    {
      ++below;
    }
    int n = 0;
    for (int r = std::max(below - 1, 0); r <= std::min(below + 2, rows - 1); ++r)
    {
      const RingRow& row = this->Layout->Rows[r];
      const int views = static_cast<int>(row.Azimuth.size());
      if (views == 0)
      {
        continue;
      }
      const int upper = static_cast<int>(row.Upper(azimuth));
      // The first of the 4 (cyclically); the others wrap at most once.
      const int start = ((upper - 2) % views + views) % views;
      for (int i = 0; i < std::min(views, 4); ++i)
      {
        const int index = start + i;
        const int view = row.View[index < views ? index : index - views];
        const glm::dvec3 toCamera = this->CameraCenter(view) - x;
        const double along = glm::dot(toCamera, toEye);
        out.Nearness[n] = along * std::abs(along) / glm::dot(toCamera, toCamera);
        out.View[n] = view;
        out.ToCamera[n++] = toCamera;
      }
    }
    out.Count = n;
    std::fill(out.Nearness + n,
      out.Nearness + ProxyCandidates::Maximum,
      -std::numeric_limits<double>::infinity());
  }

  /// The centre of `view`'s camera (from CameraCenters when given).
  glm::dvec3 CameraCenter(int view) const
  {
    return this->CameraCenters ? this->CameraCenters[view] : this->Cameras[view].Center();
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
    if (!this->Labels.Present() || !IntersectCylinderEntry(this->Layout->Cyl, a, d, s))
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

/**
 * The distinct labels of a ray's samples in order of first appearance with
 * their summed weights and, WithColor, their summed weighted colours: one
 * pass for the vote and the blend of the vote's label (LookUndeformed).
 * A sample whose label `excluded` marks (null: none) weighs 0. The sums run
 * in the samples' order, as BlendLabel's, so the blend is BlendLabel's to
 * the bit.
 */
template<bool WithColor>
struct LabelTally
{
  int Labels[16];
  double Weights[16];
  double Colors[16][3]; // WithColor only
  int Distinct = 0;

  explicit LabelTally(const RaySamples& samples, const bool* excluded = nullptr)
  {
    // The sums of a run of samples of one label (most rays' 16 samples are
    // one run) are kept in registers: through memory, each sample's sums
    // waited for the stores of the sample before (the fish at rest 0.97x).
    int k = -1; // the run's label's entry
    double weight = 0.0;
    double color[3] = { 0.0, 0.0, 0.0 };
    const auto keep = [&]
    {
      this->Weights[k] = weight;
      if constexpr (WithColor)
      {
        for (int c = 0; c < 3; ++c)
        {
          this->Colors[k][c] = color[c];
        }
      }
    };
    for (int i = 0; i < samples.Count; ++i)
    {
      const RaySample& sample = samples.Samples[i];
      if (k < 0 || this->Labels[k] != sample.Label)
      {
        if (k >= 0)
        {
          keep();
        }
        k = 0;
        while (k < this->Distinct && this->Labels[k] != sample.Label)
        {
          ++k;
        }
        if (k == this->Distinct)
        {
          this->Labels[k] = sample.Label;
          this->Weights[k] = 0.0;
          if constexpr (WithColor)
          {
            this->Colors[k][0] = this->Colors[k][1] = this->Colors[k][2] = 0.0;
          }
          ++this->Distinct;
        }
        weight = this->Weights[k];
        if constexpr (WithColor)
        {
          for (int c = 0; c < 3; ++c)
          {
            color[c] = this->Colors[k][c];
          }
        }
      }
      const double w = excluded && excluded[sample.Label] ? 0.0 : sample.Weight;
      weight += w;
      if constexpr (WithColor)
      {
        for (int c = 0; c < 3; ++c)
        {
          color[c] += w * sample.Color[c];
        }
      }
    }
    if (k >= 0)
    {
      keep();
    }
  }

  /// Index of the heaviest label (ties go to the first seen); -1 when none weighs anything.
  int Heaviest() const
  {
    int best = -1;
    double bestWeight = 0.0;
    for (int k = 0; k < this->Distinct; ++k)
    {
      if (this->Weights[k] > bestWeight)
      {
        best = k;
        bestWeight = this->Weights[k];
      }
    }
    return best;
  }
};

inline int VoteLabel(const RaySamples& samples)
{
  // The heaviest of the distinct labels; ties go to the first seen.
  const LabelTally<false> tally(samples);
  const int best = tally.Heaviest();
  return best < 0 ? -1 : tally.Labels[best];
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
