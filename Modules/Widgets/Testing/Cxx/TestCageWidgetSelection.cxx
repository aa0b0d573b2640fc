// Recorded selection and transforms: B + drag rubber-bands the top face,
// which TwistFace() then twists; A selects everything and S, X scales it
// along X only; R then Esc puts the points back; a click on empty space
// clears the selection and shift-clicks toggle points. Cage points are
// checked against the transforms computed here.
#include "lfdCageWidgetTestUtilities.h"

#include <algorithm>
#include <vector>

using lfdtest::Check;

namespace
{
std::vector<double> Points(vtkDeformationCage* cage)
{
  std::vector<double> p(3 * cage->GetNumberOfPoints());
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    cage->GetDeformedPoint(i, &p[3 * i]);
  }
  return p;
}
}

int TestCageWidgetSelection(int, char*[])
{
  vtkNew<vtkDeformationCage> cage;
  lfdtest::MakeGridCage(cage, 1, 1, 1);
  const double focal[3] = { 0.5, 0.5, 0.5 };
  const double position[3] = { 1.7, -2.964, 2.5 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  lfdtest::WidgetScene scene(cage, focal, position, up);
  vtkCageRepresentation* rep = scene.Representation;
  lfdtest::InteractionCounter events(scene.Widget);

  // Rubber band around the top face (points 4 5 6 7; box face 5).
  double lo[2] = { 1e9, 1e9 }, hi[2] = { -1e9, -1e9 };
  std::vector<std::array<double, 3>> display(8);
  for (vtkIdType id = 0; id < 8; ++id)
  {
    double p[3];
    cage->GetDeformedPoint(id, p);
    scene.ToDisplay(p, display[id].data());
    if (id >= 4)
    {
      for (int c = 0; c < 2; ++c)
      {
        lo[c] = std::min(lo[c], display[id][c]);
        hi[c] = std::max(hi[c], display[id][c]);
      }
    }
  }
  const int x0 = static_cast<int>(lo[0]) - 4, y0 = static_cast<int>(lo[1]) - 4;
  const int x1 = static_cast<int>(hi[0]) + 4, y1 = static_cast<int>(hi[1]) + 4;
  for (vtkIdType id = 0; id < 4; ++id)
  {
    Check(display[id][0] < x0 || display[id][0] > x1 || display[id][1] < y0 || display[id][1] > y1,
      "the bottom corner " + std::to_string(id) + " lies outside the rectangle");
  }
  scene.Play(lfdtest::Key('b', x0, y0) + lfdtest::Drag(x0, y0, x1, y1, 4));
  Check(lfdtest::SelectedIds(rep) == "4 5 6 7",
    "rubber band selects the top face: got " + lfdtest::SelectedIds(rep));
  Check(events.Summary() == "0 0 0", "a selection is no interaction: " + events.Summary());

  // Twist the selected face by 30 degrees about the box axis (+Z) through
  // its centre (0.5, 0.5, 1).
  Check(rep->TwistFace(0, 5, 30.0), "TwistFace accepted");
  Check(events.Summary() == "1 1 1", "TwistFace is one interaction: " + events.Summary());
  const double c30 = std::cos(vtkMath::RadiansFromDegrees(30.0));
  const double s30 = std::sin(vtkMath::RadiansFromDegrees(30.0));
  for (vtkIdType id = 4; id < 8; ++id)
  {
    double rest[3];
    cage->GetRestPoint(id, rest);
    const double dx = rest[0] - 0.5, dy = rest[1] - 0.5;
    const double expected[3] = { 0.5 + c30 * dx - s30 * dy, 0.5 + s30 * dx + c30 * dy, 1.0 };
    Check(lfdtest::CheckPoint(cage, id, expected, 1e-12, "twisted top corner"), "twist");
  }

  // A selects all; S, X scales along X about the centroid (0.5, 0.5, 0.5).
  const double pivot[3] = { 0.5, 0.5, 0.5 };
  double c[3];
  scene.ToDisplay(pivot, c);
  const int sx0 = static_cast<int>(std::lround(c[0])) + 50,
            sy = static_cast<int>(std::lround(c[1]));
  const int sx1 = sx0 + 25;
  const double factor = std::hypot(sx1 - c[0], sy - c[1]) / std::hypot(sx0 - c[0], sy - c[1]);
  const std::vector<double> beforeScale = Points(cage);
  events.Reset();
  scene.Play(lfdtest::Key('a', sx0, sy) + lfdtest::Key('s', sx0, sy) + lfdtest::Key('x', sx0, sy) +
    "MouseMoveEvent " + std::to_string(sx0 + 10) + " " + std::to_string(sy) + " 0 0 0 0 0\n" +
    "MouseMoveEvent " + std::to_string(sx1) + " " + std::to_string(sy) + " 0 0 0 0 0\n" +
    lfdtest::Click(sx1, sy));
  Check(lfdtest::SelectedIds(rep) == "0 1 2 3 4 5 6 7", "A selects all");
  Check(rep->GetConstraint() == vtkCageRepresentation::ConstraintX, "X constrains to the X axis");
  // X, 2 motions and the click's own motion.
  Check(events.Summary() == "1 4 1", "S ... click is one interaction: " + events.Summary());
  for (vtkIdType id = 0; id < 8; ++id)
  {
    const double expected[3] = { pivot[0] + factor * (beforeScale[3 * id] - pivot[0]),
      beforeScale[3 * id + 1],
      beforeScale[3 * id + 2] };
    Check(lfdtest::CheckPoint(cage, id, expected, 1e-9, "scaled along X"), "scale");
  }
  std::cout << "scale factor along X: " << factor << "\n";

  // R, a motion, Esc: the points go back where they were, exactly.
  const std::vector<double> beforeRotate = Points(cage);
  events.Reset();
  scene.Play(lfdtest::Key('r', sx0, sy) + "MouseMoveEvent " + std::to_string(sx0) + " " +
    std::to_string(sy + 60) + " 0 0 0 0 0\n" + "KeyPressEvent " + std::to_string(sx0) + " " +
    std::to_string(sy + 60) + " 0 0 27 1 Escape\nCharEvent " + std::to_string(sx0) + " " +
    std::to_string(sy + 60) + " 0 0 27 1 Escape\n");
  Check(Points(cage) == beforeRotate, "Esc cancels the rotation exactly");
  Check(events.Summary() == "1 2 1", "R ... Esc is one interaction: " + events.Summary());

  // G, shift + Z: the selection follows the cursor in the plane
  // perpendicular to Z (the view-plane motion without its Z part); Enter.
  const std::vector<double> beforeGrab = Points(cage);
  double w0[3], w1[3];
  scene.ToWorld(sx0, sy, pivot, w0);
  scene.ToWorld(sx0 - 30, sy + 20, pivot, w1);
  scene.Play(lfdtest::Key('g', sx0, sy) + lfdtest::Key('Z', sx0, sy, true) + "MouseMoveEvent " +
    std::to_string(sx0 - 30) + " " + std::to_string(sy + 20) + " 0 0 0 0 0\n" + "KeyPressEvent " +
    std::to_string(sx0 - 30) + " " + std::to_string(sy + 20) + " 0 0 13 1 Return\nCharEvent " +
    std::to_string(sx0 - 30) + " " + std::to_string(sy + 20) + " 0 0 13 1 Return\n");
  Check(rep->GetConstraint() == vtkCageRepresentation::ConstraintPlaneZ,
    "shift + Z constrains to the plane perpendicular to Z");
  for (vtkIdType id = 0; id < 8; ++id)
  {
    const double expected[3] = { beforeGrab[3 * id] + w1[0] - w0[0],
      beforeGrab[3 * id + 1] + w1[1] - w0[1],
      beforeGrab[3 * id + 2] };
    Check(lfdtest::CheckPoint(cage, id, expected, 1e-9, "grabbed in the XY plane"), "grab");
  }

  // A click on empty space clears; shift-clicks toggle handles.
  scene.Play(lfdtest::Click(5, 5));
  Check(lfdtest::SelectedIds(rep).empty(), "a click on empty space clears the selection");
  double p4[3], p5[3], d4[3], d5[3];
  cage->GetDeformedPoint(4, p4);
  cage->GetDeformedPoint(5, p5);
  scene.ToDisplay(p4, d4);
  scene.ToDisplay(p5, d5);
  const int x4 = static_cast<int>(std::lround(d4[0])), y4 = static_cast<int>(std::lround(d4[1]));
  const int x5 = static_cast<int>(std::lround(d5[0])), y5 = static_cast<int>(std::lround(d5[1]));
  std::cout << "points 4 and 5 at (" << x4 << ", " << y4 << ") and (" << x5 << ", " << y5 << ")\n";
  scene.Play(lfdtest::Click(x4, y4) + lfdtest::Click(x5, y5, true));
  Check(lfdtest::SelectedIds(rep) == "4 5", "click + shift-click: " + lfdtest::SelectedIds(rep));
  scene.Play(lfdtest::Click(x4, y4, true));
  Check(lfdtest::SelectedIds(rep) == "5", "shift-click toggles: " + lfdtest::SelectedIds(rep));
  Check(cage->Validate().empty(), "the cage stays valid: " + cage->Validate());
  return lfdtest::Result();
}
