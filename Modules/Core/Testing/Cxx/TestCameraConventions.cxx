// The OpenCV convention of vtkCameraRig against VTK's own camera: a view
// applied to a vtkCamera projects world points to the same pixels (with the
// top-left / bottom-left flip and half-pixel shift), including an
// off-centre principal point, and CameraToPinhole inverts ApplyToCamera.
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

int TestCameraConventions(int, char*[])
{
  const int width = 320;
  const int height = 200;
  const double position[3] = { 0.3, -0.2, 4.0 };
  double forward[3] = { -0.1, 0.05, -1.0 };
  vtkMath::Normalize(forward);
  double down[3] = { 0.0, -1.0, 0.0 };
  const double d = vtkMath::Dot(down, forward);
  for (int c = 0; c < 3; ++c)
  {
    down[c] -= d * forward[c];
  }
  vtkMath::Normalize(down);
  double right[3];
  vtkMath::Cross(down, forward, right);
  // Off-centre principal point, square pixels.
  const double K[9] = { 400.0, 0.0, 171.0, 0.0, 400.0, 88.5, 0.0, 0.0, 1.0 };
  const double R[9] = {
    right[0], right[1], right[2], down[0], down[1], down[2], forward[0], forward[1], forward[2]
  };
  const double t[3] = {
    -vtkMath::Dot(right, position), -vtkMath::Dot(down, position), -vtkMath::Dot(forward, position)
  };

  vtkNew<vtkCameraRig> rig;
  rig->SetImageSize(width, height);
  rig->SetNumberOfViews(1);
  rig->SetView(0, K, R, t);

  vtkNew<vtkCamera> camera;
  rig->ApplyToCamera(0, camera);
  camera->SetClippingRange(0.1, 100.0);
  vtkMatrix4x4* m =
    camera->GetCompositeProjectionTransformMatrix(double(width) / height, -1.0, 1.0);

  double worst = 0.0;
  const double points[4][3] = {
    { 0, 0, 0 }, { 0.5, 0.3, -0.2 }, { -0.4, -0.25, 0.5 }, { 0.2, -0.3, 1.0 }
  };
  for (const auto& p : points)
  {
    double pixel[2];
    if (!rig->Project(0, p, pixel))
    {
      std::cout << "FAIL point behind the camera\n";
      return EXIT_FAILURE;
    }
    const double in[4] = { p[0], p[1], p[2], 1.0 };
    double out[4];
    m->MultiplyPoint(in, out);
    // NDC -> VTK display (origin bottom-left corner) -> OpenCV pixel.
    const double xd = 0.5 * (out[0] / out[3] + 1.0) * width;
    const double yd = 0.5 * (out[1] / out[3] + 1.0) * height;
    const double u = xd - 0.5;
    const double v = height - yd - 0.5;
    const double err = std::hypot(u - pixel[0], v - pixel[1]);
    std::cout << "rig (" << pixel[0] << ", " << pixel[1] << ")  vtkCamera (" << u << ", " << v
              << ")\n";
    worst = std::max(worst, err);
  }
  std::cout << "largest disagreement: " << worst << " px\n";
  if (worst > 1e-9)
  {
    std::cout << "FAIL ApplyToCamera does not reproduce the pinhole\n";
    return EXIT_FAILURE;
  }

  double K2[9], R2[9], t2[3];
  vtkCameraRig::CameraToPinhole(camera, width, height, K2, R2, t2);
  double roundTrip = 0.0;
  for (int i = 0; i < 9; ++i)
  {
    roundTrip = std::max(roundTrip, std::abs(K2[i] - K[i]) / 400.0);
    roundTrip = std::max(roundTrip, std::abs(R2[i] - R[i]));
  }
  for (int i = 0; i < 3; ++i)
  {
    roundTrip = std::max(roundTrip, std::abs(t2[i] - t[i]));
  }
  std::cout << "CameraToPinhole round trip error: " << roundTrip << "\n";
  if (roundTrip > 1e-9)
  {
    std::cout << "FAIL CameraToPinhole is not the inverse of ApplyToCamera\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
