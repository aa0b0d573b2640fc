/**
 * @file   lfdRenderView.h
 * @brief  RENDER_VIEW of Chen, Ofek, Shum and Levoy 2005 (Sec. 6): one view ray through a cage.
 *
 * A view ray o + t d in deformed space crosses the deformed boxes of the
 * cage. RenderView() collects every interval of the ray inside a box
 * (lfdRayWarp.h, every interval of a twisted box), sorts them by distance
 * along the ray, and walks them front to back: each interval is warped back
 * to rest space (the straight warped ray through the rest images of its
 * entry and exit points) and looked up in the light field; the first
 * interval whose looked-up label is its box's label gives the ray its colour
 * (DESIGN.md section 4.3). That is how occlusion between parts comes out
 * right without any geometry. Silhouettes of moved parts are anti-aliased
 * (RenderViewSettings::AntiAliasing): each interval is as opaque as the
 * share of its samples that carry its box's label, composited front to
 * back, while the label and depth still come from the first match. A box
 * that did not move warps a ray onto
 * itself: its intervals are looked up along the view ray itself, once per
 * ray, so a cage at rest renders exactly the undeformed light field.
 *
 * When no interval matches, a moved box may have uncovered a region that
 * the nearby cameras saw hidden behind another part: the widened search of
 * paper Sec. 8 looks in further cameras, front to back. A ray that no box
 * claims sees the undeformed light field, but only the parts that no box
 * owns: a part that has a box is wherever its box put it.
 *
 * The light field is reached through a lookup object (the renderer passes a
 * SamplerLookup over lfd::LightFieldSampler; tests pass analytic ones) with
 *
 *   bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const;
 *     the weighted samples of the rest-space ray o + s d (false: none);
 *   bool Widen(const glm::dvec3& a, const glm::dvec3& b, int label, glm::dvec3& color) const;
 *     the widened search along the rest-space segment [a, b] for `label`;
 *   double FocalDepth(const glm::dvec3& o, const glm::dvec3& d) const;
 *     the depth reported for a ray that no box claims and whose samples are
 *     not focused on a proxy surface (RaySamples::Surface NaN);
 *   double FocalParameter(const glm::dvec3& o, const glm::dvec3& d) const;
 *     the s of the point o + s d of the rest-space ray that Gather samples
 *     the cameras at on its focal plane or cylinder (with a proxy, the
 *     samples' own RaySamples::Surface is used instead when it is set).
 *
 * and may gather in two stages, which RenderPlainViews() then runs over a
 * batch of rays (SamplerLookup does): a type Aimed, AimBatch(o, d, count,
 * Aimed*, bool* aimed) (the geometry of the rays o + s d[i] through pixels
 * of one row, in order; aimed[i] false: no sample), Sample(o, d, Aimed&,
 * RaySamples&) (Gather's result) and FocalDepth(o, const Aimed&); and
 * AimBatch(const glm::dvec3* o, d, count, Aimed*, bool* aimed), the rays
 * o[i] + s d[i] from origins of their own (the warped rays of RenderWalks()).
 *
 * A lookup sees the first surface along the whole line of a warped ray, not
 * only along its interval, and it samples the cameras at the line's focal
 * point. In a tessellated box (lfdTessellation.h) the intervals in front of
 * the part warp to lines that are tangent to the curved rest image of the
 * view ray far before the focal point, and stray from it there; the
 * interval that holds the focal point follows the curve where the cameras
 * are sampled. So a matching interval of a moved box whose focal point lies
 * beyond its exit is held back while the next intervals of the same part
 * are tried: the first whose focal point is not beyond its exit gives the
 * pixel, else the held one (DeferredMatch). With a proxy, an interval whose
 * lookup found no surface (focused on the plane instead) does not displace
 * one held on the surface.
 *
 * Segments have no fixed cap: they go to a caller-owned vector that keeps
 * its capacity from ray to ray (one per thread), so a ray allocates nothing
 * once the vector has grown to the deepest ray seen.
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdRenderView_h
#define lfdRenderView_h

#include "lfdCylinderSampling.h"
#include "lfdRayWarp.h"
#include "lfdTessellation.h"
#include "lfdTrilinear.h"

#include <glm/glm.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace lfd
{

/// A box of the cage (or a sub-box of its tessellation) as RENDER_VIEW uses it.
struct RenderBox
{
  Hexahedron Rest;
  Hexahedron Deformed;
  AxisBounds Bounds{ glm::dvec3(0.0), glm::dvec3(0.0) }; ///< of the deformed box
  int Label = 0;                                         ///< the part it owns, 1..255
  /// Deformed differs from rest (by more than 1e-9 of the box size): its
  /// warp is not the identity, and it may uncover regions (Sec. 8).
  bool Moved = false;
  /// The eye lies outside the deformed box (see PlaceEye).
  bool EyeOutside = false;
};

/// The RenderBox of a box with corners `rest` and `deformed` owning `label`.
inline RenderBox MakeRenderBox(const Hexahedron& rest, const Hexahedron& deformed, int label)
{
  RenderBox box;
  box.Rest = rest;
  box.Deformed = deformed;
  box.Bounds = BoxBounds(deformed);
  box.Label = label;
  const double size = BoxSize(rest);
  for (int c = 0; c < 8; ++c)
  {
    box.Moved = box.Moved || glm::distance(rest.Corners[c], deformed.Corners[c]) > 1e-9 * size;
  }
  return box;
}

/**
 * Appends the k^3 sub-boxes of `box` (lfdTessellation.h) to `out`. They
 * keep the box's label and its Moved flag: a part moves or stays as a whole.
 */
inline void Tessellate(const RenderBox& box, int k, std::vector<RenderBox>& out)
{
  ForEachSubBox(k,
    [&](const glm::ivec3& cell)
    {
      RenderBox sub;
      sub.Rest = SubBox(box.Rest, k, cell);
      sub.Deformed = SubBox(box.Deformed, k, cell);
      sub.Bounds = BoxBounds(sub.Deformed);
      sub.Label = box.Label;
      sub.Moved = box.Moved;
      out.push_back(sub);
    });
}

/// Marks the boxes that do not contain the eye, so that their rays skip
/// the inside test of the stretch before the first face (WarpRayThroughBox).
inline void PlaceEye(std::vector<RenderBox>& boxes, const glm::dvec3& eye)
{
  for (RenderBox& box : boxes)
  {
    glm::dvec3 uvw(0.5);
    const bool inBounds = glm::all(glm::greaterThanEqual(eye, box.Bounds.Min)) &&
      glm::all(glm::lessThanEqual(eye, box.Bounds.Max));
    box.EyeOutside = !inBounds || !Contains(box.Deformed, eye, uvw);
  }
}

/// Slab test of the half-line o + t d (t >= 0) against axis-aligned bounds;
/// `tEnter` is where the half-line enters them (0 when o is inside).
inline bool RayEntersBounds(const glm::dvec3& o,
  const glm::dvec3& d,
  const AxisBounds& bounds,
  double& tEnter)
{
  double tLeave;
  return RayStretchInBounds(o, d, bounds, tEnter, tLeave);
}

/// Slab test of the half-line o + t d (t >= 0) against axis-aligned bounds.
inline bool RayHitsBounds(const glm::dvec3& o, const glm::dvec3& d, const AxisBounds& bounds)
{
  double tEnter;
  return RayEntersBounds(o, d, bounds, tEnter);
}

/// An interval of a view ray inside box `Box`, and the label the light
/// field showed along its warped ray (-1: not looked up, or nothing seen).
struct BoxSegment
{
  /// The interval left unset, for the warp to write in place (FrameCage::NextSegment).
  BoxSegment() {}
  BoxSegment(const WarpedSegment& segment, int box, int seen = -1, bool joins = false)
    : Segment(segment)
    , Box(box)
    , Seen(seen)
    , Joins(joins)
  {
  }

  WarpedSegment Segment;
  int Box = 0;
  int Seen = -1;
  /// It goes on with the run of the interval handed out before it, across
  /// pieces of the run that the walk left out (FrameCage::LeaveOut).
  bool Joins = false;
};

namespace detail
{
/// Appends the intervals of the ray o + t d (t >= 0) inside box `b` to
/// `segments`; `seen` is the box seen from o, or null to build it here.
inline void AppendSegments(const std::vector<RenderBox>& boxes,
  int b,
  const BoxFromOrigin* seen,
  const glm::dvec3& o,
  const glm::dvec3& d,
  std::vector<BoxSegment>& segments)
{
  const RenderBox& box = boxes[b];
  if (!RayHitsBounds(o, d, box.Bounds))
  {
    return;
  }
  WarpedSegment found[MaxWarpedSegments];
  const int n = seen
    ? WarpRayThroughBox(
        *seen, box.Rest, box.Deformed, d, 0.0, found, MaxWarpedSegments, box.EyeOutside)
    : WarpRayThroughBox(
        box.Rest, box.Deformed, o, d, 0.0, found, MaxWarpedSegments, box.EyeOutside);
  for (int k = 0; k < n; ++k)
  {
    segments.push_back({ found[k], b, -1 });
  }
}

/// The order of a ray's intervals: by entry parameter, then by box index,
/// so that it does not depend on the sort or on the order boxes were tried.
inline bool NearerSegment(const BoxSegment& a, const BoxSegment& b)
{
  return a.Segment.TEnter < b.Segment.TEnter ||
    (a.Segment.TEnter == b.Segment.TEnter && a.Box < b.Box);
}

inline void SortSegments(std::vector<BoxSegment>& segments)
{
  std::sort(segments.begin(), segments.end(), NearerSegment);
}
} // namespace detail

/**
 * Every interval of the ray o + t d (t >= 0) inside the deformed boxes,
 * into `segments` (cleared first), sorted by distance: by entry parameter,
 * then by box index, so that the order does not depend on the sort.
 */
inline void CollectSegments(const std::vector<RenderBox>& boxes,
  const glm::dvec3& o,
  const glm::dvec3& d,
  std::vector<BoxSegment>& segments)
{
  segments.clear();
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    detail::AppendSegments(boxes, static_cast<int>(b), nullptr, o, d, segments);
  }
  detail::SortSegments(segments);
}

/**
 * The convex hull of a deformed box's (or face's) projection into a frame's image, as
 * the inward edge lines of a counter-clockwise polygon (n.x x + n.y y + c,
 * |n| = 1: the signed distance in pixels). A trilinear box lies in the
 * convex hull of its 8 corners (Eq. 2 is a convex combination of them), so
 * the projection of that hull, the hull of the projected corners, holds
 * every pixel whose ray meets the box. No edges (Count 0): the box has a
 * corner at or behind the eye plane, or projects to a line; every ray may
 * meet it.
 */
struct ScreenHull
{
  int Count = 0;
  glm::dvec3 Edges[8];

  /// Pixels this far outside the hull (far more than the rounding of the
  /// projection and the warp's patch slack) may still meet the box.
  static constexpr double Margin = 1e-3;

  /// The hull of `points` (`n` <= 8 projected corners), by Andrew's monotone chain.
  static ScreenHull Of(glm::dvec2 points[8], int n)
  {
    std::sort(points,
      points + n,
      [](const glm::dvec2& a, const glm::dvec2& b)
      { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
    { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    glm::dvec2 chain[16];
    int k = 0;
    for (int pass = 0; pass < 2; ++pass) // lower chain, then upper
    {
      const int start = k;
      for (int i = 0; i < n; ++i)
      {
        const glm::dvec2& point = points[pass == 0 ? i : n - 1 - i];
        while (k >= start + 2 && turn(chain[k - 2], chain[k - 1], point) <= 0.0)
        {
          --k;
        }
        chain[k++] = point;
      }
      --k; // each chain's last point starts the other
    }
    ScreenHull hull;
    if (k < 3)
    {
      return hull;
    }
    for (int i = 0; i < k; ++i)
    {
      const glm::dvec2 edge = chain[(i + 1) % k] - chain[i];
      const glm::dvec2 normal = glm::dvec2(-edge.y, edge.x) / glm::length(edge);
      hull.Edges[hull.Count++] = glm::dvec3(normal, -glm::dot(normal, chain[i]));
    }
    return hull;
  }

  /// False when the ray through pixel (x, y) surely misses the box.
  bool MayHold(double x, double y) const { return this->MayHold(x, y, (1u << this->Count) - 1); }

  /**
   * MayHold testing only the edges in `edges` (bit i: Edges[i]), the others
   * known to let the pixel through (EdgesAcross): the same answer when
   * `edges` holds every edge that EdgesAcross gives for a rectangle around
   * the pixel.
   */
  bool MayHold(double x, double y, unsigned edges) const
  {
    // Set bit after set bit: no test of a bit, whose outcome varies from
    // tile to tile (a mispredicted branch), for the edges in between.
    for (; edges != 0; edges &= edges - 1)
    {
      const glm::dvec3& edge = this->Edges[detail::LowestSetBit(static_cast<int>(edges))];
      if (edge.x * x + edge.y * y + edge.z < -Margin)
      {
        return false;
      }
    }
    return true;
  }

  /**
   * The pixels of a tile of at most 8 x 8 pixels, (x0, y0) its first, at
   * which MayHold(x, y, edges) is true: bit 8 (y - y0) + (x - x0); bits
   * outside the tile's `rows` are set. The same products and sums as
   * MayHold's, pixel by pixel, so the same answers: once per frame and
   * tile, for the many rays of a tile that each test the projected hull of
   * every box listed there (a ray of the bent 100-slab fish tries about 17).
   * With SSE2, two pixels a vector, the edge's x terms computed once for
   * the tile's columns.
   */
  std::uint64_t HeldPixels(int x0, int y0, int rows, unsigned edges) const
  {
    std::uint64_t failed = 0;
    for (; edges != 0; edges &= edges - 1)
    {
      const glm::dvec3& edge = this->Edges[detail::LowestSetBit(static_cast<int>(edges))];
#if defined(__SSE2__)
      __m128d across[4];
      for (int k = 0; k < 4; ++k)
      {
        across[k] = _mm_mul_pd(_mm_set1_pd(edge.x), _mm_set_pd(x0 + 2 * k + 1, x0 + 2 * k));
      }
      const __m128d offset = _mm_set1_pd(edge.z);
      const __m128d limit = _mm_set1_pd(-Margin);
      for (int r = 0; r < rows; ++r)
      {
        const __m128d down = _mm_set1_pd(edge.y * (y0 + r));
        int row = 0;
        for (int k = 0; k < 4; ++k)
        {
          const __m128d distance = _mm_add_pd(_mm_add_pd(across[k], down), offset);
          row |= _mm_movemask_pd(_mm_cmplt_pd(distance, limit)) << (2 * k);
        }
        failed |= static_cast<std::uint64_t>(row) << (8 * r);
      }
#else
      for (int r = 0; r < rows; ++r)
      {
        for (int c = 0; c < 8; ++c)
        {
          const double x = x0 + c, y = y0 + r;
          failed |= static_cast<std::uint64_t>(edge.x * x + edge.y * y + edge.z < -Margin)
            << (8 * r + c);
        }
      }
#endif
    }
    return ~failed;
  }

  /**
   * The edges whose test in MayHold may fail at some pixel of the rectangle
   * [x0, x1] x [y0, y1] (bit i: Edges[i]), or -1 when MayHold is false at
   * every one. An edge's distance is linear, so its extremes over the
   * rectangle are at its 4 corners: an edge at least 0 at every corner
   * passes MayHold's test (>= -Margin) all over the rectangle, and one below
   * -2 Margin at every corner fails it all over (the margin is far more than
   * the rounding of evaluating the distance in between).
   */
  int EdgesAcross(double x0, double y0, double x1, double y1) const
  {
    int across = 0;
    for (int i = 0; i < this->Count; ++i)
    {
      const glm::dvec3& e = this->Edges[i];
      const double farthest = std::max(e.x * x0, e.x * x1) + std::max(e.y * y0, e.y * y1) + e.z;
      if (farthest < -2.0 * Margin)
      {
        return -1;
      }
      const double nearest = std::min(e.x * x0, e.x * x1) + std::min(e.y * y0, e.y * y1) + e.z;
      across |= (nearest < 0.0) << i;
    }
    return across;
  }

  /// False when MayHold is false at every pixel of the rectangle [x0, x1] x [y0, y1].
  bool MayHoldAny(double x0, double y0, double x1, double y1) const
  {
    return this->EdgesAcross(x0, y0, x1, y1) >= 0;
  }
};

/**
 * How the projected hulls of a box and of its faces (ScreenHull) meet a tile
 * of a frame: the edges that each must test at the tile's pixels
 * (ScreenHull::EdgesAcross). Most pixels of a tile that lists a box lie
 * well inside its hull and inside or outside each face's, where the
 * per-pixel tests answer without evaluating an edge.
 */
struct HullsInTile
{
  std::uint8_t Box = 0;         ///< the box's hull's edges that cross the tile
  std::uint8_t FacesIn = 0;     ///< the faces (bit k: face k) whose hull holds the whole tile
  std::uint8_t FacesAcross = 0; ///< the faces whose hull's edges cross the tile
  std::uint8_t Faces[6] = { 0, 0, 0, 0, 0, 0 }; ///< per face, its hull's edges that cross the tile
};

/**
 * Bounds of a deformed box along its own axes, seen from a fixed eye: a
 * bent slab's axis-aligned bounds are far thicker than the slab, so a ray
 * enters them far before the slab, while bounds along the slab's axes stay
 * about as thin as the slab. The box lies in the convex hull of its 8
 * corners (Eq. 2 is a convex combination of them), so in any bounds of the
 * corners along any three orthonormal axes.
 */
struct OrientedBounds
{
  glm::dmat3 ToAxes{ 1.0 }; ///< world to the axes' frame (rows: the unit axes)
  /// The corners' bounds in that frame, less the eye's image there: the
  /// rays of a frame leave the eye, and their entry needs no more.
  AxisBounds Bounds{ glm::dvec3(0.0), glm::dvec3(0.0) };

  /**
   * The bounds of `box` along its axes (its mean edges, orthonormalised from
   * the shortest: a slab's thin axis is kept exactly), widened by `margin`
   * on every side; a degenerate box gets the world axes.
   */
  static OrientedBounds Of(const Hexahedron& box, const glm::dvec3& eye, double margin)
  {
    const glm::dvec3* c = box.Corners;
    glm::dvec3 edges[3] = { (c[1] - c[0]) + (c[2] - c[3]) + (c[5] - c[4]) + (c[6] - c[7]),
      (c[3] - c[0]) + (c[2] - c[1]) + (c[7] - c[4]) + (c[6] - c[5]),
      (c[4] - c[0]) + (c[5] - c[1]) + (c[6] - c[2]) + (c[7] - c[3]) };
    std::sort(edges,
      edges + 3,
      [](const glm::dvec3& a, const glm::dvec3& b) { return glm::dot(a, a) < glm::dot(b, b); });
    OrientedBounds oriented;
    const double scale = glm::length(edges[2]);
    const glm::dvec3 second =
      edges[1] - glm::dot(edges[1], edges[0]) / glm::dot(edges[0], edges[0]) * edges[0];
    if (glm::length(edges[0]) > 1e-9 * scale && glm::length(second) > 1e-9 * scale)
    {
      const glm::dvec3 a0 = glm::normalize(edges[0]);
      const glm::dvec3 a1 = glm::normalize(second);
      // glm matrices are column-major: the transpose has the axes as rows.
      oriented.ToAxes = glm::transpose(glm::dmat3(a0, a1, glm::cross(a0, a1)));
    }
    Hexahedron local;
    for (int k = 0; k < 8; ++k)
    {
      local.Corners[k] = oriented.ToAxes * c[k];
    }
    oriented.Bounds = BoxBounds(local);
    oriented.Bounds.Min -= glm::dvec3(margin);
    oriented.Bounds.Max += glm::dvec3(margin);
    // (The slab test's differences to the eye, once per frame: the same values.)
    const glm::dvec3 axesEye = oriented.ToAxes * eye;
    oriented.Bounds.Min -= axesEye;
    oriented.Bounds.Max -= axesEye;
    return oriented;
  }

  /**
   * Where the ray from the eye in direction `d` enters the bounds (false: it
   * misses them): RayEntersBounds from the origin along ToAxes d. A ray of
   * a many-slab cage computes this for every box whose projected hull holds
   * its pixel (about 9 a ray of the bent 100-slab fish, most of them left
   * out of its walk later), so with SSE2 the first two axes run as one
   * vector and without a branch per axis: the same products, sums and
   * quotients as the slab test's, so the same entry and outcome (the slab
   * test's running maximum and minimum reach the maximum and minimum over
   * the axes, and one axis whose interval ends before the entry makes the
   * last test fail too). A component of ToAxes d that is zero takes the
   * slab test's own branch.
   */
  bool Entry(glm::dvec3 d, double& tEnter) const
  {
    const glm::dmat3& m = this->ToAxes;
#if defined(__SSE2__)
    // (glm's product: (m[0] d.x + m[1] d.y) + m[2] d.z, row by row.)
    const __m128d along =
      _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_loadu_pd(&m[0][0]), _mm_set1_pd(d.x)),
                   _mm_mul_pd(_mm_loadu_pd(&m[1][0]), _mm_set1_pd(d.y))),
        _mm_mul_pd(_mm_loadu_pd(&m[2][0]), _mm_set1_pd(d.z)));
    const double alongZ = m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z;
    if (_mm_movemask_pd(_mm_cmpeq_pd(along, _mm_setzero_pd())) == 0 && alongZ != 0.0)
    {
      const __m128d low = _mm_div_pd(_mm_loadu_pd(&this->Bounds.Min.x), along);
      const __m128d high = _mm_div_pd(_mm_loadu_pd(&this->Bounds.Max.x), along);
      const double lowZ = this->Bounds.Min.z / alongZ, highZ = this->Bounds.Max.z / alongZ;
      const __m128d nearXY = _mm_min_pd(low, high), farXY = _mm_max_pd(low, high);
      const __m128d nearZ = _mm_max_sd(_mm_set_sd(std::min(lowZ, highZ)), _mm_setzero_pd());
      const __m128d farZ = _mm_set_sd(std::max(lowZ, highZ));
      const __m128d enter = _mm_max_sd(_mm_max_sd(nearXY, _mm_unpackhi_pd(nearXY, nearXY)), nearZ);
      const __m128d leave = _mm_min_sd(_mm_min_sd(farXY, _mm_unpackhi_pd(farXY, farXY)), farZ);
      tEnter = _mm_cvtsd_f64(enter);
      return _mm_comile_sd(enter, leave);
    }
#endif
    return RayEntersBounds(glm::dvec3(0.0), m * d, this->Bounds, tEnter);
  }
};

/// A box a ray of a frame may meet (FrameCage::StartWalk).
struct WalkEntry
{
  WalkEntry() = default;
  WalkEntry(double t, int box, int listed)
    : T(t)
    , Box(box)
    , Listed(listed)
  {
  }

  /// Where the ray enters the box's widened oriented bounds (0 for a ray's
  /// only box: there is nothing to order, see FrameCage::StartWalk).
  double T;
  int Box;
  int Listed; ///< the box's place in the ray's tile (FrameCage::TileBoxes)

  /// Nearer first, then by box index.
  bool operator<(const WalkEntry& other) const
  {
    return this->T < other.T || (this->T == other.T && this->Box < other.Box);
  }
};

/// One thread's scratch space for the rays of a frame (FrameCage::NextSegment),
/// reused from ray to ray: a ray allocates nothing once it has grown.
struct FrameRayScratch
{
  /// The ray's intervals: [0, Handed) handed out, front to back; then those
  /// warped and not handed out yet, sorted. A warp writes its intervals here
  /// once, where they stay (StartWalk reserves room for the most there can be).
  std::vector<BoxSegment> Segments;
  std::size_t Handed = 0;
  /// The boxes still to warp, sorted from NextEntry.
  std::vector<WalkEntry> Entries;
  std::size_t NextEntry = 0;
  std::size_t Warps = 0;   ///< the boxes NextSegment warped for the ray
  glm::dvec2 Pixel{ 0.0 }; ///< the pixel of the ray (StartWalk)
  /// Per box, the number of the last ray that left it out (FrameCage::LeaveOut).
  std::vector<unsigned> Skipped;
  /// Per box, the number of the last ray whose pixel its projected hull holds (StartWalk).
  std::vector<unsigned> Held;
  unsigned Ray = 0;                       ///< this ray's number
  const BoxSegment* RunSkipped = nullptr; ///< the interval whose run LeaveOut last left out
  int Landing = -1;       ///< the box where the run left out ahead of an interval goes on
  std::vector<int> Chain; ///< FrameCage::FollowRun's chain of boxes
  /// The box of the ray's first entry when FrameCage::WarpAhead() warped it
  /// (-1: none), its number of intervals (0 or 1) and its interval.
  int AheadBox = -1;
  int AheadCount = 0;
  WarpedSegment Ahead;
};

/**
 * The cage as the rays of one frame meet it. Every ray of a frame leaves the
 * same eye through a pixel (x, y) of the image, in the direction
 * PixelToDirection (x, y, 1), so what does not depend on the pixel is
 * computed once per frame instead of once per ray and box:
 *
 * - each box seen from the eye (BoxFromOrigin: the warp's per-face terms)
 *   and the convex hull of its projection (ScreenHull): a ray outside it
 *   misses the box, which is then neither bounds-tested nor warped (the
 *   bounds of a rotated thin slab are far wider than the slab);
 * - the convex hull of each face's projection: a bilinear face lies in the
 *   convex hull of its 4 corners, so a ray outside that hull misses the
 *   face, which the warp then does not intersect (a ray across a thin slab
 *   meets its 2 wide faces, and is outside the slivers of its 4 sides);
 *   per tile that lists the box, the edges of these hulls that cross the
 *   tile (HullsInTile): a ray tests only those (the 3-box swim's frame
 *   195.3 -> 189.0 M instructions);
 * - a culling structure: the image is cut into square tiles and each box is
 *   listed in the tiles of its screen-space bounding rectangle (the
 *   projection of its bounds' 8 corners, one pixel wider on every side; a
 *   box with a corner at or behind the eye plane has no bounded projection
 *   and goes into every tile) that its projected hull may reach. A ray then
 *   tries only its tile's boxes. A ray that meets a box passes through its
 *   projected hull and the bounds' projection, so every box that the ray's
 *   hull test would let through is in its tile: the intervals, and so the
 *   pixels, are exactly those of CollectSegments over every box;
 * - the bounds of each box along its own axes (OrientedBounds), widened by
 *   1e-6 of its axis-aligned bounds' diagonal, which order the boxes along a
 *   ray: an interval of a box starts on its faces or at the eye, inside the
 *   widened bounds, so never before the ray enters them. NextSegment hands
 *   the ray's intervals out front to back and warps a box only when it
 *   could hold the next one; RENDER_VIEW stops at the first interval that
 *   shows its label, so the boxes behind it are never warped. The
 *   axis-aligned bounds of the bent slabs of a 100-slab cage overlap so
 *   much that a ray entering each there would warp about 8% more boxes
 *   ahead of the interval it needs (22% for TestRenderView's tilted slabs).
 *   The ray is not tested against the axis-aligned bounds at all: a ray
 *   whose pixel a box's projected hull holds about always meets them, and
 *   the later of the two entries ordered the boxes of the bent 100-slab
 *   fish no tighter (its warps took 0.06% fewer instructions, its whole
 *   frame 7% more).
 *
 * Build with `tileSize` 0 to list every box in one tile covering the image
 * (no culling: every ray tries every box, as CollectSegments does).
 */
struct FrameCage
{
  const std::vector<RenderBox>* Boxes = nullptr;
  std::vector<BoxFromOrigin> Seen;      ///< per box, seen from Eye
  std::vector<ScreenHull> Hulls;        ///< per box, its projection's convex hull
  std::vector<OrientedBounds> Oriented; ///< per box, along its axes, widened (see above)
  /// Per box, the projected hull of each face (HexFacePatch order).
  std::vector<std::array<ScreenHull, 6>> FaceHulls;
  /// Per box and face, the box sharing the face (the same 4 deformed corners)
  /// times 6 plus the face's index in it; -1 for none.
  std::vector<std::array<int, 6>> Neighbors;
  /// Per box and face, where a run goes on straight through the face
  /// (FollowRun): the neighbour's index times 8 plus its face opposite the
  /// one shared, when the neighbour moved and has the box's label; else -1.
  std::vector<std::array<int, 6>> Through;
  glm::dvec3 Eye{ 0.0 };
  glm::dmat3 PixelToDirection{ 1.0 };
  int TileSize = 1;
  int TilesX = 1;
  int TilesY = 1;
  /// Per pixel column x, x / TileSize; per pixel row y, (y / TileSize)
  /// TilesX: TileOf without the two integer divisions, whose latency (tens
  /// of cycles) every ray in a tile that lists a box waited for.
  std::vector<int> TileColumns, TileRows;
  std::vector<int> TileStart; ///< tile i lists TileBoxes[TileStart[i], TileStart[i + 1])
  std::vector<int> TileBoxes; ///< box indices, nearest first within a tile (BinBoxes)
  /// Per entry of TileBoxes, how the box's projected hulls meet the tile.
  std::vector<HullsInTile> TileHulls;
  /// Per entry of TileBoxes, the tile's pixels whose ray the box's projected
  /// hull may hold (ScreenHull::HeldPixels); only with tiles of at most
  /// 8 x 8 pixels (else empty: each ray tests the hull).
  std::vector<std::uint64_t> TilePixels;
  /// Per pixel column x and row y, the bit of the pixel (x, y) in TilePixels: their sum.
  std::vector<int> PixelColumns, PixelRows;

  /// Tile side (pixels) that the renderer uses: small enough that a tile of
  /// the fish's 100-slab cage at 512x512 lists a few boxes (about 2.4 per
  /// ray over the frame at 16 pixels, 3.5 before the tiles followed the
  /// projected hulls), large enough that binning a cage of the sub-box
  /// budget (4096) stays a small part of a frame. 8 pixels against 16: the
  /// bent 100 slabs 297.5 -> 293.1 M instructions a frame, the 3-box swim
  /// 142.8 -> 143.0 M (the renderer's label-hull mask keeps 16-pixel tiles);
  /// 4 pixels: 312.7 and 147.8 M.
  static constexpr int DefaultTileSize = 8;

  /**
   * The frame of a width x height image seen from `eye` through
   * `pixelToDirection` (PlaceEye() called for this eye), its loops (over
   * boxes and over binned tile-box pairs) run by `loop` (the same frame
   * cage whatever runs them). `boxes` must outlive the frame cage.
   */
  void Build(const std::vector<RenderBox>& boxes,
    const glm::dvec3& eye,
    const glm::dmat3& pixelToDirection,
    int width,
    int height,
    int tileSize,
    const RangeLoop& loop = SerialLoop)
  {
    this->Boxes = &boxes;
    this->Eye = eye;
    this->PixelToDirection = pixelToDirection;
    this->Seen.resize(boxes.size());
    this->Hulls.resize(boxes.size());
    this->Oriented.resize(boxes.size());
    this->FaceHulls.resize(boxes.size());
    loop(boxes.size(),
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t b = begin; b < end; ++b)
        {
          this->Seen[b] = BoxFromOrigin(boxes[b].Rest, boxes[b].Deformed, eye);
          this->Hulls[b] = this->ProjectedHull(boxes[b].Deformed.Corners, HexCorners);
          for (int face = 0; face < 6; ++face)
          {
            this->FaceHulls[b][face] =
              this->ProjectedHull(boxes[b].Deformed.Corners, HexFacePatch[face]);
          }
          const AxisBounds& bounds = boxes[b].Bounds;
          this->Oriented[b] = OrientedBounds::Of(
            boxes[b].Deformed, eye, 1e-6 * glm::distance(bounds.Min, bounds.Max));
        }
      });
    this->LinkFaces(boxes);
    this->TileSize = tileSize > 0 ? tileSize : std::max(width, height);
    this->TilesX = (width + this->TileSize - 1) / this->TileSize;
    this->TilesY = (height + this->TileSize - 1) / this->TileSize;
    this->TileColumns.resize(width);
    this->PixelColumns.resize(width);
    for (int x = 0; x < width; ++x)
    {
      this->TileColumns[x] = x / this->TileSize;
      this->PixelColumns[x] = x % this->TileSize;
    }
    this->TileRows.resize(height);
    this->PixelRows.resize(height);
    for (int y = 0; y < height; ++y)
    {
      this->TileRows[y] = (y / this->TileSize) * this->TilesX;
      this->PixelRows[y] = 8 * (y % this->TileSize);
    }
    this->BinBoxes(boxes, width, height, tileSize > 0, loop);
  }

  /// The direction of the ray through pixel (x, y) (OpenCV pixel coordinates).
  glm::dvec3 Direction(int x, int y) const
  {
    return this->PixelToDirection * glm::dvec3(x, static_cast<double>(y), 1.0);
  }

  /// Number of boxes the ray through pixel (x, y) tries.
  int CountCandidates(int x, int y) const
  {
    const int tile = this->TileOf(x, y);
    return this->TileStart[tile + 1] - this->TileStart[tile];
  }

  /**
   * Starts the walk of the ray through pixel (x, y), direction `d`, through
   * the boxes of its tile whose projected hull holds the pixel and whose
   * oriented bounds it meets. Returns their number.
   */
  std::size_t StartWalk(int x, int y, const glm::dvec3& d, FrameRayScratch& scratch) const
  {
    scratch.Segments.clear();
    scratch.Handed = 0;
    scratch.Entries.clear();
    scratch.NextEntry = 0;
    scratch.Warps = 0;
    scratch.Pixel = glm::dvec2(x, y);
    const int tile = this->TileOf(x, y);
    if (this->TileStart[tile] == this->TileStart[tile + 1])
    {
      return 0; // (most rays of a frame: 216 000 of the 262 000 of the 100-slab fish)
    }
    if (scratch.Skipped.size() != this->Boxes->size() || ++scratch.Ray == 0)
    {
      scratch.Skipped.assign(this->Boxes->size(), 0);
      scratch.Held.assign(this->Boxes->size(), 0);
      scratch.Ray = 1;
    }
    // The boxes whose projected hull holds the pixel, then in order of their
    // oriented entries. A ray whose pixel one box's hull holds (most rays
    // that meet a box of the swim) has nothing to order, and about always
    // meets the bounds: a ray through the projected hull of the corners
    // meets their convex hull, which the bounds hold. Its box goes to the
    // warp without the entry (the swim's frame 154.6 -> 152.7 M
    // instructions). (Locals, not members: the stores into scratch could
    // alias the tile's tables and the direction, which the compiler would
    // then read again box after box.)
    const int end = this->TileStart[tile + 1];
    const int* tileBoxes = this->TileBoxes.data();
    const std::uint64_t* pixels = this->TilePixels.empty() ? nullptr : this->TilePixels.data();
    const int bit = this->PixelColumns[x] + this->PixelRows[y];
    unsigned* held = scratch.Held.data();
    const unsigned ray = scratch.Ray;
    for (int i = this->TileStart[tile]; i < end; ++i)
    {
      const int b = tileBoxes[i];
      if (pixels ? !((pixels[i] >> bit) & 1u)
                 : !this->Hulls[b].MayHold(x, y, this->TileHulls[i].Box))
      {
        continue;
      }
      held[b] = ray;
      // (Built in place: pushed as a braced temporary, the entry was stored
      // in two halves on the stack and copied at once in one load, which
      // waited for the stores; that was a third of the bent 100-slab
      // fish's walks' starts.)
      scratch.Entries.emplace_back(0.0, b, i);
    }
    if (scratch.Entries.size() > 1)
    {
      // Where the ray enters each box's oriented bounds; a box whose bounds
      // it misses is dropped: the widened bounds hold the box, so a ray that
      // meets only them (by less than their margin) crosses the box for no
      // interval the warp keeps. (One loop over the held boxes, after the
      // hull tests: the ray's direction stays in registers.)
      const glm::dvec3 direction = d;
      WalkEntry* entries = scratch.Entries.data();
      const OrientedBounds* oriented = this->Oriented.data();
      std::size_t kept = 0;
      // (Field by field, here and in the sort: the entries were just
      // stored so, and a whole entry loaded at once would wait for them.)
      for (std::size_t k = 0; k < scratch.Entries.size(); ++k)
      {
        const int box = entries[k].Box, listed = entries[k].Listed;
        double t = 0.0;
        if (oriented[box].Entry(direction, t))
        {
          entries[kept].T = t;
          entries[kept].Box = box;
          entries[kept].Listed = listed;
          ++kept;
        }
      }
      scratch.Entries.resize(kept);
      // An insertion sort: the tile lists its boxes nearest first, so the
      // entries come about sorted (std::sort's own insertion sort took
      // about twice the instructions of this loop over the same moves).
      for (std::size_t k = 1; k < kept; ++k)
      {
        const WalkEntry entry(entries[k].T, entries[k].Box, entries[k].Listed);
        std::size_t j = k;
        for (; j > 0 && entry < entries[j - 1]; --j)
        {
          entries[j].T = entries[j - 1].T;
          entries[j].Box = entries[j - 1].Box;
          entries[j].Listed = entries[j - 1].Listed;
        }
        entries[j].T = entry.T;
        entries[j].Box = entry.Box;
        entries[j].Listed = entry.Listed;
      }
    }
    if (scratch.Entries.empty())
    {
      return 0;
    }
    scratch.RunSkipped = nullptr;
    scratch.Landing = -1;
    scratch.AheadBox = -1;
    // NextSegment's intervals never move: ShadeSegments holds one back.
    scratch.Segments.reserve(scratch.Entries.size() * MaxWarpedSegments);
    return scratch.Entries.size();
  }

  /**
   * The next interval, front to back (in CollectSegments' order), of the ray
   * StartWalk started, handed out of scratch.Segments; nullptr after the last.
   * Boxes for which `skip(box index)` is true are not warped: their
   * intervals are left out. (Always inlined: a step of the walk, see
   * detail::RunCursor::Advance.)
   */
  template<typename Skip>
  __attribute__((always_inline)) BoxSegment* NextSegment(const glm::dvec3& d,
    FrameRayScratch& scratch,
    Skip&& skip) const
  {
    std::vector<BoxSegment>& segments = scratch.Segments;
    // (Counted here: segments.size() divides by the 136 bytes of an interval.)
    std::size_t count = segments.size();
    // Warp every box the ray enters no later than the nearest pending interval.
    while (scratch.NextEntry < scratch.Entries.size() &&
      (scratch.Handed == count ||
        !(scratch.Entries[scratch.NextEntry].T > segments[scratch.Handed].Segment.TEnter)))
    {
      const WalkEntry& entry = scratch.Entries[scratch.NextEntry++];
      const int b = entry.Box;
      if (scratch.Skipped[b] == scratch.Ray || skip(b))
      {
        continue;
      }
      ++scratch.Warps;
      // The warp writes its intervals in place after the list's end, in room
      // for the most it writes (StartWalk reserved it; made by emplace_back's
      // inline path, resize() was a library call). Copied from an array of
      // the warp's own, each interval was read back while its stores were in
      // flight, in 16-byte loads that no 8-byte store forwards. (A box
      // warped ahead has its intervals, none or one, already.)
      const bool ahead = b == scratch.AheadBox;
      if (!ahead)
      {
        for (int k = 0; k < MaxWarpedSegments; ++k)
        {
          segments.emplace_back();
        }
      }
      else if (scratch.AheadCount > 0)
      {
        segments.emplace_back();
      }
      BoxSegment* written = segments.data() + count;
      struct InPlace
      {
        BoxSegment* First;
        WarpedSegment& operator[](int k) const { return this->First[k].Segment; }
      };
      int n = 0;
      if (ahead)
      {
        // (Warped with other rays' first boxes: WarpAhead.)
        n = scratch.AheadCount;
        scratch.AheadBox = -1;
        if (n > 0)
        {
          written[0].Segment = scratch.Ahead;
        }
      }
      else
      {
        const RenderBox& box = (*this->Boxes)[b];
        n = WarpRayThroughBox(this->Seen[b],
          box.Rest,
          box.Deformed,
          d,
          0.0,
          InPlace{ written },
          MaxWarpedSegments,
          box.EyeOutside,
          this->FacesMet(entry, scratch));
      }
      segments.resize(count + n);
      for (int k = 0; k < n; ++k)
      {
        written[k].Box = b;
        written[k].Joins = b == scratch.Landing;
        // Into its place among the pending intervals, after those of equal
        // order (the first pending one stays where it is written).
        if (++count > scratch.Handed + 1)
        {
          std::rotate(std::upper_bound(segments.begin() + scratch.Handed,
                        segments.end() - 1,
                        segments.back(),
                        detail::NearerSegment),
            segments.end() - 1,
            segments.end());
        }
      }
    }
    if (scratch.Handed == count)
    {
      return nullptr;
    }
    return &segments[scratch.Handed++];
  }

  /**
   * The faces of the box of `entry` that the ray StartWalk started for
   * `scratch` may cross (bit k: face k): those whose projected hull holds
   * the pixel (the others the warp does not intersect).
   */
  int FacesMet(const WalkEntry& entry, const FrameRayScratch& scratch) const
  {
    const HullsInTile& hulls = this->TileHulls[entry.Listed];
    int faces = hulls.FacesIn;
    for (int across = hulls.FacesAcross; across != 0; across &= across - 1) // (as MayHold's edges)
    {
      const int face = detail::LowestSetBit(across);
      if (this->FaceHulls[entry.Box][face].MayHold(
            scratch.Pixel.x, scratch.Pixel.y, hulls.Faces[face]))
      {
        faces |= 1 << face;
      }
    }
    return faces;
  }

  /**
   * Warps the first box of the walks of the rays i < count <= MaximumPlainBatch
   * that StartWalk started in scratch[i] (walked[i]; direction d[i]), where
   * WarpRaysThroughBox decides it, into scratch[i].Ahead, which NextSegment
   * then hands out as WarpRayThroughBox's intervals, the same to the bit: a
   * box that moved (the walk never leaves its first box out, see
   * FrameWalk), seen from outside, whose ray crosses two of its faces, both
   * planar (every face of a cage posed by turning its layers: the swim, the
   * bend), by runs of rays of one box and two faces, up to MaximumWarpBatch
   * (the 3-box swim's frame 8.8 -> 7.9 ms, the bent 100-slab fish's 2%
   * less: its rays' next pieces are warped one by one).
   */
  void WarpAhead(const glm::dvec3* d, const bool* walked, int count, FrameRayScratch* scratch) const
  {
    const std::vector<RenderBox>& boxes = *this->Boxes;
    int rays[MaximumWarpBatch];
    glm::dvec3 directions[MaximumWarpBatch];
    int status[MaximumWarpBatch];
    int n = 0, box = -1, faces = 0;
    // (The batch writes each ray's interval into its scratch: no copy.)
    struct IntoScratch
    {
      FrameRayScratch* Scratch;
      const int* Rays;
      WarpedSegment& operator[](int k) const { return this->Scratch[this->Rays[k]].Ahead; }
    };
    const auto flush = [&]
    {
      WarpRaysThroughBox(
        this->Seen[box], faces, directions, n, IntoScratch{ scratch, rays }, status);
      for (int k = 0; k < n; ++k)
      {
        if (status[k] >= 0)
        {
          scratch[rays[k]].AheadBox = box;
          scratch[rays[k]].AheadCount = status[k];
        }
      }
      n = 0;
    };
    for (int i = 0; i < count; ++i)
    {
      if (!walked[i])
      {
        continue;
      }
      const WalkEntry& entry = scratch[i].Entries.front();
      const RenderBox& first = boxes[entry.Box];
      if (!first.Moved || !first.EyeOutside)
      {
        continue;
      }
      // (A curved face that the ray surely crosses rules the box out before
      // the faces are found: the twisted figure's.)
      const int curved = this->Seen[entry.Box].CurvedFaces;
      if (this->TileHulls[entry.Listed].FacesIn & curved)
      {
        continue;
      }
      const int met = this->FacesMet(entry, scratch[i]);
      const int second = met & (met - 1); // (met less its lowest face)
      if (second == 0 || (second & (second - 1)) != 0 || (met & curved) != 0)
      {
        continue; // (not two planar faces)
      }
      if (n > 0 && (entry.Box != box || met != faces || n == MaximumWarpBatch))
      {
        flush();
      }
      box = entry.Box;
      faces = met;
      rays[n] = i;
      directions[n++] = d[i];
    }
    if (n > 0)
    {
      flush();
    }
  }

  /**
   * The boxes that go on with the run of `from` (RenderViewSettings::
   * FocalBeforeLookup; see ShadeSegments), at most `limit`, into
   * scratch.Chain: from the face `from` leaves by, the chain of face
   * neighbours straight through (each entered by one face, left by the
   * opposite one, as through a stack of slabs) while they are moved boxes
   * of its part whose projected hull holds the pixel.
   */
  void FollowRun(const BoxSegment& from, std::size_t limit, FrameRayScratch& scratch) const
  {
    std::vector<int>& chain = scratch.Chain;
    chain.clear();
    const std::size_t most = std::min(limit, this->Boxes->size());
    const unsigned* held = scratch.Held.data();
    const unsigned ray = scratch.Ray;
    int b = from.Box;
    int face = from.Segment.FaceExit;
    // (Each box of the chain moved and has the label of the one before it,
    // so of `from`: Through.)
    while (face >= 0 && chain.size() < most)
    {
      const int next = this->Through[b][face];
      if (next < 0 || held[next >> 3] != ray)
      {
        break;
      }
      b = next >> 3;
      face = next & 7;
      chain.push_back(b);
    }
  }

  /**
   * Leaves the first `count` boxes of scratch.Chain (FollowRun) out of the
   * ray's walk: they are not warped. Returns the chain's box after them
   * (-1: none).
   */
  int LeaveOut(std::size_t count, FrameRayScratch& scratch) const
  {
    const std::vector<int>& chain = scratch.Chain;
    for (std::size_t i = 0; i < count; ++i)
    {
      scratch.Skipped[chain[i]] = scratch.Ray;
    }
    return count < chain.size() ? chain[count] : -1;
  }

private:
  /// Neighbors: faces whose 4 deformed corners are the same points, paired; and Through.
  void LinkFaces(const std::vector<RenderBox>& boxes)
  {
    std::vector<std::pair<std::array<double, 12>, int>> faces;
    faces.reserve(6 * boxes.size());
    for (std::size_t b = 0; b < boxes.size(); ++b)
    {
      for (int face = 0; face < 6; ++face)
      {
        std::array<glm::dvec3, 4> corners;
        for (int c = 0; c < 4; ++c)
        {
          corners[c] = boxes[b].Deformed.Corners[HexFacePatch[face][c]];
        }
        // The same corners in any order give the same key.
        std::sort(corners.begin(),
          corners.end(),
          [](const glm::dvec3& p, const glm::dvec3& q)
          { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
        std::array<double, 12> key;
        for (int c = 0; c < 4; ++c)
        {
          std::copy(&corners[c].x, &corners[c].x + 3, key.begin() + 3 * c);
        }
        faces.emplace_back(key, static_cast<int>(6 * b) + face);
      }
    }
    std::sort(faces.begin(), faces.end());
    this->Neighbors.assign(boxes.size(), { -1, -1, -1, -1, -1, -1 });
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
      const std::size_t end = std::find_if(faces.begin() + i,
                                faces.end(),
                                [&](const auto& f) { return f.first != faces[i].first; }) -
        faces.begin();
      if (end == i + 2) // a face shared by exactly two boxes
      {
        const int a = faces[i].second, b = faces[i + 1].second;
        this->Neighbors[a / 6][a % 6] = b;
        this->Neighbors[b / 6][b % 6] = a;
      }
      i = end - 1;
    }
    this->Through.assign(boxes.size(), { -1, -1, -1, -1, -1, -1 });
    for (std::size_t b = 0; b < boxes.size(); ++b)
    {
      for (int face = 0; face < 6; ++face)
      {
        const int link = this->Neighbors[b][face];
        if (link >= 0 && boxes[link / 6].Moved && boxes[link / 6].Label == boxes[b].Label)
        {
          this->Through[b][face] =
            link / 6 * 8 + ((link % 6) ^ 1); // the face opposite the shared one
        }
      }
    }
  }

  /// The tile of pixel (x, y) of the image.
  int TileOf(int x, int y) const { return this->TileRows[y] + this->TileColumns[x]; }

  /// The pixel (x z, y z, z) of `point`, z its depth along the eye's axis;
  /// false when it lies at or behind the eye plane.
  bool ProjectToPixel(const glm::dmat3& toPixel, const glm::dvec3& point, glm::dvec2& pixel) const
  {
    const glm::dvec3 v = toPixel * (point - this->Eye);
    if (!(v.z > 1e-6 * glm::length(v)))
    {
      return false;
    }
    pixel = glm::dvec2(v) / v.z;
    return true;
  }

  /// The ScreenHull of the corners `points[N]` of a deformed box (a box: all 8; a face: its
  /// 4, its bilinear patch lies in their convex hull); no edges when one does not project.
  template<std::size_t N>
  ScreenHull ProjectedHull(const glm::dvec3 (&corners)[8], const int (&points)[N]) const
  {
    const glm::dmat3 toPixel = glm::inverse(this->PixelToDirection);
    glm::dvec2 projected[8];
    for (std::size_t c = 0; c < N; ++c)
    {
      if (!this->ProjectToPixel(toPixel, corners[points[c]], projected[c]))
      {
        return {};
      }
    }
    return ScreenHull::Of(projected, static_cast<int>(N));
  }

  /// The 8 corners of a box, for ProjectedHull.
  static constexpr int HexCorners[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };

  /// The tiles (inclusive range; x1 < x0 for none) that the projection of
  /// `bounds` may touch.
  glm::ivec4 TileRange(const AxisBounds& bounds, int width, int height) const
  {
    const glm::dmat3 toPixel = glm::inverse(this->PixelToDirection);
    glm::dvec2 low(std::numeric_limits<double>::infinity());
    glm::dvec2 high(-std::numeric_limits<double>::infinity());
    for (int c = 0; c < 8; ++c)
    {
      const glm::dvec3 corner((c & 1) ? bounds.Max.x : bounds.Min.x,
        (c & 2) ? bounds.Max.y : bounds.Min.y,
        (c & 4) ? bounds.Max.z : bounds.Min.z);
      glm::dvec2 pixel;
      if (!this->ProjectToPixel(toPixel, corner, pixel))
      {
        return { 0, 0, this->TilesX - 1, this->TilesY - 1 };
      }
      low = glm::min(low, pixel);
      high = glm::max(high, pixel);
    }
    // One pixel of margin absorbs the rounding of the projection.
    const double x0 = std::max(std::floor(low.x) - 1.0, 0.0);
    const double y0 = std::max(std::floor(low.y) - 1.0, 0.0);
    const double x1 = std::min(std::ceil(high.x) + 1.0, width - 1.0);
    const double y1 = std::min(std::ceil(high.y) + 1.0, height - 1.0);
    if (x0 > x1 || y0 > y1)
    {
      return { 0, 0, -1, -1 };
    }
    return { static_cast<int>(x0) / this->TileSize,
      static_cast<int>(y0) / this->TileSize,
      static_cast<int>(x1) / this->TileSize,
      static_cast<int>(y1) / this->TileSize };
  }

  /**
   * Lists each box in the tiles of its bounds' TileRange that its projected
   * hull may reach (ScreenHull::MayHoldAny over the tile's pixels): a thin
   * slab turned across the view is listed along its sliver, not over its
   * bounds' whole rectangle. Each tile lists its boxes nearest first (by the
   * depth of their bounds' centres), so that the entries of a ray, where it
   * enters each box's bounds, come nearly sorted. Without culling, every box
   * goes into the one tile.
   */
  void BinBoxes(const std::vector<RenderBox>& boxes,
    int width,
    int height,
    bool culling,
    const RangeLoop& loop)
  {
    // Each box's tiles (in `loop`), then the (tile, box) pairs, nearest box
    // first, counted into place by tile.
    std::vector<std::vector<int>> tilesOf(boxes.size());
    loop(boxes.size(),
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t b = begin; b < end; ++b)
        {
          // Tile ranges x0, y0, x1, y1 (inclusive); without culling, the one tile.
          const glm::ivec4 r =
            culling ? this->TileRange(boxes[b].Bounds, width, height) : glm::ivec4(0);
          for (int ty = r.y; ty <= r.w; ++ty)
          {
            for (int tx = r.x; tx <= r.z; ++tx)
            {
              const int x0 = tx * this->TileSize, y0 = ty * this->TileSize;
              if (!culling ||
                this->Hulls[b].MayHoldAny(x0,
                  y0,
                  std::min(x0 + this->TileSize, width) - 1,
                  std::min(y0 + this->TileSize, height) - 1))
              {
                tilesOf[b].push_back(ty * this->TilesX + tx);
              }
            }
          }
        }
      });
    const glm::dmat3 toPixel = glm::inverse(this->PixelToDirection);
    std::vector<std::pair<double, int>> nearest(boxes.size());
    for (std::size_t b = 0; b < boxes.size(); ++b)
    {
      const glm::dvec3 centre = 0.5 * (boxes[b].Bounds.Min + boxes[b].Bounds.Max);
      nearest[b] = { (toPixel * (centre - this->Eye)).z, static_cast<int>(b) };
    }
    std::sort(nearest.begin(), nearest.end());
    this->TileStart.assign(static_cast<std::size_t>(this->TilesX) * this->TilesY + 1, 0);
    std::size_t pairs = 0;
    for (const std::vector<int>& tiles : tilesOf)
    {
      for (int tile : tiles)
      {
        ++this->TileStart[tile + 1];
      }
      pairs += tiles.size();
    }
    for (std::size_t i = 1; i < this->TileStart.size(); ++i)
    {
      this->TileStart[i] += this->TileStart[i - 1];
    }
    // Each pair's place in TileBoxes (its tile's in `pairTile`), then (in
    // `loop`) how the box meets its tile.
    this->TileBoxes.resize(pairs);
    std::vector<int> pairTile(pairs);
    std::vector<int> next(this->TileStart.begin(), this->TileStart.end() - 1);
    for (const auto& [depth, b] : nearest)
    {
      for (int tile : tilesOf[b])
      {
        const int i = next[tile]++;
        this->TileBoxes[i] = b;
        pairTile[i] = tile;
      }
    }
    this->TileHulls.assign(pairs, HullsInTile());
    this->TilePixels.resize(this->TileSize <= 8 ? pairs : 0);
    loop(pairs,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          const int tile = pairTile[i], b = this->TileBoxes[i];
          // The tile's pixels (x0, y0) to (x1, y1).
          const int x0 = tile % this->TilesX * this->TileSize;
          const int y0 = tile / this->TilesX * this->TileSize;
          const int x1 = std::min(x0 + this->TileSize, width) - 1;
          const int y1 = std::min(y0 + this->TileSize, height) - 1;
          HullsInTile& hulls = this->TileHulls[i];
          // (Without culling, a box whose hull misses the tile tests every edge.)
          const int boxAcross = this->Hulls[b].EdgesAcross(x0, y0, x1, y1);
          hulls.Box =
            static_cast<std::uint8_t>(boxAcross >= 0 ? boxAcross : (1 << this->Hulls[b].Count) - 1);
          if (!this->TilePixels.empty())
          {
            this->TilePixels[i] = this->Hulls[b].HeldPixels(x0, y0, y1 - y0 + 1, hulls.Box);
          }
          for (int face = 0; face < 6; ++face)
          {
            const int across = this->FaceHulls[b][face].EdgesAcross(x0, y0, x1, y1);
            hulls.FacesIn |= (across == 0) << face;
            hulls.FacesAcross |= (across > 0) << face;
            hulls.Faces[face] = static_cast<std::uint8_t>(std::max(across, 0));
          }
        }
      });
  }
};

/// What a view ray sees.
struct ViewSample
{
  int Label = -1; ///< the part (0: background or a part without a box; -1: no camera sees the ray)
  /// Meaningful when Label >= 0 or Coverage > 0 (then background is blended in).
  glm::dvec3 Color{ 0.0 };
  /// The ray parameter t of the seen point: with a proxy, its surface point
  /// (SegmentDepth); without, approximate: the middle of the accepted
  /// interval, or the lookup's FocalDepth when no box claims the ray; 0 for a
  /// ray that shows background through a fully owned light field.
  double Depth = 0.0;
  /// The part of the pixel that moved parts cover by anti-aliasing (see
  /// RenderViewSettings::AntiAliasing) where Label does not say so: > 0 on a
  /// ray whose Label is 0 or -1 that still shows a silhouette's soft edge in
  /// Color. 0 everywhere without a moved box.
  double Coverage = 0.0;
};

/// How RenderView treats the light field's parts.
struct RenderViewSettings
{
  /// The light field has labels. Without them no interval can match its
  /// box, and every ray sees the light field as it is (label 0).
  bool UseLabels = true;
  /// Try the widened search (paper Sec. 8) before giving up on the boxes.
  bool WidenedSearch = false;
  /// Every part of the light field has a box: a ray that no box claims is
  /// background (label 0), without a lookup.
  bool AllOwned = false;
  /// The labels that have a box (see OwnedLabels).
  std::array<bool, 256> Owned{};
  /**
   * Anti-aliased silhouettes of moved parts: the interval of a moved box is
   * as opaque as the share of its warped ray's samples (their interpolation
   * weights, up to 16 rays around it) that carry the box's label, and the
   * walk composites the intervals front to back by that coverage, so a
   * silhouette pixel blends the part with what lies behind it (another
   * part, the undeformed light field or Background) instead of a staircase
   * of whole pixels. Label and Depth still follow the vote (the first
   * interval whose vote is its box's label). Boxes at rest keep the vote's
   * all-or-nothing: a cage at rest renders exactly the undeformed light field.
   */
  bool AntiAliasing = true;
  /// The colour of background rays (0..255), blended behind soft edges.
  glm::dvec3 Background{ 0.0 };
  /**
   * The lookup samples every line at its focal plane or cylinder (no proxy:
   * Lookup::FocalParameter is where the cameras are sampled, known before
   * the lookup), so a run of a moved part's intervals is looked up only
   * from the one that holds the focal point (see ShadeSegments). Off: every
   * interval is looked up.
   */
  bool FocalBeforeLookup = false;
};

/// The labels of `boxes`, as RenderViewSettings::Owned.
inline std::array<bool, 256> OwnedLabels(const std::vector<RenderBox>& boxes)
{
  std::array<bool, 256> owned{};
  for (const RenderBox& box : boxes)
  {
    owned[box.Label] = true;
  }
  return owned;
}

/// The Lookup of RENDER_VIEW over a LightFieldSampler; the depth of a ray
/// that no box claims is its focal point's distance along `Forward` (the
/// camera's optical axis: camera z for rays whose camera z component is 1).
struct SamplerLookup
{
  const LightFieldSampler& Sampler;
  int WidenReach; ///< views tried on each side by the widened search
  glm::dvec3 Forward;

  /// Points tried along a segment by the widened search.
  static constexpr int WidenSteps = 8;

  bool Gather(const glm::dvec3& o, const glm::dvec3& d, RaySamples& out) const
  {
    return this->Sampler.Gather(o, d, out);
  }
  /// Gather in two stages over a batch of rays (RenderPlainViews).
  using Aimed = RayAim;
  void AimBatch(const glm::dvec3& o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    this->Sampler.AimBatch(o, d, count, aims, aimed);
  }
  /// The same from an origin per ray (RenderWalks).
  void AimBatch(const glm::dvec3* o,
    const glm::dvec3* d,
    int count,
    RayAim* aims,
    bool* aimed) const
  {
    this->Sampler.AimBatch(o, d, count, aims, aimed);
  }
  bool Sample(const glm::dvec3& o, const glm::dvec3& d, const RayAim& aim, RaySamples& out) const
  {
    return this->Sampler.Sample(o, d, aim, out);
  }
  /// FocalDepth() of an aimed ray (its focal point known).
  double FocalDepth(const glm::dvec3& o, const RayAim& aim) const
  {
    return glm::dot(aim.Focal - o, this->Forward);
  }
  bool Widen(const glm::dvec3& a, const glm::dvec3& b, int label, glm::dvec3& color) const
  {
    return this->Sampler.Widen(a, b, label, WidenSteps, this->WidenReach, color);
  }
  double FocalDepth(const glm::dvec3& o, const glm::dvec3& d) const
  {
    return glm::dot(
      FocalPoint(this->Sampler.Layout->Cyl, o, d, this->Sampler.FocalDistance) - o, this->Forward);
  }
  // (Always inlined: called out of line, through the library's PLT, by
  // every walked ray; the swim 0.99x.)
  __attribute__((always_inline)) double FocalParameter(const glm::dvec3& o,
    const glm::dvec3& d) const
  {
    return lfd::FocalParameter(this->Sampler.Layout->Cyl, o, d, this->Sampler.FocalDistance);
  }
};

namespace detail
{
/// Whether `Lookup` gathers in two stages (Aim(), Sample(); RenderPlainViews).
template<typename Lookup, typename = void>
struct Staged : std::false_type
{
};
template<typename Lookup>
struct Staged<Lookup, std::void_t<typename Lookup::Aimed>> : std::true_type
{
};

/// The first stage of a Lookup's gathering (Lookup::Aimed; none for a lookup without stages).
template<typename Lookup, bool = Staged<Lookup>::value>
struct FirstStage
{
  using type = typename Lookup::Aimed;
};
template<typename Lookup>
struct FirstStage<Lookup, false>
{
  struct type
  {
  };
};

/**
 * The light field's samples along the view ray itself, gathered at most once
 * per ray: a box that did not move warps the ray onto itself, so every
 * interval in such a box, and the final undeformed lookup, see exactly
 * these samples.
 */
template<typename Lookup>
struct ViewRayLook
{
  // A constructor, not aggregate initialisation: braces would zero the
  // ~700 bytes of Samples for every ray (10% of an undeformed frame).
  ViewRayLook(const Lookup& light, const glm::dvec3& o, const glm::dvec3& d)
    : Light(light)
    , O(o)
    , D(d)
  {
  }

  const Lookup& Light;
  const glm::dvec3& O;
  const glm::dvec3& D;
  std::optional<RaySamples> Samples; // constructed by the first lookup only
  bool Found = false;
  int Seen = -2; // -2: not voted yet

  /// Looks the view ray up once; false when it has no sample.
  bool Gather()
  {
    if (!this->Samples)
    {
      this->Samples.emplace();
      this->Found = this->Light.Gather(this->O, this->D, *this->Samples);
    }
    return this->Found;
  }

  /// The label voted along the view ray (-1: no sample).
  int Look()
  {
    if (this->Seen == -2)
    {
      this->Seen = this->Gather() ? VoteLabel(*this->Samples) : -1;
    }
    return this->Seen;
  }
};

/**
 * The ray parameter t of the point an interval shows: the proxy surface
 * point the samples were focused on (RaySamples::Surface), clamped to the
 * interval (a moved box: its rest depth along the warped ray, mapped to the
 * same fraction of the view ray's interval; a box at rest: the view ray's
 * own parameter), else the middle of the interval.
 */
inline double SegmentDepth(const WarpedSegment& segment, bool moved, double surface)
{
  if (std::isnan(surface))
  {
    return 0.5 * (segment.TEnter + segment.TExit);
  }
  if (moved)
  {
    return segment.TEnter + std::clamp(surface, 0.0, 1.0) * (segment.TExit - segment.TEnter);
  }
  return std::clamp(surface, segment.TEnter, segment.TExit);
}

/**
 * How much of the pixel of a ray shows a label that carries `covered` of its
 * samples' total weight `total` (summed in the samples' order): the share
 * s = covered / total, steepened about the vote's threshold,
 * clamp(0.5 + 2 (s - 0.5), 0, 1). One camera's bilinear weights ramp s over
 * one source pixel across a silhouette, as a pixel's coverage does; where
 * the ray's cameras disagree about the silhouette (parallax off the focal
 * surface), the mix of their ramps is wider, and the steepening keeps the
 * faint side of it (s <= 0.25: one camera of two, weighted least, sees the
 * part) from ghosting.
 */
inline double LabelCoverage(double covered, double total)
{
  if (!(total > 0.0))
  {
    return 0.0;
  }
  if (covered == total)
  {
    return 1.0;
  }
  return std::clamp(2.0 * (covered / total) - 0.5, 0.0, 1.0);
}

/**
 * Front-to-back compositing of a ray's intervals by label coverage: Color
 * holds what is in front, Transmittance what is left for what lies behind.
 */
struct CoverageComposite
{
  glm::dvec3 Color{ 0.0 };
  double Transmittance = 1.0;

  /// What lies behind under less than a quarter of a grey level of 255 is
  /// not looked up.
  static constexpr double Opaque = 1.0 / 1024.0;

  void Add(double alpha, const glm::dvec3& color)
  {
    this->Color += (this->Transmittance * alpha) * color;
    this->Transmittance *= 1.0 - alpha;
  }
  /// Color with `behind` filling the rest (exactly `behind` when nothing was added).
  glm::dvec3 Over(const glm::dvec3& behind) const
  {
    return this->Color + this->Transmittance * behind;
  }
};

/**
 * A matching interval held back (see the file's description): its part,
 * coverage, colour and depth.
 */
struct DeferredMatch
{
  int Label = -1; ///< -1: none held
  double Alpha = 0.0;
  glm::dvec3 Color{ 0.0 };
  double Depth = 0.0;
  bool OnSurface = false; ///< its samples were focused on the proxy surface
};

/// Composites `match` (a matching interval) and makes it the ray's label and depth.
inline void AcceptMatch(const DeferredMatch& match,
  CoverageComposite& composite,
  ViewSample& result,
  bool& matched)
{
  composite.Add(match.Alpha, match.Color);
  if (!matched)
  {
    matched = true;
    result.Label = match.Label;
    result.Depth = match.Depth;
  }
}

/// Whether the part an interval of `box` shows may be the part its lookup
/// saw rather than the box's own (ShownPart): the proxy puts the surface
/// at `surface` inside this moved box. Else the vote does not decide it.
inline bool ShowsSeenPart(const RenderBox& box, double surface)
{
  return box.Moved && surface >= 0.0 && surface <= 1.0;
}

/**
 * The part an interval of `box` shows when its lookup saw part `seen` on a
 * surface at `surface` (the proxy's crossing, in units of the rest segment;
 * NaN on the focal plane): its own label (Sec. 6's test), or, beyond the
 * paper, the part seen when the proxy puts that surface inside this moved
 * box (0 <= surface <= 1): the cage map moves whatever a box holds, so a
 * slice of a neighbouring part that the box's slab cut off (the figure's
 * torso above its slab face, inside the head's box) moves with this box, as
 * in the ground truth, instead of vanishing under the label test.
 */
inline int ShownPart(const RenderBox& box, int seen, double surface)
{
  return ShowsSeenPart(box, surface) && seen > 0 ? seen : box.Label;
}

/// `next` goes on with the part of `entry` where `entry` leaves off: a moved
/// box of the same label, entered where `entry` exits (up to rounding) or
/// across pieces left out (BoxSegment::Joins).
inline bool GoesOn(const std::vector<RenderBox>& boxes,
  const BoxSegment& entry,
  const BoxSegment& next)
{
  const RenderBox& box = boxes[next.Box];
  return box.Moved && box.Label == boxes[entry.Box].Label &&
    (next.Joins || next.Segment.TEnter <= entry.Segment.TExit * (1.0 + 1e-9));
}

/**
 * How many pieces of its run ShadeSegments leaves out ahead of an interval
 * whose focal point lies `focal` (> 1, SegmentFocal) rest segments
 * along its warped ray: pieces about as long as it along the ray put the
 * focal point floor(focal) pieces ahead; the walk jumps to the one before
 * and takes the last steps itself.
 */
inline std::size_t PiecesAhead(double focal)
{
  return focal >= 3.0 ? static_cast<std::size_t>(std::min(focal, 1e6)) - 2 : 0;
}

/**
 * How many of the `following` pieces that go on with the run of an interval
 * whose focal point lies `focal` rest segments along its warped ray the
 * walk jumps over: PiecesAhead, but never the run's last (it is looked up
 * when the focal point lies beyond it). The one rule of both walks: the
 * frame cage's, whose pieces follow along face neighbours
 * (FrameCage::FollowRun), and RenderView's over every interval, whose
 * pieces follow in the sorted intervals (GoesOn).
 */
inline std::size_t PiecesLeftOut(double focal, std::size_t following)
{
  return std::min(PiecesAhead(focal), following - (following > 0));
}

/**
 * Where the warped ray of `entry` samples the cameras, in units of its rest
 * segment (RenderViewSettings::FocalBeforeLookup; NaN without it, or for a
 * box that did not move). Beyond 1, the lookup of `entry` waits for the
 * next interval; in [0, 1], `entry` holds its run's focal point.
 * (Always inlined: a step of the walk, see RunCursor::Advance.)
 */
template<typename Lookup>
__attribute__((always_inline)) inline double SegmentFocal(const std::vector<RenderBox>& boxes,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  const BoxSegment& entry)
{
  if (!settings.FocalBeforeLookup || !boxes[entry.Box].Moved)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const WarpedSegment& segment = entry.Segment;
  return lookup.FocalParameter(segment.RestEnter, segment.RestExit - segment.RestEnter);
}

/// Where ShadeSegments is in a run, for the walk that hands its intervals out.
struct RunState
{
  BoxSegment* Looked = nullptr;   ///< the last interval of a run that was looked up
  BoxSegment* Deferred = nullptr; ///< an interval whose lookup waits for the next one
  double Focal = 0.0;             ///< the deferred one's SegmentFocal (> 1)
};

/**
 * Which of a ray's intervals ShadeSegments looks up, and in what order: the
 * rules on runs of its description, apart from the lookups (which decide
 * only when the walk stops), so that RenderWalks() can take the rays of a
 * batch to their first lookup before any ray is looked up.
 */
struct RunCursor
{
  RunState Run; ///< where the run is, as `next` sees it
  /// Handed out behind a deferred interval that ended its run (Waits):
  /// looked up after it.
  BoxSegment* Waiting = nullptr;
  bool Waits = false;

  /**
   * The next interval to look up, of those `next(view, run)` hands out
   * front to back (`focal`: its SegmentFocal, Shade's `known`); nullptr
   * when none is left.
   */
  // (Inlined into both its callers, RenderWalks' first steps and
  // ShadeSegments, with the walk's steps it calls, as one loop: as calls,
  // they cost the 100-slab bend 255.0 M instructions a frame, 244.3 M
  // inlined.)
  template<typename Lookup, typename Next>
  __attribute__((always_inline)) BoxSegment* Advance(const std::vector<RenderBox>& boxes,
    const Lookup& lookup,
    const RenderViewSettings& settings,
    Next& next,
    ViewRayLook<Lookup>& view,
    double& focal)
  {
    for (;;)
    {
      BoxSegment* handed = this->Waiting;
      if (this->Waits)
      {
        this->Waits = false;
      }
      else
      {
        handed = next(view, this->Run);
        if (this->Run.Deferred && !(handed && GoesOn(boxes, *this->Run.Deferred, *handed)))
        {
          // The run ends with the deferred interval: it is looked up after all.
          focal = this->Run.Focal;
          this->Waiting = handed;
          this->Waits = true;
          return std::exchange(this->Run.Deferred, nullptr);
        }
        this->Run.Deferred = nullptr;
      }
      if (!handed)
      {
        return nullptr;
      }
      if (this->Run.Looked && GoesOn(boxes, *this->Run.Looked, *handed))
      {
        // The run was looked up from its focal piece: the pieces behind it
        // sample the cameras at a focal point in front of their entry, about
        // where that lookup did.
        this->Run.Looked = handed;
        continue;
      }
      focal = SegmentFocal(boxes, lookup, settings, *handed);
      if (focal > 1.0)
      {
        this->Run.Deferred = handed;
        this->Run.Focal = focal;
        this->Run.Looked = nullptr;
        continue;
      }
      // A run entered behind its focal point is looked up from its first piece:
      // the pieces behind sample the cameras near where it did too (against
      // the ground truth, looking each up was worse: a dragged slab corner,
      // 23.60 dB; this, 25.92 dB; only runs holding their focal point, 23.65).
      this->Run.Looked = std::isnan(focal) ? nullptr : handed;
      return handed;
    }
  }
};

/**
 * A ray's walk taken ahead to its first lookup with those of other rays
 * (RenderWalks()): Run, where the walk then is; Segment, the interval
 * looked up first (nullptr: none, the walk ends at once), and Focal, its
 * SegmentFocal; with a lookup that gathers in two stages, the first stage
 * of its warped ray (Aim; nullptr: not aimed ahead, the walk gathers it)
 * and whether the ray may have samples (Found: the first stage's result).
 */
template<typename Lookup>
struct PrimedSegment
{
  RunCursor Run;
  BoxSegment* Segment = nullptr;
  double Focal = 0.0;
  const typename FirstStage<Lookup>::type* Aim = nullptr;
  bool Found = false;
};

/**
 * One ray's walk through its intervals, front to back (ShadeSegments):
 * composited by label coverage (RenderViewSettings::AntiAliasing) into
 * Composite; the first interval whose warped ray shows its box's label
 * (Sec. 6; an interval of a moved box whose focal point lies beyond its
 * exit is held back for the next ones of its part, see DeferredMatch) gives
 * Result its label and depth. Without anti-aliasing (and in boxes at rest)
 * an interval covers all or nothing, so the first match gives the whole
 * colour.
 */
template<typename Lookup>
struct SegmentWalk
{
  // A constructor, not aggregate initialisation: braces zero the whole walk,
  // the ~650 bytes of Samples included, for every ray that meets a box.
  SegmentWalk(const std::vector<RenderBox>& boxes,
    const Lookup& light,
    const RenderViewSettings& settings,
    ViewRayLook<Lookup>& view,
    ViewSample& result,
    CoverageComposite& composite)
    : Boxes(boxes)
    , Light(light)
    , Settings(settings)
    , View(view)
    , Result(result)
    , Composite(composite)
  {
  }

  const std::vector<RenderBox>& Boxes;
  const Lookup& Light;
  const RenderViewSettings& Settings;
  ViewRayLook<Lookup>& View;
  ViewSample& Result;
  CoverageComposite& Composite;
  RaySamples Samples;
  bool Matched = false;
  DeferredMatch Held;
  /// The interval aimed ahead of the walk, if any (see RenderWalks()).
  const PrimedSegment<Lookup>* Primed = nullptr;

  /// Gather() of the warped ray of `entry`, from its first stage if it was aimed ahead.
  bool Gather(const BoxSegment& entry, const glm::dvec3& direction)
  {
    if constexpr (Staged<Lookup>::value)
    {
      if (this->Primed && this->Primed->Segment == &entry && this->Primed->Aim)
      {
        if (!this->Primed->Found)
        {
          this->Samples.Clear(); // (as Gather)
          return false;
        }
        return this->Light.Sample(
          entry.Segment.RestEnter, direction, *this->Primed->Aim, this->Samples);
      }
    }
    return this->Light.Gather(entry.Segment.RestEnter, direction, this->Samples);
  }

  /// Past the match, only what still shows through is looked up.
  bool Going() const
  {
    return this->Held.Label >= 0 || !this->Matched ||
      this->Composite.Transmittance > CoverageComposite::Opaque;
  }

  /**
   * Looks `entry` up and composites it (records what it showed in
   * BoxSegment::Seen); `known` is its SegmentFocal, so that a focal point found
   * before the lookup is not found again.
   */
  // (Always inlined, into the walk's loop in ShadeSegments, inlined in turn
  // into RenderWalks (see ShadeView): the swim 111.0 -> 110.0 M instructions
  // a frame, the 3-box bend 113.5 -> 112.4 M, 100 slabs 220.0 -> 218.5 M.)
  __attribute__((always_inline)) void Shade(BoxSegment& entry, double known)
  {
    const RenderBox& box = this->Boxes[entry.Box];
    if (this->Held.Label >= 0 && box.Label != this->Held.Label)
    {
      // Another part: the held interval of the part in front gives the pixel.
      AcceptMatch(this->Held, this->Composite, this->Result, this->Matched);
      this->Held.Label = -1;
      if (this->Composite.Transmittance <= CoverageComposite::Opaque)
      {
        return;
      }
    }
    const WarpedSegment& segment = entry.Segment;
    const glm::dvec3 direction = segment.RestExit - segment.RestEnter;
    // The pixel's label is the box's part even where it shows a slice of
    // another: the part that moves it (as lfd eval groundtruth labels the
    // mesh by the rest boxes).
    DeferredMatch candidate;
    candidate.Label = box.Label;
    int shown = box.Label;
    double surface = 0.0;
    if (!box.Moved)
    {
      entry.Seen = this->View.Look();
      if (entry.Seen != shown) // (ShownPart: a box at rest shows its own label)
      {
        return;
      }
      candidate.Alpha = 1.0;
      surface = this->View.Samples->Surface;
      BlendLabel(*this->View.Samples, shown, candidate.Color);
    }
    else
    {
      if (glm::dot(direction, direction) <= 0.0 || !this->Gather(entry, direction))
      {
        return;
      }
      surface = this->Samples.Surface;
      const bool byVote = ShowsSeenPart(box, surface);
      if (byVote)
      {
        entry.Seen = VoteLabel(this->Samples);
        shown = ShownPart(box, entry.Seen, surface);
      }
      // The coverage and the blend of the shown label in one pass over the
      // samples (each sum in the samples' order, as BlendLabel's), which
      // also finds whether they all carry the first one's label.
      double total = 0.0, covered = 0.0;
      glm::dvec3 sum(0.0);
      const int first = this->Samples.Count > 0 ? this->Samples.Samples[0].Label : -1;
      bool uniform = true;
      for (int i = 0; i < this->Samples.Count; ++i)
      {
        const RaySample& sample = this->Samples.Samples[i];
        total += sample.Weight;
        uniform &= sample.Label == first;
        if (sample.Label == shown)
        {
          covered += sample.Weight;
          sum += sample.Weight * sample.Color;
        }
      }
      if (!byVote)
      {
        // One label (most intervals: inside a part, or beside it) is the
        // vote when it weighs anything, its weight summed as `total`, as
        // VoteLabel's tally sums it; else the tally decides.
        entry.Seen = uniform ? (total > 0.0 ? first : -1) : VoteLabel(this->Samples);
      }
      candidate.Alpha = this->Settings.AntiAliasing ? LabelCoverage(covered, total)
                                                    : (entry.Seen == shown ? 1.0 : 0.0);
      if (candidate.Alpha <= 0.0)
      {
        return;
      }
      if (covered > 0.0)
      {
        candidate.Color = sum / covered;
      }
    }
    if (entry.Seen != shown)
    {
      this->Composite.Add(candidate.Alpha, candidate.Color);
      return;
    }
    candidate.Depth = SegmentDepth(segment, box.Moved, surface);
    candidate.OnSurface = !std::isnan(surface);
    if (box.Moved && this->Held.Label >= 0 && this->Held.OnSurface && !candidate.OnSurface)
    {
      // A later interval whose lookup found no surface is focused on the
      // plane, on other texels than the surface the held one found: it
      // neither gives the pixel nor replaces the held interval.
      return;
    }
    const double focal = candidate.OnSurface ? surface
      : std::isnan(known) ? this->Light.FocalParameter(segment.RestEnter, direction)
                          : known;
    if (box.Moved && focal > 1.0)
    {
      this->Held = candidate;
      return;
    }
    this->Held.Label = -1; // this interval of the held part holds its focal point
    AcceptMatch(candidate, this->Composite, this->Result, this->Matched);
  }
};

/**
 * The intervals, front to back (`next(view, run)` hands them out, nullptr
 * after the last; a pointer it returned stays valid for the ray; `run` is a
 * RunState), shaded by SegmentWalk into `result` and `composite`, in
 * RunCursor's order; `primed`, if not null, the walk taken ahead to its
 * first lookup (RenderWalks()). True when an interval matched.
 *
 * With RenderViewSettings::FocalBeforeLookup, a run of intervals of a moved
 * part (boxes of one label, each entered where the one before is left: the
 * slabs of a cage, the sub-boxes of a tessellation) is looked up only from
 * the interval that holds the focal point of its warped ray (or the run's
 * last): an interval whose focal point lies beyond its exit is skipped when
 * the next one goes on with its part. The cameras are sampled at a warped
 * ray's focal point, and the run's pieces in front of the one that holds it
 * stray from the curved rest image of the view ray there (see the file's
 * description), so their lookups are at best the held fallback of a
 * DeferredMatch; a ray through 100 slabs would otherwise look up every one
 * up to its focal point. The run is looked up once: the intervals that go
 * on with it behind the looked-up one sample the cameras at a focal point
 * in front of their entry, about where that lookup did, and are skipped
 * (looking them up composited the part's coverage again at a silhouette:
 * the bent 100-slab fish against its ground truth, 26.23 -> 27.56 dB).
 */
template<typename Lookup, typename Next>
bool ShadeSegments(const std::vector<RenderBox>& boxes,
  Next&& next,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  ViewRayLook<Lookup>& view,
  ViewSample& result,
  CoverageComposite& composite,
  const PrimedSegment<Lookup>* primed)
{
  SegmentWalk<Lookup> walk{ boxes, lookup, settings, view, result, composite };
  walk.Primed = primed;
  RunCursor run;
  double focal = 0.0;
  BoxSegment* entry = nullptr;
  if (primed)
  {
    run = primed->Run;
    entry = primed->Segment;
    focal = primed->Focal;
  }
  else
  {
    entry = run.Advance(boxes, lookup, settings, next, view, focal);
  }
  while (entry)
  {
    walk.Shade(*entry, focal);
    entry = walk.Going() ? run.Advance(boxes, lookup, settings, next, view, focal) : nullptr;
  }
  if (walk.Held.Label >= 0)
  {
    AcceptMatch(walk.Held, composite, result, walk.Matched);
  }
  return walk.Matched;
}

/// Sec. 8: where the nearby cameras saw another part in a moved box, that
/// part may have hidden this one before the deformation uncovered it: look
/// in further cameras, front to back.
template<typename Lookup>
bool WidenSegments(const std::vector<RenderBox>& boxes,
  const std::vector<BoxSegment>& segments,
  const Lookup& lookup,
  ViewSample& result)
{
  for (const BoxSegment& entry : segments)
  {
    const RenderBox& box = boxes[entry.Box];
    const WarpedSegment& segment = entry.Segment;
    if (box.Moved && entry.Seen > 0 &&
      lookup.Widen(segment.RestEnter, segment.RestExit, box.Label, result.Color))
    {
      result.Label = box.Label;
      result.Depth = 0.5 * (segment.TEnter + segment.TExit);
      return true;
    }
  }
  return false;
}

/**
 * The undeformed light field seen by a ray that no box claims, from its
 * samples: with labels, the heaviest label that no box owns (background
 * included). `focalDepth()` is the depth of samples not focused on a proxy
 * surface.
 */
template<typename FocalDepth>
ViewSample ShadeUndeformed(const RaySamples& samples,
  const RenderViewSettings& settings,
  FocalDepth&& focalDepth)
{
  ViewSample result;
  result.Depth = std::isnan(samples.Surface) ? focalDepth() : samples.Surface;
  if (!settings.UseLabels)
  {
    BlendLabel(samples, 0, result.Color);
    result.Label = 0;
    return result;
  }
  // The vote and the blend of its label in one pass, the samples of owned
  // labels weighing nothing.
  const LabelTally<true> tally(samples, settings.Owned.data());
  const int best = tally.Heaviest();
  if (best >= 0)
  {
    result.Label = tally.Labels[best];
    result.Color = glm::dvec3(tally.Colors[best][0], tally.Colors[best][1], tally.Colors[best][2]) /
      tally.Weights[best];
  }
  return result;
}

/// The undeformed light field along a ray that no box claims (ShadeUndeformed()).
template<typename Lookup>
ViewSample LookUndeformed(ViewRayLook<Lookup>& view, const RenderViewSettings& settings)
{
  if (!view.Gather())
  {
    return {};
  }
  return ShadeUndeformed(
    *view.Samples, settings, [&] { return view.Light.FocalDepth(view.O, view.D); });
}
} // namespace detail

namespace detail
{
/// The colour a ray shows behind soft edges: Background where `seen` is
/// background (with labels) or nothing.
inline glm::dvec3 ShownColor(const ViewSample& seen, const RenderViewSettings& settings)
{
  return seen.Label < 0 || (settings.UseLabels && seen.Label == 0) ? settings.Background
                                                                   : seen.Color;
}

/// `seen` (what lies behind), in place, under the intervals composited in front of it.
inline void Composite(const CoverageComposite& front,
  ViewSample& seen,
  const RenderViewSettings& settings)
{
  if (front.Transmittance < 1.0)
  {
    seen.Color = front.Over(ShownColor(seen, settings));
    seen.Coverage = 1.0 - front.Transmittance;
  }
}

/**
 * RENDER_VIEW (Sec. 6) of the ray `view` looks up, whose intervals
 * `next(view, run)` hands out front to back into `segments` (`any`: the ray
 * may have some), into `result`; `primed` as ShadeSegments'.
 */
// (Always inlined: into RenderWalks(), with ShadeSegments, which the
// compiler then inlines there too, a walked ray's shading is no longer
// three nested calls, each saving registers and passing its arguments and
// its ViewSample through memory: the swim 113.7 -> 111.0 M instructions a
// frame. Shaded in the caller's ViewSample, the frame's own: returned, it
// was copied twice on its way there, each copy read back while the stores
// of the one before were in flight.)
template<typename Lookup, typename Next>
__attribute__((always_inline)) inline void ShadeView(ViewRayLook<Lookup>& view,
  const std::vector<RenderBox>& boxes,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  bool any,
  Next&& next,
  const std::vector<BoxSegment>& segments,
  const PrimedSegment<Lookup>* primed,
  ViewSample& result)
{
  result = ViewSample();
  CoverageComposite front;
  if (settings.UseLabels && !boxes.empty())
  {
    // (Most rays of a frame miss every box: they skip the segment walk. The
    // widened search runs after the walk handed every interval out.)
    if (any && ShadeSegments(boxes, next, lookup, settings, view, result, front, primed))
    {
      if (front.Transmittance <= CoverageComposite::Opaque)
      {
        result.Color = front.Color;
        return;
      }
      // A soft edge: what no box owns shows behind it.
      ViewSample behind;
      behind.Label = 0;
      if (!settings.AllOwned)
      {
        behind = LookUndeformed(view, settings);
      }
      result.Color = front.Over(ShownColor(behind, settings));
      return;
    }
    if (any && settings.WidenedSearch && WidenSegments(boxes, segments, lookup, result))
    {
      Composite(front, result, settings);
      return;
    }
    if (settings.AllOwned)
    {
      result.Label = 0;
      Composite(front, result, settings);
      return;
    }
  }
  result = LookUndeformed(view, settings);
  Composite(front, result, settings);
}
} // namespace detail

/**
 * RENDER_VIEW (Sec. 6) for the view ray o + t d, t >= 0, through `boxes`
 * (rest and deformed corners, PlaceEye() called for this eye). `segments`
 * is scratch space whose capacity is reused from ray to ray; on return it
 * holds the ray's intervals, sorted by distance.
 */
template<typename Lookup>
ViewSample RenderView(const glm::dvec3& o,
  const glm::dvec3& d,
  const std::vector<RenderBox>& boxes,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  std::vector<BoxSegment>& segments)
{
  segments.clear();
  if (settings.UseLabels && !boxes.empty())
  {
    CollectSegments(boxes, o, d, segments);
  }
  std::size_t k = 0;
  const BoxSegment* jumped = nullptr;
  detail::ViewRayLook<Lookup> view{ lookup, o, d };
  ViewSample seen;
  detail::ShadeView(
    view,
    boxes,
    lookup,
    settings,
    !segments.empty(),
    [&](detail::ViewRayLook<Lookup>&, const detail::RunState& run)
    {
      if (run.Deferred && run.Deferred != jumped && detail::PiecesAhead(run.Focal) > 0)
      {
        // The run's pieces that follow are the intervals that go on with it.
        jumped = run.Deferred;
        std::size_t last = k; // one past the run's pieces that follow
        while (last < segments.size() &&
          detail::GoesOn(boxes, last == k ? *run.Deferred : segments[last - 1], segments[last]))
        {
          ++last;
        }
        const std::size_t left = detail::PiecesLeftOut(run.Focal, last - k);
        k += left;
        segments[std::min(k, segments.size() - 1)].Joins = left > 0;
      }
      return k < segments.size() ? &segments[k++] : nullptr;
    },
    segments,
    static_cast<const detail::PrimedSegment<Lookup>*>(nullptr),
    seen);
  return seen;
}

/// The most rays RenderPlainViews takes at once.
constexpr int MaximumPlainBatch = LightFieldSampler::MaximumBatch;

/**
 * RenderView for the rays through the pixels (xs[i], y), i < count <=
 * MaximumPlainBatch, xs ascending, of a frame, rays that no box may claim
 * (not walked by RenderWalks(): the frame has no box or no labels, the
 * ray's tile lists none or its walk finds none): the same results, into
 * `seen`. With a lookup that gathers in two stages (SamplerLookup:
 * AimBatch() and Sample()), the batch runs the first stage, the rays'
 * geometry, for every ray before the second, the texels, for any (and the
 * first stage may bound the batch's geometry at once: LightFieldSampler::
 * EntrySectors()). A ray's lookup is one dependent chain of divisions and
 * square roots (some 900 instructions, more than the processor's reorder
 * window holds), so looked up ray after ray, the rays do not overlap; the
 * first stages of neighbouring rays, run back to back, do.
 */
template<typename Lookup>
void RenderPlainViews(const FrameCage& cage,
  const int* xs,
  int y,
  int count,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  ViewSample* seen)
{
  if (settings.UseLabels && !cage.Boxes->empty() && settings.AllOwned)
  {
    // As ShadeView: every part has a box, none claims these rays.
    for (int i = 0; i < count; ++i)
    {
      seen[i] = ViewSample{};
      seen[i].Label = 0;
    }
    return;
  }
  glm::dvec3 d[MaximumPlainBatch];
  if constexpr (detail::Staged<Lookup>::value)
  {
    typename Lookup::Aimed aims[MaximumPlainBatch];
    bool aimed[MaximumPlainBatch];
    for (int i = 0; i < count; ++i)
    {
      d[i] = cage.Direction(xs[i], y);
    }
    lookup.AimBatch(cage.Eye, d, count, aims, aimed);
    RaySamples samples;
    for (int i = 0; i < count; ++i)
    {
      seen[i] = aimed[i] && lookup.Sample(cage.Eye, d[i], aims[i], samples)
        ? detail::ShadeUndeformed(
            samples, settings, [&] { return lookup.FocalDepth(cage.Eye, aims[i]); })
        : ViewSample{};
    }
  }
  else
  {
    for (int i = 0; i < count; ++i)
    {
      d[i] = cage.Direction(xs[i], y);
      detail::ViewRayLook<Lookup> view{ lookup, cage.Eye, d[i] };
      seen[i] = detail::LookUndeformed(view, settings);
    }
  }
}

namespace detail
{
/**
 * The intervals of the ray `cage` walks in `Ray` (FrameCage::StartWalk()),
 * handed out one by one as ShadeSegments' `next` (RenderWalks()): boxes
 * warped only as far as needed, a run's pieces that its lookup leaves out
 * not warped.
 */
template<typename Lookup>
struct FrameWalk
{
  const FrameCage& Cage;
  FrameRayScratch& Ray;
  const glm::dvec3& D;

  // (Inlined: see RunCursor::Advance.)
  __attribute__((always_inline)) BoxSegment* operator()(ViewRayLook<Lookup>& view,
    const RunState& run) const
  {
    const FrameCage& cage = this->Cage;
    const std::vector<RenderBox>& boxes = *cage.Boxes;
    FrameRayScratch& ray = this->Ray;
    // (Once every box of the walk is warped, there is none left to leave
    // out: most rays that meet a box of the swim have one.)
    const bool warping = ray.NextEntry < ray.Entries.size();
    if (warping && run.Looked && run.Looked != ray.RunSkipped)
    {
      // The run was looked up: its pieces behind are not warped either.
      cage.FollowRun(*run.Looked, boxes.size(), ray);
      cage.LeaveOut(ray.Chain.size(), ray);
      ray.RunSkipped = run.Looked;
    }
    else if (warping && run.Deferred && run.Deferred != ray.RunSkipped &&
      PiecesAhead(run.Focal) > 0)
    {
      // (One piece more than the jump: the run's last is never left out.)
      cage.FollowRun(*run.Deferred, PiecesAhead(run.Focal) + 1, ray);
      ray.Landing = cage.LeaveOut(PiecesLeftOut(run.Focal, ray.Chain.size()), ray);
      ray.RunSkipped = run.Deferred;
    }
    // A box that did not move shows the view ray's own label (ShadeSegments):
    // when that is not its label, none of its intervals can give the pixel
    // (and the widened search only tries moved boxes), so it is not warped.
    return cage.NextSegment(this->D,
      ray,
      [&](int b)
      {
        const RenderBox& box = boxes[b];
        return !box.Moved && view.Look() != box.Label;
      });
  }
};

/// A walked ray of RenderWalks(): its view ray's lookup and its walk taken
/// ahead to its first lookup.
template<typename Lookup>
struct WalkedRay
{
  WalkedRay(const Lookup& light, const glm::dvec3& o, const glm::dvec3& d)
    : View(light, o, d)
  {
  }

  ViewRayLook<Lookup> View;
  PrimedSegment<Lookup> Primed;
};
} // namespace detail

/**
 * RenderView for the rays through the pixels (xs[i], y), i < count <=
 * MaximumPlainBatch, of a frame, into seen[i], when a box may claim the
 * ray (walked[i]): the frame has labels and the ray's walk finds a box
 * (FrameCage::StartWalk()). The boxes are tried and warped through `cage`,
 * front to back and only as far as needed, ray i in scratch[i]. On return
 * the first scratch[i].Handed of scratch[i].Segments are the ray's
 * intervals up to the one that gave the pixel (all of them when none did),
 * but those of boxes that did not move and whose label the view ray does
 * not show.
 *
 * walked[i] false, seen[i] untouched: no box may claim the ray, which sees
 * what RenderPlainViews() gives it. A frame's renderer batches those rays,
 * and calls RenderWalks only in the tiles that list a box (FrameCage::
 * CountCandidates(): 40 800 of the 3-box swim's 262 000 rays, 3 400 of
 * which meet none).
 *
 * Every ray's walk is taken to its first lookup (RunCursor: its boxes
 * warped, a slab run's pieces in front of its focal point left out) before
 * any ray's walk goes on, the box each walk warps first warped for the
 * batch at once, four rays at a time (FrameCage::WarpAhead(): a warp is a
 * dependent chain too); with a lookup that gathers in two stages, the
 * warped rays of those first lookups (of moved boxes) are aimed in one
 * batch (AimBatch() from an origin per ray): each one's geometry is a long
 * dependent chain, as a plain ray's (RenderPlainViews()), and the chains
 * of the batch overlap. Only what the walk looks up is aimed.
 */
template<typename Lookup>
void RenderWalks(const FrameCage& cage,
  const int* xs,
  int y,
  int count,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  FrameRayScratch* scratch,
  ViewSample* seen,
  bool* walked)
{
  if (!settings.UseLabels)
  {
    std::fill(walked, walked + count, false);
    return;
  }
  const std::vector<RenderBox>& boxes = *cage.Boxes;
  glm::dvec3 d[MaximumPlainBatch];
  // The walked rays' view lookups and walks, constructed for the walked
  // rays only (as arrays, all ~12 KB would be initialised for every batch,
  // most of it for rays that are not walked: a tile row holds 8 rays).
  static_assert(std::is_trivially_destructible<detail::WalkedRay<Lookup>>::value,
    "the walked rays are never destroyed");
  union Walks
  {
    Walks() {} // (none constructed)
    detail::WalkedRay<Lookup> Ray[MaximumPlainBatch];
  } walks;
  for (int i = 0; i < count; ++i)
  {
    d[i] = cage.Direction(xs[i], y);
    walked[i] = cage.StartWalk(xs[i], y, d[i], scratch[i]) > 0;
  }
  cage.WarpAhead(d, walked, count, scratch);
  for (int i = 0; i < count; ++i)
  {
    if (walked[i])
    {
      detail::WalkedRay<Lookup>& ray =
        *new (&walks.Ray[i]) detail::WalkedRay<Lookup>(lookup, cage.Eye, d[i]);
      detail::FrameWalk<Lookup> next{ cage, scratch[i], d[i] };
      ray.Primed.Segment =
        ray.Primed.Run.Advance(boxes, lookup, settings, next, ray.View, ray.Primed.Focal);
    }
  }
  typename detail::FirstStage<Lookup>::type aims[MaximumPlainBatch]; // (PrimedSegment::Aim)
  if constexpr (detail::Staged<Lookup>::value)
  {
    glm::dvec3 origins[MaximumPlainBatch], directions[MaximumPlainBatch];
    bool aimed[MaximumPlainBatch];
    int rays[MaximumPlainBatch];
    int n = 0;
    for (int i = 0; i < count; ++i)
    {
      // (SegmentWalk::Shade gathers the warped rays of moved boxes only, and
      // only when they have a direction.)
      const BoxSegment* first = walked[i] ? walks.Ray[i].Primed.Segment : nullptr;
      if (first && boxes[first->Box].Moved)
      {
        origins[n] = first->Segment.RestEnter;
        directions[n] = first->Segment.RestExit - first->Segment.RestEnter;
        if (glm::dot(directions[n], directions[n]) > 0.0)
        {
          rays[n++] = i;
        }
      }
    }
    lookup.AimBatch(origins, directions, n, aims, aimed);
    for (int k = 0; k < n; ++k)
    {
      walks.Ray[rays[k]].Primed.Aim = &aims[k];
      walks.Ray[rays[k]].Primed.Found = aimed[k];
    }
  }
  for (int i = 0; i < count; ++i)
  {
    if (walked[i])
    {
      // (The widened search reads scratch[i].Segments when no interval
      // matched: the walk then handed every one out.)
      detail::ShadeView(walks.Ray[i].View,
        boxes,
        lookup,
        settings,
        true,
        detail::FrameWalk<Lookup>{ cage, scratch[i], d[i] },
        scratch[i].Segments,
        &walks.Ray[i].Primed,
        seen[i]);
    }
  }
}

/**
 * RenderView for the ray through pixel (x, y) of a frame: the same result,
 * with the boxes tried and warped through `cage` (RenderWalks(), a batch
 * of one); scratch as RenderWalks leaves it.
 */
template<typename Lookup>
ViewSample RenderView(const FrameCage& cage,
  int x,
  int y,
  const Lookup& lookup,
  const RenderViewSettings& settings,
  FrameRayScratch& scratch)
{
  ViewSample seen;
  bool walked;
  RenderWalks(cage, &x, y, 1, lookup, settings, &scratch, &seen, &walked);
  if (!walked)
  {
    scratch.Segments.clear();
    scratch.Handed = 0;
    RenderPlainViews(cage, &x, y, 1, lookup, settings, &seen);
  }
  return seen;
}

} // namespace lfd

#endif
