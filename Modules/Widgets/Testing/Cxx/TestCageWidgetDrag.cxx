// A recorded drag of the corner two boxes share moves that one cage point,
// so both boxes follow (one handle per cage point), as one interaction; the
// regression image shows the dragged, selected corner.
#include "lfdCageWidgetTestUtilities.h"

#include "vtkRegressionTestImage.h"

int TestCageWidgetDrag(int argc, char* argv[])
{
  vtkNew<vtkDeformationCage> cage;
  lfdtest::MakeGridCage(cage, 2, 1, 1);
  const double focal[3] = { 1.0, 0.5, 0.5 };
  const double position[3] = { 2.5, -3.5, 3.0 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  lfdtest::WidgetScene scene(cage, focal, position, up);
  lfdtest::InteractionCounter events(scene.Widget);

  // Point 7 = grid corner (1, 0, 1): the top front corner of both boxes.
  const vtkIdType shared = 7;
  double start[3], display[3];
  cage->GetDeformedPoint(shared, start);
  scene.ToDisplay(start, display);
  const int x0 = static_cast<int>(std::lround(display[0]));
  const int y0 = static_cast<int>(std::lround(display[1]));
  const int x1 = x0 + 40;
  const int y1 = y0 + 30;
  // The drag moves the handle in the plane through it parallel to the view,
  // by the cursor's motion (from the press position, not the handle centre).
  double w0[3], w1[3];
  scene.ToWorld(x0, y0, start, w0);
  scene.ToWorld(x1, y1, start, w1);
  const double expected[3] = {
    start[0] + w1[0] - w0[0], start[1] + w1[1] - w0[1], start[2] + w1[2] - w0[2]
  };

  scene.Play(lfdtest::Drag(x0, y0, x1, y1, 5));

  int failures = 0;
  if (!lfdtest::CheckPoint(cage, shared, expected, 1e-9, "shared corner"))
  {
    ++failures;
  }
  for (vtkIdType id = 0; id < cage->GetNumberOfPoints(); ++id)
  {
    double rest[3];
    cage->GetRestPoint(id, rest);
    if (id != shared && !lfdtest::CheckPoint(cage, id, rest, 0.0, "unmoved corner"))
    {
      ++failures;
    }
  }
  // Both boxes see the moved corner: box 0 as its corner 5, box 1 as its 4.
  double corners0[24], corners1[24];
  cage->GetDeformedCorners(0, corners0);
  cage->GetDeformedCorners(1, corners1);
  for (int c = 0; c < 3; ++c)
  {
    if (corners0[15 + c] != corners1[12 + c] || std::abs(corners0[15 + c] - expected[c]) > 1e-9)
    {
      std::cerr << "box corners differ from the moved point on axis " << c << "\n";
      ++failures;
    }
  }
  if (lfdtest::SelectedIds(scene.Representation) != "7")
  {
    std::cerr << "selection after the drag: " << lfdtest::SelectedIds(scene.Representation)
              << ", expected 7\n";
    ++failures;
  }
  // One drag = one interaction: 1 start, 5 moves, 1 end.
  if (events.Summary() != "1 5 1")
  {
    std::cerr << "interaction events: " << events.Summary() << ", expected 1 5 1\n";
    ++failures;
  }
  if (!cage->Validate().empty())
  {
    std::cerr << "cage after the drag: " << cage->Validate() << "\n";
    ++failures;
  }
  std::cout << "shared corner moved to (" << expected[0] << ", " << expected[1] << ", "
            << expected[2] << ")\n";

  scene.Window->Render();
  const int image = vtkRegressionTestImage(scene.Window);
  if (image == vtkRegressionTester::DO_INTERACTOR)
  {
    scene.Interactor->Start();
  }
  return failures == 0 && image != vtkRegressionTester::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
