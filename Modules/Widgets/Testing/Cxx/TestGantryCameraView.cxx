// The gantry-camera view of the fish (24 views, 128 x 128): the projected
// rest boxes of its part cage hold its labelled pixels in every view
// (coverage >= 0.98, the figure `lfd split check` reports, from the same
// vtkBoxCoverageCheck), distorted edges curve, a shrunken box highlights the
// pixels it loses; regression image of two views side by side.
#include "lfdWidgetsTestUtilities.h"

#include "vtkBoxCoverageCheck.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkGantryCameraView.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>

namespace
{
// Largest distance of the middle sample of a projected edge from the chord
// between its ends, in pixels.
double MiddleBulge(vtkPolyData* boxes)
{
  double bulge = 0.0;
  for (vtkIdType line = 0; line < boxes->GetNumberOfLines(); ++line)
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    boxes->GetLines()->GetCellAtId(line, count, ids);
    double a[3], b[3], m[3];
    boxes->GetPoint(ids[0], a);
    boxes->GetPoint(ids[count - 1], b);
    boxes->GetPoint(ids[count / 2], m);
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    bulge = std::max(bulge, std::abs(dx * (m[1] - a[1]) - dy * (m[0] - a[0])) / std::hypot(dx, dy));
  }
  return bulge;
}
}

int TestGantryCameraView(int argc, char* argv[])
{
  lfdtest::Fish fish;
  lfdtest::MakeFish(fish);
  vtkLightField* lightField = fish.LightField;
  const int views = lightField->GetNumberOfViews();

  vtkNew<vtkGantryCameraView> view;
  view->SetLightField(lightField);
  view->SetCage(fish.Cage);

  // What `lfd split check` runs, on its own.
  vtkNew<vtkBoxCoverageCheck> check;
  check->SetInputData(lightField);
  check->SetCageData(fish.Cage);
  check->Update();
  vtkTable* table = check->GetOutput();
  double worstView = 1.0;
  for (int v = 0; v < views; ++v)
  {
    view->SetView(v);
    const double coverage = view->GetCoverage();
    double expected = 1.0;
    for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row)
    {
      if (table->GetValueByName(row, "View").ToInt() == v)
      {
        expected = std::min(expected, table->GetValueByName(row, "Fraction").ToDouble());
      }
    }
    std::cout << "view " << v << ": ";
    lfdtest::Check(coverage >= 0.98, "coverage", coverage, 0.98);
    lfdtest::Check(coverage == expected, "  equals the check's table", expected, coverage);
    worstView = std::min(worstView, coverage);
  }
  double worstLabel = 1.0;
  for (int i = 0; i < check->GetNumberOfLabels(); ++i)
  {
    worstLabel = std::min(worstLabel, check->GetWorstFraction(i));
  }
  lfdtest::Check(
    worstView == worstLabel, "worst view = worst label fraction", worstView, worstLabel);

  // 3 boxes x 12 edges, all in front of the camera: 36 polylines; straight
  // without distortion.
  view->SetView(3);
  vtkPolyData* boxes = view->GetProjectedBoxes();
  lfdtest::Check(boxes->GetNumberOfLines() == 36, "projected edges", boxes->GetNumberOfLines(), 36);
  lfdtest::Check(
    MiddleBulge(boxes) < 1e-4, "edge bulge without distortion", MiddleBulge(boxes), 1e-4);

  // Lens distortion bends the projected edges (the same rig, k1 = -0.3).
  vtkNew<vtkLightField> distorted;
  distorted->ShallowCopy(lightField);
  vtkNew<vtkCameraRig> rig;
  rig->DeepCopy(lightField->GetRig());
  const double k[5] = { -0.3, 0.0, 0.0, 0.0, 0.0 };
  for (int v = 0; v < views; ++v)
  {
    rig->SetDistortion(v, k);
  }
  distorted->SetRig(rig);
  view->SetLightField(distorted);
  const double bulge = MiddleBulge(view->GetProjectedBoxes());
  lfdtest::Check(bulge > 0.1, "edge bulge with k1 = -0.3 (pixels)", bulge, 0.1);

  // A cage whose body box (label 2) is shrunk by 30 % towards its centre:
  // the body's pixels outside are highlighted, the coverage drops.
  vtkNew<vtkDeformationCage> shrunk;
  shrunk->DeepCopy(fish.Cage);
  vtkIdType body = 0;
  while (shrunk->GetBoxLabel(body) != 2)
  {
    ++body;
  }
  double bounds[6];
  shrunk->GetRestBounds(body, bounds);
  vtkNew<vtkIdList> corners;
  shrunk->GetCellPoints(body, corners);
  for (vtkIdType c = 0; c < corners->GetNumberOfIds(); ++c)
  {
    double rest[3];
    shrunk->GetRestPoint(corners->GetId(c), rest);
    for (int a = 0; a < 3; ++a)
    {
      rest[a] += 0.3 * (0.5 * (bounds[2 * a] + bounds[2 * a + 1]) - rest[a]);
    }
    shrunk->SetRestPoint(corners->GetId(c), rest);
    shrunk->SetDeformedPoint(corners->GetId(c), rest);
  }
  vtkNew<vtkGantryCameraView> shrunkView;
  shrunkView->SetLightField(lightField);
  shrunkView->SetCage(shrunk);
  shrunkView->SetView(0);
  shrunkView->SetPass(vtkLightField::LABEL);
  vtkDataArray* outside =
    shrunkView->GetCoverageCheck()->GetOutsideMask()->GetPointData()->GetScalars();
  vtkIdType expectedOutside = 0;
  const vtkIdType pixels = 128 * 128;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    expectedOutside += outside->GetComponent(p, 0) != 0 ? 1 : 0;
  }
  const vtkIdType highlighted = shrunkView->GetNumberOfOutsidePixels();
  lfdtest::Check(highlighted > 100, "highlighted pixels, shrunken body", highlighted, 100);
  lfdtest::Check(
    highlighted == expectedOutside, "  = the check's outside mask", expectedOutside, highlighted);
  lfdtest::Check(shrunkView->GetCoverage() < 0.98, "  coverage", shrunkView->GetCoverage(), 0.98);

  // Regression image: view 3 coaxial with the boxes, and view 0's label
  // pass under the shrunken cage with its outside pixels in magenta.
  view->SetLightField(lightField);
  view->SetView(3);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(512, 256);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  view->SetRenderer(left);
  shrunkView->SetRenderer(right);
  view->ResetCamera();
  shrunkView->ResetCamera();
  window->Render();
  const int result = vtkRegressionTestImage(window);
  return (lfdtest::Failures() == 0 && result != vtkRegressionTester::FAILED) ? 0 : 1;
}
