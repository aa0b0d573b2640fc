// RENDER_VIEW (paper Sec. 6, lfdRenderView.h) on analytic light fields whose
// parts are spheres: an identity cage renders exactly what the undeformed
// light field shows; of two moved boxes on a ray the nearer one wins in
// whichever order the boxes are given; a ray through a twisted box gets two
// intervals and the first visible one gives the pixel; a ray through 200
// boxes keeps all 200 segments, sorted by distance; a frame of 100 moved
// boxes through the per-frame culling (lfd::FrameCage) renders every pixel
// exactly as testing every box does, trying and warping far fewer boxes;
// an interval held on the proxy surface is not displaced by a later one
// focused on the plane.
#include "lfdRenderView.h"
#include "lfdTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using lfdtest::Expect;

namespace TestRenderViewHelpers
{
/// A part of the light field: the rays whose line meets the sphere see it.
struct Part
{
  glm::dvec3 Center;
  double Radius;
  int Label;
  glm::dvec3 Color;
};

/**
 * A light field of spheres in rest space, looked up like lfd::SamplerLookup:
 * the line o + s d sees the part it meets first along d, one sample whose
 * colour varies with where the line passes (so that any change of the looked
 * up line shows), else background (label 0). Every lookup is counted.
 */
struct SphereLookup
{
  std::vector<Part> Parts;
  mutable int Gathers = 0;

  bool Gather(const glm::dvec3& o, const glm::dvec3& d, lfd::RaySamples& out) const
  {
    ++this->Gathers;
    lfd::RaySample& sample = out.Samples[0];
    out.Count = 1;
    sample = { glm::dvec3(10.0, 20.0, 30.0), 1.0, 0 };
    double nearest = std::numeric_limits<double>::infinity();
    for (const Part& part : this->Parts)
    {
      const double s = glm::dot(part.Center - o, d) / glm::dot(d, d);
      const glm::dvec3 offset = o + s * d - part.Center;
      if (glm::length(offset) < part.Radius && s < nearest)
      {
        nearest = s;
        sample = { part.Color + 50.0 * offset / part.Radius, 1.0, part.Label };
      }
    }
    return true;
  }
  bool Widen(const glm::dvec3&, const glm::dvec3&, int, glm::dvec3&) const { return false; }
  double FocalDepth(const glm::dvec3& o, const glm::dvec3& d) const
  {
    return -glm::dot(o, d) / glm::dot(d, d);
  }
  /// Focused at the line's closest approach to the origin.
  double FocalParameter(const glm::dvec3& o, const glm::dvec3& d) const
  {
    return -glm::dot(o, d) / glm::dot(d, d);
  }
};

/// The axis-aligned box [low, low + size].
lfd::Hexahedron Cube(const glm::dvec3& low, double size = 1.0)
{
  lfd::Hexahedron box;
  for (int c = 0; c < 8; ++c)
  {
    box.Corners[c] =
      low + size * glm::dvec3(lfd::HexCorner[c][0], lfd::HexCorner[c][1], lfd::HexCorner[c][2]);
  }
  return box;
}

lfd::RenderViewSettings SettingsFor(const std::vector<lfd::RenderBox>& boxes)
{
  lfd::RenderViewSettings settings;
  settings.Owned = lfd::OwnedLabels(boxes);
  return settings;
}

lfd::ViewSample Render(const glm::dvec3& o,
  const glm::dvec3& d,
  std::vector<lfd::RenderBox> boxes,
  const SphereLookup& lookup)
{
  lfd::PlaceEye(boxes, o);
  std::vector<lfd::BoxSegment> segments;
  return lfd::RenderView(o, d, boxes, lookup, SettingsFor(boxes), segments);
}

void IdentityCage()
{
  // Two parts, each inside its own box of a 2 x 1 x 1 cage at rest, the cage
  // tessellated 3 x 3 x 3 as the renderer does; a 33 x 33 grid of rays.
  SphereLookup lookup;
  lookup.Parts = { { { 0.5, 0.5, 0.5 }, 0.45, 1, { 200, 60, 40 } },
    { { 1.5, 0.5, 0.5 }, 0.45, 2, { 40, 180, 90 } } };
  std::vector<lfd::RenderBox> boxes;
  lfd::Tessellate(lfd::MakeRenderBox(Cube({ 0, 0, 0 }), Cube({ 0, 0, 0 }), 1), 3, boxes);
  lfd::Tessellate(lfd::MakeRenderBox(Cube({ 1, 0, 0 }), Cube({ 1, 0, 0 }), 2), 3, boxes);
  const glm::dvec3 eye(0.9, 0.4, -3.0);
  int rays = 0, different = 0, parts = 0;
  for (int i = 0; i <= 32; ++i)
  {
    for (int j = 0; j <= 32; ++j)
    {
      const glm::dvec3 d = glm::dvec3(-0.4 + 0.8 * i / 32.0, -0.25 + 0.5 * j / 32.0, 1.0);
      const lfd::ViewSample caged = Render(eye, d, boxes, lookup);
      const lfd::ViewSample undeformed = Render(eye, d, {}, lookup);
      different += caged.Label != undeformed.Label || caged.Color != undeformed.Color;
      parts += caged.Label > 0;
      ++rays;
    }
  }
  Expect("identity cage: rays", rays, 33 * 33, 0.0);
  Expect("identity cage: rays seeing a part", parts, 276, 0.0);
  Expect("identity cage: rays whose label or colour differs from the undeformed lookup",
    different,
    0,
    0.0);
}

void OcclusionOrder()
{
  // Parts 1 and 2 rest side by side; both boxes are moved onto the ray
  // x = y = 0.5, one of them nearer the eye.
  SphereLookup lookup;
  lookup.Parts = { { { 0.5, 0.5, 0.5 }, 0.3, 1, { 250, 0, 0 } },
    { { 3.5, 0.5, 0.5 }, 0.3, 2, { 0, 250, 0 } } };
  const glm::dvec3 eye(0.5, 0.5, -10.0), d(0.0, 0.0, 1.0);
  for (int nearer = 1; nearer <= 2; ++nearer)
  {
    const lfd::RenderBox one =
      lfd::MakeRenderBox(Cube({ 0, 0, 0 }), Cube({ 0, 0, nearer == 1 ? 0.0 : 2.0 }), 1);
    const lfd::RenderBox two =
      lfd::MakeRenderBox(Cube({ 3, 0, 0 }), Cube({ 0, 0, nearer == 2 ? 0.0 : 2.0 }), 2);
    for (int order = 0; order < 2; ++order)
    {
      const std::string what = "box " + std::to_string(nearer) + " nearer, boxes given " +
        (order == 0 ? "1, 2" : "2, 1") + ": ";
      const lfd::ViewSample seen =
        Render(eye, d, order == 0 ? std::vector{ one, two } : std::vector{ two, one }, lookup);
      Expect(what + "label", seen.Label, nearer);
      Expect(what + "red", std::round(seen.Color.r), nearer == 1 ? 250.0 : 0.0);
      Expect(what + "green", std::round(seen.Color.g), nearer == 1 ? 0.0 : 250.0);
      Expect(what + "depth", seen.Depth, 10.5);
    }
  }
}

void TwistedBox()
{
  // The unit cube with its top face turned by 90 degrees (as in
  // TestRayWarp): the vertical line through (0.1, 0.1) leaves through the
  // face u = 0 at height w0 and comes back in at w1 (w - w^2 = 0.1). In rest
  // space the first interval runs from (0.1, 0.1, 0) to (0, w0, w0), the
  // second from (0, w1, w1) to (0.1, 0.9, 1).
  const double w0 = 0.5 * (1 - std::sqrt(0.6)), w1 = 0.5 * (1 + std::sqrt(0.6));
  const lfd::Hexahedron rest = Cube({ 0, 0, 0 });
  lfd::Hexahedron twisted = rest;
  for (int i = 4; i < 8; ++i)
  {
    const glm::dvec3 c = rest.Corners[i] - glm::dvec3(0.5, 0.5, 0);
    twisted.Corners[i] = glm::dvec3(0.5 - c.y, 0.5 + c.x, c.z);
  }
  std::vector<lfd::RenderBox> boxes{ lfd::MakeRenderBox(rest, twisted, 1) };
  const glm::dvec3 eye(0.1, 0.1, -1.0), d(0.0, 0.0, 1.0);
  lfd::PlaceEye(boxes, eye);
  std::vector<lfd::BoxSegment> segments;
  lfd::CollectSegments(boxes, eye, d, segments);
  Expect("twisted box: intervals", static_cast<double>(segments.size()), 2, 0.0);
  if (segments.size() != 2)
  {
    return;
  }
  Expect("  first exit", segments[0].Segment.TExit, 1 + w0, 1e-12);
  Expect("  second entry", segments[1].Segment.TEnter, 1 + w1, 1e-12);

  // A part on the second interval's warped ray only: the pixel is the
  // second interval; add one on the first: the first, nearer, wins.
  SphereLookup lookup;
  lookup.Parts = { { { 0.05, 0.5 * (w1 + 0.9), 0.5 * (w1 + 1) }, 0.05, 1, { 0, 0, 200 } } };
  lfd::ViewSample seen = lfd::RenderView(eye, d, boxes, lookup, SettingsFor(boxes), segments);
  Expect("  part behind the fold: label", seen.Label, 1, 0.0);
  Expect("  part behind the fold: blue", std::round(seen.Color.b), 200, 0.0);
  Expect("  part behind the fold: depth", seen.Depth, 1.5 + 0.5 * w1, 1e-12);
  Expect("  part behind the fold: lookups (2 intervals)", lookup.Gathers, 2, 0.0);
  lookup.Parts.push_back({ { 0.05, 0.5 * (0.1 + w0), 0.5 * w0 }, 0.05, 1, { 200, 200, 0 } });
  seen = lfd::RenderView(eye, d, boxes, lookup, SettingsFor(boxes), segments);
  Expect("  parts on both intervals: red", std::round(seen.Color.r), 200, 0.0);
  Expect("  parts on both intervals: depth", seen.Depth, 1 + 0.5 * w0, 1e-12);
}

void TwoHundredBoxes()
{
  // Box i rests at x = 3i and is moved onto the ray, at z in [2i, 2i + 1];
  // its part (label i + 1) sits at its rest centre. The boxes are given far
  // to near, so a cap that kept the first segments in box order would lose
  // the near ones.
  const int count = 200;
  SphereLookup lookup;
  std::vector<lfd::RenderBox> boxes;
  for (int b = 0; b < count; ++b)
  {
    const int i = count - 1 - b;
    boxes.push_back(lfd::MakeRenderBox(Cube({ 3.0 * i, 0, 0 }), Cube({ 0, 0, 2.0 * i }), i + 1));
    lookup.Parts.push_back({ { 3.0 * i + 0.5, 0.5, 0.5 }, 0.3, i + 1, { 100, 100, 100 } });
  }
  const glm::dvec3 eye(0.5, 0.5, -1.0), d(0.0, 0.0, 1.0);
  lfd::PlaceEye(boxes, eye);
  std::vector<lfd::BoxSegment> segments;
  lfd::CollectSegments(boxes, eye, d, segments);
  Expect("200 boxes: segments", static_cast<double>(segments.size()), count, 0.0);
  int misplaced = 0;
  for (std::size_t k = 0; k < segments.size(); ++k)
  {
    const lfd::BoxSegment& s = segments[k];
    misplaced += s.Box != count - 1 - static_cast<int>(k) || s.Segment.TEnter != 2.0 * k + 1 ||
      s.Segment.TExit != 2.0 * k + 2;
  }
  Expect("  segments out of distance order or off their box", misplaced, 0, 0.0);

  lfd::ViewSample seen = lfd::RenderView(eye, d, boxes, lookup, SettingsFor(boxes), segments);
  Expect("  every part visible: label of the nearest", seen.Label, 1, 0.0);
  Expect("  every part visible: depth", seen.Depth, 1.5, 0.0);
  Expect("  every part visible: lookups", lookup.Gathers, 1, 0.0);
  // The same ray as the one pixel of a frame: walked front to back, it warps
  // only the boxes up to the one whose interval gives the pixel.
  lfd::FrameCage frame;
  frame.Build(boxes, eye, glm::dmat3(1.0), 1, 1, lfd::FrameCage::DefaultTileSize);
  lfd::FrameRayScratch scratch;
  lookup.Gathers = 0;
  seen = lfd::RenderView(frame, 0, 0, lookup, SettingsFor(boxes), scratch);
  Expect("  one-pixel frame: label", seen.Label, 1, 0.0);
  Expect("  one-pixel frame: depth", seen.Depth, 1.5, 0.0);
  Expect("  one-pixel frame: lookups", lookup.Gathers, 1, 0.0);
  Expect("  one-pixel frame: boxes warped", static_cast<double>(scratch.NextEntry), 1, 0.0);
  lookup.Parts.erase(lookup.Parts.begin() + 1, lookup.Parts.end());
  lookup.Gathers = 0;
  seen = lfd::RenderView(eye, d, boxes, lookup, SettingsFor(boxes), segments);
  Expect("  only the farthest part: label", seen.Label, 200, 0.0);
  Expect("  only the farthest part: depth", seen.Depth, 399.5, 0.0);
  Expect("  only the farthest part: lookups", lookup.Gathers, 200, 0.0);
  lookup.Gathers = 0;
  seen = lfd::RenderView(frame, 0, 0, lookup, SettingsFor(boxes), scratch);
  Expect("  one-pixel frame, only the farthest part: label", seen.Label, 200, 0.0);
  Expect("  one-pixel frame, only the farthest part: depth", seen.Depth, 399.5, 0.0);
  Expect("  one-pixel frame, only the farthest part: boxes warped",
    static_cast<double>(scratch.NextEntry),
    200,
    0.0);
}
/// The twisted copy of `box`: its top face (corners 4-7) turned by `angle` about its centre.
lfd::Hexahedron TurnTop(const lfd::Hexahedron& box, double angle)
{
  lfd::Hexahedron turned = box;
  glm::dvec3 centre(0.0);
  for (int c = 4; c < 8; ++c)
  {
    centre += 0.25 * box.Corners[c];
  }
  for (int c = 4; c < 8; ++c)
  {
    const glm::dvec3 r = box.Corners[c] - centre;
    turned.Corners[c] = centre +
      glm::dvec3(std::cos(angle) * r.x - std::sin(angle) * r.y,
        std::sin(angle) * r.x + std::cos(angle) * r.y,
        r.z);
  }
  return turned;
}

/// A frame's pixel to direction: d = ((x - centre) / focal, (y - centre) / focal, 1).
glm::dmat3 PixelToDirection(double centre, double focal)
{
  return glm::dmat3(glm::dvec3(1.0 / focal, 0.0, 0.0),
    glm::dvec3(0.0, 1.0 / focal, 0.0),
    glm::dvec3(-centre / focal, -centre / focal, 1.0));
}

void HundredBoxFrame()
{
  // 100 parts rest in a row along x; their boxes are moved, twisted, into a
  // 10 x 10 grid in front of the eye (box i at (2 (i % 10), 2 (i / 10), 0)),
  // plus one box around the eye and one behind it (their projections are
  // unbounded: every tile lists them). A 64 x 64 frame, tiles of 8 pixels.
  SphereLookup lookup;
  std::vector<lfd::RenderBox> boxes;
  for (int i = 0; i < 100; ++i)
  {
    const glm::dvec3 grid(2.0 * (i % 10), 2.0 * (i / 10), 0.0);
    boxes.push_back(
      lfd::MakeRenderBox(Cube({ 3.0 * i, 0, 0 }), TurnTop(Cube(grid), 0.02 * (i % 7)), i + 1));
    lookup.Parts.push_back({ { 3.0 * i + 0.5, 0.5, 0.5 }, 0.45, i + 1, { 2.0 * i, 50, 100 } });
  }
  const glm::dvec3 eye(9.5, 9.5, -12.0);
  boxes.push_back(lfd::MakeRenderBox(Cube({ 400, 0, 0 }), Cube(eye - 0.5), 101));
  boxes.push_back(lfd::MakeRenderBox(Cube({ 403, 0, 0 }), Cube(eye - glm::dvec3(0, 0, 3)), 102));
  lfd::PlaceEye(boxes, eye);
  // d = ((x - 32) / 38.4, (y - 32) / 38.4, 1): the grid fills the frame.
  const glm::dmat3 pixelToDirection = PixelToDirection(32.0, 38.4);
  lfd::FrameCage culled, unculled;
  culled.Build(boxes, eye, pixelToDirection, 64, 64, 8);
  unculled.Build(boxes, eye, pixelToDirection, 64, 64, 0);
  // A tile's pixel masks (FrameCage::TilePixels) answer as each pixel's own
  // hull test; unculled, each ray tests the hull.
  int maskedUnlike = 0;
  for (int tile = 0; tile < 64; ++tile)
  {
    for (int i = culled.TileStart[tile]; i < culled.TileStart[tile + 1]; ++i)
    {
      const lfd::ScreenHull& hull = culled.Hulls[culled.TileBoxes[i]];
      for (int pixel = 0; pixel < 64; ++pixel)
      {
        const int x = tile % 8 * 8 + pixel % 8, y = tile / 8 * 8 + pixel / 8;
        maskedUnlike +=
          static_cast<bool>((culled.TilePixels[i] >> pixel) & 1u) != hull.MayHold(x, y);
      }
    }
  }
  Expect("100-box frame: tile pixels whose mask is not their hull test", maskedUnlike, 0, 0.0);
  // Its loops run in ranges out of order (as threads take them: 7 at a
  // time, the last range first), the same frame cage.
  lfd::FrameCage ranged;
  ranged.Build(boxes,
    eye,
    pixelToDirection,
    64,
    64,
    8,
    [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
    {
      for (std::size_t end = n; end > 0; end -= std::min<std::size_t>(end, 7))
      {
        body(end - std::min<std::size_t>(end, 7), end);
      }
    });
  int rangedUnlike = ranged.TileStart != culled.TileStart;
  rangedUnlike += ranged.TileBoxes != culled.TileBoxes;
  rangedUnlike += ranged.TilePixels != culled.TilePixels;
  rangedUnlike += ranged.TileHulls.size() != culled.TileHulls.size() ||
    std::memcmp(ranged.TileHulls.data(),
      culled.TileHulls.data(),
      culled.TileHulls.size() * sizeof(lfd::HullsInTile)) != 0;
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    rangedUnlike += ranged.Hulls[b].Count != culled.Hulls[b].Count ||
      std::memcmp(&ranged.Oriented[b], &culled.Oriented[b], sizeof(lfd::OrientedBounds)) != 0;
  }
  Expect("  built in ranges out of order: tables or boxes unlike the serial build",
    rangedUnlike,
    0,
    0.0);
  Expect(culled.TileBoxes.size() > 200, "  tile-box pairs (> 200)", culled.TileBoxes.size());
  Expect("  unculled frame's pixel masks", static_cast<double>(unculled.TilePixels.size()), 0, 0.0);
  const lfd::RenderViewSettings settings = SettingsFor(boxes);
  std::vector<lfd::BoxSegment> reference;
  lfd::FrameRayScratch scratch;
  long long tried = 0, triedUnculled = 0, met = 0, warped = 0;
  int different = 0, parts = 0, lookupsDiffer = 0;
  for (int y = 0; y < 64; ++y)
  {
    for (int x = 0; x < 64; ++x)
    {
      const glm::dvec3 d = culled.Direction(x, y);
      lookup.Gathers = 0;
      const lfd::ViewSample expected = lfd::RenderView(eye, d, boxes, lookup, settings, reference);
      const int expectedGathers = lookup.Gathers;
      // The walk leaves out the intervals of boxes at rest (box 0) whose
      // label the view ray does not show: they cannot give the pixel.
      lfd::RaySamples viewSamples;
      lookup.Gather(eye, d, viewSamples);
      const int viewLabel = lfd::VoteLabel(viewSamples);
      std::vector<lfd::BoxSegment> kept;
      for (const lfd::BoxSegment& segment : reference)
      {
        const lfd::RenderBox& box = boxes[segment.Box];
        if (box.Moved || box.Label == viewLabel)
        {
          kept.push_back(segment);
        }
      }
      for (const lfd::FrameCage* frame : { &culled, &unculled })
      {
        lookup.Gathers = 0;
        const lfd::ViewSample seen = lfd::RenderView(*frame, x, y, lookup, settings, scratch);
        // The walk hands the intervals out up to the one that gave the pixel.
        const std::vector<lfd::BoxSegment>& segments = scratch.Segments;
        bool same = seen.Label == expected.Label && seen.Color == expected.Color &&
          seen.Depth == expected.Depth && scratch.Handed <= kept.size() &&
          (seen.Label > 0 || scratch.Handed == kept.size());
        for (std::size_t k = 0; same && k < scratch.Handed; ++k)
        {
          same = segments[k].Box == kept[k].Box &&
            segments[k].Segment.TEnter == kept[k].Segment.TEnter &&
            segments[k].Segment.RestExit == kept[k].Segment.RestExit;
        }
        different += !same;
        lookupsDiffer += lookup.Gathers != expectedGathers;
      }
      parts += expected.Label > 0;
      tried += culled.CountCandidates(x, y);
      triedUnculled += unculled.CountCandidates(x, y);
      met += static_cast<long long>(scratch.Entries.size());
      warped += static_cast<long long>(scratch.NextEntry);
    }
  }
  Expect("100-box frame: pixels seeing a part", parts, 767, 0.0);
  Expect("  pixels (culled or not) unlike testing every box", different, 0, 0.0);
  Expect("  pixels whose lookups differ", lookupsDiffer, 0, 0.0);
  Expect("  boxes tried without culling", static_cast<double>(triedUnculled), 64 * 64 * 102, 0.0);
  // (29888 when a box was listed over its bounds' whole rectangle of tiles,
  // not only in the tiles its projected hull may reach.)
  Expect("  boxes tried with culling", static_cast<double>(tried), 21056, 0.0);
  // (9 boxes more than the bounds themselves let through: rays that meet
  // only the margin of the widened bounds, which no interval comes of.)
  Expect("  boxes whose projected hull and widened bounds a ray meets",
    static_cast<double>(met),
    5762,
    0.0);
  Expect("  boxes warped, front to back up to the pixel's interval",
    static_cast<double>(warped),
    5762,
    0.0);
}

/**
 * The bent slabs of a many-slab cage (FrameCage's OrientedBounds): 40 slabs
 * 0.025 thick stacked along z, one part, tilted 50 degrees about y and
 * shifted. The slabs' axis-aligned bounds overlap far more than the slabs:
 * the ray's entry into the oriented bounds orders them tighter, so fewer
 * boxes are warped ahead of the interval the walk needs, for the same
 * pixels (those of CollectSegments over every box). A ray across a slab is
 * outside the projected hulls of its 4 thin sides: the warp intersects only
 * the faces whose hull holds the pixel. Rendered 16 rays a batch
 * (RenderWalks, their first boxes warped four at a time), the same pixels.
 */
void TiltedSlabs()
{
  SphereLookup lookup;
  lookup.Parts = { { glm::dvec3(0.5, 0.5, 0.0), 0.35, 1, glm::dvec3(200.0, 100.0, 50.0) } };
  const double angle = 50.0 * M_PI / 180.0;
  std::vector<lfd::RenderBox> boxes;
  for (int i = 0; i < 40; ++i)
  {
    lfd::Hexahedron rest, tilted;
    for (int c = 0; c < 8; ++c)
    {
      const glm::dvec3 p(
        lfd::HexCorner[c][0], lfd::HexCorner[c][1], -0.5 + 0.025 * (i + lfd::HexCorner[c][2]));
      rest.Corners[c] = p;
      tilted.Corners[c] = glm::dvec3(std::cos(angle) * (p.x - 0.5) + std::sin(angle) * p.z + 0.6,
        p.y,
        -std::sin(angle) * (p.x - 0.5) + std::cos(angle) * p.z);
    }
    boxes.push_back(lfd::MakeRenderBox(rest, tilted, 1));
  }
  const glm::dvec3 eye(0.5, 0.5, -3.0);
  lfd::PlaceEye(boxes, eye);
  const glm::dmat3 pixelToDirection = PixelToDirection(16.0, 64.0);
  // `unoriented` enters every box where its axis-aligned bounds begin (the
  // world's axes, the same margin).
  lfd::FrameCage oriented, unoriented;
  oriented.Build(boxes, eye, pixelToDirection, 32, 32, 8);
  unoriented.Build(boxes, eye, pixelToDirection, 32, 32, 8);
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    const lfd::AxisBounds& bounds = boxes[b].Bounds;
    const glm::dvec3 margin(1e-6 * glm::distance(bounds.Min, bounds.Max));
    unoriented.Oriented[b] = { glm::dmat3(1.0),
      { bounds.Min - margin - eye, bounds.Max + margin - eye } };
  }
  lfd::RenderViewSettings settings = SettingsFor(boxes);
  settings.FocalBeforeLookup = true;
  std::vector<lfd::BoxSegment> reference;
  lfd::FrameRayScratch scratch;
  long long axisAligned = 0, warped[2] = { 0, 0 }, faces = 0;
  int different = 0, parts = 0;
  for (int y = 0; y < 32; ++y)
  {
    for (int x = 0; x < 32; ++x)
    {
      const glm::dvec3 d = oriented.Direction(x, y);
      const lfd::ViewSample expected = lfd::RenderView(eye, d, boxes, lookup, settings, reference);
      for (const int k : { 0, 1 })
      {
        const lfd::ViewSample seen =
          lfd::RenderView(k == 0 ? oriented : unoriented, x, y, lookup, settings, scratch);
        different += seen.Label != expected.Label || seen.Color != expected.Color ||
          seen.Depth != expected.Depth;
        // The boxes warped, and the faces their warps intersected: those
        // whose projected hull holds the pixel (of the boxes the walk reached
        // but did not leave out, FrameCage::LeaveOut).
        warped[k] += static_cast<long long>(scratch.Warps);
        for (std::size_t i = 0; i < scratch.NextEntry; ++i)
        {
          const int b = scratch.Entries[i].Box;
          if (scratch.Skipped[b] == scratch.Ray)
          {
            continue;
          }
          for (const lfd::ScreenHull& hull : oriented.FaceHulls[b])
          {
            faces += k == 0 && hull.MayHold(x, y);
          }
        }
      }
      parts += expected.Label > 0;
      for (const lfd::RenderBox& box : boxes)
      {
        axisAligned += lfd::RayHitsBounds(eye, d, box.Bounds);
      }
    }
  }
  Expect("40 tilted slabs: pixels seeing the part", parts, 179);
  Expect("  pixels unlike testing every box", different, 0);
  Expect("  boxes whose axis-aligned bounds a ray meets", static_cast<double>(axisAligned), 16063);
  // (11970, 12810 and 23940 before runs were looked up once and their
  // pieces left out unwarped, ahead of the focal piece and behind it.
  // Counted by FrameRayScratch::Warps; counted as the boxes reached and not
  // left out, 1527 and 1860: a run's LeaveOut may mark boxes already warped.)
  Expect("  boxes warped, entered at their oriented bounds", static_cast<double>(warped[0]), 1527);
  Expect(
    "  boxes warped, entered at their axis-aligned bounds", static_cast<double>(warped[1]), 4292);
  Expect("  faces intersected (of 6 per box warped)", static_cast<double>(faces), 3054);

  // The frame rendered 16 rays a batch, as the renderer does (RenderWalks:
  // the first box of each walk warped four rays at a time, FrameCage::
  // WarpAhead), for the same pixels; and those warps, taken alone, the
  // intervals WarpRayThroughBox gives, to the bit.
  std::vector<lfd::FrameRayScratch> batch(lfd::MaximumPlainBatch);
  int batchedUnlike = 0, ahead = 0, aheadUnlike = 0;
  for (int y = 0; y < 32; ++y)
  {
    for (int x0 = 0; x0 < 32; x0 += lfd::MaximumPlainBatch)
    {
      int xs[lfd::MaximumPlainBatch];
      glm::dvec3 d[lfd::MaximumPlainBatch];
      lfd::ViewSample seen[lfd::MaximumPlainBatch];
      bool walked[lfd::MaximumPlainBatch];
      for (int i = 0; i < lfd::MaximumPlainBatch; ++i)
      {
        xs[i] = x0 + i;
        d[i] = oriented.Direction(xs[i], y);
      }
      lfd::RenderWalks(
        oriented, xs, y, lfd::MaximumPlainBatch, lookup, settings, batch.data(), seen, walked);
      for (int i = 0; i < lfd::MaximumPlainBatch; ++i)
      {
        if (!walked[i])
        {
          lfd::RenderPlainViews(oriented, &xs[i], y, 1, lookup, settings, &seen[i]);
        }
        const lfd::ViewSample expected =
          lfd::RenderView(eye, d[i], boxes, lookup, settings, reference);
        batchedUnlike += seen[i].Label != expected.Label || seen[i].Color != expected.Color ||
          seen[i].Depth != expected.Depth;
        walked[i] = oriented.StartWalk(xs[i], y, d[i], batch[i]) > 0;
      }
      oriented.WarpAhead(d, walked, lfd::MaximumPlainBatch, batch.data());
      for (int i = 0; i < lfd::MaximumPlainBatch; ++i)
      {
        const lfd::FrameRayScratch& ray = batch[i];
        if (!walked[i] || ray.AheadBox < 0)
        {
          continue;
        }
        ++ahead;
        const lfd::RenderBox& box = boxes[ray.AheadBox];
        lfd::WarpedSegment one[lfd::MaxWarpedSegments];
        const int n = lfd::WarpRayThroughBox(oriented.Seen[ray.AheadBox],
          box.Rest,
          box.Deformed,
          d[i],
          0.0,
          one,
          lfd::MaxWarpedSegments,
          true,
          oriented.FacesMet(ray.Entries.front(), ray));
        aheadUnlike += n != ray.AheadCount ||
          (n == 1 &&
            (one[0].TEnter != ray.Ahead.TEnter || one[0].TExit != ray.Ahead.TExit ||
              one[0].RestEnter != ray.Ahead.RestEnter || one[0].RestExit != ray.Ahead.RestExit ||
              one[0].FaceExit != ray.Ahead.FaceExit));
      }
    }
  }
  Expect("  pixels rendered 16 a batch unlike testing every box", batchedUnlike, 0);
#if defined(__GNUC__) && defined(__x86_64__)
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
  {
    Expect("  first boxes warped ahead, four rays at a time", ahead, 694);
  }
#endif
  Expect("  of those, unlike WarpRayThroughBox", aheadUnlike, 0);
}

/**
 * A run of moved slabs of one part along the ray (lfd::ShadeSegments with
 * RenderViewSettings::FocalBeforeLookup): unit cubes stacked along z, all
 * shifted by 0.1 along x, so that every warped ray is the line x = 0.4,
 * y = 0.5 and meets the part. With the focal point (z = 0) in the third
 * slab, the two slabs in front are not looked up; with the run ending in
 * front of it (two slabs), only the run's last is. Same pixel either way.
 */
void RunOfSlabs()
{
  SphereLookup lookup;
  lookup.Parts = { { glm::dvec3(0.4, 0.5, 0.0), 0.3, 1, glm::dvec3(200.0, 100.0, 50.0) } };
  const glm::dvec3 o(0.5, 0.5, -10.0), d(0.0, 0.0, 1.0);
  for (const int count : { 4, 2 })
  {
    std::vector<lfd::RenderBox> boxes;
    for (int i = 0; i < count; ++i)
    {
      const glm::dvec3 low(0.0, 0.0, -2.5 + i);
      boxes.push_back(lfd::MakeRenderBox(Cube(low), Cube(low + glm::dvec3(0.1, 0.0, 0.0)), 1));
    }
    lfd::PlaceEye(boxes, o);
    const std::string name = std::to_string(count) + " slabs, focal point " +
      (count == 4 ? "in the third" : "beyond the run");
    lfd::ViewSample seen[2];
    int gathers[2];
    for (const bool focalFirst : { false, true })
    {
      lfd::RenderViewSettings settings = SettingsFor(boxes);
      settings.FocalBeforeLookup = focalFirst;
      std::vector<lfd::BoxSegment> segments;
      lookup.Gathers = 0;
      seen[focalFirst] = lfd::RenderView(o, d, boxes, lookup, settings, segments);
      gathers[focalFirst] = lookup.Gathers;
    }
    Expect(name + ": lookups, every interval", gathers[0], count == 4 ? 3 : 2);
    Expect(name + ": lookups, from the focal piece", gathers[1], 1);
    Expect(name + ": label", seen[1].Label, 1);
    Expect(name + ": depth", seen[1].Depth, count == 4 ? 10.0 : 9.0, 1e-12);
    Expect(name + ": colour unlike every interval's lookup",
      glm::length(seen[1].Color - seen[0].Color) + std::abs(seen[1].Depth - seen[0].Depth),
      0.0);
  }
}

/**
 * A run is looked up once (lfd::ShadeSegments): six unit cubes stacked along
 * z, all shifted by 0.1 along x, over a light field without parts (every
 * lookup sees background). The focal point (z = 0) is in the third: the two
 * in front wait for it, the three behind go on with the run and are neither
 * looked up nor, through a FrameCage, warped (FrameCage::FollowRun, LeaveOut: face
 * neighbours straight through). The one other lookup is the view ray's.
 */
void RunLookedUpOnce()
{
  SphereLookup lookup;
  const glm::dvec3 eye(0.5, 0.5, -10.0), d(0.0, 0.0, 1.0);
  std::vector<lfd::RenderBox> boxes;
  for (int i = 0; i < 6; ++i)
  {
    const glm::dvec3 low(0.0, 0.0, -2.5 + i);
    boxes.push_back(lfd::MakeRenderBox(Cube(low), Cube(low + glm::dvec3(0.1, 0.0, 0.0)), 1));
  }
  lfd::PlaceEye(boxes, eye);
  lfd::RenderViewSettings settings = SettingsFor(boxes);
  std::vector<lfd::BoxSegment> segments;
  lfd::RenderView(eye, d, boxes, lookup, settings, segments);
  Expect("6 cubes, no part: lookups, every interval and the view ray", lookup.Gathers, 7);
  settings.FocalBeforeLookup = true;
  lookup.Gathers = 0;
  const lfd::ViewSample single = lfd::RenderView(eye, d, boxes, lookup, settings, segments);
  Expect("  lookups, the run once and the view ray", lookup.Gathers, 2);
  Expect("  label", single.Label, 0);
  // Pixel (0, 0) of a 1 x 1 frame looks along d.
  lfd::FrameCage cage;
  cage.Build(boxes, eye, glm::dmat3(1.0), 1, 1, 0);
  lfd::FrameRayScratch scratch;
  lookup.Gathers = 0;
  const lfd::ViewSample framed = lfd::RenderView(cage, 0, 0, lookup, settings, scratch);
  Expect("  through the frame cage: lookups", lookup.Gathers, 2);
  Expect("  through the frame cage: same colour",
    glm::length(framed.Color - single.Color) + std::abs(framed.Label - single.Label),
    0.0);
  int skipped = 0;
  for (std::size_t i = 0; i < scratch.NextEntry; ++i)
  {
    skipped += scratch.Skipped[scratch.Entries[i].Box] == scratch.Ray;
  }
  Expect("  cubes behind the looked-up one left out unwarped", skipped, 3);
  Expect("  the third cube's neighbour through its top (w = 1)", cage.Neighbors[2][5], 6 * 3 + 4);
}

/// lfd::detail::ShownPart: a moved box shows a neighbouring part only where the
/// proxy puts its surface inside the box's interval.
void ShownPartInsideBox()
{
  lfd::RenderBox box;
  box.Label = 1;
  box.Moved = true;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Expect("slice of part 2 inside a moved box of part 1", lfd::detail::ShownPart(box, 2, 0.4), 2);
  Expect("part 2 beyond the box's exit", lfd::detail::ShownPart(box, 2, 1.5), 1);
  Expect("part 2 on the focal plane (no surface point)", lfd::detail::ShownPart(box, 2, nan), 1);
  Expect("background inside the box", lfd::detail::ShownPart(box, 0, 0.4), 1);
  box.Moved = false;
  Expect("a box at rest keeps Sec. 6's test", lfd::detail::ShownPart(box, 2, 0.4), 1);
}

/**
 * A light field whose every lookup sees part 1: the interval whose warped
 * line starts at rest z in [k - 0.5, k + 0.5) gets script entry k, its
 * colour and its proxy surface (NaN: no surface, focused on the plane at
 * the entry's FocalParameter instead).
 */
struct ScriptedLookup
{
  struct Entry
  {
    double Surface;
    double Focal;
    glm::dvec3 Color;
  };
  std::vector<Entry> Script;

  const Entry& Find(const glm::dvec3& o) const
  {
    return this->Script[static_cast<std::size_t>(std::lround(o.z))];
  }
  bool Gather(const glm::dvec3& o, const glm::dvec3&, lfd::RaySamples& out) const
  {
    out.Count = 1;
    out.Samples[0] = { this->Find(o).Color, 1.0, 1 };
    out.Surface = this->Find(o).Surface;
    return true;
  }
  bool Widen(const glm::dvec3&, const glm::dvec3&, int, glm::dvec3&) const { return false; }
  double FocalDepth(const glm::dvec3&, const glm::dvec3&) const { return 0.0; }
  double FocalParameter(const glm::dvec3& o, const glm::dvec3&) const
  {
    return this->Find(o).Focal;
  }
};

void HeldOnSurface()
{
  // Two moved boxes of part 1 one behind the other on the ray (rest z in
  // [0, 1] and [1, 2], both shifted along x). The first interval's lookup
  // is focused beyond its exit (s = 3) and held; the second's finds no
  // surface and is focused on the plane within it (s = 0.5).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<lfd::RenderBox> boxes;
  for (int k = 0; k < 2; ++k)
  {
    boxes.push_back(lfd::MakeRenderBox(
      Cube({ 0, 0, static_cast<double>(k) }), Cube({ 0.01, 0, static_cast<double>(k) }), 1));
  }
  const glm::dvec3 eye(0.5, 0.5, -5.0), d(0.0, 0.0, 1.0);
  lfd::PlaceEye(boxes, eye);
  const lfd::RenderViewSettings settings = SettingsFor(boxes);
  std::vector<lfd::BoxSegment> segments;
  ScriptedLookup proxy;
  proxy.Script = { { 3.0, nan, { 200, 0, 0 } }, { nan, 0.5, { 0, 200, 0 } } };
  const lfd::ViewSample held = lfd::RenderView(eye, d, boxes, proxy, settings, segments);
  Expect("held on the surface, then a plane lookup: label", held.Label, 1);
  Expect("  the held interval gives the pixel (red)", held.Color.r, 200.0);
  // On the plane alone (no proxy) the first interval is held for its focal
  // point beyond its exit, and the second, focused within, gives the pixel.
  ScriptedLookup plane;
  plane.Script = { { nan, 3.0, { 200, 0, 0 } }, { nan, 0.5, { 0, 200, 0 } } };
  const lfd::ViewSample planar = lfd::RenderView(eye, d, boxes, plane, settings, segments);
  Expect("plane lookups only: the interval holding its focal point gives the pixel (green)",
    planar.Color.g,
    200.0);
}
}

int TestRenderView(int, char*[])
{
  using namespace TestRenderViewHelpers;
  IdentityCage();
  OcclusionOrder();
  TwistedBox();
  TwoHundredBoxes();
  HundredBoxFrame();
  TiltedSlabs();
  RunOfSlabs();
  RunLookedUpOnce();
  ShownPartInsideBox();
  HeldOnSurface();
  return lfdtest::Result();
}
