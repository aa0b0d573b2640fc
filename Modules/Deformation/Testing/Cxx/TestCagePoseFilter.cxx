// vtkCagePoseFilter on the fish cage of vtkPartCageSource (paper Figs. 1
// and 13): a twist turns the last layer by exactly Angle about the axis and
// leaves the first; a swim turns layer k by Angle sin(Phase - k Wavelength)
// about the vertical and shifts it sideways; a bend turns the end layers
// Angle apart and places them on the arc; all of them validate; a turn axis
// parallel to the slab axis is refused.
#include "lfdDeformationTestUtilities.h"
#include "lfdPartCageTestMeshes.h"

#include "vtkCagePoseFilter.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkPartCageSource.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
using lfdtest::ErrorText;
using lfdtest::Near;

/// The turn in degrees of layer k (points 4k..4k+3 of a slab cage along x)
/// about `axis`: the rotation of its z edge (points 4k -> 4k+1).
double LayerAngle(vtkDeformationCage* cage, int k, const double axis[3])
{
  double r0[3], r1[3], d0[3], d1[3];
  cage->GetRestPoint(4 * k, r0);
  cage->GetRestPoint(4 * k + 1, r1);
  cage->GetDeformedPoint(4 * k, d0);
  cage->GetDeformedPoint(4 * k + 1, d1);
  const double rest[3] = { r1[0] - r0[0], r1[1] - r0[1], r1[2] - r0[2] };
  const double moved[3] = { d1[0] - d0[0], d1[1] - d0[1], d1[2] - d0[2] };
  double cross[3];
  vtkMath::Cross(rest, moved, cross);
  return vtkMath::DegreesFromRadians(
    std::atan2(vtkMath::Dot(cross, axis), vtkMath::Dot(rest, moved)));
}

/// The mean of the deformed (or rest) points of layer k.
void LayerCentre(vtkDeformationCage* cage, int k, bool rest, double centre[3])
{
  centre[0] = centre[1] = centre[2] = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    double p[3];
    if (rest)
    {
      cage->GetRestPoint(4 * k + i, p);
    }
    else
    {
      cage->GetDeformedPoint(4 * k + i, p);
    }
    for (int a = 0; a < 3; ++a)
    {
      centre[a] += 0.25 * p[a];
    }
  }
}

}

int TestCagePoseFilter(int, char*[])
{
  bool ok = true;
  vtkNew<vtkPartCageSource> source;
  source->SetInputData(lfdtest::MakeFishMesh());
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(source->GetOutputPort());
  const double xAxis[3] = { 1, 0, 0 };
  const double yAxis[3] = { 0, 1, 0 };

  // TWIST 45 (Fig. 1).
  pose->SetModeToTwist();
  pose->SetAngle(45.0);
  pose->Update();
  vtkDeformationCage* cage = pose->GetOutput();
  std::printf("twist: %d layers, %lld boxes\n",
    pose->GetNumberOfLayers(),
    static_cast<long long>(cage->GetNumberOfBoxes()));
  ok &= lfdtest::Check(pose->GetNumberOfLayers() == 4, "4 layers");
  ok &= lfdtest::Check(cage->GetNumberOfBoxes() == 3, "3 boxes");
  ok &= Near("twist of the last layer", LayerAngle(cage, 3, xAxis), 45.0);
  double first = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    double r[3], d[3];
    cage->GetRestPoint(i, r);
    cage->GetDeformedPoint(i, d);
    first = std::max(first, std::sqrt(vtkMath::Distance2BetweenPoints(r, d)));
  }
  ok &= Near("motion of the first layer", first, 0.0);
  double c3r[3], c3d[3];
  LayerCentre(cage, 3, true, c3r);
  LayerCentre(cage, 3, false, c3d);
  ok &= Near("the last layer turns about its centre",
    std::sqrt(vtkMath::Distance2BetweenPoints(c3r, c3d)),
    0.0);
  // The middle layers turn in proportion to their position along the axis.
  double r1[3], r3[3], r0[3];
  LayerCentre(cage, 0, true, r0);
  LayerCentre(cage, 1, true, r1);
  LayerCentre(cage, 3, true, r3);
  ok &=
    Near("twist of layer 1", LayerAngle(cage, 1, xAxis), 45.0 * (r1[0] - r0[0]) / (r3[0] - r0[0]));
  ok &= lfdtest::CheckValid(cage, "twist 45 validates");

  // SWIM 20 (Fig. 13): layer angles and sideways shifts over a swim cycle.
  pose->SetModeToSwim();
  pose->SetAngle(20.0);
  const double length = r3[0] - r0[0];
  for (int step = 0; step < 8; ++step)
  {
    const double phase = step * vtkMath::Pi() / 4.0;
    pose->SetPhase(phase);
    pose->Update();
    cage = pose->GetOutput();
    std::printf("swim phase %.4f\n", phase);
    for (int k = 0; k < 4; ++k)
    {
      const double wave = phase - k * 1.2;
      ok &= Near("  layer angle", LayerAngle(cage, k, yAxis), 20.0 * std::sin(wave));
      double rest[3], moved[3];
      LayerCentre(cage, k, true, rest);
      LayerCentre(cage, k, false, moved);
      // n = TurnAxis x Axis = y x x = -z.
      ok &=
        Near("  layer shift along -z", rest[2] - moved[2], 0.06 * length * std::sin(wave + 0.5));
      ok &= Near("  no shift along x", moved[0] - rest[0], 0.0);
    }
    ok &= lfdtest::CheckValid(cage, "swim 20 validates");
  }

  // BEND 90: end layers 90 degrees apart, centres on the arc.
  pose->SetModeToBend();
  pose->SetAngle(90.0);
  pose->Update();
  cage = pose->GetOutput();
  const double a0 = LayerAngle(cage, 0, yAxis), a3 = LayerAngle(cage, 3, yAxis);
  ok &= Near("bend: first layer", a0, -45.0);
  ok &= Near("bend: endpoints' angle difference", a3 - a0, 90.0);
  double e0[3], e3[3];
  LayerCentre(cage, 0, false, e0);
  LayerCentre(cage, 3, false, e3);
  const double radius = length / vtkMath::RadiansFromDegrees(90.0);
  ok &= Near("bend: chord between the end layers",
    std::sqrt(vtkMath::Distance2BetweenPoints(e0, e3)),
    2.0 * radius * std::sin(vtkMath::Pi() / 4));
  ok &= lfdtest::CheckValid(cage, "bend 90 validates");
  pose->SetAngle(-60.0);
  pose->Update();
  ok &= Near("bend -60: endpoints' angle difference",
    LayerAngle(pose->GetOutput(), 3, yAxis) - LayerAngle(pose->GetOutput(), 0, yAxis),
    -60.0);
  ok &= lfdtest::CheckValid(pose->GetOutput(), "bend -60 validates");

  // A turn axis along the slab axis cannot swim.
  pose->SetModeToSwim();
  pose->SetTurnAxis(1, 0, 0);
  vtkNew<vtkTest::ErrorObserver> observer;
  pose->AddObserver(vtkCommand::ErrorEvent, observer);
  vtkNew<vtkTest::ErrorObserver> pipelineObserver;
  pose->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineObserver);
  pose->Update();
  const std::string message = ErrorText(observer->GetErrorMessage());
  std::printf("parallel turn axis: error \"%s\"\n", message.c_str());
  ok &= lfdtest::Check(observer->GetError() && message.find("parallel") != std::string::npos,
    "a turn axis parallel to the slab axis is refused");

  std::printf("%s\n", ok ? "PASSED" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
