// The exact ray warp (Sec. 5, lfdRayWarp.h): on random deformed boxes the
// warped entry and exit points equal the rest images of the Newton inverse
// of the deformed ones, and the segments are exactly the inside of the box;
// rays through edges and corners and rays grazing a face give the right
// number of segments and no NaN; a twisted box is entered twice; a ray
// leaving one box enters its face neighbour at the same point; a point of a
// face maps into the rest box as well through the face's 4 corners alone;
// rays warped four at a time through two planar faces (WarpRaysThroughBox)
// get the intervals of WarpRayThroughBox to the bit.
#include "lfdRayWarp.h"
#include "lfdTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>

using lfdtest::Expect;

namespace TestRayWarpHelpers
{
lfd::Hexahedron UnitCube(double scale = 1.0)
{
  lfd::Hexahedron box;
  for (int i = 0; i < 8; ++i)
  {
    box.Corners[i] =
      scale * glm::dvec3(lfd::HexCorner[i][0], lfd::HexCorner[i][1], lfd::HexCorner[i][2]);
  }
  return box;
}

// The map does not fold: the Jacobian determinant has one sign at the 8
// corners and the centre.
bool Unfolded(const lfd::Hexahedron& box)
{
  int positive = 0;
  for (int i = 0; i <= 8; ++i)
  {
    const glm::dvec3 uvw = i < 8
      ? glm::dvec3(lfd::HexCorner[i][0], lfd::HexCorner[i][1], lfd::HexCorner[i][2])
      : glm::dvec3(0.5);
    positive += glm::determinant(lfd::TrilinearJacobian(box, uvw)) > 0.0 ? 1 : 0;
  }
  return positive == 9;
}

lfd::Hexahedron RandomBox(std::mt19937_64& rng, double amplitude)
{
  std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
  lfd::Hexahedron box;
  do
  {
    box = UnitCube();
    for (auto& corner : box.Corners)
    {
      corner += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
    }
  } while (!Unfolded(box));
  return box;
}

bool Inside(const lfd::Hexahedron& box, const glm::dvec3& p)
{
  glm::dvec3 uvw;
  return lfd::Contains(box, p, uvw);
}

// Distance between the warped point of a segment end and the rest image of
// the Newton inverse of the deformed point.
double WarpError(const lfd::Hexahedron& rest,
  const lfd::Hexahedron& deformed,
  const glm::dvec3& point,
  const glm::dvec3& warped)
{
  glm::dvec3 restPoint, uvw;
  if (!lfd::WarpPoint(rest, deformed, point, restPoint, uvw))
  {
    return HUGE_VAL;
  }
  return glm::distance(restPoint, warped);
}

bool Finite(const lfd::WarpedSegment& s)
{
  const double sum = s.TEnter + s.TExit + s.RestEnter.x + s.RestEnter.y + s.RestEnter.z +
    s.RestExit.x + s.RestExit.y + s.RestExit.z;
  return std::isfinite(sum);
}

int Warp(const lfd::Hexahedron& rest,
  const lfd::Hexahedron& deformed,
  const glm::dvec3& o,
  const glm::dvec3& d,
  lfd::WarpedSegment* segments,
  double tMin = 0.0)
{
  return lfd::WarpRayThroughBox(rest, deformed, o, d, tMin, segments, lfd::MaxWarpedSegments);
}

void RandomBoxes()
{
  std::mt19937_64 rng(2005);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  double worstWarp = 0.0;
  int segmentCount = 0, multiple = 0, originInside = 0, wrongInside = 0, wrongOutside = 0,
      uncovered = 0, invalid = 0, parityRays = 0, parityMismatches = 0;
  for (int i = 0; i < 1000; ++i)
  {
    const lfd::Hexahedron rest = RandomBox(rng, 0.1);
    const lfd::Hexahedron deformed = RandomBox(rng, 0.45);
    const double size = lfd::BoxSize(deformed);
    // A ray through a random interior point, from outside or (one in four)
    // from that point.
    const glm::dvec3 target =
      lfd::TrilinearMap(deformed, glm::dvec3(unit(rng), unit(rng), unit(rng)) * 0.9 + 0.05);
    const glm::dvec3 d = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    const double tTarget = i % 4 == 0 ? 0.0 : 3.0 * size;
    const glm::dvec3 o = target - tTarget * d;
    lfd::WarpedSegment segments[lfd::MaxWarpedSegments];
    const int n = Warp(rest, deformed, o, d, segments);
    segmentCount += n;
    multiple += n > 1 ? 1 : 0;
    bool covered = false;
    for (int k = 0; k < n; ++k)
    {
      const lfd::WarpedSegment& s = segments[k];
      invalid +=
        Finite(s) && s.TExit > s.TEnter && (k == 0 || s.TEnter > segments[k - 1].TExit) ? 0 : 1;
      originInside += s.TEnter == 0.0 ? 1 : 0;
      worstWarp =
        std::max(worstWarp, WarpError(rest, deformed, o + s.TEnter * d, s.RestEnter) / size);
      worstWarp =
        std::max(worstWarp, WarpError(rest, deformed, o + s.TExit * d, s.RestExit) / size);
      wrongInside += Inside(deformed, o + 0.5 * (s.TEnter + s.TExit) * d) ? 0 : 1;
      const double step = 1e-4 * size;
      if (s.TEnter > 0.0)
      {
        wrongOutside += Inside(deformed, o + (s.TEnter - step) * d) ? 1 : 0;
      }
      wrongOutside += Inside(deformed, o + (s.TExit + step) * d) ? 1 : 0;
      covered = covered || (s.TEnter <= tTarget && tTarget <= s.TExit);
    }
    uncovered += covered ? 0 : 1;

    // From an origin known to be outside, the parity shortcut (no Newton
    // test for a two-crossing ray) gives the same segments.
    if (tTarget > 0.0 && !Inside(deformed, o))
    {
      lfd::WarpedSegment fast[lfd::MaxWarpedSegments];
      const int m = lfd::WarpRayThroughBox(
        rest, deformed, o, d, 0.0, fast, lfd::MaxWarpedSegments, /*startsOutside=*/true);
      bool same = m == n;
      for (int k = 0; same && k < n; ++k)
      {
        same = std::abs(fast[k].TEnter - segments[k].TEnter) <= 1e-12 * size &&
          std::abs(fast[k].TExit - segments[k].TExit) <= 1e-12 * size &&
          glm::distance(fast[k].RestEnter, segments[k].RestEnter) <= 1e-12 * size &&
          glm::distance(fast[k].RestExit, segments[k].RestExit) <= 1e-12 * size;
      }
      parityMismatches += same ? 0 : 1;
      ++parityRays;
    }
  }
  std::cout << "1000 random boxes: " << segmentCount << " segments, " << multiple
            << " rays with more than one, " << originInside << " starting inside\n";
  Expect("random boxes: max warp error / box size", worstWarp, 0.0, 1e-6);
  Expect("random boxes: segments not finite, empty or unsorted", invalid, 0);
  Expect("random boxes: segment midpoints outside the box", wrongInside, 0);
  Expect("random boxes: points just outside segments inside the box", wrongOutside, 0);
  Expect("random boxes: interior points on the ray not covered", uncovered, 0);
  std::cout << parityRays << " rays from outside checked with the parity shortcut\n";
  Expect("random boxes: parity shortcut differing from the Newton tests", parityMismatches, 0);
}

void EdgesCornersAndGrazing()
{
  // A unit cube warped onto a cube of side 2: rest = 2 x deformed.
  const lfd::Hexahedron rest = UnitCube(2.0), cube = UnitCube();
  lfd::WarpedSegment s[lfd::MaxWarpedSegments];

  int n = Warp(rest, cube, { -0.5, -0.5, 0.5 }, { 1, 1, 0 }, s);
  Expect("through the edges x = y = 0 and x = y = 1: segments", n, 1);
  Expect("  enter T", n == 1 ? s[0].TEnter : -1, 0.5);
  Expect("  exit T", n == 1 ? s[0].TExit : -1, 1.5);
  Expect("  rest entry distance to (0, 0, 1)",
    n == 1 ? glm::distance(s[0].RestEnter, glm::dvec3(0, 0, 1)) : -1,
    0.0);
  Expect("  rest exit distance to (2, 2, 1)",
    n == 1 ? glm::distance(s[0].RestExit, glm::dvec3(2, 2, 1)) : -1,
    0.0);

  n = Warp(rest, cube, { -1, -1, -1 }, { 1, 1, 1 }, s);
  Expect("corner to opposite corner: segments", n, 1);
  Expect("  rest exit distance to (2, 2, 2)",
    n == 1 ? glm::distance(s[0].RestExit, glm::dvec3(2, 2, 2)) : -1,
    0.0);

  Expect("touching only the edge x = y = 0: segments",
    Warp(rest, cube, { -1, 1, 0.5 }, { 1, -1, 0 }, s),
    0);
  Expect("touching only the corner 0: segments",
    Warp(rest, cube, { -1, 1, -0.3 }, { 1, -1, 0.3 }, s),
    0);
  n = Warp(rest, cube, { -1, 0.5, 0 }, { 1, 0, 0 }, s);
  Expect("lying in the face z = 0: segments (the closed box)", n, 1);
  Expect("  length", n == 1 ? s[0].TExit - s[0].TEnter : -1, 1.0);
  Expect("lying in the plane z = 0 beside the face: segments",
    Warp(rest, cube, { -1, 1.5, 0 }, { 1, 0, 0 }, s),
    0);

  // The top face a saddle z = 1 + k (1 - 2x)(1 - 2y), tangent to the plane
  // z = 1 at its centre. Over the diagonal x = y it rises, over x = -y it falls.
  const double k = 0.2;
  lfd::Hexahedron saddle = cube;
  saddle.Corners[4].z += k;
  saddle.Corners[5].z -= k;
  saddle.Corners[6].z += k;
  saddle.Corners[7].z -= k;
  n = Warp(rest, saddle, { 1.5, -0.5, 1 }, { -1, 1, 0 }, s);
  Expect("tangent to the saddle from outside: segments", n, 0);
  n = Warp(rest, saddle, { -0.5, -0.5, 1 }, { 1, 1, 0 }, s);
  Expect("tangent to the saddle from inside, through 2 edges: segments", n, 1);
  Expect("  enter T", n == 1 ? s[0].TEnter : -1, 0.5);
  Expect("  exit T", n == 1 ? s[0].TExit : -1, 1.5);
  Expect("  rest exit distance to (2, 2, 2 / (1 + k))",
    n == 1 ? glm::distance(s[0].RestExit, glm::dvec3(2, 2, 2 / (1 + k))) : -1,
    0.0);

  // Rays shifted and tilted by up to 5e-8 around both tangencies: finite and
  // never shorter than the dropping threshold. Shifted up, the inner one
  // leaves the box around the centre and comes back (2 segments); shifted
  // down, the outer one dips into the box (1 segment).
  int bad = 0, mostInner = 0, mostOuter = 0;
  for (int i = -50; i <= 50; ++i)
  {
    const double h = i * 1e-9;
    n = Warp(rest, saddle, { -0.5, -0.5, 1 + h }, { 1, 1, h }, s);
    mostInner = std::max(mostInner, n);
    for (int j = 0; j < n; ++j)
    {
      bad += Finite(s[j]) && s[j].TExit - s[j].TEnter >= 1e-7 ? 0 : 1;
    }
    n = Warp(rest, saddle, { 1.5, -0.5, 1 + h }, { -1, 1, h }, s);
    mostOuter = std::max(mostOuter, n);
    for (int j = 0; j < n; ++j)
    {
      bad += Finite(s[j]) && s[j].TExit - s[j].TEnter >= 1e-7 ? 0 : 1;
    }
  }
  Expect("202 nearly grazing rays: NaN or too short segments", bad, 0);
  Expect("101 nearly tangent from inside: most segments", mostInner, 2);
  Expect("101 nearly tangent from outside: most segments", mostOuter, 1);

  // The origin inside: the segment starts at tMin, warped by the inverse map.
  n = Warp(rest, cube, { 0.25, 0.5, 0.5 }, { 1, 0, 0 }, s, 0.5);
  Expect("origin inside, tMin = 0.5: segments", n, 1);
  Expect("  enter T", n == 1 ? s[0].TEnter : -1, 0.5);
  Expect("  rest entry distance to (1.5, 1, 1)",
    n == 1 ? glm::distance(s[0].RestEnter, glm::dvec3(1.5, 1, 1)) : -1,
    0.0);
  Expect("ray leaving the box before tMin: segments",
    Warp(rest, cube, { 0.25, 0.5, 0.5 }, { 1, 0, 0 }, s, 2.0),
    0);
}

void TwistedBox()
{
  // The top face rotated by 90 degrees about the vertical axis: the cross
  // section at height w is the square (w,0) (1,w) (1-w,1) (0,1-w), smallest
  // at mid-height. The vertical line through (0.1, 0.1) leaves through the
  // face u = 0 where w - w^2 = 0.1 and comes back in.
  const lfd::Hexahedron rest = UnitCube();
  lfd::Hexahedron twisted = rest;
  for (int i = 4; i < 8; ++i)
  {
    const glm::dvec3 c = rest.Corners[i] - glm::dvec3(0.5, 0.5, 0);
    twisted.Corners[i] = glm::dvec3(0.5 - c.y, 0.5 + c.x, c.z);
  }
  Expect("twisted box is unfolded", Unfolded(twisted), 1);
  lfd::WarpedSegment s[lfd::MaxWarpedSegments];
  const int n = Warp(rest, twisted, { 0.1, 0.1, -1 }, { 0, 0, 1 }, s);
  const double w0 = 0.5 * (1 - std::sqrt(0.6)), w1 = 0.5 * (1 + std::sqrt(0.6));
  Expect("twisted box, vertical ray at (0.1, 0.1): segments", n, 2);
  if (n == 2)
  {
    Expect("  first enter T", s[0].TEnter, 1.0);
    Expect("  first exit T", s[0].TExit, 1.0 + w0);
    Expect("  second enter T", s[1].TEnter, 1.0 + w1);
    Expect("  second exit T", s[1].TExit, 2.0);
    double worst = 0.0, worstForward = 0.0;
    for (int k = 0; k < n; ++k)
    {
      const glm::dvec3 enter(0.1, 0.1, s[k].TEnter - 1), exit(0.1, 0.1, s[k].TExit - 1);
      worst = std::max(worst, WarpError(rest, twisted, enter, s[k].RestEnter));
      worst = std::max(worst, WarpError(rest, twisted, exit, s[k].RestExit));
      worstForward =
        std::max(worstForward, glm::distance(lfd::TrilinearMap(twisted, s[k].UvwEnter), enter));
      worstForward =
        std::max(worstForward, glm::distance(lfd::TrilinearMap(twisted, s[k].UvwExit), exit));
    }
    Expect("  max warp error", worst, 0.0, 1e-9);
    Expect("  max |deformed map(uvw) - ray point|", worstForward, 0.0, 1e-9);
  }
}

void SharedFace()
{
  // Two boxes of a perturbed 2 x 1 x 1 lattice: box A's face u = 1 is box
  // B's face u = 0, at rest and deformed.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15), unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  double worstT = 0.0, worstRest = 0.0;
  int crossings = 0, unmatched = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    glm::dvec3 lattice[3][2][2], restLattice[3][2][2];
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 2; ++y)
        for (int z = 0; z < 2; ++z)
        {
          restLattice[x][y][z] = glm::dvec3(x, y, z);
          lattice[x][y][z] =
            restLattice[x][y][z] + glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
        }
    lfd::Hexahedron restA, restB, a, b;
    for (int i = 0; i < 8; ++i)
    {
      const int* c = lfd::HexCorner[i];
      restA.Corners[i] = restLattice[c[0]][c[1]][c[2]];
      restB.Corners[i] = restLattice[c[0] + 1][c[1]][c[2]];
      a.Corners[i] = lattice[c[0]][c[1]][c[2]];
      b.Corners[i] = lattice[c[0] + 1][c[1]][c[2]];
    }
    if (!Unfolded(a) || !Unfolded(b))
    {
      continue;
    }
    const glm::dvec3 pa = lfd::TrilinearMap(a, glm::dvec3(unit(rng), unit(rng), unit(rng)));
    const glm::dvec3 pb = lfd::TrilinearMap(b, glm::dvec3(unit(rng), unit(rng), unit(rng)));
    const glm::dvec3 d = glm::normalize(pb - pa);
    const glm::dvec3 o = pa - 3.0 * d;
    lfd::WarpedSegment sa[lfd::MaxWarpedSegments], sb[lfd::MaxWarpedSegments];
    const int na = Warp(restA, a, o, d, sa);
    const int nb = Warp(restB, b, o, d, sb);
    // Every exit of A through the shared face is an entry of B, and back.
    for (int i = 0; i < na; ++i)
    {
      if (sa[i].UvwExit.x != 1.0)
      {
        continue;
      }
      ++crossings;
      int match = -1;
      for (int j = 0; j < nb; ++j)
      {
        match = std::abs(sb[j].TEnter - sa[i].TExit) < 1e-6 ? j : match;
      }
      if (match < 0)
      {
        ++unmatched;
        continue;
      }
      worstT = std::max(worstT, std::abs(sb[match].TEnter - sa[i].TExit));
      worstRest = std::max(worstRest, glm::distance(sb[match].RestEnter, sa[i].RestExit));
    }
  }
  std::cout << "shared face: " << crossings << " crossings from A into B\n";
  Expect("shared face: crossings of A's exit without B's entry", unmatched, 0);
  Expect("shared face: max |T exit A - T enter B|", worstT, 0.0, 1e-9);
  Expect("shared face: max rest distance exit A - enter B", worstRest, 0.0, 1e-9);

  // The cube pair [0,1] and [1,2] along x, straight through the middle.
  lfd::Hexahedron a = UnitCube(), b = UnitCube();
  for (auto& corner : b.Corners)
  {
    corner.x += 1.0;
  }
  lfd::WarpedSegment sa[lfd::MaxWarpedSegments], sb[lfd::MaxWarpedSegments];
  const int na = Warp(a, a, { -1, 0.3, 0.6 }, { 1, 0.1, 0.05 }, sa);
  const int nb = Warp(b, b, { -1, 0.3, 0.6 }, { 1, 0.1, 0.05 }, sb);
  Expect("cube pair: segments in A", na, 1);
  Expect("cube pair: segments in B", nb, 1);
  if (na == 1 && nb == 1)
  {
    Expect("cube pair: T exit A - T enter B", sa[0].TExit - sb[0].TEnter, 0.0);
    Expect(
      "cube pair: rest exit A - rest enter B", glm::distance(sa[0].RestExit, sb[0].RestEnter), 0.0);
  }
}
}

/**
 * The warp maps its face crossings into the rest box with FaceOfBox: box
 * points on the face, and the same rest points, to the bit, as TrilinearMap
 * of them, on random boxes (corners anywhere, of either sign) at random
 * points of every face, its edges and its corners.
 */
void MapOnFaces()
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), corner(-3.0, 3.0);
  int different = 0, misplaced = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    lfd::Hexahedron box;
    for (auto& c : box.Corners)
    {
      c = glm::dvec3(corner(rng), corner(rng), corner(rng));
    }
    // Every fourth point on an edge or a corner of the face.
    const glm::dvec2 st = trial % 4 == 0
      ? glm::dvec2(
          std::floor(2.0 * unit(rng)), trial % 8 == 0 ? std::floor(2.0 * unit(rng)) : unit(rng))
      : glm::dvec2(unit(rng), unit(rng));
    for (int face = 0; face < 6; ++face)
    {
      const lfd::FaceOfBox onBox(box, face);
      const glm::dvec3 uvw = onBox.BoxPoint(st.x, st.y);
      const int* axes = lfd::FaceAxes[face];
      misplaced += uvw[axes[0]] != face % 2 || uvw[axes[1]] != st.x || uvw[axes[2]] != st.y;
      const glm::dvec3 onFace = onBox.Map(st.x, st.y);
      const glm::dvec3 anywhere = lfd::TrilinearMap(box, uvw);
      different += std::memcmp(&onFace, &anywhere, sizeof(onFace)) != 0;
    }
  }
  Expect("points of faces (12000) off their face's box coordinates", misplaced, 0);
  Expect("points of faces (12000) mapped unlike TrilinearMap, bitwise", different, 0);
}

/**
 * WarpRaysThroughBox against WarpRayThroughBox through the same two faces
 * (every pair of planar faces; a ray crossing neither or one gets no
 * interval), bitwise: frusta hinged at one end (two sides trapezoids, two
 * curved, the ends parallelograms), turned and moved, seen from outside,
 * rays at random points near the box, at its corners and at its edges'
 * midpoints, and parallel to 4 of its faces, in batches of 1 to 4.
 */
void WarpsInBatches()
{
  using namespace TestRayWarpHelpers;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  int compared = 0, decided = 0, intervals = 0, different = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    lfd::Hexahedron rest = UnitCube(), deformed = UnitCube();
    const double taper = 0.4 + 0.8 * unit(rng), hinge = 0.6 * sym(rng);
    for (int i = 4; i < 8;
         ++i) // (w = 1: narrowed, then turned about the x axis through (0.5, 0.5, 0))
    {
      glm::dvec3& c = deformed.Corners[i];
      c = glm::dvec3(0.5 + taper * (c.x - 0.5), 0.5 + taper * (c.y - 0.5), c.z);
      const double y = c.y - 0.5, z = c.z;
      c.y = 0.5 + std::cos(hinge) * y - std::sin(hinge) * z;
      c.z = std::sin(hinge) * y + std::cos(hinge) * z;
    }
    const glm::dvec3 axis = glm::normalize(glm::dvec3(sym(rng), sym(rng), sym(rng)));
    const double angle = 3.0 * sym(rng);
    const glm::dvec3 shift(sym(rng), sym(rng), sym(rng));
    for (auto& c : deformed.Corners)
    {
      // Rodrigues' rotation, then a shift.
      c = c * std::cos(angle) + glm::cross(axis, c) * std::sin(angle) +
        axis * glm::dot(axis, c) * (1.0 - std::cos(angle)) + shift;
    }
    for (auto& c : rest.Corners)
    {
      c = 2.0 * c + shift;
    }
    const glm::dvec3 centre = lfd::TrilinearMap(deformed, glm::dvec3(0.5));
    glm::dvec3 eye;
    do
    {
      eye = centre + 4.0 * glm::dvec3(sym(rng), sym(rng), sym(rng));
    } while (Inside(deformed, eye) || glm::distance(eye, centre) < 2.0);
    const lfd::BoxFromOrigin seen(rest, deformed, eye);
    glm::dvec3 d[lfd::MaximumWarpBatch];
    for (int batch = 0; batch < 20; ++batch)
    {
      const int count = 1 + batch % lfd::MaximumWarpBatch;
      for (int i = 0; i < count; ++i)
      {
        const int kind = (batch + i) % 5;
        const glm::dvec3 target = kind == 0 ? deformed.Corners[(batch + i) % 8]
          : kind == 1
          ? 0.5 * (deformed.Corners[(batch + i) % 8] + deformed.Corners[(batch + 3 * i) % 8])
          : lfd::TrilinearMap(
              deformed, glm::dvec3(1.4 * unit(rng) - 0.2, 1.4 * unit(rng) - 0.2, unit(rng)));
        // (Every fifth ray along an edge of faces 2 and 4: parallel to
        // their planes, which it does not cross, or lies in.)
        d[i] = kind == 4 ? deformed.Corners[1] - deformed.Corners[0]
                         : (0.5 + unit(rng)) * (target - eye);
      }
      for (int face0 = 0; face0 < 6; ++face0)
      {
        for (int face1 = face0 + 1; face1 < 6; ++face1)
        {
          if (seen.Faces[face0].Form == lfd::PatchFromOrigin::Shape::Curved ||
            seen.Faces[face1].Form == lfd::PatchFromOrigin::Shape::Curved)
          {
            continue;
          }
          lfd::WarpedSegment batched[lfd::MaximumWarpBatch];
          int status[lfd::MaximumWarpBatch];
          lfd::WarpRaysThroughBox(seen, (1 << face0) | (1 << face1), d, count, batched, status);
          for (int i = 0; i < count; ++i)
          {
            lfd::WarpedSegment one[lfd::MaxWarpedSegments];
            const int n = lfd::WarpRayThroughBox(seen,
              rest,
              deformed,
              d[i],
              0.0,
              one,
              lfd::MaxWarpedSegments,
              true,
              (1 << face0) | (1 << face1));
            ++compared;
            if (status[i] < 0)
            {
              continue;
            }
            ++decided;
            intervals += status[i];
            const lfd::WarpedSegment& a = batched[i];
            const lfd::WarpedSegment& b = one[0];
            different += n != status[i] ||
              (n == 1 &&
                (std::memcmp(&a.TEnter, &b.TEnter, sizeof(double)) != 0 ||
                  std::memcmp(&a.TExit, &b.TExit, sizeof(double)) != 0 ||
                  std::memcmp(&a.RestEnter, &b.RestEnter, sizeof(glm::dvec3)) != 0 ||
                  std::memcmp(&a.RestExit, &b.RestExit, sizeof(glm::dvec3)) != 0 ||
                  std::memcmp(&a.UvwEnter, &b.UvwEnter, sizeof(glm::dvec3)) != 0 ||
                  std::memcmp(&a.UvwExit, &b.UvwExit, sizeof(glm::dvec3)) != 0 ||
                  a.FaceExit != b.FaceExit));
          }
        }
      }
    }
  }
  std::cout << "batched warps: " << compared << " rays and face pairs, " << decided << " decided, "
            << intervals << " intervals\n";
  Expect("batched warps unlike WarpRayThroughBox, bitwise", different, 0);
#if defined(__GNUC__) && defined(__x86_64__)
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
  {
    // (Undecided: the rays parallel to faces 2 and 4, with either face.)
    lfdtest::Check(decided >= 0.8 * compared && decided < compared,
      "batched warps decide 80% or more of the rays, not the rays parallel to a face");
    lfdtest::Check(intervals >= 2000, "batched warps give at least 2000 intervals");
  }
#endif
}

int TestRayWarp(int, char*[])
{
  using namespace TestRayWarpHelpers;
  MapOnFaces();
  RandomBoxes();
  EdgesCornersAndGrazing();
  TwistedBox();
  SharedFace();
  WarpsInBatches();
  return lfdtest::Result();
}
