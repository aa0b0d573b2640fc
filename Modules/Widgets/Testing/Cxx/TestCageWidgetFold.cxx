// In standalone mode (ApplyToCage on) a drag that would fold a box is
// clamped: after every step of the drag the cage is valid, and the corner
// stops short of where the cursor would take it.
#include "lfdCageWidgetTestUtilities.h"

namespace
{
struct ValidityProbe
{
  vtkDeformationCage* Cage;
  int Steps = 0;
  int Invalid = 0;
};
}

int TestCageWidgetFold(int, char*[])
{
  vtkNew<vtkDeformationCage> cage;
  lfdtest::MakeGridCage(cage, 1, 1, 1);
  const double focal[3] = { 0.5, 0.5, 0.5 };
  const double position[3] = { 0.5, 0.5, 10.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  lfdtest::WidgetScene scene(cage, focal, position, up, true, 1.5);

  ValidityProbe probe{ cage };
  vtkNew<vtkCallbackCommand> validate;
  validate->SetClientData(&probe);
  validate->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*)
    {
      ValidityProbe* p = static_cast<ValidityProbe*>(data);
      ++p->Steps;
      p->Invalid += p->Cage->Validate().empty() ? 0 : 1;
    });
  scene.Widget->AddObserver(vtkCommand::InteractionEvent, validate);

  // Point 4 = (0, 0, 1), in front of point 0 in this view, dragged across
  // the box to (1.8, 1.8, 1). At (0.5, 0.5, 1) it is in line with its
  // neighbours 5 and 7, where the box's Jacobian vanishes: the clamp.
  double p4[3], d4[3];
  cage->GetDeformedPoint(4, p4);
  scene.ToDisplay(p4, d4);
  const int x0 = static_cast<int>(std::lround(d4[0]));
  const int y0 = static_cast<int>(std::lround(d4[1]));
  const int pixels = static_cast<int>(std::lround(1.8 * 400 / 3.0));
  scene.Play(lfdtest::Drag(x0, y0, x0 + pixels, y0 + pixels, 10));

  int failures = 0;
  double p[3];
  cage->GetDeformedPoint(4, p);
  std::cout << "corner 4 stopped at (" << p[0] << ", " << p[1] << ", " << p[2] << ") after "
            << probe.Steps << " steps\n";
  if (lfdtest::SelectedIds(scene.Representation) != "4")
  {
    std::cerr << "the drag grabbed " << lfdtest::SelectedIds(scene.Representation)
              << ", expected 4\n";
    ++failures;
  }
  if (probe.Steps != 10 || probe.Invalid != 0)
  {
    std::cerr << probe.Invalid << " of " << probe.Steps << " drag steps left a folded cage\n";
    ++failures;
  }
  if (!cage->Validate().empty() || !(p[0] > 0.49 && p[0] < 0.5 && std::abs(p[0] - p[1]) < 1e-9) ||
    p[2] != 1.0)
  {
    std::cerr << "corner 4 should stop on the drag's line just short of (0.5, 0.5, 1): "
              << cage->Validate() << "\n";
    ++failures;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
