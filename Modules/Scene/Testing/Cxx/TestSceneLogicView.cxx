// The scene logic's view side (issue 9, item 2: the CLI's scene glue moved
// into the logic): slabs along the ring axis, orbit cameras, the scene's
// view on a renderer, animation times, and a mesh labelled by the boxes.
#include "lfdIOTestUtilities.h"
#include "lfdPartCageTestMeshes.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkLightField.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cmath>

using lfdtest::Check;
using lfdtest::CheckEqual;
using lfdtest::CheckRange;

namespace
{
void TestRingSlabs(vtkLightFieldSceneLogic* logic, vtkLightField* lightField)
{
  // A ring about y: slabs along "the ring axis" stack along y.
  const double center[3] = { 0.0, 0.0, 0.0 }, axis[3] = { 0.0, 1.0, 0.0 }, heights[1] = { 0.0 };
  vtkCameraRig* rig = lightField->GetRig();
  rig->MakeCylinder(center, axis, 2.0, 12, 1, heights, 64, 64, 40.0);
  Check(rig->HasCylinder() || rig->FitCylinder(), "the ring is fitted");
  logic->SetLightField(lightField);
  const double bounds[6] = { -0.5, 0.5, -1.0, 1.0, -0.25, 0.25 };
  Check(logic->BuildCageFromSlabs(bounds, 2, -1, 1), "2 slabs along the ring axis");
  double p[3];
  logic->GetCage()->GetRestPoint(4, p);
  CheckEqual(p[1], 0.0, "layer 1 lies halfway up y");
  logic->GetCage()->GetRestPoint(8, p);
  CheckEqual(p[1], 1.0, "layer 2 at the top");

  vtkNew<vtkCamera> camera;
  vtkLightFieldSceneLogic::OrbitCamera(rig, 0.5, 1.5, 0.1, 30.0, camera);
  const double* position = camera->GetPosition();
  CheckRange(std::hypot(position[0], position[2]),
    3.0 - 1e-12,
    3.0 + 1e-12,
    "orbit radius: 1.5 x the ring's");
  CheckRange(position[1], 0.1 - 1e-12, 0.1 + 1e-12, "orbit height along the axis");
  CheckEqual(camera->GetViewAngle(), 30.0, "orbit view angle");
}

void TestView(vtkLightFieldSceneLogic* logic, vtkLightField* lightField)
{
  logic->SetSize(100, 80);
  logic->SetFocalDistance(0.3);
  logic->SetSubdivision(3);
  logic->SetWidenedSearch(4);
  logic->SetObjectThreshold(60.0);
  logic->SetBackground(0.25, 0.5, 1.0);
  logic->GetScene()->SetAntiAliasing(false); // render.antialiasing
  vtkNew<vtkDeformationCage> cage;
  Check(logic->GetCurrentCage(lightField, cage), "the current cage validates");
  vtkNew<vtkLightFieldRenderer> renderer;
  logic->ConfigureRenderer(renderer, lightField, cage);
  CheckEqual(renderer->GetWidth() * 1000 + renderer->GetHeight(), 100080, "renderer size");
  CheckEqual(renderer->GetFocalDistance(), 0.3, "renderer focal distance");
  CheckEqual(renderer->GetSubdivision(), 3, "renderer subdivision");
  CheckEqual(renderer->GetWidenedSearch(), 4, "renderer widened search");
  CheckEqual(renderer->GetObjectThreshold(), 60.0, "renderer object threshold");
  CheckEqual(renderer->GetBackground()[2], 1.0, "renderer background");
  CheckEqual(renderer->GetAntiAliasing(), false, "renderer anti-aliasing");
  Check(renderer->GetCamera() &&
      renderer->GetCamera()->GetViewAngle() == logic->GetScene()->GetCamera()->GetViewAngle(),
    "renderer camera");
}

void TestAnimationTimes(vtkLightFieldSceneLogic* logic)
{
  CheckEqual(logic->GetAnimationTime(3, 5), 0.0, "animation time without keyframes");
  logic->SetKeyframe(1.0);
  logic->SetKeyframe(3.0);
  CheckEqual(logic->GetAnimationTime(0, 5), 1.0, "first frame: first keyframe");
  CheckEqual(logic->GetAnimationTime(2, 5), 2.0, "middle frame");
  CheckEqual(logic->GetAnimationTime(4, 5), 3.0, "last frame: last keyframe");
}

void TestLabelMesh(vtkLightFieldSceneLogic* logic)
{
  auto fish = lfdtest::MakeFishMesh();
  logic->SetLightField(nullptr);
  Check(logic->BuildCageFromLabels(fish, -1), "boxes from the fish's parts");
  vtkNew<vtkPolyData> labelled;
  Check(logic->LabelMesh(fish, labelled), "the fish labelled by the boxes");
  vtkDataArray* found = labelled->GetCellData()->GetArray("Label");
  vtkDataArray* truth = fish->GetCellData()->GetArray("Label");
  vtkIdType same = 0;
  for (vtkIdType c = 0; found && c < found->GetNumberOfTuples(); ++c)
  {
    same += found->GetComponent(c, 0) == truth->GetComponent(c, 0) ? 1 : 0;
  }
  // The fish's ellipsoids overlap along x, so slab boundaries put some of
  // their cells in the neighbour's box: 0.767 measured.
  CheckRange(static_cast<double>(same) / fish->GetNumberOfCells(),
    0.75,
    1.0,
    "cells whose box label is their part's");
}

void TestAdoptScene()
{
  vtkNew<vtkLightFieldScene> scene;
  vtkNew<vtkDeformationCage> cage;
  const double rest[3] = { 0.0, 0.0, 0.0 };
  cage->AddPoint(rest);
  scene->SetCage(cage);
  scene->SetWidth(77);
  vtkNew<vtkLightFieldSceneLogic> logic;
  logic->SetScene(scene);
  Check(logic->GetScene() == scene.Get() && scene->GetCage() == logic->GetCage(),
    "an adopted scene shares the logic's cage");
  CheckEqual(
    logic->GetCage()->GetNumberOfPoints(), static_cast<vtkIdType>(1), "the adopted cage's points");
  Check(logic->SetSize(78, 78) && scene->GetWidth() == 78, "edits reach the adopted document");
  logic->SetScene(scene);
  CheckEqual(logic->GetCage()->GetNumberOfPoints(),
    static_cast<vtkIdType>(1),
    "adopting the same document again keeps its cage");
}
}

int TestSceneLogicView(int, char*[])
{
  TestAdoptScene();
  vtkNew<vtkLightFieldSceneLogic> logic;
  vtkNew<vtkLightField> lightField;
  TestRingSlabs(logic, lightField);
  TestView(logic, lightField);
  TestAnimationTimes(logic);
  TestLabelMesh(logic);
  return lfdtest::Result();
}
