// Every refusal of vtkDeformationCage::Validate(), each with the box named in
// the message, and the cages it must accept.
#include "lfdDeformationTestUtilities.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkLightField.h"
#include "vtkTestErrorObserver.h"

#include <cstdlib>
#include <string>

namespace
{
/// Checks a refusal `message` of Validate() or ValidateBoxes(): one line
/// holding every one of `expected`.
bool CheckRefusal(const char* what,
  const std::string& message,
  std::initializer_list<const char*> expected)
{
  std::printf("%s: message \"%s\"\n", what, message.c_str());
  bool ok = lfdtest::Check(!message.empty(), "the cage is refused");
  ok &= lfdtest::Check(message.find('\n') == std::string::npos, "the message is one line");
  for (const char* fragment : expected)
  {
    if (message.find(fragment) == std::string::npos)
    {
      std::printf("FAILED: the message lacks \"%s\"\n", fragment);
      ok = false;
    }
  }
  return ok;
}

/// Validates `cage` expecting a refusal whose message holds every one of
/// `expected`; the cage, a data object, must report nothing itself.
bool ExpectRefusal(const char* what,
  vtkDeformationCage* cage,
  vtkLightField* lightField,
  std::initializer_list<const char*> expected)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long tag = cage->AddObserver(vtkCommand::ErrorEvent, observer);
  const std::string message = cage->Validate(lightField);
  cage->RemoveObserver(tag);
  bool ok = CheckRefusal(what, message, expected);
  ok &= lfdtest::Check(!observer->GetError(), "the cage raises no error event (the caller does)");
  return ok;
}

/// Two unit boxes, the second at x offset `dx` with its own points.
vtkSmartPointer<vtkDeformationCage> TwoBoxes(double dx)
{
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  auto cage = lfdtest::MakeBoxCage(lo, hi, 1);
  const double lo2[3] = { dx, 0.25, 0 }, hi2[3] = { dx + 1, 1.25, 1 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
  cage->AddBox(ids, 2);
  return cage;
}

constexpr double Lo[3] = { 0, 0, 0 }, Hi[3] = { 1, 1, 1 };

/// Cages Validate() must accept.
bool TestAccepted()
{
  bool ok = lfdtest::CheckValid(lfdtest::MakeBoxCage(Lo, Hi), "one unit box");
  ok &= lfdtest::CheckValid(TwoBoxes(1.0), "two boxes with coincident faces, separate points");
  ok &=
    lfdtest::CheckValid(lfdtest::MakeTwistedBox(vtkMath::Pi() / 4), "a twisted box (45 degrees)");
  vtkNew<vtkDeformationCage> empty;
  ok &= lfdtest::CheckValid(empty, "an empty cage");
  // A box on top of another, shifted by half a box: they share half a face.
  auto cage = lfdtest::MakeBoxCage(Lo, Hi, 1);
  const double lo2[3] = { 0.5, 1, 0 }, hi2[3] = { 1.5, 2, 1 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
  cage->AddBox(ids, 2);
  ok &= lfdtest::CheckValid(cage, "boxes sharing half a face");
  return ok;
}

/// Cells that are no boxes, labels out of 1..255, arrays missing.
bool TestBadCells()
{
  bool ok = true;
  // A corner index out of range: the second box names point 99 of 16.
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi);
    const vtkIdType corners[8] = { 1, 8, 9, 2, 5, 10, 99, 6 };
    const double lo2[3] = { 1, 0, 0 }, hi2[3] = { 2, 1, 1 };
    vtkIdType ids[8];
    lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
    cage->AddBox(corners, 4);
    ok &= ExpectRefusal("corner out of range",
      cage,
      nullptr,
      { "box 1 (label 4)", "corner 6 is point 99", "[0, 16)" });
  }

  // A cell that is not a hexahedron.
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi);
    const vtkIdType tetra[4] = { 0, 1, 3, 4 };
    cage->InsertNextCell(VTK_TETRA, 4, tetra);
    cage->GetCellData()->GetArray("Label")->InsertNextTuple1(2);
    ok &=
      ExpectRefusal("not a hexahedron", cage, nullptr, { "box 1 (label 2)", "not a hexahedron" });
  }

  // Labels out of 1..255.
  for (int label : { 0, 256, -3 })
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi, label);
    const std::string name = "box 0 (label " + std::to_string(label) + ")";
    ok &= ExpectRefusal("label out of range", cage, nullptr, { name.c_str(), "[1, 255]" });
  }

  // Arrays missing.
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi);
    cage->GetCellData()->RemoveArray("Label");
    ok &= ExpectRefusal("no Label array", cage, nullptr, { "\"Label\"" });
  }
  return ok;
}

/// Rest or deformed boxes whose trilinear map folds, collapses or inverts.
bool TestFolds()
{
  bool ok = true;
  // A deformed box that folds: corner 6 pushed through the box to (0.1, 0.1, 0.1).
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi, 9);
    const double through[3] = { 0.1, 0.1, 0.1 };
    cage->SetDeformedPoint(6, through);
    ok &= ExpectRefusal(
      "deformed box folds", cage, nullptr, { "box 0 (label 9)", "deformed box folds" });
  }

  // A rest box that folds (the deformed one is fine).
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi, 9);
    const double through[3] = { 0.1, 0.1, 0.1 };
    cage->SetRestPoint(6, through);
    cage->SetDeformedPoint(6, Hi);
    ok &= ExpectRefusal("rest box folds", cage, nullptr, { "box 0 (label 9)", "rest box folds" });
  }

  // A half turn collapses the middle section (w = 1/2) to the axis although
  // the Jacobian is fine at every corner.
  {
    auto cage = lfdtest::MakeTwistedBox(vtkMath::Pi());
    ok &= ExpectRefusal(
      "180 degree twist", cage, nullptr, { "box 0 (label 1)", "deformed box collapses" });
  }

  // A flat deformed box: the top face dropped onto the bottom one.
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi, 5);
    for (vtkIdType i = 4; i < 8; ++i)
    {
      double p[3];
      cage->GetRestPoint(i, p);
      p[2] = 0;
      cage->SetDeformedPoint(i, p);
    }
    ok &= ExpectRefusal("flat box", cage, nullptr, { "box 0 (label 5)", "deformed box collapses" });
  }

  // An inverted box: top and bottom faces swapped in the corner order.
  {
    auto cage = lfdtest::MakeBoxCage(Lo, Hi);
    const vtkIdType swapped[8] = { 4, 5, 6, 7, 0, 1, 2, 3 };
    auto inverted = vtkSmartPointer<vtkDeformationCage>::New();
    for (vtkIdType i = 0; i < 8; ++i)
    {
      double p[3];
      cage->GetRestPoint(i, p);
      inverted->AddPoint(p);
    }
    inverted->AddBox(swapped, 6);
    ok &= ExpectRefusal(
      "inverted box", inverted, nullptr, { "box 0 (label 6)", "rest box is inverted" });
  }
  return ok;
}

/// Rest boxes that overlap: by half a box, by a 0.01 sliver, nested.
bool TestOverlaps()
{
  bool ok = ExpectRefusal("overlap by 0.5",
    TwoBoxes(0.5),
    nullptr,
    { "box 1 (label 2) overlaps box 0 (label 1)", "in rest space" });
  ok &= ExpectRefusal(
    "overlap by 0.01", TwoBoxes(0.99), nullptr, { "box 1 (label 2) overlaps box 0 (label 1)" });
  auto cage = lfdtest::MakeBoxCage(Lo, Hi, 1);
  const double lo2[3] = { 0.4, 0.4, 0.4 }, hi2[3] = { 0.6, 0.6, 0.6 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
  cage->AddBox(ids, 3);
  ok &= ExpectRefusal("nested boxes", cage, nullptr, { "box 1 (label 3) overlaps box 0" });
  return ok;
}

/// Labels against the light field's: one that no ray carries, two on an
/// unsplit light field.
bool TestLabelsAgainstLightField()
{
  vtkNew<vtkLightField> lightField;
  lightField->SetLayout(4, 2, 1);
  // Unsplit, the light field is one part: boxes of two labels are refused,
  // boxes sharing one label (a lattice, a tessellation) are not.
  bool ok = ExpectRefusal("two labels, light field without a Label pass",
    TwoBoxes(1.0),
    lightField,
    { "box 0 (label 1) and box 1 (label 2)", "no Label pass", "split it first (lfd split" });
  auto sameLabel = TwoBoxes(1.0);
  sameLabel->GetCellData()->GetArray("Label")->SetComponent(1, 0, 1);
  ok &= lfdtest::CheckValid(
    sameLabel, "one label in two boxes, light field without a Label pass", lightField);
  vtkDataArray* labels = lightField->AllocatePass(vtkLightField::LABEL);
  labels->SetComponent(3, 0, 1);
  labels->SetComponent(5, 0, 7);
  ok &= ExpectRefusal("label without sub-light field",
    TwoBoxes(1.0),
    lightField,
    { "box 1 (label 2)", "no sub-light field 2" });
  labels->SetComponent(6, 0, 2);
  labels->Modified(); // edited in place: as for GetRange(), say so
  ok &= lfdtest::CheckValid(TwoBoxes(1.0), "labels 1 and 2 in the Label pass", lightField);
  return ok;
}

/// ValidateBoxes(): the checks of the listed boxes only, with the messages
/// of Validate(); the overlaps of a listed box with every other box.
bool TestValidateBoxes()
{
  const auto boxes = [](std::initializer_list<vtkIdType> ids)
  {
    vtkSmartPointer<vtkIdList> list = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType id : ids)
    {
      list->InsertNextId(id);
    }
    return list;
  };
  // Boxes 0 and 1 overlap by half a box; box 2 (label 3) lies apart.
  auto cage = TwoBoxes(0.5);
  const double lo3[3] = { 5, 0, 0 }, hi3[3] = { 6, 1, 1 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(cage, lo3, hi3, ids);
  cage->AddBox(ids, 3);
  const std::string overlap = cage->Validate();
  bool ok = CheckRefusal(
    "Validate: boxes 0 and 1 overlap", overlap, { "box 1 (label 2) overlaps box 0 (label 1)" });
  ok &= lfdtest::Check(
    cage->ValidateBoxes(boxes({ 1 })) == overlap && cage->ValidateBoxes(boxes({ 0 })) == overlap,
    "ValidateBoxes of box 0 or of box 1 gives Validate's message");
  const std::string alone = cage->ValidateBoxes(boxes({ 2, 2 }));
  std::printf("ValidateBoxes of box 2: \"%s\"\n", alone.c_str());
  ok &= lfdtest::Check(alone.empty(), "box 2 validates (the overlap of boxes 0 and 1 is not its)");
  ok &=
    lfdtest::Check(cage->ValidateBoxes(boxes({})).empty() && cage->ValidateBoxes(nullptr).empty(),
      "no boxes listed: nothing to refuse");

  // Box 2's deformed corner 6 pushed through it: it folds.
  const double through[3] = { 5.1, 0.1, 0.1 };
  cage->SetDeformedPoint(ids[6], through);
  const std::string fold = cage->Validate();
  ok &= CheckRefusal("Validate: the fold of box 2 before any overlap",
    fold,
    { "box 2 (label 3)", "deformed box folds" });
  ok &= lfdtest::Check(
    cage->ValidateBoxes(boxes({ 2 })) == fold && cage->ValidateBoxes(boxes({ 0, 2 })) == fold,
    "ValidateBoxes of box 2 (and 0) gives Validate's message");
  ok &= lfdtest::Check(cage->ValidateBoxes(boxes({ 1 })) == overlap,
    "ValidateBoxes of box 1 ignores the fold of box 2");
  ok &= CheckRefusal("ValidateBoxes of a box that does not exist",
    cage->ValidateBoxes(boxes({ 0, 7 })),
    { "cage: box 7 does not exist (the cage has 3 boxes)" });
  cage->GetCellData()->RemoveArray("Label");
  ok &= CheckRefusal("ValidateBoxes without the Label array",
    cage->ValidateBoxes(boxes({ 2 })),
    { "\"Label\" is missing" });
  return ok;
}
} // namespace

int TestDeformationCageValidation(int, char*[])
{
  bool ok = TestAccepted();
  ok &= TestBadCells();
  ok &= TestFolds();
  ok &= TestOverlaps();
  ok &= TestLabelsAgainstLightField();
  ok &= TestValidateBoxes();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
