// The ring of a gantry from one board image per camera position: per-view
// poses with known intrinsics, then the rig's cylinder fit. 9 views on an
// arc of 120 degrees of a ring of radius 0.6 whose axis is tilted 4 degrees
// and offset from the board: radius within 0.5 %, axis within 0.5 degrees,
// every camera centre within 3 mm.
#include "lfdCalibrationTestUtilities.h"
#include "vtkCameraCalibration.h"
#include "vtkCameraRig.h"

#include <cstdio>

int TestRingCalibration(int, char*[])
{
  auto board = lfdtest::Board();
  const double K[9] = { 800.0, 0.0, 319.5, 0.0, 800.0, 239.5, 0.0, 0.0, 1.0 };
  const double D[5] = { -0.08, 0.02, 0.0, 0.0, 0.0 };
  const double pi = 3.14159265358979323846;
  const double radius = 0.6;
  const double tilt = 4.0 * pi / 180.0;
  // The ring's axis: the board's "up" (-y) tilted towards +x; its centre
  // behind the board, off its centre. Azimuth 0 (`zero`) is the board's
  // back (+z): the cameras are on the front half of the ring.
  const glm::dvec3 axis(std::sin(tilt), -std::cos(tilt), 0.0);
  const glm::dvec3 centre = lfdtest::BoardCentre(board) + glm::dvec3(0.02, -0.01, 0.03);
  const glm::dvec3 zero = glm::normalize(glm::cross(axis, glm::dvec3(1.0, 0.0, 0.0)));
  const glm::dvec3 quarter = glm::cross(axis, zero);
  vtkNew<vtkCameraCalibration> calibration;
  calibration->SetBoard(board);
  calibration->SetIntrinsics(K);
  calibration->SetDistortion(D);
  calibration->FixIntrinsicsOn();
  std::vector<glm::dvec3> truth;
  for (int v = 0; v < 9; ++v)
  {
    // Azimuths -60 .. 60 degrees about the board's normal side (z < 0).
    const double azimuth = (-60.0 + 15.0 * v) * pi / 180.0;
    const glm::dvec3 position =
      centre + radius * (-std::cos(azimuth) * zero + std::sin(azimuth) * quarter);
    lfdtest::Camera camera = lfdtest::LookAt(K, position, centre, axis);
    std::copy(D, D + 5, camera.D);
    truth.push_back(position);
    calibration->AddImage(lfdtest::Render(board, camera, 11 + v));
  }
  lfdtest::Check(calibration->Calibrate(), "poses estimated", 1, 1);

  vtkNew<vtkCameraRig> rig;
  calibration->GetRig(rig);
  std::string problem;
  lfdtest::Check(rig->FitCylinder(problem), "cylinder fitted", 1, 1);
  std::printf("radius %.5f, axis %.4f %.4f %.4f, fit residual %.2e, RMS %.3f px\n",
    rig->GetRadius(),
    rig->GetAxis()[0],
    rig->GetAxis()[1],
    rig->GetAxis()[2],
    rig->GetFitResidual(),
    calibration->GetRms());
  for (int v = 0; v < 9; ++v)
  {
    std::printf("  view %d: azimuth %.2f deg, RMS %.3f px\n",
      v,
      rig->GetAzimuth(v) * 180.0 / pi,
      calibration->GetViewRms(v));
  }
  lfdtest::Check(std::abs(rig->GetRadius() / radius - 1.0) < 0.005,
    "radius relative error",
    rig->GetRadius() / radius - 1.0,
    0.005);
  const glm::dvec3 fitted(rig->GetAxis()[0], rig->GetAxis()[1], rig->GetAxis()[2]);
  const double axisError = std::acos(std::min(1.0, std::abs(glm::dot(fitted, axis)))) * 180.0 / pi;
  lfdtest::Check(axisError < 0.5, "axis error (degrees)", axisError, 0.5);
  double worst = 0.0;
  for (int v = 0; v < 9; ++v)
  {
    double c[3];
    rig->GetCameraCenter(v, c);
    worst = std::max(worst, glm::length(glm::dvec3(c[0], c[1], c[2]) - truth[v]));
  }
  lfdtest::Check(worst < 0.003, "worst camera centre error (m)", worst, 0.003);
  // Neighbouring views are 15 degrees apart on the fitted ring.
  double spacing = 0.0;
  for (int v = 1; v < 9; ++v)
  {
    double step = std::remainder(rig->GetAzimuth(v) - rig->GetAzimuth(v - 1), 2.0 * pi);
    spacing = std::max(spacing, std::abs(std::abs(step) * 180.0 / pi - 15.0));
  }
  lfdtest::Check(spacing < 0.2, "worst azimuth step error (degrees)", spacing, 0.2);
  lfdtest::Check(rig->GetNumberOfRows() == 1, "rows", rig->GetNumberOfRows(), 1);
  lfdtest::Check(calibration->GetRms() < 0.3, "RMS (px)", calibration->GetRms(), 0.3);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
