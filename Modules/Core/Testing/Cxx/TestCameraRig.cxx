// Cylinder fit of vtkCameraRig: a noisy, tilted synthetic ring with a
// near-duplicate and a view rolled by 180 degrees, a three-row rig, rows
// found at every count, spacing and radius (and uneven, noisy rows), the fit
// made once and cached by the rig's modification time (reading the layout
// neither fits nor modifies the rig), and the refusal of a degenerate rig.
#include "lfdCylinderSampling.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkIdList.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using lfdtest::Check;

namespace
{
// A camera at `position` looking at `target`, image up along `up`.
void SetLookAt(vtkCameraRig* rig,
  int view,
  const double position[3],
  const double target[3],
  const double up[3])
{
  glm::dmat3 K(1.0);
  K[0][0] = K[1][1] = 500.0;
  K[2][0] = 319.5;
  K[2][1] = 239.5;
  const glm::dvec3 p(position[0], position[1], position[2]);
  const glm::dvec3 f = glm::dvec3(target[0], target[1], target[2]) - p;
  rig->SetView(view, lfd::PinholeCamera::LookAt(K, p, f, glm::dvec3(up[0], up[1], up[2])));
}

/// A tilted ring of 60 cameras: fit, duplicates, azimuths, layout, and the fit
/// cached until the rig changes. False when the fit is refused.
bool TestNoisyRing()
{
  // A tilted ring of 60 cameras, 1 cm noise on a 5 m radius, plus a near
  // duplicate of view 7 and a copy of view 20 rolled by 180 degrees.
  const double center[3] = { 1.0, 2.0, 3.0 };
  double axis[3] = { 0.2, 1.0, 0.1 };
  vtkMath::Normalize(axis);
  double u[3], v[3];
  vtkMath::Perpendiculars(axis, u, v, 0.0);
  const double radius = 5.0;
  const int ring = 60;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);

  vtkNew<vtkCameraRig> rig;
  rig->SetImageSize(640, 480);
  rig->SetNumberOfViews(ring + 2);
  double positions[ring][3];
  for (int i = 0; i < ring; ++i)
  {
    const double phi = 2.0 * vtkMath::Pi() * i / ring;
    for (int c = 0; c < 3; ++c)
    {
      positions[i][c] =
        center[c] + radius * (std::cos(phi) * u[c] + std::sin(phi) * v[c]) + noise(rng);
    }
    SetLookAt(rig, i, positions[i], center, axis);
  }
  double nearDuplicate[3] = { positions[7][0] + 0.002, positions[7][1], positions[7][2] };
  SetLookAt(rig, ring, nearDuplicate, center, axis);
  const double down[3] = { -axis[0], -axis[1], -axis[2] };
  SetLookAt(rig, ring + 1, positions[20], center, down);

  // Set up view by view: no fit until FitCylinder(), and reading the
  // layout does not fit (or modify) the rig.
  const vtkMTimeType unfittedTime = rig->GetMTime();
  const bool noLayout = !rig->HasCylinder() && rig->GetRingLayout().Rows.empty();
  Check(noLayout && rig->GetMTime() == unfittedTime && !rig->HasCylinder(),
    "no fit, no layout, no modification before FitCylinder",
    static_cast<double>(rig->GetMTime() - unfittedTime),
    0);
  if (!rig->FitCylinder())
  {
    std::cout << "FAIL FitCylinder refused a valid ring\n";
    return false;
  }
  const double angle =
    vtkMath::DegreesFromRadians(std::acos(std::min(1.0, vtkMath::Dot(rig->GetAxis(), axis))));
  Check(angle < 0.5, "axis error (degrees)", angle, 0.5);
  const double centerError = std::sqrt(vtkMath::Distance2BetweenPoints(rig->GetCenter(), center));
  Check(centerError < 0.02, "centre error", centerError, 0.02);
  Check(std::abs(rig->GetRadius() - radius) < 0.01,
    "radius error",
    std::abs(rig->GetRadius() - radius),
    0.01);
  Check(rig->GetFitResidual() < 0.03, "RMS residual", rig->GetFitResidual(), 0.03);
  Check(rig->GetNumberOfRows() == 1, "rows", rig->GetNumberOfRows(), 1);
  Check(rig->GetNumberOfDuplicates() == 2, "duplicates", rig->GetNumberOfDuplicates(), 2);
  Check(rig->GetDuplicateOf(ring) == 7, "duplicate of view 60", rig->GetDuplicateOf(ring), 7);
  Check(
    rig->GetDuplicateOf(ring + 1) == 20, "duplicate of view 61", rig->GetDuplicateOf(ring + 1), 20);
  Check(rig->GetDuplicateOf(5) == -1, "view 5 is no duplicate", rig->GetDuplicateOf(5), -1);

  // Azimuths follow the ring order, starting at 0 on view 0.
  double maxStepError = 0.0;
  for (int i = 1; i < ring; ++i)
  {
    const double step = rig->GetAzimuth(i) - rig->GetAzimuth(i - 1);
    maxStepError = std::max(maxStepError, std::abs(std::abs(step) - 2.0 * vtkMath::Pi() / ring));
  }
  Check(maxStepError < 0.01, "azimuth step error (rad)", maxStepError, 0.01);
  Check(rig->GetAzimuth(0) == 0.0, "azimuth of view 0", rig->GetAzimuth(0), 0.0);

  // The sampling layout leaves duplicates out; leave-one-out of view 7 also
  // removes its duplicate.
  lfd::RingLayout layout = rig->GetRingLayout();
  Check(layout.Rows.size() == 1 && layout.Rows[0].View.size() == ring,
    "views in layout",
    static_cast<double>(layout.Rows[0].View.size()),
    ring);
  layout = rig->GetRingLayout({ ring });
  Check(layout.Rows[0].View.size() == ring - 1,
    "views in layout without view 60's group",
    static_cast<double>(layout.Rows[0].View.size()),
    ring - 1);

  // The fit is cached by the modification time: a copy keeps it, any change
  // makes it stale until the next FitCylinder().
  vtkNew<vtkCameraRig> copy;
  copy->DeepCopy(rig);
  Check(copy->HasCylinder() && copy->GetNumberOfDuplicates() == 2,
    "a deep copy keeps the fit",
    copy->GetNumberOfDuplicates(),
    2);
  copy->SetMinimumRowGap(0.1);
  Check(!copy->HasCylinder() && copy->GetNumberOfRows() == 0 && copy->GetRingLayout().Rows.empty(),
    "a changed tolerance makes the fit stale",
    copy->GetNumberOfRows(),
    0);
  SetLookAt(rig, 3, positions[3], center, axis);
  Check(!rig->HasCylinder(), "a changed view makes the fit stale", rig->HasCylinder(), 0);
  Check(rig->FitCylinder() && rig->HasCylinder() && rig->GetNumberOfDuplicates() == 2,
    "fitted again",
    rig->GetNumberOfDuplicates(),
    2);
  return true;
}

/// Three rows from MakeCylinder, fitted as they are built.
void TestRows()
{
  vtkNew<vtkCameraRig> rows;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double yAxis[3] = { 0.0, 1.0, 0.0 };
  const double heights[3] = { -0.5, 0.0, 0.5 };
  rows->MakeCylinder(origin, yAxis, 3.0, 40, 3, heights, 64, 64, 30.0);
  Check(rows->HasCylinder(), "MakeCylinder fits what it builds", rows->HasCylinder(), 1);
  Check(rows->GetNumberOfViews() == 120, "views", rows->GetNumberOfViews(), 120);
  Check(rows->GetNumberOfRows() == 3, "rows", rows->GetNumberOfRows(), 3);
  Check(std::abs(rows->GetRadius() - 3.0) < 1e-9, "radius error", rows->GetRadius() - 3.0, 1e-9);
  Check(std::abs(rows->GetRowHeight(2) - 0.5) < 1e-9, "row 2 height", rows->GetRowHeight(2), 0.5);
  Check(rows->GetNumberOfDuplicates() == 0, "duplicates", rows->GetNumberOfDuplicates(), 0);
  Check(rows->GetAxis()[1] > 0.999999, "axis +Y", rows->GetAxis()[1], 1.0);
  vtkNew<vtkIdList> sorted;
  rows->GetSortedViews(sorted);
  Check(sorted->GetNumberOfIds() == 120 && sorted->GetId(0) == 0 && sorted->GetId(40) == 40,
    "sorted views",
    static_cast<double>(sorted->GetId(40)),
    40);
  double c0[3];
  rows->GetCameraCenter(0, c0);
  Check(std::abs(c0[2] - 3.0) < 1e-12 && std::abs(c0[1] + 0.5) < 1e-12,
    "view 0 at +Z of the lowest row",
    c0[2],
    3.0);

  double zero[3], quarter[3];
  rows->GetAzimuthFrame(zero, quarter);
  Check(zero[2] > 1.0 - 1e-12 && quarter[0] > 1.0 - 1e-12, "azimuth frame +Z, +X", zero[2], 1.0);
}

/// Rows told apart at any spacing (issue 11: a spacing equal to the old
/// fixed tolerance of 0.05 x radius merged rows): 1, 2, 3, 5, 7 and 11 rows
/// at spacings from 0.2 % to 100 % of radii from 0.1 to 250, evenly spaced
/// or not, exact or with noise; a noisy single ring stays one row.
void TestRowCounts()
{
  const double center[3] = { 0.5, -1.0, 2.0 };
  double axis[3] = { 0.1, 1.0, -0.2 };
  vtkMath::Normalize(axis);
  const int counts[] = { 1, 2, 3, 5, 7, 11 };
  // x radius; from a fifth of the duplicate tolerance (views of two rows
  // are never near-duplicates, however close) to a whole radius.
  const double spacings[] = { 0.002, 0.05, 0.2, 1.0 };
  const double radii[] = { 0.1, 3.0, 250.0 };
  const int ring = 24;
  int wrong = 0;
  int rigs = 0;
  for (int rows : counts)
  {
    for (double spacing : spacings)
    {
      for (double radius : radii)
      {
        std::vector<double> heights(rows);
        for (int r = 0; r < rows; ++r)
        {
          heights[r] = (r - 0.5 * (rows - 1)) * spacing * radius;
        }
        vtkNew<vtkCameraRig> rig;
        rig->MakeCylinder(center, axis, radius, ring, rows, heights.data(), 32, 32, 30.0);
        const lfd::RingLayout layout = rig->GetRingLayout();
        bool ok = rig->HasCylinder() && rig->GetNumberOfRows() == rows &&
          static_cast<int>(layout.Rows.size()) == rows;
        for (int r = 0; ok && r < rows; ++r)
        {
          ok = static_cast<int>(layout.Rows[r].View.size()) == ring &&
            std::abs(rig->GetRowHeight(r) - heights[r]) < 1e-9 * radius;
          for (int k = 0; ok && k < ring; ++k)
          {
            ok = rig->GetRow(r * ring + k) == r;
          }
        }
        ++rigs;
        if (!ok)
        {
          ++wrong;
          std::cout << "     " << rows << " rows " << spacing << " x radius " << radius
                    << " apart: found " << rig->GetNumberOfRows() << ", row 0 at "
                    << rig->GetRowHeight(0) << " (built at " << heights[0] << ")\n";
        }
      }
    }
  }
  Check(wrong == 0, "rigs with the wrong rows (of 72: 6 counts x 4 spacings x 3 radii)", wrong, 0);
  Check(rigs == 72, "rigs tried", rigs, 72);

  // Uneven rows (0.1 to 0.8 radius apart) with 0.2 % radius noise on the
  // centres, and 5 views of a sixth row: 6 rows of 30, 30, 30, 30, 30, 5.
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.002);
  const double uneven[6] = { -1.0, -0.2, 0.0, 0.1, 0.9, 1.5 };
  vtkNew<vtkCameraRig> rig;
  rig->SetImageSize(32, 32);
  rig->SetNumberOfViews(5 * 30 + 5);
  const double yAxis[3] = { 0.0, 1.0, 0.0 };
  int view = 0;
  for (int r = 0; r < 6; ++r)
  {
    const int views = r < 5 ? 30 : 5;
    for (int k = 0; k < views; ++k, ++view)
    {
      const double phi = 2.0 * vtkMath::Pi() * k / views;
      const double p[3] = {
        std::cos(phi) + noise(rng), uneven[r] + noise(rng), std::sin(phi) + noise(rng)
      };
      const double target[3] = { 0.0, uneven[r], 0.0 };
      SetLookAt(rig, view, p, target, yAxis);
    }
  }
  const bool fitted = rig->FitCylinder();
  const lfd::RingLayout layout = rig->GetRingLayout();
  bool ok = fitted && rig->GetNumberOfRows() == 6 && layout.Rows.size() == 6;
  for (int r = 0; ok && r < 6; ++r)
  {
    ok = layout.Rows[r].View.size() == (r < 5 ? 30u : 5u);
  }
  Check(ok, "uneven noisy rows found (6)", rig->GetNumberOfRows(), 6);

  // Rows closer than their own noise are one row: 2 rows 0.002 apart with
  // 0.002 noise.
  for (int k = 0; k < 60; ++k)
  {
    const double phi = 2.0 * vtkMath::Pi() * k / 30;
    const double h = k < 30 ? 0.0 : 0.002;
    const double p[3] = { std::cos(phi) + noise(rng), h + noise(rng), std::sin(phi) + noise(rng) };
    const double target[3] = { 0.0, h, 0.0 };
    SetLookAt(rig, k, p, target, yAxis);
  }
  rig->SetNumberOfViews(60);
  const bool refitted = rig->FitCylinder();
  Check(refitted && rig->GetNumberOfRows() == 1,
    "rows within the noise are one row",
    rig->GetNumberOfRows(),
    1);
}

/// A degenerate rig is refused with one error line.
void TestDegenerate()
{
  const double yAxis[3] = { 0.0, 1.0, 0.0 };
  vtkNew<vtkCameraRig> line;
  line->SetNumberOfViews(3);
  for (int i = 0; i < 3; ++i)
  {
    const double p[3] = { static_cast<double>(i), 0.0, 0.0 };
    const double target[3] = { static_cast<double>(i), 0.0, 1.0 };
    SetLookAt(line, i, p, target, yAxis);
  }
  vtkNew<vtkLightFieldErrorObserver> observer;
  observer->Observe(line);
  const std::string expected = "FitCylinder: the camera centres are collinear or coincide; no "
                               "ring can be fitted to them.";
  const bool refused = !line->FitCylinder() && observer->GetNumberOfErrors() == 1 &&
    observer->GetErrorMessage() == expected && !line->HasCylinder();
  Check(refused, "collinear rig refused with one line", refused, 1);
  std::cout << "     message: " << observer->GetErrorMessage() << "\n";
  std::string problem;
  const bool quiet = !line->FitCylinder(problem) && observer->GetNumberOfErrors() == 1 &&
    "FitCylinder: " + problem == expected;
  Check(quiet, "FitCylinder(problem) says why without reporting", quiet, 1);
}
}

int TestCameraRig(int, char*[])
{
  if (!TestNoisyRing())
  {
    return EXIT_FAILURE;
  }
  TestRows();
  TestRowCounts();
  TestDegenerate();
  return lfdtest::Result();
}
