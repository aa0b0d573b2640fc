// The automatic subdivision (lfdTessellation.h) from the measured warp
// deviation: zero for a box at rest and for an affine move, falling as
// 1 / k^2 on a twisted box; it bounds how far the straight warped rays of
// the tessellated box (lfdRayWarp.h) really stray from the exact, curved
// rest images of view rays; AutomaticSubdivision picks k = 1 at rest and
// under an affine map, more for a stronger twist, and the k it picks meets
// the tolerance.
#include "lfdRayWarp.h"
#include "lfdTessellation.h"
#include "lfdTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

using lfdtest::Expect;

namespace TestTessellationHelpers
{
lfd::Hexahedron UnitCube()
{
  lfd::Hexahedron box;
  for (int i = 0; i < 8; ++i)
  {
    box.Corners[i] = glm::dvec3(lfd::HexCorner[i][0], lfd::HexCorner[i][1], lfd::HexCorner[i][2]);
  }
  return box;
}

/// The unit cube with its top face (w = 1) turned by `degrees` about the
/// vertical axis through the cube's centre: vtkCagePoseFilter's twist.
lfd::Hexahedron Twisted(double degrees)
{
  lfd::Hexahedron box = UnitCube();
  const double a = degrees * 3.14159265358979323846 / 180.0;
  for (int i = 4; i < 8; ++i)
  {
    const glm::dvec3 p = box.Corners[i] - glm::dvec3(0.5, 0.5, 0.0);
    box.Corners[i] = glm::dvec3(0.5 + p.x * std::cos(a) - p.y * std::sin(a),
      0.5 + p.x * std::sin(a) + p.y * std::cos(a),
      p.z);
  }
  return box;
}

/**
 * The largest distance, over random view rays through the deformed box split
 * k times, between the exact rest image of a point of the view ray (Newton
 * inverse of the sub-box it is in) and the straight warped ray of its
 * interval at the same place.
 */
double MeasuredStray(const lfd::Hexahedron& rest, const lfd::Hexahedron& deformed, int k)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double stray = 0.0;
  for (int ray = 0; ray < 200; ++ray)
  {
    const glm::dvec3 o(-2.0 + unit(rng), -2.0 + 5.0 * unit(rng), -1.0 + 3.0 * unit(rng));
    const glm::dvec3 target(0.2 + 0.6 * unit(rng), 0.2 + 0.6 * unit(rng), 0.2 + 0.6 * unit(rng));
    const glm::dvec3 d = target - o;
    lfd::ForEachSubBox(k,
      [&](const glm::ivec3& cell)
      {
        const lfd::Hexahedron subRest = lfd::SubBox(rest, k, cell);
        const lfd::Hexahedron subDeformed = lfd::SubBox(deformed, k, cell);
        lfd::WarpedSegment found[lfd::MaxWarpedSegments];
        const int n =
          lfd::WarpRayThroughBox(subRest, subDeformed, o, d, 0.0, found, lfd::MaxWarpedSegments);
        for (int s = 0; s < n; ++s)
        {
          for (double f : { 0.25, 0.5, 0.75 })
          {
            const double t = found[s].TEnter + f * (found[s].TExit - found[s].TEnter);
            glm::dvec3 uvw = found[s].UvwEnter + f * (found[s].UvwExit - found[s].UvwEnter);
            if (!lfd::InvertTrilinear(subDeformed, o + t * d, uvw))
            {
              continue;
            }
            const glm::dvec3 exact = lfd::TrilinearMap(subRest, uvw);
            const glm::dvec3 warped =
              found[s].RestEnter + f * (found[s].RestExit - found[s].RestEnter);
            stray = std::max(stray, glm::distance(exact, warped));
          }
        }
      });
  }
  return stray;
}
}

int TestTessellation(int, char*[])
{
  using namespace TestTessellationHelpers;
  const lfd::Hexahedron cube = UnitCube();
  Expect("deviation of a box at rest", lfd::WarpDeviation(cube, cube, 1), 0.0, 1e-12);
  lfd::Hexahedron affine;
  const glm::dmat3 linear(1.2, 0.1, 0.0, -0.2, 0.9, 0.3, 0.1, 0.0, 1.1);
  for (int c = 0; c < 8; ++c)
  {
    affine.Corners[c] = linear * cube.Corners[c] + glm::dvec3(3.0, -1.0, 2.0);
  }
  Expect("deviation of an affine move", lfd::WarpDeviation(cube, affine, 1), 0.0, 1e-9);
  Expect("automatic k at rest", lfd::AutomaticSubdivision(cube, cube, 1e-6), 1, 0.0);
  Expect("automatic k of an affine move", lfd::AutomaticSubdivision(cube, affine, 1e-6), 1, 0.0);

  // A twist of 40 degrees: the deviation falls as 1 / k^2.
  const lfd::Hexahedron twist = Twisted(40.0);
  const double d1 = lfd::WarpDeviation(cube, twist, 1);
  const double d2 = lfd::WarpDeviation(cube, twist, 2);
  const double d4 = lfd::WarpDeviation(cube, twist, 4);
  std::cout << "twist 40: deviation k = 1, 2, 4: " << d1 << " " << d2 << " " << d4 << "\n";
  Expect("twist 40: deviation k = 1 over k = 2 (1/k^2)", d1 / d2, 4.0, 0.4);
  Expect("twist 40: deviation k = 2 over k = 4 (1/k^2)", d2 / d4, 4.0, 0.4);
  // It bounds what the warped rays of real view rays do, and not loosely.
  for (int k : { 1, 2, 4 })
  {
    const double stray = MeasuredStray(cube, twist, k);
    const double deviation = lfd::WarpDeviation(cube, twist, k);
    std::cout << "twist 40, k = " << k << ": warped rays stray " << stray << ", deviation "
              << deviation << "\n";
    Expect("  the deviation bounds the warped rays' stray (ratio in [1, 2])",
      deviation / stray,
      1.5,
      0.5);
  }

  // The automatic choice: more for a stronger twist, and it meets the tolerance.
  const double tolerance = 0.02;
  const int k40 = lfd::AutomaticSubdivision(cube, twist, tolerance);
  const int k90 = lfd::AutomaticSubdivision(cube, Twisted(90.0), tolerance);
  std::cout << "automatic k at tolerance " << tolerance << ": twist 40 " << k40 << ", twist 90 "
            << k90 << "\n";
  Expect("twist 40: automatic k", k40, 4, 0.0);
  Expect("twist 90: automatic k", k90, 6, 0.0);
  Expect("twist 40: the automatic k meets the tolerance",
    lfd::WarpDeviation(cube, twist, k40) <= tolerance,
    1,
    0.0);
  Expect(
    "twist 40: one less does not", lfd::WarpDeviation(cube, twist, k40 - 1) > tolerance, 1, 0.0);
  Expect("a tolerance no k meets: the largest k",
    lfd::AutomaticSubdivision(cube, twist, 1e-12),
    lfd::MaximumAutomaticSubdivision,
    0.0);
  return lfdtest::Result();
}
