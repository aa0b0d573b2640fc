// Picking takes the visible, nearest handle: a corner of a back box that
// projects next to a corner of a front box, and nearer to the cursor, is
// hidden behind the front box's face and not picked; an occluder depth
// (the object's) hides handles behind it; the rubber band skips hidden
// handles.
#include "lfdCageWidgetTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

namespace
{
void FillDepth(vtkImageData* image, int width, int height, double value)
{
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  vtkDataArray* depth = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < depth->GetNumberOfTuples(); ++i)
  {
    depth->SetTuple1(i, value);
  }
}
}

int TestCageWidgetPicking(int, char*[])
{
  // Box 0 (points 0-7) in front, box 1 (points 8-15) behind it, shifted by
  // 0.02 so that its corner 8 projects 1-2 pixels from corner 4.
  vtkNew<vtkDeformationCage> cage;
  const double frontLo[3] = { 0.0, 0.0, 1.0 }, frontHi[3] = { 1.0, 1.0, 2.0 };
  const double backLo[3] = { 0.02, 0.02, -2.0 }, backHi[3] = { 1.02, 1.02, -1.0 };
  lfdtest::AddBoxAt(cage, frontLo, frontHi, 1);
  lfdtest::AddBoxAt(cage, backLo, backHi, 2);
  int failures = 0;
  auto check = [&failures](bool ok, const std::string& what)
  {
    if (!ok)
    {
      std::cerr << "FAILED: " << what << "\n";
      ++failures;
    }
  };
  check(cage->Validate().empty(), "the two boxes are a valid cage: " + cage->Validate());
  const double focal[3] = { 0.0, 0.0, 0.0 };
  const double position[3] = { 0.0, 0.0, 10.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  lfdtest::WidgetScene scene(cage, focal, position, up);
  vtkCageRepresentation* rep = scene.Representation;

  // Point 4 = (0, 0, 2), the front box's top corner; point 8 = (0.02, 0.02,
  // -2), behind the front box's top face.
  double p4[3], p8[3], d4[3], d8[3];
  cage->GetDeformedPoint(4, p4);
  cage->GetDeformedPoint(8, p8);
  scene.ToDisplay(p4, d4);
  scene.ToDisplay(p8, d8);
  const int x = static_cast<int>(std::lround(d8[0]));
  const int y = static_cast<int>(std::lround(d8[1]));
  const double to4 = std::hypot(x - d4[0], y - d4[1]);
  const double to8 = std::hypot(x - d8[0], y - d8[1]);
  std::cout << "cursor (" << x << ", " << y << "): hidden corner 8 at " << to8
            << " px, visible corner 4 at " << to4 << " px\n";
  check(to8 < to4 && to4 < rep->GetPickTolerance(), "both corners are under the cursor, 8 nearer");
  check(!rep->IsPointVisible(8), "corner 8 is hidden behind the front box");
  check(rep->IsPointVisible(4), "corner 4 is visible");
  check(rep->PickPoint(x, y) == 4, "PickPoint takes the visible corner 4");
  // A hidden front box hides nothing: a corner of box 1 is picked under the
  // cursor (8, or 12 in front of it along the same line of sight), never 4.
  rep->SetBoxVisibility(0, false);
  check(!rep->GetBoxVisibility(0) && rep->GetBoxVisibility(1), "box 0 hidden, box 1 shown");
  check(!rep->IsPointVisible(4) && rep->IsPointVisible(8), "hiding box 0 hides corner 4, shows 8");
  const vtkIdType behind = rep->PickPoint(x, y);
  check(behind == 8 || behind == 12,
    "PickPoint takes a corner of box 1 with box 0 hidden: " + std::to_string(behind));
  rep->SetBoxVisibility(0, true);
  check(rep->PickPoint(x, y) == 4, "shown again, corner 4 is picked");
  scene.Play(lfdtest::Click(x, y));
  check(lfdtest::SelectedIds(rep) == "4", "a click selects corner 4: " + lfdtest::SelectedIds(rep));

  // The rubber band over the whole view: the front box's 8 corners only
  // (every corner of the back box is behind the front one).
  rep->SelectInRectangle(0, 0, 400, 400, false);
  check(lfdtest::SelectedIds(rep) == "0 1 2 3 4 5 6 7",
    "the rubber band skips hidden corners: " + lfdtest::SelectedIds(rep));

  // An occluder just in front of corner 4 hides it (and corner 0 behind
  // it); one just behind does not. A coarser image is sampled.
  vtkNew<vtkImageData> depth;
  FillDepth(depth, 100, 100, d4[2] - 1e-3);
  rep->SetOccluderDepth(depth);
  check(!rep->IsPointVisible(4), "the occluder hides corner 4");
  check(rep->PickPoint(x, y) == -1, "nothing is picked behind the occluder");
  FillDepth(depth, 400, 400, d4[2] + 1e-3);
  depth->Modified();
  check(rep->IsPointVisible(4), "an occluder behind corner 4 does not hide it");
  check(rep->PickPoint(x, y) == 4, "corner 4 is picked in front of the occluder");
  rep->SetOccluderDepth(nullptr);
  check(rep->PickPoint(x + 30, y + 30) == -1, "nothing is picked away from the handles");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
