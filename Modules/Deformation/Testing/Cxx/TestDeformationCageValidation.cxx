// Every refusal of vtkDeformationCage::Validate(), each with the box named in
// the message, and the cages it must accept.
#include "lfdDeformationTestUtilities.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkLightField.h"
#include "vtkTestErrorObserver.h"

#include <cstdlib>
#include <string>

namespace
{
/// Validates `cage` expecting a refusal whose message holds every one of
/// `expected` (up to 3 fragments); the error must reach the observer.
bool ExpectRefusal(const char* what,
  vtkDeformationCage* cage,
  vtkLightField* lightField,
  std::initializer_list<const char*> expected)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long tag = cage->AddObserver(vtkCommand::ErrorEvent, observer);
  const bool valid = cage->Validate(lightField);
  cage->RemoveObserver(tag);
  const std::string message = cage->GetErrorMessage();
  std::printf("%s: valid %d, message \"%s\"\n", what, valid ? 1 : 0, message.c_str());
  bool ok = lfdtest::Check(!valid, "the cage is refused");
  ok &= lfdtest::Check(observer->GetError(), "the refusal is reported as a VTK error");
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

bool ExpectValid(const char* what, vtkDeformationCage* cage, vtkLightField* lightField = nullptr)
{
  const bool valid = cage->Validate(lightField);
  std::printf("%s: valid %d %s\n", what, valid ? 1 : 0, cage->GetErrorMessage());
  return lfdtest::Check(valid && std::string(cage->GetErrorMessage()).empty(), what);
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
} // namespace

int TestDeformationCageValidation(int, char*[])
{
  bool ok = true;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };

  ok &= ExpectValid("one unit box", lfdtest::MakeBoxCage(lo, hi));
  ok &= ExpectValid("two boxes with coincident faces, separate points", TwoBoxes(1.0));
  ok &= ExpectValid("a twisted box (45 degrees)", lfdtest::MakeTwistedBox(vtkMath::Pi() / 4));
  vtkNew<vtkDeformationCage> empty;
  ok &= ExpectValid("an empty cage", empty);

  // A corner index out of range: the second box names point 99 of 16.
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi);
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
    auto cage = lfdtest::MakeBoxCage(lo, hi);
    const vtkIdType tetra[4] = { 0, 1, 3, 4 };
    cage->InsertNextCell(VTK_TETRA, 4, tetra);
    cage->GetCellData()->GetArray("Label")->InsertNextTuple1(2);
    ok &=
      ExpectRefusal("not a hexahedron", cage, nullptr, { "box 1 (label 2)", "not a hexahedron" });
  }

  // Labels out of 1..255.
  for (int label : { 0, 256, -3 })
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi, label);
    const std::string name = "box 0 (label " + std::to_string(label) + ")";
    ok &= ExpectRefusal("label out of range", cage, nullptr, { name.c_str(), "[1, 255]" });
  }

  // A deformed box that folds: corner 6 pushed through the box to (0.1, 0.1, 0.1).
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi, 9);
    const double through[3] = { 0.1, 0.1, 0.1 };
    cage->SetDeformedPoint(6, through);
    ok &= ExpectRefusal(
      "deformed box folds", cage, nullptr, { "box 0 (label 9)", "deformed box folds" });
  }

  // A rest box that folds (the deformed one is fine).
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi, 9);
    const double through[3] = { 0.1, 0.1, 0.1 };
    cage->SetRestPoint(6, through);
    cage->SetDeformedPoint(6, hi);
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
    auto cage = lfdtest::MakeBoxCage(lo, hi, 5);
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
    auto cage = lfdtest::MakeBoxCage(lo, hi);
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

  // A box on top of another, shifted by half a box: they share half a face.
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi, 1);
    const double lo2[3] = { 0.5, 1, 0 }, hi2[3] = { 1.5, 2, 1 };
    vtkIdType ids[8];
    lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
    cage->AddBox(ids, 2);
    ok &= ExpectValid("boxes sharing half a face", cage);
  }

  // Overlapping rest boxes: by half a box and by a 0.01 sliver.
  ok &= ExpectRefusal("overlap by 0.5",
    TwoBoxes(0.5),
    nullptr,
    { "box 1 (label 2) overlaps box 0 (label 1)", "in rest space" });
  ok &= ExpectRefusal(
    "overlap by 0.01", TwoBoxes(0.99), nullptr, { "box 1 (label 2) overlaps box 0 (label 1)" });
  // One box inside another.
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi, 1);
    const double lo2[3] = { 0.4, 0.4, 0.4 }, hi2[3] = { 0.6, 0.6, 0.6 };
    vtkIdType ids[8];
    lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
    cage->AddBox(ids, 3);
    ok &= ExpectRefusal("nested boxes", cage, nullptr, { "box 1 (label 3) overlaps box 0" });
  }

  // Labels against the light field's: one that no ray carries, two on an
  // unsplit light field.
  {
    vtkNew<vtkLightField> lightField;
    lightField->SetLayout(4, 2, 1);
    // Unsplit, the light field is one part: boxes of two labels are refused,
    // boxes sharing one label (a lattice, a tessellation) are not.
    ok &= ExpectRefusal("two labels, light field without a Label pass",
      TwoBoxes(1.0),
      lightField,
      { "box 0 (label 1) and box 1 (label 2)", "no Label pass", "split it first (lfd split" });
    auto sameLabel = TwoBoxes(1.0);
    sameLabel->GetCellData()->GetArray("Label")->SetComponent(1, 0, 1);
    ok &= ExpectValid(
      "one label in two boxes, light field without a Label pass", sameLabel, lightField);
    vtkDataArray* labels = lightField->AllocatePass(vtkLightField::LABEL);
    labels->SetComponent(3, 0, 1);
    labels->SetComponent(5, 0, 7);
    ok &= ExpectRefusal("label without sub-light field",
      TwoBoxes(1.0),
      lightField,
      { "box 1 (label 2)", "no sub-light field 2" });
    labels->SetComponent(6, 0, 2);
    labels->Modified(); // edited in place: as for GetRange(), say so
    ok &= ExpectValid("labels 1 and 2 in the Label pass", TwoBoxes(1.0), lightField);
  }

  // Arrays missing.
  {
    auto cage = lfdtest::MakeBoxCage(lo, hi);
    cage->GetCellData()->RemoveArray("Label");
    ok &= ExpectRefusal("no Label array", cage, nullptr, { "\"Label\"" });
  }

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
