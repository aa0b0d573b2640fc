// The representation's numeric API: each edit is one interaction (relayed
// by the widget), moves exactly the points it should to exactly where the
// transform puts them, and in standalone mode refuses a move that folds a
// box; with ApplyToCage off the cage is untouched and the proposal exposed.
#include "lfdCageWidgetTestUtilities.h"

#include "vtkLightFieldErrorObserver.h"
#include "vtkPoints.h"

#include <vector>

using lfdtest::Check;

namespace
{
/// Points of `ids` must be `expected` (3 per id), the others at `others`.
void CheckPoints(vtkDeformationCage* cage,
  const std::vector<vtkIdType>& ids,
  const std::vector<double>& expected,
  double tolerance,
  const char* what)
{
  for (size_t k = 0; k < ids.size(); ++k)
  {
    Check(lfdtest::CheckPoint(cage, ids[k], &expected[3 * k], tolerance, what), what);
  }
}

void Rest(vtkDeformationCage* cage, vtkIdType id, double p[3])
{
  cage->GetRestPoint(id, p);
}

void TestTransforms(vtkCageWidget* widget, vtkCageRepresentation* rep, vtkDeformationCage* cage)
{
  lfdtest::InteractionCounter events(widget);
  rep->SelectBox(1);
  Check(lfdtest::SelectedIds(rep) == "1 2 4 5 7 8 10 11", "SelectBox(1)");
  const std::vector<vtkIdType> box1 = { 1, 2, 4, 5, 7, 8, 10, 11 };
  const double d[3] = { 0.1, 0.2, -0.05 };
  Check(rep->TranslateSelection(d[0], d[1], d[2]), "TranslateSelection accepted");
  std::vector<double> expected;
  for (vtkIdType id : box1)
  {
    double r[3];
    Rest(cage, id, r);
    expected.insert(expected.end(), { r[0] + d[0], r[1] + d[1], r[2] + d[2] });
  }
  CheckPoints(cage, box1, expected, 0.0, "translated");
  Check(events.Summary() == "1 1 1", "a translation is one interaction: " + events.Summary());
  vtkNew<vtkIdList> moved;
  rep->GetMovedPointIds(moved);
  Check(moved->GetNumberOfIds() == 8, "8 moved points");

  // A quarter turn of box 1 about its centre folds box 0: refused, no event.
  rep->SetPivotModeToBoxCentre();
  const double z[3] = { 0.0, 0.0, 1.0 };
  events.Reset();
  Check(!rep->RotateSelection(z, 90.0), "a folding rotation is refused");
  CheckPoints(cage, box1, expected, 0.0, "unchanged after the refused rotation");
  Check(events.Summary() == "0 0 0", "a refused edit fires nothing: " + events.Summary());
  Check(cage->Validate().empty(), "the cage stays valid: " + cage->Validate());

  // 10 degrees about the box centre is fine.
  double centre[3];
  Check(rep->GetPivot(centre), "box-centre pivot");
  Check(std::abs(centre[0] - 1.6) < 1e-12 && std::abs(centre[1] - 0.7) < 1e-12 &&
      std::abs(centre[2] - 0.45) < 1e-12,
    "the pivot is box 1's centre");
  Check(rep->RotateSelection(z, 10.0), "a 10 degree rotation is accepted");
  const double c = std::cos(vtkMath::RadiansFromDegrees(10.0));
  const double s = std::sin(vtkMath::RadiansFromDegrees(10.0));
  for (size_t k = 0; k < box1.size(); ++k)
  {
    const double x = expected[3 * k] - centre[0], y = expected[3 * k + 1] - centre[1];
    expected[3 * k] = centre[0] + c * x - s * y;
    expected[3 * k + 1] = centre[1] + s * x + c * y;
  }
  CheckPoints(cage, box1, expected, 1e-12, "rotated");

  // Scale about a chosen point.
  rep->SetPivotModeToPoint();
  rep->SetPivotPoint(1.0, 0.0, 0.0);
  Check(rep->ScaleSelection(1.2, 1.0, 0.9), "ScaleSelection accepted");
  for (size_t k = 0; k < box1.size(); ++k)
  {
    expected[3 * k] = 1.0 + 1.2 * (expected[3 * k] - 1.0);
    expected[3 * k + 2] = 0.9 * expected[3 * k + 2];
  }
  CheckPoints(cage, box1, expected, 1e-12, "scaled");

  // Reset box 1 back to rest; taper its outer face (1: x = 2) by half.
  events.Reset();
  Check(rep->ResetBox(1), "ResetBox");
  Check(!cage->IsDeformed(), "ResetBox puts the box back at rest");
  Check(rep->TaperFace(1, 1, 0.5), "TaperFace");
  Check(events.Summary() == "2 2 2", "reset + taper are two interactions: " + events.Summary());
  const std::vector<vtkIdType> face = { 2, 5, 8, 11 };
  expected.clear();
  for (vtkIdType id : face)
  {
    double r[3];
    Rest(cage, id, r);
    expected.insert(expected.end(), { r[0], 0.5 + 0.5 * (r[1] - 0.5), 0.5 + 0.5 * (r[2] - 0.5) });
  }
  CheckPoints(cage, face, expected, 1e-12, "tapered");
  rep->SelectAll();
  Check(rep->ResetSelection() && !cage->IsDeformed(), "ResetSelection");
}

void TestMirror(vtkCageRepresentation* rep, vtkDeformationCage* cage)
{
  // Point 2 (2, 0, 0) mirrors across x = 1 onto point 0 (0, 0, 0).
  rep->SelectPoint(2, false);
  Check(rep->TranslateSelection(0.1, -0.1, 0.05), "move point 2");
  const double origin[3] = { 1.0, 0.0, 0.0 }, normal[3] = { 1.0, 0.0, 0.0 };
  Check(rep->MirrorSelection(origin, normal), "MirrorSelection");
  const double mirrored[3] = { -0.1, -0.1, 0.05 };
  Check(lfdtest::CheckPoint(cage, 0, mirrored, 1e-15, "mirror image"), "mirror");
  // Both selected: the normal's side (point 2) is the source.
  rep->SelectPoint(0, false);
  rep->TranslateSelection(0.0, 0.0, 0.3);
  rep->SelectPoint(2, true);
  Check(lfdtest::SelectedIds(rep) == "0 2", "shift-selection of 0 and 2");
  Check(rep->MirrorSelection(origin, normal), "MirrorSelection of a pair");
  Check(lfdtest::CheckPoint(cage, 0, mirrored, 1e-15, "pair mirror"), "pair mirror");
  // A point on the plane has no image to change.
  rep->SelectPoint(1, false);
  Check(!rep->MirrorSelection(origin, normal), "a point on the plane moves nothing");
  rep->SelectAll();
  rep->ResetSelection();
}

void TestBend()
{
  // A bar of 4 boxes along X bent by 60 degrees about Z.
  vtkNew<vtkDeformationCage> bar;
  lfdtest::MakeGridCage(bar, 4, 1, 1);
  vtkNew<vtkCageRepresentation> rep;
  rep->SetCage(bar);
  rep->SelectAll();
  Check(rep->Bend(2, 60.0), "Bend accepted");
  Check(bar->Validate().empty(), "the bent bar is valid: " + bar->Validate());
  // Mirror symmetric about x = 2; the ends turn by +-30 degrees towards +Y.
  // Grid point (i, j, k) is (k * 2 + j) * 5 + i.
  for (int i = 0; i <= 4; ++i)
  {
    double left[3], right[3];
    bar->GetDeformedPoint(i, left);
    bar->GetDeformedPoint(4 - i, right);
    Check(std::abs(left[0] + right[0] - 4.0) < 1e-9 && std::abs(left[1] - right[1]) < 1e-9,
      "bend symmetric about the middle at i = " + std::to_string(i));
  }
  double a[3], b[3], middle[3];
  bar->GetDeformedPoint(4, a);
  bar->GetDeformedPoint(9, b);
  bar->GetDeformedPoint(2, middle);
  const double angle = vtkMath::DegreesFromRadians(std::atan2(-(b[0] - a[0]), b[1] - a[1]));
  std::cout << "end of the bent bar turned by " << angle << " degrees (30 expected)\n";
  Check(std::abs(angle - 30.0) < 1.0, "the right end turns by 30 degrees");
  Check(a[1] > middle[1] + 0.1, "the ends bend towards +Y");
}

void TestProposal(vtkCageWidget* widget, vtkCageRepresentation* rep, vtkDeformationCage* cage)
{
  rep->SetApplyToCage(false);
  rep->SelectPoint(0, false);
  Check(rep->TranslateSelection(1.0, 0.0, 0.0), "a proposal");
  Check(!cage->IsDeformed(), "ApplyToCage off leaves the cage alone");
  vtkNew<vtkIdList> ids;
  vtkNew<vtkPoints> positions;
  rep->GetMovedPointIds(ids);
  rep->GetMovedPositions(positions);
  Check(ids->GetNumberOfIds() == 1 && ids->GetId(0) == 0 && positions->GetNumberOfPoints() == 1 &&
      positions->GetPoint(0)[0] == 1.0 && positions->GetPoint(0)[1] == 0.0,
    "the proposal: point 0 at (1, 0, 0)");
  double handle[3];
  rep->GetHandlePosition(0, handle);
  Check(handle[0] == 1.0, "the handle shows the proposal");
  rep->UpdateFromCage();
  rep->GetHandlePosition(0, handle);
  Check(handle[0] == 0.0, "UpdateFromCage puts the handle back");

  // An owner that refuses every proposal: the edit reports it.
  vtkNew<vtkCallbackCommand> refuse;
  refuse->SetClientData(rep);
  refuse->SetCallback([](vtkObject*, unsigned long, void* r, void*)
    { static_cast<vtkCageRepresentation*>(r)->UpdateFromCage(); });
  const unsigned long tag = widget->AddObserver(vtkCommand::InteractionEvent, refuse);
  Check(!rep->TranslateSelection(1.0, 0.0, 0.0), "a refused proposal returns false");
  widget->RemoveObserver(tag);
  rep->SetApplyToCage(true);
}
}

int TestCageWidgetEdits(int, char*[])
{
  vtkNew<vtkDeformationCage> cage;
  lfdtest::MakeGridCage(cage, 2, 1, 1);
  vtkNew<vtkCageWidget> widget;
  widget->CreateDefaultRepresentation();
  vtkCageRepresentation* rep = widget->GetCageRepresentation();
  rep->SetCage(cage);

  TestTransforms(widget, rep, cage);
  TestMirror(rep, cage);
  TestBend();
  TestProposal(widget, rep, cage);

  // Bad indices: one error naming them, nothing changes.
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(rep);
  rep->SelectPoint(0, false);
  rep->SelectBox(5);
  Check(std::string(errors->GetErrorMessage()) == "Box 5 does not exist (the cage has 2 boxes).",
    std::string("SelectBox(5) error: ") + errors->GetErrorMessage());
  Check(lfdtest::SelectedIds(rep) == "0", "a bad box leaves the selection");
  Check(!rep->TwistFace(0, 6, 10.0), "face 6 is refused");
  Check(errors->GetNumberOfErrors() == 2, "one error per bad call");
  std::ostringstream printed;
  widget->Print(printed);
  rep->Print(printed);
  Check(printed.str().find("NumberOfSelectedPoints: 1") != std::string::npos &&
      printed.str().find("KeyboardBindings: 1") != std::string::npos,
    "PrintSelf");
  return lfdtest::Result();
}
