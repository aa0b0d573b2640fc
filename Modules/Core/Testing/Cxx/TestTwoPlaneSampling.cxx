// The two-plane sampling kernel (Levoy and Hanrahan 1996) and the rig's
// two-plane detection: the grid a vtkCameraRig::MakePlaneGrid rig is sorted
// into, leave-one-out holes, the bilinear camera weights, the aperture's tent
// weights, the focal plane (finite and at infinity) and the per-label
// merging of samples, on 3 x 3 views whose pixels are known colours so that
// every expected value is exact.
#include "lfdTestChecks.h"
#include "lfdTwoPlaneSampling.h"
#include "vtkCameraRig.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using lfdtest::Expect;

int TestTwoPlaneSampling(int, char*[])
{
  // 3 x 3 cameras 1 apart on the plane z = 0 looking along +Z (R = I),
  // 9 x 9 pixels, f = 40: view v = 3 r + c sits at (c - 1, r - 1, 0).
  const int size = 9;
  const double centre[3] = { 0.0, 0.0, 0.0 };
  const double forward[3] = { 0.0, 0.0, 1.0 };
  const double up[3] = { 0.0, -1.0, 0.0 };
  const double viewAngle = 2.0 * std::atan(0.5 * size / 40.0) * 180.0 / 3.14159265358979323846;
  vtkNew<vtkCameraRig> rig;
  rig->MakePlaneGrid(centre, forward, up, 3, 3, 1.0, size, size, viewAngle);
  double c5[3], R[9];
  rig->GetCameraCenter(5, c5);
  rig->GetRotation(5, R);
  Expect("view 5 centre x", c5[0], 1.0);
  Expect("view 5 centre y", c5[1], 0.0);
  Expect("view 5 R = I (r11 + r22 + r33)", R[0] + R[4] + R[8], 3.0);
  Expect("view 7 is named r02_c01", std::string(rig->GetViewName(7)) == "r02_c01", 1.0);
  Expect("a grid is a two-plane rig", rig->IsTwoPlane(), 1.0);

  const lfd::TwoPlaneLayout layout = rig->GetTwoPlaneLayout();
  Expect("columns", static_cast<double>(layout.Columns.size()), 3.0);
  Expect("rows", static_cast<double>(layout.Rows.size()), 3.0);
  Expect("first column u", layout.Columns.front(), -1.0);
  Expect("last row v", layout.Rows.back(), 1.0);
  Expect("grid cell (2, 1) is view 7", layout.At(2, 1), 7.0);
  Expect("leave-one-out empties view 4's cell", rig->GetTwoPlaneLayout({ 4 }).At(1, 1), -1.0);

  // A ring is not a two-plane rig; nor is a grid with one camera turned.
  vtkNew<vtkCameraRig> ring;
  const double heights[1] = { 0.0 };
  ring->MakeCylinder(centre, up, 5.0, 12, 1, heights, size, size, 30.0);
  Expect("a ring is not a two-plane rig", ring->IsTwoPlane(), 0.0);
  vtkNew<vtkCameraRig> turned;
  turned->DeepCopy(rig);
  lfd::PinholeCamera camera = rig->GetCamera(3);
  camera.R = glm::dmat3(glm::dvec3(std::cos(0.01), 0.0, std::sin(0.01)),
               glm::dvec3(0.0, 1.0, 0.0),
               glm::dvec3(-std::sin(0.01), 0.0, std::cos(0.01))) *
    camera.R;
  turned->SetView(3, camera);
  Expect("a view turned by 0.01 rad breaks the grid", turned->IsTwoPlane(), 0.0);

  // Pixel (x, y) of view v: red 10 v, green 10 x; label 2 on view 8, else 1.
  std::vector<std::uint8_t> rgb(3 * size * size * 9), labels(size * size * 9);
  std::vector<lfd::PinholeCamera> cameras(9);
  for (int v = 0; v < 9; ++v)
  {
    cameras[v] = rig->GetCamera(v);
    for (int p = 0; p < size * size; ++p)
    {
      const std::size_t id = static_cast<std::size_t>(v) * size * size + p;
      rgb[3 * id] = static_cast<std::uint8_t>(10 * v);
      rgb[3 * id + 1] = static_cast<std::uint8_t>(10 * (p % size));
      rgb[3 * id + 2] = 0;
      labels[id] = v == 8 ? 2 : 1;
    }
  }
  lfd::TwoPlaneSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = { rgb.data(), size, size, 3 };
  sampler.Labels = { labels.data(), size, size, 1 };
  sampler.FocalDepth = 10.0;
  lfd::RaySamples samples;
  double weight = 0.0;
  glm::dvec3 color(0.0);

  // A ray through a camera centre sees that camera alone, at its focal point:
  // (0.25, 0, 10) projects to x = 40 x 0.025 + 4 = 5 in view 4.
  Expect(
    "gather through view 4's centre", sampler.Gather({ 0, 0, 0 }, { 0.25, 0, 10 }, samples), 1);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("  all the weight on view 4", weight, 1.0);
  Expect("  its red", color.r, 40.0);
  Expect("  the pixel of the focal point (green)", color.g, 50.0);

  // Between cameras: bilinear weights over views 4, 5, 7, 8 (u = 0.25,
  // v = 0.5), view 8 (weight 0.125) is label 2; label 1 is 4, 5, 7.
  Expect("gather between views", sampler.Gather({ 0.25, 0.5, -1 }, { 0, 0, 1 }, samples), 1);
  Expect("  samples merged per label", samples.Count, 2.0);
  Expect("  vote", lfd::VoteLabel(samples), 1.0);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("  label 1 weight 0.375 + 0.125 + 0.375", weight, 0.875);
  Expect("  label 1 red (15 + 6.25 + 26.25) / 0.875", color.r, 47.5 / 0.875);
  weight = lfd::BlendLabel(samples, 2, color);
  Expect("  label 2 weight", weight, 0.125);
  Expect("  label 2 red", color.r, 80.0);

  // The focal plane: 10 in front of the camera plane; at infinity every
  // camera sees the ray's direction (here the principal point, x = 4).
  const lfd::TwoPlaneLookup lookup{ sampler, { 0.0, 0.0, 1.0 } };
  Expect(
    "focal depth of a ray from z = -1", lookup.FocalDepth({ 0.25, 0.5, -1 }, { 0, 0, 2 }), 11.0);
  sampler.FocalDepth = 0.0;
  Expect(
    "focal depth at infinity reported as 0", lookup.FocalDepth({ 0, 0, -1 }, { 0, 0, 1 }), 0.0);
  sampler.Gather({ 0.25, 0.5, -1 }, { 0, 0, 1 }, samples);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("at infinity every view samples x = 4", color.g, 40.0);

  // A ray heading back towards the cameras carries no captured light.
  Expect("backward ray", sampler.Gather({ 0, 0, 5 }, { 0, 0, -1 }, samples), 0.0);

  // Aperture 2 on the centre: tent weights 0.5, 1, 0.5 along each axis,
  // 4 in all; labels 1 (weight 4 - 0.25) and 2 (view 8: 0.5 x 0.5).
  sampler.Aperture = 2.0;
  sampler.Gather({ 0, 0, -1 }, { 0, 0, 1 }, samples);
  weight = lfd::BlendLabel(samples, 2, color);
  Expect("aperture 2: view 8's weight", weight, 0.25);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("aperture 2: the other views' weight", weight, 3.75);
  Expect("aperture 2: their red", color.r, (4.0 * 40.0 - 0.25 * 80.0) / 3.75);
  // An aperture below the spacing is the bilinear case.
  sampler.Aperture = 0.5;
  sampler.Gather({ 0.25, 0.5, -1 }, { 0, 0, 1 }, samples);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("aperture below the spacing is bilinear", weight, 0.875);
  // Outside the grid, the ray is clamped to its edge: view 2's column.
  sampler.Aperture = 0.0;
  sampler.Gather({ 5, -1, -1 }, { 0, 0, 1 }, samples);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("beyond the grid: the corner view 2", color.r, 20.0);
  // Aperture 0 is bilinear on an uneven grid too: columns at -1, 0 and 0.2,
  // a ray at u = -0.5 weighs views 3 and 4 (row v = 0) by half, not view 5.
  lfd::TwoPlaneLayout uneven = layout;
  uneven.Columns = { -1.0, 0.0, 0.2 };
  sampler.Layout = &uneven;
  sampler.Gather({ -0.5, 0, -1 }, { 0, 0, 1 }, samples);
  weight = lfd::BlendLabel(samples, 1, color);
  Expect("uneven grid: the two columns around the ray only", weight, 1.0);
  Expect("uneven grid: their red (30 + 40) / 2", color.r, 35.0);
  return lfdtest::Result();
}
