// vtkKeyframeInterpolator: keyframes are hit exactly, linear interpolation
// is linear, Catmull-Rom passes through the keyframes with the expected
// value between them, times clamp, and inconsistent keyframes are refused.
#include "lfdTestChecks.h"
#include "vtkKeyframeInterpolator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

using lfdtest::Expect;

namespace
{
// Two points; point 0 at (x, 0, 0), point 1 at (0, x * x, 1).
vtkNew<vtkPoints> Frame(double x)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x, 0.0, 0.0);
  points->InsertNextPoint(0.0, x * x, 1.0);
  return points;
}
}

int TestKeyframeInterpolator(int, char*[])
{
  vtkNew<vtkKeyframeInterpolator> keys;
  // Added out of order: they are kept sorted by time.
  keys->AddKeyframe(2.0, Frame(2.0));
  keys->AddKeyframe(0.0, Frame(0.0));
  keys->AddKeyframe(1.0, Frame(1.0));
  keys->AddKeyframe(3.0, Frame(3.0));
  Expect("keyframes", keys->GetNumberOfKeyframes(), 4, 1e-12);
  Expect("start time", keys->GetStartTime(), 0.0, 1e-12);
  Expect("end time", keys->GetEndTime(), 3.0, 1e-12);

  vtkNew<vtkPoints> out;
  keys->SetInterpolationToLinear();
  keys->InterpolatePoints(1.25, out);
  Expect("linear x at 1.25", out->GetPoint(0)[0], 1.25, 1e-12);
  Expect("linear y at 1.25 (between 1 and 4)", out->GetPoint(1)[1], 1.75, 1e-12);

  keys->SetInterpolationToCatmullRom();
  keys->InterpolatePoints(2.0, out);
  Expect("Catmull-Rom hits keyframe 2", out->GetPoint(1)[1], 4.0, 1e-12);
  keys->InterpolatePoints(1.5, out);
  // Uniform Catmull-Rom reproduces quadratics on an interior segment.
  Expect("Catmull-Rom y at 1.5 (x^2)", out->GetPoint(1)[1], 2.25, 1e-12);
  Expect("Catmull-Rom x at 1.5 (linear)", out->GetPoint(0)[0], 1.5, 1e-12);
  keys->InterpolatePoints(-5.0, out);
  Expect("clamped before the first keyframe", out->GetPoint(0)[0], 0.0, 1e-12);
  keys->InterpolatePoints(7.0, out);
  Expect("clamped after the last keyframe", out->GetPoint(0)[0], 3.0, 1e-12);

  vtkNew<vtkTest::ErrorObserver> observer;
  keys->AddObserver(vtkCommand::ErrorEvent, observer);
  vtkNew<vtkPoints> three;
  three->SetNumberOfPoints(3);
  Expect("keyframe with another point count refused", keys->AddKeyframe(4.0, three), 0, 1e-12);
  Expect("its error names the point counts",
    observer->GetErrorMessage().find("has 3 points") != std::string::npos,
    1,
    1e-12);
  observer->Clear();
  Expect("second keyframe at the same time refused", keys->AddKeyframe(1.0, Frame(5.0)), 0, 1e-12);
  Expect("its error names the time",
    observer->GetErrorMessage().find("Two keyframes at time 1") != std::string::npos,
    1,
    1e-12);
  return lfdtest::Result();
}
