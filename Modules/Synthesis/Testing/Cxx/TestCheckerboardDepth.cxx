// The Depth pass of the checkerboard against the analytic distance along
// each camera's optical axis to the plane z = 0.
#include "lfdSynthesisTestUtilities.h"

#include <cmath>

int TestCheckerboardDepth(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToCheckerboard();
  auto capture = lfdtest::RingCapture(source);
  capture->CaptureCoaxialOff();
  capture->Update();
  vtkLightField* lightField = capture->GetOutput();
  vtkCameraRig* rig = lightField->GetRig();
  vtkDataArray* depth = lightField->GetPass(vtkLightField::DEPTH);
  vtkDataArray* label = lightField->GetPass(vtkLightField::LABEL);

  double maxError = 0.0;
  int compared = 0;
  int misses = 0;
  for (int view = 0; view < lightField->GetNumberOfViews(); ++view)
  {
    double forward[3];
    rig->GetViewDirection(view, forward);
    if (std::abs(forward[2]) < 0.3)
    {
      continue; // the board is seen edge-on
    }
    for (int y = 0; y < 128; ++y)
    {
      for (int x = 0; x < 128; ++x)
      {
        double hit[3], expected;
        const bool meets = lfdtest::HitCheckerboardPlane(rig, view, x, y, hit, &expected);
        const vtkIdType p = lightField->GetPointIndex(view, x, y);
        const double measured = depth->GetComponent(p, 0);
        const double extent = std::max(std::abs(hit[0]), std::abs(hit[1]));
        if (meets && extent < 0.47)
        {
          maxError = std::max(maxError, std::abs(measured - expected));
          misses += label->GetComponent(p, 0) == 1 ? 0 : 1;
          ++compared;
        }
        else if (!meets || extent > 0.53)
        {
          // Off the board: background, depth 0 and label 0.
          misses += (measured == 0.0 && label->GetComponent(p, 0) == 0) ? 0 : 1;
        }
      }
    }
  }
  std::cout << "radius " << rig->GetRadius() << ", pixels compared " << compared << "\n";
  lfdtest::Check(compared > 10000, "board pixels compared", compared, 10000);
  lfdtest::Check(maxError < 1e-3 * rig->GetRadius(),
    "max |depth - analytic| (world units)",
    maxError,
    1e-3 * rig->GetRadius());
  lfdtest::Check(misses == 0, "pixels whose label/background disagrees with the plane", misses, 0);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
