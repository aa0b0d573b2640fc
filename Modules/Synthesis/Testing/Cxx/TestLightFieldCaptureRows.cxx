// Where vtkLightFieldCapture puts its rows (issue 11): elevations, rows that
// cover an eye above them (checked with vtkCameraRig::DescribeExtrapolation,
// which is what lfd render warns with), the default 3 rows fitted as 3, and
// the refusals (rows that cannot be framed, two rows at one height), each
// with its one error line.
#include "lfdCylinderSampling.h"
#include "lfdSynthesisTestUtilities.h"
#include "vtkDoubleArray.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkPoints.h"

#include <cmath>
#include <string>

namespace
{
// A small capture of the fish (tiny images: only the rig is looked at).
vtkSmartPointer<vtkLightFieldCapture> SmallCapture(vtkProceduralObjectSource* source)
{
  auto capture = vtkSmartPointer<vtkLightFieldCapture>::New();
  capture->SetInputConnection(source->GetOutputPort());
  capture->SetViewsPerRing(12);
  capture->SetWidth(16);
  capture->SetHeight(16);
  capture->CaptureDepthOff();
  capture->CaptureLabelOff();
  return capture;
}

// The capture's error line after an update, "" when it succeeded.
std::string UpdateError(vtkLightFieldCapture* capture)
{
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(capture);
  capture->Modified();
  capture->Update();
  return errors->GetNumberOfErrors() == 1 ? errors->GetErrorMessage()
                                          : std::to_string(errors->GetNumberOfErrors()) + " errors";
}
}

int TestLightFieldCaptureRows(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  source->SetResolution(12);
  source->Update();
  double bounds[6];
  source->GetOutput()->GetBounds(bounds);

  // The default: 3 rows, 0.05 x radius apart, fitted as 3 rows of 12 (the
  // old fitter's tolerance was that spacing, and merged them).
  vtkSmartPointer<vtkLightFieldCapture> capture = SmallCapture(source);
  capture->Update();
  vtkCameraRig* rig = capture->GetOutput()->GetRig();
  lfdtest::Check(rig->GetNumberOfRows() == 3 && rig->GetRingLayout().Rows[1].View.size() == 12,
    "default capture fitted as 3 rows",
    rig->GetNumberOfRows(),
    3);

  // Elevations: rows at radius x tan(elevation), whatever radius the
  // framing picks.
  vtkNew<vtkDoubleArray> elevations;
  for (double e : { -12.0, 0.0, 4.0, 20.0 })
  {
    elevations->InsertNextValue(e);
  }
  capture->SetRowElevations(elevations);
  capture->SetViewAngle(60.0);
  capture->Update();
  rig = capture->GetOutput()->GetRig();
  double elevationError = rig->GetNumberOfRows() == 4 ? 0.0 : 1.0;
  // Fitted heights are relative to the fitted centre (the cameras' mean
  // height), elevations to the capture's centre (the mesh's, on axis +Y).
  const double offset = rig->GetCenter()[1] - 0.5 * (bounds[2] + bounds[3]);
  for (int r = 0; r < rig->GetNumberOfRows() && r < 4; ++r)
  {
    const double e =
      vtkMath::DegreesFromRadians(std::atan((rig->GetRowHeight(r) + offset) / rig->GetRadius()));
    elevationError = std::max(elevationError, std::abs(e - elevations->GetValue(r)));
  }
  lfdtest::Check(
    elevationError < 1e-9, "4 rows at their elevations (degrees)", elevationError, 1e-9);
  capture->SetRowElevations(nullptr);

  // An eye above the default rows, 1.3 radii out: the default rows leave
  // it extrapolating; rows that cover it do not.
  capture->SetViewAngle(30.0);
  capture->SetRadius(4.0);
  const double eye[3] = { 0.5 * (bounds[0] + bounds[1]),
    0.5 * (bounds[2] + bounds[3]) + 2.0,
    0.5 * (bounds[4] + bounds[5]) + 5.2 };
  capture->Update();
  const std::string before = capture->GetOutput()->GetRig()->DescribeExtrapolation(eye, bounds);
  std::cout << "     default rows: " << before << "\n";
  lfdtest::Check(before.find("above the highest of the 3 captured rows") != std::string::npos,
    "default rows: the eye above extrapolates",
    before.size(),
    0);
  vtkNew<vtkPoints> eyes;
  eyes->InsertNextPoint(eye);
  capture->SetEyes(eyes);
  capture->Update();
  rig = capture->GetOutput()->GetRig();
  const std::string after = rig->DescribeExtrapolation(eye, bounds);
  lfdtest::Check(after.empty() && rig->GetNumberOfRows() == 3,
    "rows covering the eye: no extrapolation, 3 rows",
    static_cast<double>(after.size()),
    0);
  std::cout << "     covering rows at " << rig->GetRowHeight(0) << ", " << rig->GetRowHeight(1)
            << ", " << rig->GetRowHeight(2) << "\n";
  // The highest row reaches the margin (0.05 x radius) above the highest
  // entry height, which lies below the eye.
  const double top = rig->GetRowHeight(2) - (eye[1] - rig->GetCenter()[1]);
  lfdtest::Check(top < 0.0 && rig->GetRowHeight(2) > 0.05 * rig->GetRadius(),
    "highest row below the eye, above the default rows",
    top,
    0.0);
  capture->SetEyes(nullptr);
  capture->SetRadius(0.0);

  // 11 rows 0.05 x radius apart span +-14 degrees: a 30-degree view cannot
  // frame the fish from the outer rows; the error names what to change.
  capture->SetNumberOfRows(11);
  const std::string framing = UpdateError(capture);
  const std::string expected = "Cannot frame the mesh: the rows span too wide a range of heights "
                               "for a view angle of 30 degrees; give fewer or closer rows "
                               "(NumberOfRows, RowSpacing, RowHeights, RowElevations; lfd synth "
                               "--rows, --row-spacing, --row-heights, --elevations), a wider "
                               "ViewAngle (--view-angle) or a Radius (--radius).";
  lfdtest::Check(
    framing == expected, "11 rows unframeable: one error line", framing == expected, 1);
  std::cout << "     " << framing << "\n";
  // With closer rows, 11 rows frame and are fitted as 11.
  capture->SetRowSpacing(0.01);
  capture->Update();
  rig = capture->GetOutput()->GetRig();
  lfdtest::Check(rig->GetNumberOfRows() == 11 &&
      std::abs(rig->GetRowHeight(1) - rig->GetRowHeight(0) - 0.01) < 1e-9,
    "11 rows 0.01 apart",
    rig->GetNumberOfRows(),
    11);

  // Two rows at one height are refused.
  vtkNew<vtkDoubleArray> heights;
  heights->InsertNextValue(0.1);
  heights->InsertNextValue(-0.2);
  heights->InsertNextValue(0.1);
  capture->SetRowHeights(heights);
  const std::string twice = UpdateError(capture);
  lfdtest::Check(twice ==
      "Two rows at the same height 0.1 (RowHeights or RowElevations): give "
      "each row its own height.",
    "two rows at one height refused",
    twice.size(),
    0);
  std::cout << "     " << twice << "\n";
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
