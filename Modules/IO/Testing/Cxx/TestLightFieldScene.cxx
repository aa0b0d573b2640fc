// scene.json round trip: a two-box cage sharing a face, deformed points,
// keyframes, camera and render settings, written and read back bit for bit;
// defaults of omitted sections; relative light-field paths.
#include "lfdIOTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>

using lfdtest::Check;
using lfdtest::CheckEqual;

namespace
{
// Two unit boxes side by side along x sharing the face x = 1 (12 points).
vtkSmartPointer<vtkUnstructuredGrid> MakeCage()
{
  auto cage = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> rest;
  rest->SetName("RestPosition");
  rest->SetNumberOfComponents(3);
  for (int z = 0; z < 2; ++z)
  {
    for (int y = 0; y < 2; ++y)
    {
      for (int x = 0; x < 3; ++x)
      {
        const double p[3] = { x + 0.1, y / 3.0, z * std::sqrt(2.0) };
        rest->InsertNextTuple(p);
        const double q[3] = { p[0] + 1e-3 * y, p[1] + 1.0 / 7.0 * z, p[2] };
        points->InsertNextPoint(q);
      }
    }
  }
  cage->SetPoints(points);
  cage->GetPointData()->AddArray(rest);
  auto id = [](int x, int y, int z) { return static_cast<vtkIdType>(x + 3 * y + 6 * z); };
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  for (int b = 0; b < 2; ++b)
  {
    const vtkIdType corners[8] = { id(b, 0, 0),
      id(b + 1, 0, 0),
      id(b + 1, 1, 0),
      id(b, 1, 0),
      id(b, 0, 1),
      id(b + 1, 0, 1),
      id(b + 1, 1, 1),
      id(b, 1, 1) };
    cage->InsertNextCell(VTK_HEXAHEDRON, 8, corners);
    labels->InsertNextValue(b + 1);
  }
  cage->GetCellData()->AddArray(labels);
  return cage;
}

int DifferingValues(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfValues() != b->GetNumberOfValues())
  {
    return -1;
  }
  int differing = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      differing += a->GetComponent(i, c) == b->GetComponent(i, c) ? 0 : 1;
    }
  }
  return differing;
}
}

int TestLightFieldScene(int, char*[])
{
  const std::string folder = lfdtest::ScratchFolder("TestLightFieldScene");
  const std::string file = folder + "/scene.json";

  vtkNew<vtkLightFieldScene> scene;
  scene->SetLightFieldPath("fish.lf");
  scene->SetCage(MakeCage());
  vtkNew<vtkPoints> keyPoints;
  keyPoints->SetDataTypeToDouble();
  keyPoints->DeepCopy(scene->GetCage()->GetPoints());
  scene->AddKeyframe(0.0, keyPoints);
  keyPoints->SetPoint(4, 1.1, 0.25, -1e-12);
  scene->AddKeyframe(2.5, keyPoints);
  scene->GetCamera()->SetPosition(0.3, 0.2, 4.0 / 3.0);
  scene->GetCamera()->SetFocalPoint(0.1, -0.05, 0.0);
  scene->GetCamera()->SetViewUp(0.0, 1.0, 0.0);
  scene->GetCamera()->SetViewAngle(27.5);
  scene->SetWidth(640);
  scene->SetHeight(360);
  scene->SetFocalDistance(0.35);
  scene->SetSubdivision(3);
  scene->SetWidenedSearch(0);
  scene->SetBackground(0.25, 0.5, 1.0);
  scene->SetInterpolationToLinear();
  Check(scene->Write(file.c_str()), "Write " + file);
  Check(lfdtest::ReadText(file).find("\"interpolation\": \"linear\"") != std::string::npos,
    "interpolation written by name");
  CheckEqual(lfdtest::CountEntries(folder, "scene.tmp-"), 0, "temporary files left");

  vtkNew<vtkLightFieldScene> read;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(read);
  Check(read->Read(file.c_str()), std::string("Read: ") + errors->GetErrorMessage());
  CheckEqual(std::string(read->GetLightFieldPath()), std::string("fish.lf"), "lightfield");
  CheckEqual(
    std::string(read->GetResolvedLightFieldPath()), folder + "/fish.lf", "resolved light field");
  Check(read->HasCage(), "HasCage");
  vtkUnstructuredGrid* cage = read->GetCage();
  CheckEqual(cage->GetNumberOfPoints(), vtkIdType(12), "cage points");
  CheckEqual(cage->GetNumberOfCells(), vtkIdType(2), "boxes");
  CheckEqual(cage->GetCellType(1), static_cast<int>(VTK_HEXAHEDRON), "box 1 cell type");
  vtkNew<vtkIdList> ids;
  cage->GetCellPoints(1, ids);
  std::string corners;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    corners += (k ? " " : "") + std::to_string(ids->GetId(k));
  }
  CheckEqual(corners, std::string("1 2 5 4 7 8 11 10"), "box 1 corners");
  CheckEqual(
    DifferingValues(cage->GetPoints()->GetData(), scene->GetCage()->GetPoints()->GetData()),
    0,
    "deformed points differing");
  CheckEqual(DifferingValues(cage->GetPointData()->GetArray("RestPosition"),
               scene->GetCage()->GetPointData()->GetArray("RestPosition")),
    0,
    "rest points differing");
  vtkDataArray* labels = cage->GetCellData()->GetArray("Label");
  Check(
    labels && labels->GetComponent(0, 0) == 1 && labels->GetComponent(1, 0) == 2, "labels 1, 2");
  CheckEqual(read->GetNumberOfKeyframes(), 2, "keyframes");
  CheckEqual(read->GetKeyframeTime(1), 2.5, "keyframe 1 time");
  CheckEqual(DifferingValues(read->GetKeyframePoints(1)->GetData(), keyPoints->GetData()),
    0,
    "keyframe 1 points differing");
  CheckEqual(read->GetKeyframePoints(1)->GetPoint(4)[2], -1e-12, "keyframe 1 point 4 z");
  CheckEqual(read->GetCamera()->GetPosition()[2], 4.0 / 3.0, "camera position z (bitwise)");
  CheckEqual(read->GetCamera()->GetFocalPoint()[1], -0.05, "camera focal point y");
  CheckEqual(read->GetCamera()->GetViewAngle(), 27.5, "view angle");
  CheckEqual(read->GetWidth(), 640, "width");
  CheckEqual(read->GetHeight(), 360, "height");
  CheckEqual(read->GetFocalDistance(), 0.35, "focal distance");
  CheckEqual(read->GetSubdivision(), 3, "subdivision");
  CheckEqual(read->GetWidenedSearch(), 0, "widened search");
  CheckEqual(read->GetBackground()[0], 0.25, "background red");
  CheckEqual(read->GetBackground()[2], 1.0, "background blue");
  CheckEqual(read->GetInterpolation(),
    static_cast<int>(vtkLightFieldScene::INTERPOLATION_LINEAR),
    "interpolation read back");

  // A second write of what was read gives the same bytes.
  const std::string again = folder + "/again.json";
  Check(read->Write(again.c_str()), "write the scene read back");
  Check(lfdtest::ReadText(again) == lfdtest::ReadText(file), "identical text after a round trip");

  // Omitted sections take their defaults; "points" omitted = rest.
  const std::string minimal = folder + "/minimal.json";
  lfdtest::WriteText(
    minimal, "{\"format\": \"lfd-scene\", \"version\": 1, \"lightfield\": \"/data/a.lf\"}");
  vtkNew<vtkLightFieldScene> plain;
  errors->Observe(plain);
  Check(plain->Read(minimal.c_str()), std::string("minimal scene: ") + errors->GetErrorMessage());
  Check(!plain->HasCage(), "no cage");
  CheckEqual(plain->GetNumberOfKeyframes(), 0, "no keyframes");
  CheckEqual(std::string(plain->GetResolvedLightFieldPath()),
    std::string("/data/a.lf"),
    "absolute path kept");
  CheckEqual(plain->GetWidth(), 512, "default width");
  CheckEqual(plain->GetHeight(), 512, "default height");
  CheckEqual(plain->GetCamera()->GetViewAngle(), 30.0, "default view angle");
  CheckEqual(plain->GetSubdivision(), 1, "default subdivision");
  CheckEqual(plain->GetWidenedSearch(), 2, "default widened search");
  CheckEqual(plain->GetFocalDistance(), 0.0, "default focal distance");
  CheckEqual(plain->GetInterpolation(),
    static_cast<int>(vtkLightFieldScene::INTERPOLATION_CATMULL_ROM),
    "default interpolation");
  // Without keyframes, at the default, the field is not written (files of
  // scenes without an animation keep their bytes).
  const std::string plainAgain = folder + "/plain-again.json";
  Check(plain->Write(plainAgain.c_str()), "write the minimal scene");
  Check(lfdtest::ReadText(plainAgain).find("interpolation") == std::string::npos,
    "no interpolation field without keyframes at the default");

  const std::string restOnly = folder + "/rest.json";
  lfdtest::WriteText(restOnly,
    "{\"format\": \"lfd-scene\", \"version\": 1, \"lightfield\": \"../x.lf\",\n"
    " \"cage\": {\"rest_points\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],"
    "[0,1,1]],\n \"boxes\": [{\"corners\": [0,1,2,3,4,5,6,7], \"label\": 4}]},\n"
    " \"render\": {\"subdivision\": \"auto\", \"focal\": \"proxy\", \"focal_depth\": 3.5,"
    " \"aperture\": 0.15, \"antialiasing\": false}}");
  vtkNew<vtkLightFieldScene> undeformed;
  errors->Observe(undeformed);
  Check(undeformed->Read(restOnly.c_str()),
    std::string("undeformed scene: ") + errors->GetErrorMessage());
  CheckEqual(DifferingValues(undeformed->GetCage()->GetPoints()->GetData(),
               undeformed->GetCage()->GetPointData()->GetArray("RestPosition")),
    0,
    "points equal rest when omitted");
  Check(undeformed->GetSubdivisionAuto(), "subdivision \"auto\"");
  CheckEqual(undeformed->GetFocalSurface(), 2, "render.focal \"proxy\"");
  CheckEqual(undeformed->GetFocalDepth(), 3.5, "render.focal_depth");
  CheckEqual(undeformed->GetAperture(), 0.15, "render.aperture");
  CheckEqual(undeformed->GetAntiAliasing(), false, "render.antialiasing false");
  CheckEqual(std::string(undeformed->GetResolvedLightFieldPath()),
    std::filesystem::path(LFD_TEST_TEMP_DIR).lexically_normal().string() + "/x.lf",
    "relative path resolved against the scene folder");
  const std::string autoFile = folder + "/auto.json";
  Check(undeformed->Write(autoFile.c_str()), "write auto subdivision");
  Check(lfdtest::ReadText(autoFile).find("\"subdivision\": \"auto\"") != std::string::npos,
    "\"auto\" written back");
  Check(lfdtest::ReadText(autoFile).find("\"focal\": \"proxy\"") != std::string::npos,
    "render.focal written back");
  Check(lfdtest::ReadText(autoFile).find("\"focal_depth\": 3.5") != std::string::npos &&
      lfdtest::ReadText(autoFile).find("\"aperture\": 0.15") != std::string::npos,
    "render.focal_depth and render.aperture written back");
  Check(lfdtest::ReadText(autoFile).find("\"antialiasing\": false") != std::string::npos,
    "render.antialiasing false written back");
  undeformed->SetFocalSurface(0);
  undeformed->SetAntiAliasing(true);
  undeformed->SetFocalDepth(0.0);
  undeformed->SetAperture(0.0);
  Check(undeformed->Write(autoFile.c_str()) &&
      lfdtest::ReadText(autoFile).find("\"focal\"") == std::string::npos &&
      lfdtest::ReadText(autoFile).find("\"focal_depth\"") == std::string::npos &&
      lfdtest::ReadText(autoFile).find("\"aperture\"") == std::string::npos &&
      lfdtest::ReadText(autoFile).find("\"antialiasing\"") == std::string::npos,
    "render.focal \"auto\", focal_depth and aperture 0, antialiasing true (the defaults) not "
    "written");
  return lfdtest::Result();
}
