// A cage of 100 boxes (10 x 10 x 1, 242 points): the corner four boxes
// share is picked among all the handles and dragged; all four boxes follow.
// Prints the time of one pick and of one drag step (not a timed test: the
// figures are for the reader). Regression image of the dragged cage.
#include "lfdCageWidgetTestUtilities.h"

#include "vtkRegressionTestImage.h"

#include <chrono>

int TestCageWidgetManyBoxes(int argc, char* argv[])
{
  vtkNew<vtkDeformationCage> cage;
  lfdtest::MakeGridCage(cage, 10, 10, 1);
  const double focal[3] = { 5.0, 5.0, 0.5 };
  const double position[3] = { 9.0, -9.0, 14.0 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  lfdtest::WidgetScene scene(cage, focal, position, up);
  vtkCageRepresentation* rep = scene.Representation;
  int failures = 0;

  // Grid corner (5, 5, 1): point (1 * 11 + 5) * 11 + 5 = 181, shared by
  // boxes 44, 45, 54 and 55.
  const vtkIdType shared = 181;
  double start[3], display[3];
  cage->GetDeformedPoint(shared, start);
  scene.ToDisplay(start, display);
  const int x0 = static_cast<int>(std::lround(display[0]));
  const int y0 = static_cast<int>(std::lround(display[1]));
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point t0)
  { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  Clock::time_point t0 = Clock::now();
  const vtkIdType picked = rep->PickPoint(x0, y0);
  const double pickTime = seconds(t0);
  std::cout << "pick among " << cage->GetNumberOfPoints() << " handles of "
            << cage->GetNumberOfBoxes() << " boxes: " << 1e3 * pickTime << " ms\n";
  if (picked != shared)
  {
    std::cerr << "picked " << picked << ", expected " << shared << "\n";
    ++failures;
  }

  const int x1 = x0 + 25, y1 = y0 + 35;
  double w0[3], w1[3];
  scene.ToWorld(x0, y0, start, w0);
  scene.ToWorld(x1, y1, start, w1);
  const double expected[3] = {
    start[0] + w1[0] - w0[0], start[1] + w1[1] - w0[1], start[2] + w1[2] - w0[2]
  };
  t0 = Clock::now();
  scene.Play(lfdtest::Drag(x0, y0, x1, y1, 10));
  std::cout << "drag of 10 steps with rendering: " << 1e3 * seconds(t0) / 12 << " ms per event\n";
  if (!lfdtest::CheckPoint(cage, shared, expected, 1e-9, "dragged shared corner"))
  {
    ++failures;
  }
  const vtkIdType boxes[4] = { 44, 45, 54, 55 };
  const int corner[4] = { 6, 7, 5, 4 }; // where point 181 sits in each box
  for (int b = 0; b < 4; ++b)
  {
    double corners[24];
    cage->GetDeformedCorners(boxes[b], corners);
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(corners[3 * corner[b] + c] - expected[c]) > 1e-9)
      {
        std::cerr << "box " << boxes[b] << " corner " << corner[b] << " did not follow\n";
        ++failures;
        break;
      }
    }
  }
  if (cage->GetLargestDisplacement() !=
    std::sqrt(vtkMath::Distance2BetweenPoints(start, cage->GetPoint(shared))))
  {
    std::cerr << "another point moved\n";
    ++failures;
  }

  scene.Window->Render();
  const int image = vtkRegressionTestImage(scene.Window);
  if (image == vtkRegressionTester::DO_INTERACTOR)
  {
    scene.Interactor->Start();
  }
  return failures == 0 && image != vtkRegressionTester::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
