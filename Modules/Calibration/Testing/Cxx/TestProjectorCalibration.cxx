// A projector from Gray-code captures (Moreno and Taubin 2012): a known
// camera and a known projector beside it, the board at 8 poses tilted up to 35 degrees, each lit by
// the whole vtkGrayCodePattern sequence and rendered by
// vtkCalibrationImageSource. Projector focal length within 0.5 %, principal
// point within 1 projector pixel, pose within 1 mm and 0.2 degrees.
#include "lfdCalibrationTestUtilities.h"
#include "vtkCameraRig.h"
#include "vtkDoubleArray.h"
#include "vtkGrayCodePattern.h"
#include "vtkProjectorCalibration.h"

#include <cstdio>
#include <vector>

int TestProjectorCalibration(int, char*[])
{
  auto board = lfdtest::Board();
  const double pi = 3.14159265358979323846;
  const double cameraK[9] = { 640.0, 0.0, 255.5, 0.0, 640.0, 191.5, 0.0, 0.0, 1.0 };
  const double cameraD[5] = { -0.05, 0.0, 0.0, 0.0, 0.0 };
  const int projectorSize[2] = { 320, 240 };
  const double projectorK[9] = { 450.0, 0.0, 161.0, 0.0, 452.0, 118.0, 0.0, 0.0, 1.0 };
  // Camera to projector: 12 cm to the camera's right, turned 12 degrees
  // towards its optical axis.
  const double angle = 12.0 * pi / 180.0;
  const double toProjectorR[9] = {
    std::cos(angle), 0.0, std::sin(angle), 0.0, 1.0, 0.0, -std::sin(angle), 0.0, std::cos(angle)
  };
  const glm::dvec3 projectorCentre(0.12, 0.01, 0.0);
  double toProjectorT[3];
  for (int row = 0; row < 3; ++row)
  {
    toProjectorT[row] =
      -(toProjectorR[3 * row] * projectorCentre.x + toProjectorR[3 * row + 1] * projectorCentre.y +
        toProjectorR[3 * row + 2] * projectorCentre.z);
  }

  vtkNew<vtkGrayCodePattern> sequence;
  sequence->SetProjectorSize(projectorSize[0], projectorSize[1]);
  const int patterns = sequence->GetNumberOfPatterns();
  lfdtest::Check(patterns == 2 * (9 + 8) + 2, "patterns for 320 x 240", patterns, 36);
  std::vector<vtkSmartPointer<vtkImageData>> shown(patterns);
  for (int i = 0; i < patterns; ++i)
  {
    shown[i] = vtkSmartPointer<vtkImageData>::New();
    sequence->GetPattern(i, shown[i]);
  }

  // The camera's offsets from the board's centre at each pose, and where it
  // looks (offset from the centre): 8 poses, tilted up to 35 degrees, the
  // last three placing the board off the images' centres (with 5 the
  // projector's principal point and the radial distortion estimated with
  // it stay within 1.6 px only).
  const double poses[8][5] = {
    { -0.20, -0.10, -0.38, 0.0, 0.0 },
    { 0.16, 0.08, -0.40, 0.0, 0.0 },
    { 0.00, 0.20, -0.38, 0.0, 0.0 },
    { -0.06, -0.20, -0.40, 0.0, 0.0 },
    { 0.00, 0.00, -0.45, 0.0, 0.0 },
    { -0.25, 0.05, -0.33, 0.06, -0.04 },
    { 0.22, -0.15, -0.33, -0.06, 0.04 },
    { 0.05, 0.25, -0.33, -0.04, -0.05 },
  };
  const int poseCount = 8;
  const glm::dvec3 centre = lfdtest::BoardCentre(board);
  vtkNew<vtkProjectorCalibration> calibration;
  calibration->SetBoard(board);
  calibration->SetProjectorSize(projectorSize[0], projectorSize[1]);
  calibration->SetCamera(cameraK, cameraD);
  calibration->SetNumberOfPoses(poseCount);
  std::vector<lfd::PinholeCamera> trueCameras;
  std::vector<lfd::PinholeCamera> trueProjectors;
  vtkNew<vtkCalibrationImageSource> source;
  source->SetBoard(board);
  source->SetImageSize(512, 384);
  source->SetSupersampling(2);
  source->SetAmbient(0.05);
  source->SetNoiseSigma(1.0);
  for (int p = 0; p < poseCount; ++p)
  {
    const lfdtest::Camera camera = lfdtest::LookAt(cameraK,
      centre + glm::dvec3(poses[p][0], poses[p][1], poses[p][2]),
      centre + glm::dvec3(poses[p][3], poses[p][4], 0.0),
      glm::dvec3(0.0, -1.0, 0.0));
    // The projector moves with the camera: world -> camera -> projector.
    double R[9];
    double t[3];
    for (int row = 0; row < 3; ++row)
    {
      t[row] = toProjectorT[row];
      for (int col = 0; col < 3; ++col)
      {
        R[3 * row + col] = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          R[3 * row + col] += toProjectorR[3 * row + k] * camera.R[3 * k + col];
        }
        t[row] += toProjectorR[3 * row + col] * camera.t[col];
      }
    }
    trueCameras.push_back(lfd::PinholeCamera::FromRowMajor(camera.K, camera.R, camera.t));
    trueCameras.back().Lens = lfd::LensDistortion::FromArray(cameraD);
    trueProjectors.push_back(lfd::PinholeCamera::FromRowMajor(projectorK, R, t));
    source->SetCamera(camera.K, camera.R, camera.t);
    source->SetDistortion(cameraD);
    source->SetProjector(projectorK, R, t);
    for (int i = 0; i < patterns; ++i)
    {
      source->SetProjectorPattern(shown[i]);
      source->SetNoiseSeed(100 * p + i);
      source->Update();
      auto image = vtkSmartPointer<vtkImageData>::New();
      image->DeepCopy(source->GetOutput());
      calibration->SetImage(p, i, image);
    }
  }
  lfdtest::Check(calibration->Calibrate(), "calibrated", 1, 1);

  // The decoded corners against their true camera and projector pixels:
  // the local homographies carry the camera's corners into the projector
  // with no loss.
  double cameraWorst = 0.0;
  double projectorWorst = 0.0;
  for (int p = 0; p < poseCount; ++p)
  {
    vtkNew<vtkDoubleArray> positions;
    vtkNew<vtkDoubleArray> cameraPixels;
    vtkNew<vtkDoubleArray> projectorPixels;
    calibration->GetCorners(p, positions, cameraPixels, projectorPixels);
    double cameraSum = 0.0;
    double projectorSum = 0.0;
    const vtkIdType corners = positions->GetNumberOfTuples();
    for (vtkIdType c = 0; c < corners; ++c)
    {
      const glm::dvec3 X(positions->GetComponent(c, 0), positions->GetComponent(c, 1), 0.0);
      glm::dvec2 inCamera;
      glm::dvec2 inProjector;
      trueCameras[p].Project(X, inCamera);
      trueProjectors[p].Project(X, inProjector);
      const glm::dvec2 cameraError =
        glm::dvec2(cameraPixels->GetComponent(c, 0), cameraPixels->GetComponent(c, 1)) - inCamera;
      const glm::dvec2 projectorError =
        glm::dvec2(projectorPixels->GetComponent(c, 0), projectorPixels->GetComponent(c, 1)) -
        inProjector;
      cameraSum += glm::dot(cameraError, cameraError);
      projectorSum += glm::dot(projectorError, projectorError);
    }
    const double cameraRms = std::sqrt(cameraSum / corners);
    const double projectorRms = std::sqrt(projectorSum / corners);
    std::printf("  pose %d corners against the truth: camera RMS %.3f px, projector RMS %.3f px\n",
      p,
      cameraRms,
      projectorRms);
    cameraWorst = std::max(cameraWorst, cameraRms);
    projectorWorst = std::max(projectorWorst, projectorRms);
  }
  lfdtest::Check(cameraWorst < 0.15, "worst camera corner RMS (px)", cameraWorst, 0.15);
  lfdtest::Check(projectorWorst < 0.12, "worst projector corner RMS (px)", projectorWorst, 0.12);

  double K[9];
  double R[9];
  double t[3];
  calibration->GetProjectorIntrinsics(K);
  calibration->GetProjectorRotation(R);
  calibration->GetProjectorTranslation(t);
  std::printf("projector K = [%.3f 0 %.3f; 0 %.3f %.3f], t = %.5f %.5f %.5f\n",
    K[0],
    K[2],
    K[4],
    K[5],
    t[0],
    t[1],
    t[2]);
  for (int p = 0; p < poseCount; ++p)
  {
    std::printf("  pose %d: %d corners, projector RMS %.3f px\n",
      p,
      calibration->GetNumberOfCorners(p),
      calibration->GetPoseRms(p));
  }
  std::printf("projector RMS %.3f px\n", calibration->GetRms());
  lfdtest::Check(std::abs(K[0] / projectorK[0] - 1.0) < 0.005,
    "projector fx relative error",
    K[0] / projectorK[0] - 1.0,
    0.005);
  lfdtest::Check(std::abs(K[4] / projectorK[4] - 1.0) < 0.005,
    "projector fy relative error",
    K[4] / projectorK[4] - 1.0,
    0.005);
  lfdtest::Check(
    std::abs(K[2] - projectorK[2]) < 1.0, "projector cx error (px)", K[2] - projectorK[2], 1.0);
  lfdtest::Check(
    std::abs(K[5] - projectorK[5]) < 1.0, "projector cy error (px)", K[5] - projectorK[5], 1.0);
  const double rotationError = lfdtest::RotationAngle(R, toProjectorR);
  lfdtest::Check(rotationError < 0.2, "projector rotation error (degrees)", rotationError, 0.2);
  // The projector's centre, in the camera's frame.
  const glm::dvec3 fitted = lfd::PinholeCamera::FromRowMajor(K, R, t).Center();
  const double positionError = glm::length(fitted - projectorCentre);
  lfdtest::Check(positionError < 0.001, "projector position error (m)", positionError, 0.001);
  lfdtest::Check(calibration->GetRms() < 0.1, "projector RMS (px)", calibration->GetRms(), 0.1);

  vtkNew<vtkCameraRig> projector;
  calibration->GetProjector(projector);
  lfdtest::Check(projector->GetNumberOfViews() == 1 && projector->GetImageSize()[0] == 320,
    "projector rig",
    projector->GetNumberOfViews(),
    1);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
