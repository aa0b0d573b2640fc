// The cylindrical sampling kernel (Sec. 6.2): entry intersection, choice of
// the neighbouring views and their weights (including the wrap-around of the
// ring and two rows), and label-aware blending, on a light field whose views
// are flat colours so that every expected value is exact.
#include "lfdCylinderSampling.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

using lfdtest::Expect;

namespace
{
// The texel stage's SSE2 kernels against their scalar definitions, to the
// bit: lfd::BlendTexels against the lerp form on random texels and
// fractions, lfd::BilinearFootprint against std::floor at the edges of its
// range (-1, negative fractions, the last column, NaN) and at random points.
void TexelKernelsMatchScalar()
{
  std::uint32_t seed = 2005;
  const auto next = [&seed]()
  {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  int blendDiffers = 0;
  for (int i = 0; i < 20000; ++i)
  {
    std::uint8_t top[6], bottom[6];
    for (int k = 0; k < 6; ++k)
    {
      top[k] = static_cast<std::uint8_t>(next());
      bottom[k] = static_cast<std::uint8_t>(next());
    }
    const double ax = next() / double(1u << 24);
    const double ay = i % 16 == 0 ? 0.0 : next() / double(1u << 24);
    double color[3];
    lfd::BlendTexels(top, bottom, ax, ay, color);
    for (int c = 0; c < 3; ++c)
    {
      const double upper = top[c] + ax * (double(top[3 + c]) - double(top[c]));
      const double lower = bottom[c] + ax * (double(bottom[3 + c]) - double(bottom[c]));
      blendDiffers += color[c] != upper + ay * (lower - upper);
    }
  }
  Expect("BlendTexels channels differing from the scalar lerp (of 60000)", blendDiffers, 0.0, 0.0);

  const int width = 7, height = 5;
  std::vector<glm::dvec2> points = { { -1.0, -1.0 },
    { -0.5, 0.25 },
    { -1e-17, 3.0 },
    { 0.0, 0.0 },
    { width - 1e-9, height - 1e-9 },
    { width, 0.0 },
    { 0.0, height },
    { -1.0 - 1e-12, 0.0 },
    { std::nan(""), 0.0 },
    { 0.0, std::nan("") } };
  for (int i = 0; i < 2000; ++i)
  {
    const double u = -2.0 + (width + 3.0) * next() / double(1u << 24);
    points.emplace_back(u, -2.0 + (height + 3.0) * next() / double(1u << 24));
  }
  int footprintDiffers = 0;
  for (const glm::dvec2& uv : points)
  {
    int x0 = 0, y0 = 0;
    glm::dvec2 fraction;
    const bool inside = lfd::BilinearFootprint(uv, width, height, x0, y0, fraction);
    const bool expected = uv.x >= -1.0 && uv.y >= -1.0 && uv.x < width && uv.y < height;
    footprintDiffers += inside != expected ||
      (expected &&
        (x0 != std::floor(uv.x) || y0 != std::floor(uv.y) ||
          fraction.x != uv.x - std::floor(uv.x) || fraction.y != uv.y - std::floor(uv.y)));
  }
  Expect(
    "BilinearFootprint points differing from std::floor's footprint", footprintDiffers, 0.0, 0.0);
}

// The ray from far outside the ring at azimuth `phi` (radians, measured like
// the rig: from +Z towards +X for a +Y axis) and height `h`, aimed at the axis.
void RayAt(double phi, double h, glm::dvec3& o, glm::dvec3& d)
{
  o = glm::dvec3(10.0 * std::sin(phi), h, 10.0 * std::cos(phi));
  d = glm::normalize(glm::dvec3(0.0, h, 0.0) - o);
}

// lfd::Azimuth against std::atan2 shifted into [0, 2 pi): the axes to the
// last bits (-0.0 and tiny negative y at 0, not 2 pi), within 2e-10 radian
// over 100 000 directions around the circle at lengths from 1e-3 to 70.
void AzimuthMatchesAtan2()
{
  Expect("azimuth of +x", lfd::Azimuth(0.0, 1.0), 0.0, 0.0);
  Expect("azimuth of -0.0 y", lfd::Azimuth(-0.0, 1.0), 0.0, 0.0);
  Expect("azimuth of a tiny negative y", lfd::Azimuth(-1e-300, 1.0), 0.0, 0.0);
  Expect("azimuth of +y", lfd::Azimuth(1.0, 0.0), 0.25 * lfd::TwoPi, 1e-15);
  Expect("azimuth of -x", lfd::Azimuth(0.0, -1.0), 0.5 * lfd::TwoPi, 1e-15);
  Expect("azimuth of -y", lfd::Azimuth(-1.0, 0.0), 0.75 * lfd::TwoPi, 1e-15);
  Expect("azimuth of the origin", lfd::Azimuth(0.0, 0.0), 0.0, 0.0);
  double worst = 0.0;
  bool inRange = true;
  for (int i = 0; i < 100000; ++i)
  {
    const double angle = lfd::TwoPi * (i + 0.37) / 100000;
    const double length = 1e-3 * (1 + i % 7) * std::pow(10.0, i % 5);
    const double y = length * std::sin(angle);
    const double x = length * std::cos(angle);
    double expected = std::atan2(y, x);
    expected += expected < 0.0 ? lfd::TwoPi : 0.0;
    const double azimuth = lfd::Azimuth(y, x);
    inRange = inRange && azimuth >= 0.0 && azimuth < lfd::TwoPi;
    worst = std::max(worst, std::abs(azimuth - expected));
  }
  lfdtest::Check(inRange, "every azimuth in [0, 2 pi)");
  lfdtest::Check(worst < 2e-10, "azimuth within 2e-10 radian of atan2", worst, 2e-10);
}

// The coarse-then-fine depth walk (NearestDepthTiles) gives the plain
// walk's crossings bit for bit: a fan of rays from around the ring aimed
// through, beside and past the sphere, each walked in one view's map with
// and without the tiles.
void ProxyCoarseWalk(lfd::LightFieldSampler& sampler, int views)
{
  lfd::NearestDepthTiles tiles;
  tiles.Build(sampler.Depth, views);
  Expect("nearest depth tile of view 0 (the sphere's nearest point, 3)",
    tiles.Nearest(0, glm::dvec2(0.0), glm::dvec2(63.0)),
    3.0,
    0.005);
  Expect(
    "a box outside the image has no tile", std::isinf(tiles.Nearest(0, { 64, 0 }, { 70, 9 })), 1.0);
  int crossings = 0, different = 0;
  for (int i = 0; i < 24; ++i)
  {
    for (int j = 0; j < 24; ++j)
    {
      const double phi = 0.27 * i;
      const glm::dvec3 o(10.0 * std::sin(phi), 0.2 * (j - 12), 10.0 * std::cos(phi));
      const glm::dvec3 aim(0.1 * (i - 12), 0.1 * (12 - j), 0.07 * (i + j - 24));
      double plain = 0.0, coarse = 0.0;
      sampler.DepthTiles = nullptr;
      const bool hitPlain = sampler.IntersectDepthMap(i % views, o, aim - o, 0.0, 100.0, plain);
      sampler.DepthTiles = &tiles;
      const bool hitCoarse = sampler.IntersectDepthMap(i % views, o, aim - o, 0.0, 100.0, coarse);
      crossings += hitPlain ? 1 : 0;
      different += hitPlain != hitCoarse || (hitPlain && plain != coarse) ? 1 : 0;
    }
  }
  sampler.DepthTiles = nullptr;
  Expect(
    "coarse then fine: rays whose crossing differs from the plain walk's", different, 0.0, 0.0);
  Expect("... of 576 rays, those that cross", crossings, 239.0, 0.0);
}

// Depth maps (VTK row order, 0: no surface) of a sphere of radius `radius`
// at the origin seen by `cameras` (size x size pixels each).
std::vector<float> SphereDepths(const std::vector<lfd::PinholeCamera>& cameras,
  int size,
  double radius)
{
  std::vector<float> depth(static_cast<std::size_t>(size) * size * cameras.size(), 0.0f);
  for (std::size_t v = 0; v < cameras.size(); ++v)
  {
    const lfd::PinholeCamera::Unprojection rays = cameras[v].GetUnprojection();
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        // |C + z D|^2 = r^2, D with camera z 1: the nearer root.
        const glm::dvec3 c = rays.Center;
        const glm::dvec3 d = rays.Direction(glm::dvec2(x, y));
        const double a = glm::dot(d, d), b = glm::dot(c, d);
        const double disc = b * b - a * (glm::dot(c, c) - radius * radius);
        if (disc >= 0.0)
        {
          depth[(v * size + (size - 1 - y)) * size + x] =
            static_cast<float>((-b - std::sqrt(disc)) / a);
        }
      }
    }
  }
  return depth;
}

// The proxy path (GatherOnSurface): a ring of 8 flat-coloured views of 64 x
// 64 (view v is (10 v, 0, 0)) around a sphere of radius 1 at the ring's
// centre, their depth maps computed exactly per pixel. A ray aimed at the
// axis meets it 1 before the axis; the views are chosen by angle at that
// point, and those whose own depth map hides it are left out.
void ProxySurface()
{
  const int size = 64, views = 8;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double height = 0.0;
  vtkNew<vtkLightField> lf;
  lf->SetLayout(size, size, views);
  lf->GetRig()->MakeCylinder(origin, axis, 4.0, views, 1, &height, size, size, 40.0);
  auto* rgb = static_cast<vtkUnsignedCharArray*>(lf->AllocatePass(vtkLightField::COAXIAL));
  std::vector<lfd::PinholeCamera> cameras(views);
  for (int v = 0; v < views; ++v)
  {
    cameras[v] = lf->GetRig()->GetCamera(v);
  }
  for (vtkIdType p = 0; p < lf->GetNumberOfPoints(); ++p)
  {
    rgb->SetComponent(p, 0, 10.0 * (p / (size * size)));
  }
  std::vector<float> depth = SphereDepths(cameras, size, 1.0);
  lfd::RingLayout layout = lf->GetRig()->GetRingLayout();
  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = { rgb->GetPointer(0), size, size, 3 };
  sampler.Depth = { depth.data(), size, size, 1 };
  const std::vector<double> ranges = lfd::DepthRanges(sampler.Depth, views);
  sampler.DepthRange = ranges.data();
  Expect("depth range of view 0 (nearest point 3)", ranges[0], 3.0, 0.005);
  lfd::DepthBounds(sampler.Depth, cameras.data(), views, sampler.SurfaceLow, sampler.SurfaceHigh);
  Expect("surface bounds: the sphere's (x max 1)", sampler.SurfaceHigh.x, 1.0, 0.01);

  const double step = lfd::TwoPi / views;
  glm::dvec3 o, d, color;
  RayAt(2.25 * step, 0.0, o, d);
  double hit = 0.0;
  Expect(
    "the ray meets view 2's depth map", sampler.IntersectDepthMap(2, o, d, 0.0, 100.0, hit), 1.0);
  Expect("... 1 before the axis (10 - 1)", hit, 9.0, 0.01);
  ProxyCoarseWalk(sampler, views);
  // DepthPixel: std::lround's pixel and bounds, halves and the edges included.
  int agree = 0, inside = 0;
  for (int i = -80; i <= 4 * size + 80; ++i)
  {
    const glm::dvec2 uv(0.25 * i - 10.0, std::nextafter(0.25 * i - 10.0, 0.0));
    int x = -1, y = -1;
    const bool found = sampler.DepthPixel(uv, x, y);
    const long lx = std::lround(uv.x), ly = std::lround(uv.y);
    const bool in = lx >= 0 && ly >= 0 && lx < size && ly < size;
    agree += found == in && (!in || (x == lx && y == ly));
    inside += in;
  }
  Expect("DepthPixel agrees with std::lround", agree, 4 * size + 161.0);
  Expect("... inside the map (-0.25 to 63.25)", inside, 4.0 * size - 1);
  lfd::RaySamples samples;
  sampler.ProxyViews = 1;
  Expect("proxy gather", sampler.Gather(o, d, samples), 1.0);
  Expect("focused on the sphere", samples.Surface, 9.0, 0.01);
  lfd::BlendLabel(samples, 0, color);
  Expect("one view: the nearest in angle (view 2)", color.r, 20.0);
  sampler.ProxyViews = 2;
  sampler.Gather(o, d, samples);
  double weight2 = 0.0, weight3 = 0.0;
  for (int i = 0; i < samples.Count; ++i)
  {
    const double r = samples.Samples[i].Color.r;
    weight2 += r == 20.0 ? samples.Samples[i].Weight : 0.0;
    weight3 += r == 30.0 ? samples.Samples[i].Weight : 0.0;
  }
  Expect("two views: 2 and 3 only, weights sum to 1", weight2 + weight3, 1.0);
  Expect("view 2 (nearer in angle) weighs more", weight2 > weight3, 1.0);
  // A ray that misses the sphere falls back to the focal plane.
  const glm::dvec3 above(10.0 * std::sin(2.25 * step), 2.0, 10.0 * std::cos(2.25 * step));
  sampler.Gather(above, glm::dvec3(0.0, 2.0, 0.0) - above, samples);
  Expect("a ray above the sphere: focal plane (Surface NaN)", std::isnan(samples.Surface), 1.0);
  // View 2's map now sees a surface in front of the point: it is left out.
  std::fill(depth.begin() + 2 * size * size, depth.begin() + 3 * size * size, 1.0f);
  sampler.ProxyViews = 1;
  sampler.Gather(o, d, samples);
  lfd::BlendLabel(samples, 0, color);
  Expect("an occluded view is skipped (view 3 instead)", color.r, 30.0);
  Expect("... still focused on the sphere (view 3's crossing)", samples.Surface, 9.0, 0.01);
}
}

// Whether a sample of `samples` carries a part's label.
bool AnyLabel(const lfd::RaySamples& samples)
{
  bool any = false;
  for (int k = 0; k < samples.Count; ++k)
  {
    any = any || samples.Samples[k].Label > 0;
  }
  return any;
}

// Whether two lookups gave the very same samples, focused alike.
bool SameSamples(const lfd::RaySamples& a, const lfd::RaySamples& b)
{
  bool same = a.Count == b.Count &&
    (a.Surface == b.Surface || (std::isnan(a.Surface) && std::isnan(b.Surface)));
  for (int k = 0; same && k < a.Count; ++k)
  {
    same = a.Samples[k].Weight == b.Samples[k].Weight && a.Samples[k].Label == b.Samples[k].Label &&
      a.Samples[k].Color == b.Samples[k].Color;
  }
  return same;
}

// A ray of LabelHullSkips: from 6 off the axis at a random azimuth and
// height towards a random point of the box [-1.5, 1.5]^3.
template<typename Uniform>
void RandomRay(Uniform& uniform, glm::dvec3& o, glm::dvec3& d)
{
  const double phi = uniform(0.0, lfd::TwoPi);
  o = glm::dvec3(6.0 * std::sin(phi), uniform(-2.0, 2.0), 6.0 * std::cos(phi));
  // Drawn one by one: the evaluation order of a constructor's arguments is
  // unspecified (gcc and clang differ), and the counts below must not be.
  const double tz = uniform(-1.5, 1.5);
  const double ty = uniform(-1.5, 1.5);
  const double tx = uniform(-1.5, 1.5);
  d = glm::dvec3(tx, ty, tz) - o;
}

// What the hull did to the rays looked up with and without it.
struct SkipCounts
{
  int Skipped = 0;   ///< rays the hull skips
  int Labelled = 0;  ///< rays with a labelled sample (without the hull)
  int Wrong = 0;     ///< skipped rays with a labelled sample
  int Differing = 0; ///< looked-up rays whose samples differ
};

// Looks the ray o + t d up without and with `hull` into `plain` and
// `counts`; true when the hull skipped it.
bool CountSkip(lfd::LightFieldSampler& sampler,
  const lfd::LabelHull& hull,
  const glm::dvec3& o,
  const glm::dvec3& d,
  lfd::RaySamples& plain,
  SkipCounts& counts)
{
  lfd::RaySamples skipping;
  sampler.Hull = nullptr;
  const bool found = sampler.Gather(o, d, plain);
  const bool anyLabel = AnyLabel(plain);
  counts.Labelled += anyLabel ? 1 : 0;
  sampler.Hull = &hull;
  if (!sampler.Gather(o, d, skipping) && found)
  {
    ++counts.Skipped;
    counts.Wrong += anyLabel ? 1 : 0;
    return true;
  }
  counts.Differing += SameSamples(plain, skipping) ? 0 : 1;
  return false;
}

// 1 when the hull's MaySeePart proves that the stretch of the ray o + t d
// inside the sampler's surface bounds meets no part, else 0; `seen` counts
// the labelled samples of such a stretch all the same: at 64 points along
// it, bilinear lookups in every view GatherOnSurface may blend there
// (FindProxyCandidates).
int ProvenStretch(const lfd::LightFieldSampler& sampler,
  const lfd::LabelHull& hull,
  const glm::dvec3& o,
  const glm::dvec3& d,
  int& seen)
{
  double enter, leave, s, azimuth, height;
  if (!sampler.SurfaceStretch(o, d, enter, leave) ||
    !lfd::IntersectCylinderEntry(sampler.Layout->Cyl, o, d, s))
  {
    return 0;
  }
  sampler.Layout->Locate(o + s * d, azimuth, height);
  if (hull.MaySeePart(azimuth, o + enter * d, o + leave * d, *sampler.Layout))
  {
    return 0;
  }
  for (int k = 0; k <= 64; ++k)
  {
    const glm::dvec3 x = o + (enter + (leave - enter) * k / 64.0) * d;
    lfd::LightFieldSampler::ProxyCandidates candidates;
    sampler.FindProxyCandidates(azimuth, height, x, -glm::normalize(d), candidates);
    for (int c = 0; c < candidates.Count; ++c)
    {
      lfd::RaySamples samples;
      sampler.AddBilinear(candidates.View[c], 1.0, x, samples);
      for (int i = 0; i < samples.Count; ++i)
      {
        seen += samples.Samples[i].Label > 0 ? 1 : 0;
      }
    }
  }
  return 1;
}

// A camera at `position` looking down -Z (up +Y), of focal length `focal`
// pixels and principal point `centre`.
lfd::PinholeCamera LookDownZ(double focal, const glm::dvec2& centre, const glm::dvec3& position)
{
  const glm::dmat3 k(
    glm::dvec3(focal, 0.0, 0.0), glm::dvec3(0.0, focal, 0.0), glm::dvec3(centre, 1.0));
  return lfd::PinholeCamera::LookAt(
    k, position, glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(0.0, 1.0, 0.0));
}

// What AimBatch (LightFieldSampler::EntrySectors) did to the rays of a frame.
struct BatchCounts
{
  int Bounded = 0;    ///< batches whose entry sectors are bounded
  int AcrossZero = 0; ///< bounded batches whose sectors hold 31 and 0
  int Early = 0;      ///< rays skipped before their entry, by the bound alone
  int Outside = 0;    ///< rays entering the rig in a sector outside their bound
  int Differing = 0;  ///< rays aimed differently than one by one, or than with SSE2
  int Own = 0;        ///< rays aimed from their own origins (to show the check ran)
  int Projected = 0;  ///< rays sampled from the views AimBatch projected (ProjectViews)
};

// Whether two rays were aimed alike (Aim()'s results `a` and `b`, found or
// not): the same focal point, proxy stretch, entry and weighted views.
bool SameAim(const lfd::RayAim& a, bool foundA, const lfd::RayAim& b, bool foundB)
{
  bool same = foundA == foundB;
  if (foundA && same)
  {
    same = a.Focal == b.Focal && a.Stretch == b.Stretch &&
      (!a.Stretch || (a.Enter == b.Enter && a.Leave == b.Leave)) && a.Azimuth == b.Azimuth &&
      a.Height == b.Height && a.Count == b.Count;
    for (int v = 0; v < a.Count && same; ++v)
    {
      same = a.Views[v].View == b.Views[v].View && a.Views[v].Weight == b.Views[v].Weight;
    }
  }
  return same;
}

// Aims the rays of the `width` x `height` frame of `eye` (OpenCV pixels) in
// batches of 16 along each row, as RenderPlainViews does (the last batch of
// a row shorter), and compares them with Aim() ray by ray, without a bound,
// and with the SSE2 version of the batch (AimStages; AimBatch may have taken
// the AVX2 one); and the same rays from an origin each, points along them
// (as the warped rays of lfd::RenderWalks), against Aim() from those
// origins; and with the views' projection matrices, the samples of the
// views the batch projected against AddBilinear()'s. This file is compiled
// as vtkLightFieldRenderer.cxx is, so that the batch's loops are vectorised
// here too (CMakeLists.txt).
BatchCounts AimRows(const lfd::LightFieldSampler& sampler,
  const lfd::LabelHull& hull,
  const lfd::PinholeCamera& eye,
  int width,
  int height)
{
  BatchCounts counts;
  const glm::dvec3 o = eye.Center();
  // The sampler with its views' projection matrices, whose batches project
  // the focal points into the views ahead of Sample() (ProjectViews()).
  int views = 0;
  for (const lfd::RingRow& row : sampler.Layout->Rows)
  {
    for (int view : row.View)
    {
      views = std::max(views, view + 1);
    }
  }
  std::vector<lfd::ProjectionMatrix> matrices;
  for (int view = 0; view < views; ++view)
  {
    matrices.emplace_back(sampler.Cameras[view]);
  }
  lfd::LightFieldSampler projecting = sampler;
  projecting.Projections = matrices.data();
  for (int y = 0; y < height; ++y)
  {
    for (int x0 = 0; x0 < width; x0 += 16)
    {
      const int count = std::min(16, width - x0);
      glm::dvec3 d[16];
      lfd::RayAim aims[16];
      bool aimed[16];
      for (int i = 0; i < count; ++i)
      {
        d[i] = eye.PixelToDirection() * glm::dvec3(x0 + i, y, 1.0);
      }
      const std::uint32_t sectors = sampler.EntrySectors(o, d, count);
      counts.Bounded += sectors != ~std::uint32_t(0) ? 1 : 0;
      counts.AcrossZero +=
        sectors != ~std::uint32_t(0) && (sectors & 0x80000001u) == 0x80000001u ? 1 : 0;
      sampler.AimBatch(o, d, count, aims, aimed);
      // The SSE2 version too where AimBatch took the AVX2 one.
      lfd::RayAim baseline[16];
      bool baselineAimed[16];
      sampler.AimStages<0>(&o, d, count, baseline, baselineAimed);
      glm::dvec3 origins[16];
      for (int i = 0; i < count; ++i)
      {
        origins[i] = o + (0.1 * (i % 4)) * d[i];
      }
      lfd::RayAim own[16], ownBaseline[16];
      bool ownAimed[16], ownBaselineAimed[16];
      sampler.AimBatch(origins, d, count, own, ownAimed);
      sampler.AimStages<1>(origins, d, count, ownBaseline, ownBaselineAimed);
      for (int i = 0; i < count; ++i)
      {
        counts.Differing += SameAim(baseline[i], baselineAimed[i], aims[i], aimed[i]) ? 0 : 1;
        lfd::RayAim alone;
        const bool found = sampler.Aim(o, d[i], alone);
        counts.Differing += SameAim(alone, found, aims[i], aimed[i]) ? 0 : 1;
        counts.Differing +=
          SameAim(ownBaseline[i], ownBaselineAimed[i], own[i], ownAimed[i]) ? 0 : 1;
        const bool ownFound = sampler.Aim(origins[i], d[i], alone);
        counts.Differing += SameAim(alone, ownFound, own[i], ownAimed[i]) ? 0 : 1;
        counts.Own += ownAimed[i] ? 1 : 0;
      }
      // With projection matrices: the same aims, and the samples from the
      // views the batch projected (its rays without a proxy stretch) those
      // of AddBilinear() view by view.
      lfd::RayAim projected[16];
      bool projectedAimed[16];
      projecting.AimBatch(o, d, count, projected, projectedAimed);
      for (int i = 0; i < count; ++i)
      {
        counts.Differing += SameAim(aims[i], aimed[i], projected[i], projectedAimed[i]) ? 0 : 1;
        if (projectedAimed[i] && projected[i].Projected)
        {
          lfd::RaySamples staged, alone;
          projecting.Sample(o, d[i], projected[i], staged);
          alone.Clear();
          for (int v = 0; v < projected[i].Count; ++v)
          {
            const lfd::WeightedView& view = projected[i].Views[v];
            if (view.Weight > 0.0)
            {
              projecting.AddBilinear(view.View, view.Weight, projected[i].Focal, alone);
            }
          }
          counts.Differing += SameSamples(staged, alone) ? 0 : 1;
          counts.Projected += 1;
        }
      }
      for (int i = 0; i < count; ++i)
      {
        const long cell = hull.Cell(aims[i].Focal, *sampler.Layout);
        counts.Early += cell >= 0 && hull.Union[cell] && !(hull.Union[cell] & sectors) ? 1 : 0;
        double s, azimuth, h;
        counts.Outside += sampler.Entry(o, d[i], s, azimuth, h) &&
            !(lfd::LabelHull::SectorsOnArc(azimuth, 0.0) & sectors)
          ? 1
          : 0;
      }
    }
  }
  return counts;
}

// The label hull with a proxy (LabelHull::MaySeePart, the surface box of
// ScreenTiles): the views of LabelHullSkips with the depth maps of a sphere
// of radius 0.6 at the origin. A ray the hull skips (focal point and
// stretch inside the surface's bounds both unmarked) must have no labelled
// sample without the hull, neither on the surface nor on the plane; a ray
// it does not skip must get the very same samples; the rays of a tile
// marked 0 must be skipped.
template<typename Uniform>
void ProxyLabelHullSkips(lfd::LightFieldSampler& sampler,
  const lfd::LabelHull& hull,
  const lfd::PinholeCamera& eye,
  Uniform& uniform)
{
  const int views = 48;
  const int size = sampler.Radiance.Width;
  const std::vector<lfd::PinholeCamera> cameras(sampler.Cameras, sampler.Cameras + views);
  const std::vector<float> depth = SphereDepths(cameras, size, 0.6);
  sampler.Depth = { depth.data(), size, size, 1 };
  const std::vector<double> ranges = lfd::DepthRanges(sampler.Depth, views);
  sampler.DepthRange = ranges.data();
  lfd::NearestDepthTiles tiles;
  tiles.Build(sampler.Depth, views);
  sampler.DepthTiles = &tiles;
  lfd::DepthBounds(sampler.Depth, cameras.data(), views, sampler.SurfaceLow, sampler.SurfaceHigh);
  // Their views run in ranges out of order (as vtkLightFieldRenderer runs
  // them on every thread): the same bounds, ranges and tiles.
  const lfd::RangeLoop backwards =
    [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
  {
    for (std::size_t end = n; end > 0; end -= std::min<std::size_t>(end, 5))
    {
      body(end - std::min<std::size_t>(end, 5), end);
    }
  };
  glm::dvec3 low, high;
  lfd::NearestDepthTiles ranged;
  ranged.Build(sampler.Depth, views, backwards);
  const bool bounded = lfd::DepthBounds(sampler.Depth, cameras.data(), views, low, high, backwards);
  Expect("proxy: views in ranges out of order: bounds, ranges or tiles unlike one loop's",
    !bounded || low != sampler.SurfaceLow || high != sampler.SurfaceHigh ||
      lfd::DepthRanges(sampler.Depth, views, backwards) != ranges || ranged.Depth != tiles.Depth,
    0.0);
  const lfd::RingLayout& layout = *sampler.Layout;
  SkipCounts counts;
  int stretched = 0, surface = 0, proven = 0, seen = 0;
  for (int i = 0; i < 4000; ++i)
  {
    glm::dvec3 o, d;
    RandomRay(uniform, o, d);
    proven += ProvenStretch(sampler, hull, o, d, seen);
    lfd::RaySamples plain;
    double enter, leave;
    stretched +=
      CountSkip(sampler, hull, o, d, plain, counts) && sampler.SurfaceStretch(o, d, enter, leave)
      ? 1
      : 0;
    surface += std::isnan(plain.Surface) ? 0 : 1;
  }
  Expect("proxy: stretches MaySeePart proves to see no part", proven, 29.0);
  Expect("proxy: ... labelled samples at 64 points of each in the candidate views", seen, 0.0);
  Expect("proxy: rays with a labelled sample", counts.Labelled, 607.0);
  Expect("proxy: rays focused on the sphere", surface, 174.0);
  Expect("proxy: rays the hull skips", counts.Skipped, 1923.0);
  Expect("proxy: ... of which cross the surface's bounds (MaySeePart)", stretched, 14.0);
  Expect("proxy: skipped rays with a labelled sample", counts.Wrong, 0.0);
  Expect("proxy: looked-up rays whose samples differ", counts.Differing, 0.0);

  // The screen tiles of LabelHullSkips' frame (`eye`, 96 x 80, looking at
  // the top of the grid, above the labelled heights), the surface's bounds raised there
  // (the sphere's, 1.2 higher): a tile marked 0 holds no ray that Gather
  // looks up, and none with a labelled sample, though some of its rays
  // cross those bounds.
  sampler.SurfaceLow.y += 1.2;
  sampler.SurfaceHigh.y += 1.2;
  const int tile = 8, width = 96, height = 80;
  const std::vector<std::uint8_t> mask = hull.ScreenTiles(layout,
    eye.Center(),
    eye.PixelToDirection(),
    width,
    height,
    sampler.FocalDistance,
    tile,
    sampler.SurfaceLow,
    sampler.SurfaceHigh);
  const std::vector<std::uint8_t> planeMask = hull.ScreenTiles(
    layout, eye.Center(), eye.PixelToDirection(), width, height, sampler.FocalDistance, tile);
  int skippedTiles = 0, planeTiles = 0, leaks = 0, lookedUp = 0, crossing = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const glm::dvec3 d = eye.PixelToDirection() * glm::dvec3(x, y, 1.0);
      double enter, leave;
      crossing +=
        !mask[(y / tile) * 12 + x / tile] && sampler.SurfaceStretch(eye.Center(), d, enter, leave)
        ? 1
        : 0;
      lfd::RaySamples samples;
      sampler.Hull = &hull;
      const bool looked = sampler.Gather(eye.Center(), d, samples);
      sampler.Hull = nullptr;
      sampler.Gather(eye.Center(), d, samples);
      const bool anyLabel = AnyLabel(samples);
      lookedUp += looked ? 1 : 0;
      leaks += !mask[(y / tile) * 12 + x / tile] && (looked || anyLabel) ? 1 : 0;
    }
  }
  for (std::size_t t = 0; t < mask.size(); ++t)
  {
    skippedTiles += mask[t] ? 0 : 1;
    planeTiles += planeMask[t] ? 0 : 1;
  }
  Expect("proxy: tiles skipped whole", skippedTiles, 52.0);
  Expect("proxy: ... through the plane alone", planeTiles, 53.0);
  Expect("proxy: rays of skipped tiles that cross the surface's bounds", crossing, 1458.0);
  Expect("proxy: rays looked up", lookedUp, 1557.0);
  Expect("proxy: rays of skipped tiles looked up or labelled", leaks, 0.0);
  // The batch with a proxy: its rays that cross the surface's bounds are
  // aimed, stretches included, as by Aim() alone; the others are skipped by
  // their sectors.
  sampler.Hull = &hull;
  const BatchCounts batch = AimRows(sampler, hull, eye, 96, 80);
  Expect("proxy: rays unmarked in their batch's sectors", batch.Early, 1268.0);
  Expect("proxy: rays outside their bound", batch.Outside, 0.0);
  Expect("proxy: rays aimed differently in a batch", batch.Differing, 0.0);
  Expect("proxy: rays aimed from their own origins", batch.Own, 2502.0);
  Expect("proxy: rays sampled from the views their batch projected", batch.Projected, 1053.0);
  sampler.Depth = {};
  sampler.DepthRange = nullptr;
  sampler.DepthTiles = nullptr;
  sampler.SurfaceLow = glm::dvec3(-std::numeric_limits<double>::infinity());
  sampler.SurfaceHigh = glm::dvec3(std::numeric_limits<double>::infinity());
}

// The sectors of arcs (LabelHull::SectorsOnArc), and AimBatch over the rows
// of a frame seen from outside the rig and of one seen from inside it,
// whose rays enter the rig behind the eye, across azimuth 0: the bound
// holds every ray's sector, and the batch aims every ray as Aim() alone.
void EntrySectorsBound(const lfd::LightFieldSampler& sampler,
  const lfd::LabelHull& hull,
  const lfd::PinholeCamera& outside)
{
  constexpr double sector = lfd::TwoPi / lfd::LabelHull::Sectors;
  using lfd::LabelHull;
  lfdtest::CheckEqual(LabelHull::SectorsOnArc(2.5 * sector, 0.0), 4u, "sectors of a point");
  lfdtest::CheckEqual(
    LabelHull::SectorsOnArc(2.5 * sector, 2.0 * sector), 28u, "sectors of an arc (2 to 4)");
  lfdtest::CheckEqual(LabelHull::SectorsOnArc(-0.5 * sector, 2.0 * sector),
    0x80000003u,
    "sectors of an arc across 0 (31, 0 and 1)");
  lfdtest::CheckEqual(LabelHull::SectorsOnArc(lfd::TwoPi - 0.5 * sector, sector),
    0x80000001u,
    "sectors of an arc from below 2 pi across 0");
  lfdtest::CheckEqual(LabelHull::SectorsOnArc(0.5 * sector, lfd::TwoPi - 0.25 * sector),
    ~0u,
    "sectors of an arc back into its first sector");
  lfdtest::CheckEqual(LabelHull::SectorsOnArc(0.0, lfd::TwoPi), ~0u, "sectors of the whole circle");

  const BatchCounts out = AimRows(sampler, hull, outside, 100, 80);
  Expect("outside: batches bounded (of 560)", out.Bounded, 560.0);
  Expect("outside: rays skipped before their entry by the bound", out.Early, 1364.0);
  Expect("outside: rays outside their bound", out.Outside, 0.0);
  Expect("outside: rays aimed differently", out.Differing, 0.0);
  Expect("outside: rays aimed from their own origins", out.Own, 2061.0);
  Expect("outside: rays sampled from the views their batch projected", out.Projected, 2061.0);

  const lfd::PinholeCamera inside =
    LookDownZ(120.0, glm::dvec2(49.5, 39.5), glm::dvec3(0.2, 0.3, 2.5));
  const BatchCounts in = AimRows(sampler, hull, inside, 100, 80);
  Expect("inside: batches bounded (of 560)", in.Bounded, 560.0);
  Expect("inside: ... across azimuth 0 (one per row)", in.AcrossZero, 80.0);
  Expect("inside: rays skipped before their entry by the bound", in.Early, 1770.0);
  Expect("inside: rays outside their bound", in.Outside, 0.0);
  Expect("inside: rays aimed differently", in.Differing, 0.0);
  Expect("inside: rays aimed from their own origins", in.Own, 5155.0);
  Expect("inside: rays sampled from the views their batch projected", in.Projected, 5155.0);
}

// The rig of the label hull's tests: two rings of 24 views of 32 x 32
// around the Y axis, whose Coaxial pass is 5 (v % 50) in view v and whose
// Label pass is 1 + v % 2 where `labelled(v, x, y)` (VTK pixel rows), else
// 0; and a sampler of it (focal distance 0.3). Not copied: the sampler
// points into it.
struct HullRig
{
  static constexpr int Size = 32, PerRow = 24, Views = 2 * PerRow;
  vtkNew<vtkLightField> LightField;
  std::vector<lfd::PinholeCamera> Cameras;
  lfd::RingLayout Layout;
  lfd::LightFieldSampler Sampler;

  template<typename Labelled>
  explicit HullRig(Labelled&& labelled)
  {
    const double origin[3] = { 0.0, 0.0, 0.0 };
    const double axis[3] = { 0.0, 1.0, 0.0 };
    const double heights[2] = { -0.5, 0.5 };
    vtkLightField* lf = this->LightField;
    lf->SetLayout(Size, Size, Views);
    lf->GetRig()->MakeCylinder(origin, axis, 4.0, PerRow, 2, heights, Size, Size, 40.0);
    auto* rgb = static_cast<vtkUnsignedCharArray*>(lf->AllocatePass(vtkLightField::COAXIAL));
    auto* label = static_cast<vtkUnsignedCharArray*>(lf->AllocatePass(vtkLightField::LABEL));
    for (vtkIdType p = 0; p < lf->GetNumberOfPoints(); ++p)
    {
      const int v = static_cast<int>(p / (Size * Size));
      const int x = static_cast<int>(p % Size);
      const int y = static_cast<int>(p / Size % Size);
      rgb->SetComponent(p, 0, 5.0 * (v % 50));
      label->SetComponent(p, 0, labelled(v, x, y) ? 1 + v % 2 : 0);
    }
    for (int v = 0; v < Views; ++v)
    {
      this->Cameras.push_back(lf->GetRig()->GetCamera(v));
    }
    this->Layout = lf->GetRig()->GetRingLayout();
    this->Sampler.Layout = &this->Layout;
    this->Sampler.Cameras = this->Cameras.data();
    this->Sampler.Radiance = { rgb->GetPointer(0), Size, Size, 3 };
    this->Sampler.Labels = { label->GetPointer(0), Size, Size, 1 };
    this->Sampler.FocalDistance = 0.3;
  }
  HullRig(const HullRig&) = delete;
  HullRig& operator=(const HullRig&) = delete;
};

// The label hull (LabelHull): the HullRig whose label pass is a square of
// 8 x 8 pixels (shifted by view), rays from all around
// aimed at a box around the object. A ray that the hull lets Gather skip must
// have no labelled sample without the hull; a ray it does not skip must get
// the very same samples.
void LabelHullSkips()
{
  HullRig rig(
    [](int v, int x, int y) { return x >= 10 + v % 3 && x < 18 + v % 3 && y >= 12 && y < 20; });
  const int size = HullRig::Size, views = HullRig::Views;
  const std::vector<lfd::PinholeCamera>& cameras = rig.Cameras;
  const lfd::RingLayout& layout = rig.Layout;
  lfd::LightFieldSampler& sampler = rig.Sampler;
  lfd::LabelHull hull;
  Expect("hull grid sized", hull.Initialize(layout, cameras.data(), size, size), 1.0);
  const std::vector<glm::ivec4> rects = lfd::LabelRectangles(sampler.Labels, views);
  Expect("label rectangle of view 4 (x0)", rects[4].x, 11.0);
  Expect("label rectangle of view 4 (y1, OpenCV rows)", rects[4].w, 19.0);
  for (int sector = 0; sector < lfd::LabelHull::Sectors; ++sector)
  {
    hull.MarkSector(sector, layout, cameras.data(), rects);
  }
  hull.Unite();
  std::uint32_t seed = 12345;
  const auto uniform = [&seed](double low, double high)
  {
    seed = seed * 1664525u + 1013904223u;
    return low + (high - low) * (seed >> 8) / double(1u << 24);
  };
  SkipCounts counts;
  int unmarked = 0;
  for (int i = 0; i < 4000; ++i)
  {
    glm::dvec3 o, d;
    RandomRay(uniform, o, d);
    const long cell = hull.Cell(lfd::FocalPoint(layout.Cyl, o, d, sampler.FocalDistance), layout);
    unmarked += cell >= 0 && !hull.Union[cell] ? 1 : 0;
    lfd::RaySamples plain;
    CountSkip(sampler, hull, o, d, plain, counts);
  }
  Expect("rays with a labelled sample", counts.Labelled, 615.0);
  Expect("rays the hull skips", counts.Skipped, 1913.0);
  Expect("rays unmarked in every sector (skipped before the cylinder entry)", unmarked, 869.0);
  Expect("skipped rays with a labelled sample", counts.Wrong, 0.0);
  Expect("looked-up rays whose samples differ", counts.Differing, 0.0);

  // The screen-tile mask of a 96 x 80 frame (tiles of 8) looking at the top
  // of the grid, above the labelled heights, and past it: every ray of a tile marked 0
  // is one that Gather skips (focal point in a voxel unmarked everywhere).
  const lfd::PinholeCamera eye =
    LookDownZ(300.0, glm::dvec2(47.5, 39.5), glm::dvec3(0.5, 1.4, 6.0));
  const int tile = 8, width = 96, height = 80;
  const std::vector<std::uint8_t> tiles = hull.ScreenTiles(
    layout, eye.Center(), eye.PixelToDirection(), width, height, sampler.FocalDistance, tile);
  Expect("screen tiles", static_cast<double>(tiles.size()), 12.0 * 10.0);
  int skippedTiles = 0, leaks = 0, lookedUp = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const glm::dvec3 d = eye.PixelToDirection() * glm::dvec3(x, y, 1.0);
      const long cell =
        hull.Cell(lfd::FocalPoint(layout.Cyl, eye.Center(), d, sampler.FocalDistance), layout);
      const bool skippedRay = cell >= 0 && !hull.Union[cell];
      lookedUp += skippedRay ? 0 : 1;
      leaks += !tiles[(y / tile) * 12 + x / tile] && !skippedRay ? 1 : 0;
    }
  }
  for (std::uint8_t t : tiles)
  {
    skippedTiles += t ? 0 : 1;
  }
  Expect("tiles skipped whole (3392 of the 4387 rays the union skips)", skippedTiles, 53.0);
  Expect("rays the union does not skip", lookedUp, 3293.0);
  Expect("rays of skipped tiles that Gather would look up", leaks, 0.0);
  EntrySectorsBound(sampler, hull, eye);
  ProxyLabelHullSkips(sampler, hull, eye, uniform);
  sampler.Hull = nullptr;
}

// The label hull with label blocks (LabelBlocks): the HullRig whose label
// pass is a thin diagonal stripe, whose rectangle is mostly
// background. With the blocks the hull marks fewer voxels and skips more
// rays, never one with a labelled sample, and a ray it does not skip gets
// the very same samples.
void LabelBlockHullSkips()
{
  HullRig rig([](int, int x, int y) { return x >= 6 && x < 26 && std::abs(x - y) <= 1; });
  const int size = HullRig::Size, views = HullRig::Views;
  const std::vector<lfd::PinholeCamera>& cameras = rig.Cameras;
  const lfd::RingLayout& layout = rig.Layout;
  lfd::LightFieldSampler& sampler = rig.Sampler;
  lfd::LabelBlocks blocks;
  const std::vector<glm::ivec4> rects = lfd::LabelRectangles(sampler.Labels, views, &blocks);
  Expect("label blocks per view", blocks.Columns * blocks.Rows, 64.0);
  // (OpenCV rows: the stripe runs from (6, 24..26) to (25, 5..7).)
  Expect("view 0: block (4..7, 24..27) on the stripe's end", blocks.Labelled[6 * 8 + 1], 1.0);
  Expect("view 0: block (24..27, 0..3) off it", blocks.Labelled[0 * 8 + 6], 0.0);
  Expect("view 0: any labelled pixel in (0, 0)-(7, 15)", blocks.Any(0, 0, 0, 7, 15), 0.0);
  Expect("view 0: any labelled pixel in (20, 8)-(23, 11)", blocks.Any(0, 20, 8, 23, 11), 1.0);
  lfd::LabelHull byRectangles, byBlocks;
  Expect("hull grid sized", byRectangles.Initialize(layout, cameras.data(), size, size), 1.0);
  byBlocks.Initialize(layout, cameras.data(), size, size);
  for (int sector = 0; sector < lfd::LabelHull::Sectors; ++sector)
  {
    byRectangles.MarkSector(sector, layout, cameras.data(), rects);
    byBlocks.MarkSector(sector, layout, cameras.data(), rects, &blocks);
  }
  byRectangles.Unite();
  byBlocks.Unite();
  int marked[2] = { 0, 0 }, widened = 0;
  for (std::size_t i = 0; i < byBlocks.Marks.size(); ++i)
  {
    marked[0] += byRectangles.Marks[i] ? 1 : 0;
    marked[1] += byBlocks.Marks[i] ? 1 : 0;
    widened += byBlocks.Marks[i] && !byRectangles.Marks[i] ? 1 : 0;
  }
  Expect("voxels the rectangles mark (of 32 sectors x 32^3)", marked[0], 835028.0);
  Expect("voxels the blocks mark", marked[1], 723479.0);
  Expect("voxels the blocks mark and the rectangles do not", widened, 0.0);
  std::uint32_t seed = 12345;
  const auto uniform = [&seed](double low, double high)
  {
    seed = seed * 1664525u + 1013904223u;
    return low + (high - low) * (seed >> 8) / double(1u << 24);
  };
  SkipCounts counts[2];
  for (int i = 0; i < 4000; ++i)
  {
    glm::dvec3 o, d;
    RandomRay(uniform, o, d);
    lfd::RaySamples plain;
    CountSkip(sampler, byRectangles, o, d, plain, counts[0]);
    CountSkip(sampler, byBlocks, o, d, plain, counts[1]);
  }
  Expect("rays with a labelled sample", counts[1].Labelled, 737.0);
  Expect("rays the rectangles' hull skips", counts[0].Skipped, 121.0);
  Expect("rays the blocks' hull skips", counts[1].Skipped, 513.0);
  Expect("skipped rays with a labelled sample (rectangles)", counts[0].Wrong, 0.0);
  Expect("skipped rays with a labelled sample (blocks)", counts[1].Wrong, 0.0);
  Expect("looked-up rays whose samples differ (blocks)", counts[1].Differing, 0.0);
  sampler.Hull = nullptr;
}

int TestCylinderSampling(int, char*[])
{
  AzimuthMatchesAtan2();
  TexelKernelsMatchScalar();

  // Entry intersection.
  lfd::Cylinder cylinder;
  cylinder.Radius = 4.0;
  double s = 0.0;
  Expect("entry parameter",
    lfd::IntersectCylinderEntry(cylinder, { 0, 0, 10 }, { 0, 0, -1 }, s) ? s : -1,
    6.0);
  Expect("ray parallel to the axis misses",
    lfd::IntersectCylinderEntry(cylinder, { 0, 0, 10 }, { 0, 1, 0 }, s),
    0.0);
  Expect("ray outside misses",
    lfd::IntersectCylinderEntry(cylinder, { 5, 0, 10 }, { 0, 0, -1 }, s),
    0.0);
  const glm::dvec3 focal = lfd::FocalPoint(cylinder, { 1, 2, 10 }, { 0, 0, -2 }, 0.5);
  Expect("focal point z", focal.z, 0.5);

  // One ring of 8 flat-coloured views: view v is (10 v, 0, 0), label v % 2 + 1.
  const int views = 8;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double heights[2] = { -1.0, 1.0 };
  vtkNew<vtkLightField> lf;
  lf->SetLayout(16, 16, views);
  lf->GetRig()->MakeCylinder(origin, axis, 4.0, views, 1, heights + 1, 16, 16, 40.0);
  vtkDataArray* rgb = lf->AllocatePass(vtkLightField::COAXIAL);
  vtkDataArray* label = lf->AllocatePass(vtkLightField::LABEL);
  for (vtkIdType p = 0; p < lf->GetNumberOfPoints(); ++p)
  {
    const int v = static_cast<int>(p / 256);
    rgb->SetComponent(p, 0, 10.0 * v);
    label->SetComponent(p, 0, v % 2 + 1);
  }
  std::vector<lfd::PinholeCamera> cameras(views);
  for (int v = 0; v < views; ++v)
  {
    cameras[v] = lf->GetRig()->GetCamera(v);
  }
  // The lookup's 3x4 projection matrices against the cameras' Project: the
  // same side test, pixels within 1e-9 (points in front, beside and behind).
  double worstPixel = 0.0;
  bool sameSide = true;
  for (int v = 0; v < views; ++v)
  {
    const lfd::ProjectionMatrix matrix(cameras[v]);
    for (int k = 0; k < 64; ++k)
    {
      const glm::dvec3 X(0.7 * (k % 4) - 1.0, 0.5 * (k / 4 % 4) - 0.7, 3.0 * (k / 16) - 4.0);
      glm::dvec2 expected, pixel;
      const bool front = cameras[v].Project(X, expected);
      sameSide = sameSide && front == matrix.Project(X, pixel);
      worstPixel = front ? std::max(worstPixel, glm::length(pixel - expected)) : worstPixel;
    }
  }
  lfdtest::Check(sameSide, "projection matrices: the cameras' side test");
  lfdtest::Check(worstPixel < 1e-9, "projection matrices: pixels", worstPixel, 1e-9);
  lfd::RingLayout layout = lf->GetRig()->GetRingLayout();
  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = { static_cast<vtkUnsignedCharArray*>(rgb)->GetPointer(0), 16, 16, 3 };
  sampler.Labels = { static_cast<vtkUnsignedCharArray*>(label)->GetPointer(0), 16, 16, 1 };

  const double step = lfd::TwoPi / views;
  lfd::RaySamples samples;
  glm::dvec3 o, d, color;
  RayAt(2.25 * step, 0.0, o, d);
  sampler.Gather(o, d, samples);
  // Each view's footprint carries one label: one sample per view (AddBilinear).
  Expect("samples of a single-ring ray (one per view)", samples.Count, 2);
  Expect("label vote (0.75 of view 2)", lfd::VoteLabel(samples), 1);
  Expect("weight of label 1", lfd::BlendLabel(samples, 1, color), 0.75);
  Expect("colour of label 1 (view 2 only)", color.r, 20.0);
  Expect("weight of label 2", lfd::BlendLabel(samples, 2, color), 0.25);
  Expect("colour of label 2 (view 3 only)", color.r, 30.0);

  // Wrap-around between view 7 and view 0: all labels set to 1 by asking
  // for the azimuth in the middle, where the two labels tie.
  RayAt(7.5 * step, 0.0, o, d);
  sampler.Labels.Data = nullptr;
  sampler.Gather(o, d, samples);
  lfd::BlendLabel(samples, 0, color);
  // Within 2e-8: lfd::Azimuth is within 1.3e-10 radian of atan2, which moves
  // the weights by up to 2e-10 (1 / 8 of the ring apart) and colours by 70 x that.
  Expect("colour across the ring's seam", color.r, 35.0, 2e-8);

  // Two rows at heights -1 and 1: a ray at height 0.5 weighs 0.25 / 0.75.
  vtkNew<vtkLightField> two;
  two->SetLayout(16, 16, 2 * views);
  two->GetRig()->MakeCylinder(origin, axis, 4.0, views, 2, heights, 16, 16, 40.0);
  layout = two->GetRig()->GetRingLayout();
  Expect("rows", static_cast<double>(layout.Rows.size()), 2);
  lfd::WeightedView chosen[4];
  const int n = lfd::ChooseViews(layout, 1.5 * step, 0.5, chosen);
  Expect("views chosen between two rows", n, 4);
  Expect("weight of the lower row", chosen[0].Weight + chosen[1].Weight, 0.25);
  Expect("upper row, view 9", chosen[2].View, 9);
  Expect("upper row, view 9 weight", chosen[2].Weight, 0.375);
  Expect("clamped above the top row", lfd::ChooseViews(layout, 0.0, 3.0, chosen), 2);
  Expect("clamped view is in the top row", chosen[0].View >= views, 1);

  // Leaving view 2 out widens the bracket to views 1 and 3.
  layout = lf->GetRig()->GetRingLayout({ 2 });
  sampler.Layout = &layout;
  RayAt(2.5 * step, 0.0, o, d);
  sampler.Gather(o, d, samples);
  lfd::BlendLabel(samples, 0, color);
  Expect("leave-one-out colour (views 1 and 3, weights 1/4, 3/4)", color.r, 25.0, 2e-8);

  ProxySurface();
  LabelHullSkips();
  LabelBlockHullSkips();
  return lfdtest::Result();
}
