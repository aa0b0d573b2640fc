// Camera intrinsics and lens distortion from synthetic ChArUco images taken
// by a known camera from 9 directions tilted up to 40 degrees, the board in
// every part of the image: focal lengths within 0.5 %,
// principal point within 1 pixel, the reprojection RMS reported per view.
#include "lfdCalibrationTestUtilities.h"
#include "vtkCameraCalibration.h"
#include "vtkCameraRig.h"

#include <cstdio>

int TestCameraCalibration(int, char*[])
{
  auto board = lfdtest::Board();
  const double K[9] = { 810.0, 0.0, 322.3, 0.0, 805.0, 236.8, 0.0, 0.0, 1.0 };
  const double D[5] = { -0.12, 0.05, 0.001, -0.0015, 0.0 };
  const glm::dvec3 centre = lfdtest::BoardCentre(board);
  // Camera offsets from the board's centre (the face is seen from z < 0),
  // where each looks (offset from the centre) and its roll (degrees).
  const double views[9][7] = {
    { -0.22, -0.12, -0.36, 0.05, 0.035, 0, 5 },
    { 0.22, -0.10, -0.36, -0.05, 0.035, 0, -8 },
    { -0.20, 0.14, -0.34, 0.05, -0.035, 0, 3 },
    { 0.20, 0.14, -0.36, -0.05, -0.035, 0, 12 },
    { 0.00, 0.00, -0.42, 0.00, 0.00, 0, 0 },
    { -0.26, 0.00, -0.30, 0.00, 0.00, 0, -4 },
    { 0.26, 0.02, -0.30, 0.00, 0.00, 0, 7 },
    { 0.00, -0.22, -0.33, 0.00, 0.00, 0, -10 },
    { 0.00, 0.22, -0.33, 0.00, 0.00, 0, 20 },
  };
  vtkNew<vtkCameraCalibration> calibration;
  calibration->SetBoard(board);
  for (int v = 0; v < 9; ++v)
  {
    const double roll = views[v][6] * 3.14159265358979323846 / 180.0;
    lfdtest::Camera camera = lfdtest::LookAt(K,
      centre + glm::dvec3(views[v][0], views[v][1], views[v][2]),
      centre + glm::dvec3(views[v][3], views[v][4], views[v][5]),
      glm::dvec3(std::sin(roll), -std::cos(roll), 0.0));
    std::copy(D, D + 5, camera.D);
    const std::string name = "view_" + std::to_string(v) + ".png";
    calibration->AddImage(lfdtest::Render(board, camera, v + 1), name.c_str());
  }
  lfdtest::Check(calibration->Calibrate(), "calibrated", 1, 1);

  double k[9];
  double d[5];
  calibration->GetIntrinsics(k);
  calibration->GetDistortion(d);
  std::printf("K = [%.3f 0 %.3f; 0 %.3f %.3f]  distortion = %.5f %.5f %.5f %.5f %.5f\n",
    k[0],
    k[2],
    k[4],
    k[5],
    d[0],
    d[1],
    d[2],
    d[3],
    d[4]);
  for (int v = 0; v < calibration->GetNumberOfImages(); ++v)
  {
    std::printf("  %s: %d corners, RMS %.3f px\n",
      calibration->GetImageName(v),
      calibration->GetNumberOfCorners(v),
      calibration->GetViewRms(v));
  }
  lfdtest::Check(
    std::abs(k[0] / K[0] - 1.0) < 0.005, "fx relative error", k[0] / K[0] - 1.0, 0.005);
  lfdtest::Check(
    std::abs(k[4] / K[4] - 1.0) < 0.005, "fy relative error", k[4] / K[4] - 1.0, 0.005);
  lfdtest::Check(std::abs(k[2] - K[2]) < 1.0, "cx error (px)", k[2] - K[2], 1.0);
  lfdtest::Check(std::abs(k[5] - K[5]) < 1.0, "cy error (px)", k[5] - K[5], 1.0);
  lfdtest::Check(std::abs(d[0] - D[0]) < 0.01, "k1 error", d[0] - D[0], 0.01);
  lfdtest::Check(calibration->GetRms() < 0.1, "overall RMS (px)", calibration->GetRms(), 0.1);
  int corners = 0;
  for (int v = 0; v < 9; ++v)
  {
    corners += calibration->GetNumberOfCorners(v);
  }
  // Every one of the 24 inner corners is seen in every view.
  lfdtest::Check(corners == 9 * 24, "corners found", corners, 9 * 24);

  // The rig holds the calibration, one view per image, named.
  vtkNew<vtkCameraRig> rig;
  calibration->GetRig(rig);
  double rigK[9];
  double rigD[5];
  rig->GetIntrinsics(3, rigK);
  rig->GetDistortion(3, rigD);
  lfdtest::Check(rig->GetNumberOfViews() == 9 && rigK[0] == k[0] && rigD[0] == d[0] &&
      std::string(rig->GetViewName(3)) == "view_3.png" && rig->GetImageSize()[0] == 640,
    "rig holds the calibration",
    rig->GetNumberOfViews(),
    9);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
