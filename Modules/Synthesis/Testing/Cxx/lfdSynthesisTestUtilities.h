// Helpers shared by the Synthesis tests: checks that print their numbers,
// the tests' capture set-up, views of a light field as images, regression
// comparison of an image and the analytic rays of a rig's pixels.
#ifndef lfdSynthesisTestUtilities_h
#define lfdSynthesisTestUtilities_h

#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkTrivialProducer.h"

#include <algorithm>
#include <initializer_list>
#include <iostream>

namespace lfdtest
{
// A capture of the source's object from one ring of 8 views of
// `size` x `size` pixels.
inline vtkSmartPointer<vtkLightFieldCapture> RingCapture(vtkProceduralObjectSource* source,
  int size = 128)
{
  auto capture = vtkSmartPointer<vtkLightFieldCapture>::New();
  capture->SetInputConnection(source->GetOutputPort());
  capture->SetViewsPerRing(8);
  capture->SetNumberOfRows(1);
  capture->SetWidth(size);
  capture->SetHeight(size);
  return capture;
}

// The Coaxial pass of the given views side by side, as an RGB image.
inline vtkSmartPointer<vtkImageData> CoaxialMontage(vtkLightField* lightField,
  std::initializer_list<int> views)
{
  const int w = lightField->GetWidth();
  const int h = lightField->GetHeight();
  const int n = static_cast<int>(views.size());
  auto montage = vtkSmartPointer<vtkImageData>::New();
  montage->SetDimensions(n * w, h, 1);
  montage->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(montage->GetScalarPointer());
  auto* in =
    static_cast<unsigned char*>(lightField->GetPass(vtkLightField::COAXIAL)->GetVoidPointer(0));
  int column = 0;
  for (int view : views)
  {
    for (int j = 0; j < h; ++j)
    {
      const unsigned char* row = in + 3 * ((static_cast<vtkIdType>(view) * h + j) * w);
      std::copy_n(row, 3 * w, out + 3 * (j * n * w + column * w));
    }
    ++column;
  }
  return montage;
}

// Compares `image` with the test's baseline (-V) and returns true when it
// matches within `threshold`.
inline bool MatchesBaseline(int argc, char* argv[], vtkImageData* image, double threshold)
{
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    testing->AddArgument(argv[i]);
  }
  if (!testing->IsValidImageSpecified())
  {
    std::cout << "FAIL no baseline image given (-V)\n";
    return false;
  }
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(image);
  return testing->RegressionTest(producer, threshold) == vtkTesting::PASSED;
}

// The ray of the pixel at OpenCV coordinates (x, y) of a view: camera
// centre and unit direction R^T K^-1 (x, y, 1).
inline void PixelRay(vtkCameraRig* rig,
  int view,
  double x,
  double y,
  double origin[3],
  double direction[3])
{
  double K[9], R[9];
  rig->GetIntrinsics(view, K);
  rig->GetRotation(view, R);
  rig->GetCameraCenter(view, origin);
  const double yc = (y - K[5]) / K[4];
  const double xc = (x - K[2] - K[1] * yc) / K[0];
  const double c[3] = { xc, yc, 1.0 };
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = R[k] * c[0] + R[3 + k] * c[1] + R[6 + k] * c[2];
  }
  vtkMath::Normalize(direction);
}

// Where the pixel's ray meets the plane z = 0 (the checkerboard's plane);
// false when it does not meet it in front of the camera.
inline bool HitCheckerboardPlane(vtkCameraRig* rig,
  int view,
  int x,
  int y,
  double hit[3],
  double* depth = nullptr)
{
  double origin[3], direction[3];
  PixelRay(rig, view, x, y, origin, direction);
  if (std::abs(direction[2]) < 1e-9)
  {
    return false;
  }
  const double t = -origin[2] / direction[2];
  if (t <= 0.0)
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    hit[k] = origin[k] + t * direction[k];
  }
  if (depth)
  {
    double forward[3];
    rig->GetViewDirection(view, forward);
    *depth = t * vtkMath::Dot(direction, forward);
  }
  return true;
}
}

#endif
