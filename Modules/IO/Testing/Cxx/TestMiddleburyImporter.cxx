// Import of the real templeRing set (Seitz et al., CVPR 2006): 47 views of
// 640x480, pixels identical to the PNGs, the calibration as given, and the
// cylinder fit of the ring (radius, axis, near-duplicate views, the ~32
// degree gap), plus the projection of the temple into the upright and the
// 180-degree-rotated views.
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkMath.h"
#include "vtkMiddleburyImporter.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkTesting.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

using lfdtest::Check;
using lfdtest::CheckEqual;
using lfdtest::CheckRange;

namespace
{
// Pixels: view 10 against VTK's own PNG reader (both bottom row first).
void CheckPixels(const std::string& folder, vtkDataArray* coaxial, vtkCameraRig* rig)
{
  vtkNew<vtkPNGReader> png;
  png->SetFileName((folder + "/" + rig->GetViewName(10)).c_str());
  png->Update();
  vtkDataArray* reference = png->GetOutput()->GetPointData()->GetScalars();
  const vtkIdType offset = 10LL * 640 * 480 * 3;
  int mismatches = 0;
  for (vtkIdType i = 0; i < 640 * 480; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      mismatches += coaxial->GetComponent(offset / 3 + i, c) ==
          reference->GetComponent(i, std::min(c, reference->GetNumberOfComponents() - 1))
        ? 0
        : 1;
    }
  }
  CheckEqual(
    mismatches, 0, "pixels of view 10 differing from " + std::string(rig->GetViewName(10)));
}

// The ring (measured independently from the par file: the camera centres
// lie on a circle of radius 0.5626 in a plane whose normal is within 2.5
// degrees of world -y; templeR0030 repeats templeR0001's calibration
// exactly; the largest azimuth step is 34.1 degrees).
void CheckRing(vtkCameraRig* rig)
{
  Check(rig->HasCylinder(), "the cylinder is fitted");
  const double* axis = rig->GetAxis();
  const double* center = rig->GetCenter();
  std::cout << "     axis (" << axis[0] << ", " << axis[1] << ", " << axis[2] << "), centre ("
            << center[0] << ", " << center[1] << ", " << center[2] << ")\n";
  CheckRange(rig->GetRadius(), 0.55, 0.575, "radius (m)");
  CheckRange(std::abs(axis[1]), 0.995, 1.0, "|axis . world y|");
  CheckRange(rig->GetFitResidual(), 0.0, 0.005, "fit residual (RMS, m)");
  std::cout << "     duplicates:";
  for (int i = 0; i < 47; ++i)
  {
    if (rig->GetDuplicateOf(i) >= 0)
    {
      std::cout << " " << i << "->" << rig->GetDuplicateOf(i);
    }
  }
  std::cout << "\n";
  CheckEqual(rig->GetNumberOfDuplicates(), 1, "duplicates");
  CheckEqual(rig->GetDuplicateOf(29), 0, "view 29 (templeR0030) duplicates view 0");

  // Azimuth gap between consecutive distinct views.
  std::vector<double> azimuths;
  for (int i = 0; i < 47; ++i)
  {
    if (rig->GetDuplicateOf(i) < 0)
    {
      azimuths.push_back(vtkMath::DegreesFromRadians(rig->GetAzimuth(i)));
    }
  }
  std::sort(azimuths.begin(), azimuths.end());
  double gap = 360.0 - azimuths.back() + azimuths.front();
  for (size_t i = 1; i < azimuths.size(); ++i)
  {
    gap = std::max(gap, azimuths[i] - azimuths[i - 1]);
  }
  CheckRange(gap, 30.0, 36.0, "largest azimuth gap (degrees)");
}

// In templeRing the image x axis runs along the ring axis; the views taken
// from the opposite latitude are rotated by 180 degrees, so their x axis
// points the other way. Their calibration includes the rotation: the
// temple's bounding-box centre (README.txt) projects inside every image,
// and a point moved along the ring axis moves along image x in the
// direction given by that view's own x axis.
void CheckOrientation(vtkCameraRig* rig)
{
  const double* axis = rig->GetAxis();
  const double temple[3] = {
    0.5 * (-0.023121 + 0.078626), 0.5 * (-0.038009 + 0.121636), 0.5 * (-0.091940 + -0.017395)
  };
  double along[3];
  for (int c = 0; c < 3; ++c)
  {
    along[c] = temple[c] + 0.02 * axis[c];
  }
  double R0[9];
  rig->GetRotation(0, R0);
  const double xReference = R0[0] * axis[0] + R0[1] * axis[1] + R0[2] * axis[2];
  int rotated = 0;
  int inside = 0;
  int consistent = 0;
  std::cout << "     rotated views:";
  for (int i = 0; i < 47; ++i)
  {
    double R[9], p[2] = { -1, -1 }, q[2] = { -1, -1 };
    rig->GetRotation(i, R);
    const double xDotAxis = R[0] * axis[0] + R[1] * axis[1] + R[2] * axis[2];
    const bool isRotated = xDotAxis * xReference < 0.0;
    if (isRotated)
    {
      ++rotated;
      std::cout << " " << i;
    }
    if (rig->Project(i, temple, p) && p[0] > 0 && p[0] < 640 && p[1] > 0 && p[1] < 480)
    {
      ++inside;
    }
    if (rig->Project(i, along, q))
    {
      const double dx = q[0] - p[0];
      consistent += (dx * xDotAxis > 0.0 && std::abs(dx) > 10.0) ? 1 : 0;
    }
  }
  std::cout << "\n";
  CheckEqual(rotated, 16, "views rotated by 180 degrees relative to view 0");
  CheckEqual(inside, 47, "views in which the temple centre projects inside the image");
  CheckEqual(consistent, 47, "views where a point moved along the axis moves along its own x");
  double p0[2], p29[2];
  rig->Project(0, temple, p0);
  rig->Project(29, temple, p29);
  CheckRange(std::hypot(p0[0] - p29[0], p0[1] - p29[1]),
    0.0,
    1e-9,
    "pixel distance of the temple centre in views 0 and 29");
}
}

// argv[1]: the folder holding templeR_par.txt and the 47 PNGs (ExternalData,
// see CMake/lfdTestData.cmake).
int TestMiddleburyImporter(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : "";
  const std::string par = folder + "/templeR_par.txt";
  if (!std::filesystem::is_regular_file(par))
  {
    std::cout << "skipped: " << par
              << " not found (templeRing data: see the README's Tests section)\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkMiddleburyImporter> importer;
  importer->SetFileName(par.c_str());
  importer->Update();
  vtkLightField* lightField = importer->GetOutput();
  // Everything below reads the output: a failed import stops here.
  vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
  vtkCameraRig* rig = lightField->GetRig();
  if (!CheckEqual(importer->GetErrorCode(), 0ul, "importer error code") ||
    !CheckEqual(lightField->GetNumberOfViews(), 47, "views") ||
    !CheckEqual(lightField->GetWidth(), 640, "width") ||
    !CheckEqual(lightField->GetHeight(), 480, "height") ||
    !Check(coaxial && coaxial->GetNumberOfComponents() == 3, "Coaxial pass, RGB") ||
    !Check(rig && rig->GetNumberOfViews() == 47, "rig of 47 views"))
  {
    return EXIT_FAILURE;
  }
  CheckEqual(std::string(rig->GetViewName(3)), std::string("templeR0004.png"), "view 3 name");

  CheckPixels(folder, coaxial, rig);

  // Calibration as given: line 2 of the par file is templeR0001.png.
  double K[9], t[3];
  rig->GetIntrinsics(0, K);
  rig->GetTranslation(0, t);
  CheckEqual(K[0], 1520.4, "K[0] of view 0");
  CheckEqual(K[5], 246.87, "K[5] of view 0");
  CheckEqual(t[2], 0.52269561933, "t[2] of view 0");

  // A Middlebury calibration has no lens distortion.
  Check(!rig->HasDistortion(), "no lens distortion in the imported rig");
  CheckRing(rig);
  CheckOrientation(rig);
  return lfdtest::Result();
}
