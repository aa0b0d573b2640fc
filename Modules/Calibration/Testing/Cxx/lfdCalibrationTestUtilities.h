// Helpers shared by the Calibration tests: checks that print their numbers,
// known cameras as row-major arrays, and synthetic board images through them.
#ifndef lfdCalibrationTestUtilities_h
#define lfdCalibrationTestUtilities_h

#include "lfdPinholeCamera.h"
#include "lfdTestChecks.h"
#include "vtkCalibrationImageSource.h"
#include "vtkCharucoBoard.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace lfdtest
{
/// A camera of the tests: row-major K, R, t and distortion (k1, k2, p1, p2, k3).
struct Camera
{
  double K[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double R[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double t[3] = { 0, 0, 0 };
  double D[5] = { 0, 0, 0, 0, 0 };

  glm::dvec3 Center() const
  {
    return lfd::PinholeCamera::FromRowMajor(this->K, this->R, this->t).Center();
  }
};

/// Camera of intrinsics `K` at `position` looking at `target`, image "up"
/// towards `up`.
inline Camera LookAt(const double K[9], glm::dvec3 position, glm::dvec3 target, glm::dvec3 up)
{
  glm::dmat3 k;
  for (int i = 0; i < 9; ++i)
  {
    k[i % 3][i / 3] = K[i];
  }
  const lfd::PinholeCamera pinhole = lfd::PinholeCamera::LookAt(k, position, target - position, up);
  Camera camera;
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      camera.K[3 * row + col] = K[3 * row + col];
      camera.R[3 * row + col] = pinhole.R[col][row];
    }
    camera.t[row] = pinhole.t[row];
  }
  return camera;
}

/// The tests' board: 7 x 5 squares of 30 mm, markers of 22 mm.
inline vtkSmartPointer<vtkCharucoBoard> Board()
{
  auto board = vtkSmartPointer<vtkCharucoBoard>::New();
  board->SetSquaresX(7);
  board->SetSquaresY(5);
  board->SetSquareLength(0.03);
  board->SetMarkerLength(0.022);
  board->SetDictionary("DICT_5X5_100");
  return board;
}

/// The board's centre in its frame.
inline glm::dvec3 BoardCentre(vtkCharucoBoard* board)
{
  return glm::dvec3(0.5 * board->GetSquaresX() * board->GetSquareLength(),
    0.5 * board->GetSquaresY() * board->GetSquareLength(),
    0.0);
}

/// What `camera` sees of `board` (640 x 480, 2 x 2 rays per pixel, noise
/// of 1 grey level).
inline vtkSmartPointer<vtkImageData> Render(vtkCharucoBoard* board,
  const Camera& camera,
  int seed,
  int width = 640,
  int height = 480)
{
  vtkNew<vtkCalibrationImageSource> source;
  source->SetBoard(board);
  source->SetImageSize(width, height);
  source->SetCamera(camera.K, camera.R, camera.t);
  source->SetDistortion(camera.D);
  source->SetSupersampling(2);
  source->SetNoiseSigma(1.0);
  source->SetNoiseSeed(seed);
  source->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(source->GetOutput());
  return image;
}

/// Angle in degrees between two row-major rotations.
inline double RotationAngle(const double A[9], const double B[9])
{
  // trace(A B^T) = 1 + 2 cos(angle)
  double trace = 0.0;
  for (int i = 0; i < 9; ++i)
  {
    trace += A[i] * B[i];
  }
  return std::acos(std::clamp(0.5 * (trace - 1.0), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}
}

#endif
