// Ray / bilinear-patch intersection (lfdRayWarp.h; Ramsey-Potter-Hansen
// 2004, Reshetov 2019): rays through known points of random, planar,
// parallelogram and collapsed patches hit them at the known (s,t) and T; a
// saddle is crossed twice; parallel, coplanar and missing rays get no hit;
// planar patches, intersected as their plane, hit where the general solve does.
#include "lfdRayWarp.h"
#include "lfdTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

using lfdtest::Expect;

namespace
{
glm::dvec3 Patch(const glm::dvec3 p[4], double s, double t)
{
  return (1 - s) * (1 - t) * p[0] + s * (1 - t) * p[1] + (1 - s) * t * p[2] + s * t * p[3];
}

// Largest error of the hit closest to the expected one, over s, t and T.
double HitError(const glm::dvec3 p[4],
  const glm::dvec3& o,
  const glm::dvec3& d,
  double s,
  double t,
  double T)
{
  lfd::PatchHit hits[2];
  const int n = lfd::IntersectBilinearPatch(p[0], p[1], p[2], p[3], o, d, hits);
  double best = HUGE_VAL;
  for (int k = 0; k < n; ++k)
  {
    const double e =
      std::max({ std::abs(hits[k].ST.x - s), std::abs(hits[k].ST.y - t), std::abs(hits[k].T - T) });
    best = std::min(best, std::isnan(e) ? HUGE_VAL : e);
  }
  return best;
}

// Worst `error(o, d, s, t, T)` over `trials` rays through random points
// (s, t) of the patch, in random directions d, each at a random T in [0.5, 3]
// from its origin o.
template<typename Error>
double WorstOverRandomRays(const glm::dvec3 p[4], std::mt19937_64& rng, int trials, Error&& error)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  double worst = 0.0;
  for (int i = 0; i < trials; ++i)
  {
    const double s = unit(rng), t = unit(rng), T = 0.5 + 2.5 * unit(rng);
    const glm::dvec3 d = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    worst = std::max(worst, error(Patch(p, s, t) - T * d, d, s, t, T));
  }
  return worst;
}

// Worst HitError over `trials` random rays through the patch.
double WorstOverRandomRays(const glm::dvec3 p[4], std::mt19937_64& rng, int trials)
{
  return WorstOverRandomRays(p,
    rng,
    trials,
    [p](const glm::dvec3& o, const glm::dvec3& d, double s, double t, double T)
    { return HitError(p, o, d, s, t, T); });
}

// Largest difference of (s, t, T) between the plane's solve and the general
// one (IntersectAlongS) over `trials` random rays through the patch, which
// must have `form`; HUGE_VAL when they disagree on the number of hits.
double WorstPlanarAgainstGeneral(const glm::dvec3 p[4],
  lfd::PatchFromOrigin::Shape form,
  std::mt19937_64& rng,
  int trials)
{
  return WorstOverRandomRays(p,
    rng,
    trials,
    [p, form](const glm::dvec3& o, const glm::dvec3& d, double, double, double)
    {
      const lfd::PatchFromOrigin patch(p[0], p[1], p[2], p[3], o);
      lfd::PatchHit planar[2], general[2];
      const int n = patch.IntersectPlanar(d, 1.0, planar);
      if (patch.Form != form || n != patch.IntersectAlongS(d, 1.0, general))
      {
        return HUGE_VAL;
      }
      double worst = 0.0;
      for (int k = 0; k < n; ++k)
      {
        worst = std::max({ worst,
          std::abs(planar[k].ST.x - general[k].ST.x),
          std::abs(planar[k].ST.y - general[k].ST.y),
          std::abs(planar[k].T - general[k].T) });
      }
      return worst;
    });
}

int CountHits(const glm::dvec3 p[4], const glm::dvec3& o, const glm::dvec3& d)
{
  lfd::PatchHit hits[2];
  return lfd::IntersectBilinearPatch(p[0], p[1], p[2], p[3], o, d, hits);
}
}

int TestBilinearPatch(int, char*[])
{
  std::mt19937_64 rng(20050403);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);

  // Random (generally twisted) patches.
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i)
  {
    glm::dvec3 p[4];
    for (auto& corner : p)
    {
      corner = glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng));
    }
    worst = std::max(worst, WorstOverRandomRays(p, rng, 1));
  }
  Expect("random patches: max error of (s, t, T) over 1000 rays", worst, 0.0, 1e-9);

  // A planar patch (a general quadrilateral in a tilted plane).
  const glm::dvec3 u(0.6, 0.8, 0.0), v(-0.48, 0.36, 0.8), base(1, 2, 3);
  const glm::dvec3 planar[4] = {
    base, base + 2.0 * u, base + 0.3 * u + 1.5 * v, base + 1.8 * u + 1.1 * v
  };
  Expect("planar patch: max error over 1000 rays", WorstOverRandomRays(planar, rng, 1000), 0.0);
  const glm::dvec3 parallelogram[4] = { base, base + u, base + 0.5 * u + v, base + 1.5 * u + v };
  Expect(
    "parallelogram: max error over 1000 rays", WorstOverRandomRays(parallelogram, rng, 1000), 0.0);
  const glm::dvec3 collapsed[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0.5 }, { 1, 0, 0 } };
  Expect("collapsed edge (p11 = p10): max error over 1000 rays",
    WorstOverRandomRays(collapsed, rng, 1000),
    0.0);

  Expect("planar patch: its plane's hits against the general solve's, 1000 rays",
    WorstPlanarAgainstGeneral(planar, lfd::PatchFromOrigin::Shape::Planar, rng, 1000),
    0.0,
    1e-10);
  // (Its twist rounds to exactly zero only with corners exact in binary.)
  const glm::dvec3 exact[4] = { base,
    base + glm::dvec3(0.5, 0.25, 0.0),
    base + glm::dvec3(-0.25, 0.5, 0.75),
    base + glm::dvec3(0.25, 0.75, 0.75) };
  Expect("parallelogram: its plane's hits against the general solve's, 1000 rays",
    WorstPlanarAgainstGeneral(exact, lfd::PatchFromOrigin::Shape::Parallelogram, rng, 1000),
    0.0,
    1e-10);
  // A face of a box turned about the z axis by layers (the swim, the bend):
  // its corners keep their z, but it is no parallelogram.
  const double c0 = std::cos(0.1), s0 = std::sin(0.1), c1 = std::cos(0.45), s1 = std::sin(0.45);
  const glm::dvec3 turned[4] = { { 0.3 * c0, 0.3 * s0, 0.2 },
    { 0.9 * c1, 0.9 * s1, 0.2 },
    { 0.3 * c0 - 0.4 * s0, 0.3 * s0 + 0.4 * c0, 0.2 },
    { 0.9 * c1 - 0.4 * s1, 0.9 * s1 + 0.4 * c1, 0.2 } };
  Expect("turned layer face: its plane's hits against the general solve's, 1000 rays",
    WorstPlanarAgainstGeneral(turned, lfd::PatchFromOrigin::Shape::Planar, rng, 1000),
    0.0,
    1e-10);

  // A ray perpendicular to the unit square, and its s,t.
  const glm::dvec3 square[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
  Expect("unit square, ray through (0.25, 0.75)",
    HitError(square, { 0.25, 0.75, 2 }, { 0, 0, -1 }, 0.25, 0.75, 2.0),
    0.0);
  Expect("unit square, ray through its corner (slack keeps it)",
    HitError(square, { 1, 1, 2 }, { 0, 0, -1 }, 1.0, 1.0, 2.0),
    0.0);
  Expect("ray parallel to the square, above it", CountHits(square, { -1, 0.5, 1 }, { 1, 0, 0 }), 0);
  Expect("ray in the square's plane", CountHits(square, { -1, 0.5, 0 }, { 1, 0.2, 0 }), 0);
  Expect("ray parallel to the square's t-lines", CountHits(square, { 0.5, -1, 1 }, { 0, 1, 0 }), 0);
  Expect("ray missing the square", CountHits(square, { 1.5, 0.5, 1 }, { 0, 0, -1 }), 0);
  Expect("ray hitting the square behind its origin (T < 0 reported)",
    HitError(square, { 0.5, 0.5, -1 }, { 0, 0, -1 }, 0.5, 0.5, -1.0),
    0.0);

  // The saddle z = s t, crossed twice by the chord of z = s^2 over s = t.
  const glm::dvec3 saddle[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 1 } };
  const glm::dvec3 o(0, 0, -0.16), d(1, 1, 1);
  Expect("saddle chord: hits", CountHits(saddle, o, d), 2);
  Expect("saddle chord: first hit", HitError(saddle, o, d, 0.2, 0.2, 0.2), 0.0);
  Expect("saddle chord: second hit", HitError(saddle, o, d, 0.8, 0.8, 0.8), 0.0);
  lfd::PatchHit hits[2];
  Expect("saddle: left to the general solve (IntersectPlanar's -1)",
    lfd::PatchFromOrigin(saddle[0], saddle[1], saddle[2], saddle[3], o)
      .IntersectPlanar(d, 1.0, hits),
    -1.0,
    0.0);
  Expect("saddle: ray along its ruling t = 0.5 (in the surface)",
    CountHits(saddle, { -1, 0.5, -0.5 }, { 1, 0, 0.5 }),
    0);

  return lfdtest::Result();
}
