// Malformed scene.json files: each Read() fails with one line naming the
// file and the field, and leaves the scene unchanged; a failed Write()
// leaves the existing file untouched.
#include "lfdIOTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

namespace
{
const std::string Rest = "[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]]";

std::string Scene(const std::string& cage, const std::string& extra = "")
{
  return "{\"format\": \"lfd-scene\", \"version\": 1, \"lightfield\": \"a.lf\",\n"
         " \"cage\": " +
    cage + extra + "}\n";
}

std::string Cage(const std::string& points,
  const std::string& corners,
  const std::string& label = "1")
{
  return "{\"rest_points\": " + Rest + points + ",\n \"boxes\": [{\"corners\": " + corners +
    ", \"label\": " + label + "}]}";
}
const std::string Box = "[0,1,2,3,4,5,6,7]";
}

int TestLightFieldSceneErrors(int, char*[])
{
  const std::string folder = lfdtest::ScratchFolder("TestLightFieldSceneErrors");
  vtkNew<vtkLightFieldScene> scene;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(scene);
  const std::string valid = folder + "/valid.json";
  lfdtest::WriteText(valid, Scene(Cage("", Box)));
  lfdtest::Check(scene->Read(valid.c_str()), "the valid scene reads");

  int caseNumber = 0;
  auto expectFailure =
    [&](const std::string& name, const std::string& text, std::vector<std::string> parts)
  {
    const std::string file = folder + "/case" + std::to_string(++caseNumber) + ".json";
    lfdtest::WriteText(file, text);
    catcher->Clear();
    const bool ok = scene->Read(file.c_str());
    parts.insert(parts.begin(), file);
    lfdtest::CheckFailure(name, !ok, catcher->GetErrorMessage(), parts);
  };

  expectFailure(
    "bad JSON", "{\"format\": \"lfd-scene\",\n \"version\": 1,,}", { "not valid JSON", "line 2" });
  expectFailure("wrong format",
    "{\"format\": \"lfd-lightfield\", \"version\": 1}",
    { "\"format\"", "lfd-scene" });
  expectFailure("unknown version",
    "{\"format\": \"lfd-scene\", \"version\": 7}",
    { "\"version\"", "unsupported version 7" });
  expectFailure("missing version", "{\"format\": \"lfd-scene\"}", { "\"version\"", "missing" });
  expectFailure("corner index out of range",
    Scene(Cage("", "[0,1,2,3,4,5,6,8]")),
    { "\"cage.boxes[0].corners[7]\"", "corner index 8 out of range" });
  expectFailure("negative corner index",
    Scene(Cage("", "[0,1,2,-3,4,5,6,7]")),
    { "\"cage.boxes[0].corners[3]\"", "out of range" });
  expectFailure("box with 7 corners",
    Scene(Cage("", "[0,1,2,3,4,5,6]")),
    { "\"cage.boxes[0].corners\"", "8 corners" });
  expectFailure("points and rest_points of different lengths",
    Scene(Cage(", \"points\": [[0,0,0]]", Box)),
    { "\"cage.points\"", "has 1 points" });
  expectFailure("point with 2 coordinates",
    Scene(
      Cage(", \"points\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1],[0,1,1]]", Box)),
    { "\"cage.points[6]\"", "3 numbers" });
  expectFailure(
    "label out of range", Scene(Cage("", Box, "300")), { "\"cage.boxes[0].label\"", "[0, 255]" });
  expectFailure("keyframe point count",
    Scene(Cage("", Box), ", \"keyframes\": [{\"time\": 0, \"points\": [[0,0,0]]}]"),
    { "\"keyframes[0].points\"", "has 1 points, the cage has 8" });
  expectFailure("keyframe without time",
    Scene(Cage("", Box), ", \"keyframes\": [{\"points\": " + Rest + "}]"),
    { "\"keyframes[0].time\"", "missing" });
  expectFailure("non-finite number",
    Scene(Cage("", Box), ", \"render\": {\"focal_distance\": -1e400}"),
    { "not valid JSON", "1e400" });
  expectFailure("NaN token",
    Scene(Cage("", Box), ", \"render\": {\"focal_distance\": NaN}"),
    { "not valid JSON", "line 3" });
  expectFailure("widened search out of range",
    Scene(Cage("", Box), ", \"render\": {\"widened_search\": -1}"),
    { "\"render.widened_search\"", "[0, 64]" });
  expectFailure("subdivision 0",
    Scene(Cage("", Box), ", \"render\": {\"subdivision\": 0}"),
    { "\"render.subdivision\"", "[1, 16]" });
  expectFailure("subdivision string",
    Scene(Cage("", Box), ", \"render\": {\"subdivision\": \"x\"}"),
    { "\"render.subdivision\"", "auto" });
  expectFailure("unknown focal surface",
    Scene(Cage("", Box), ", \"render\": {\"focal\": \"sphere\"}"),
    { "\"render.focal\"", "expected \"auto\", \"plane\" or \"proxy\", found" });
  expectFailure("anti-aliasing not a boolean",
    Scene(Cage("", Box), ", \"render\": {\"antialiasing\": \"on\"}"),
    { "\"render.antialiasing\"", "expected true or false, found the string \"on\"" });
  expectFailure("negative aperture",
    Scene(Cage("", Box), ", \"render\": {\"aperture\": -0.1}"),
    { "\"render.aperture\"", "expected a distance >= 0, found the number -0.1" });
  expectFailure("background out of [0, 1]",
    Scene(Cage("", Box), ", \"render\": {\"background\": [0, 255, 0]}"),
    { "\"render.background[1]\"", "[0, 1]" });
  expectFailure("view angle 0",
    Scene(Cage("", Box), ", \"camera\": {\"view_angle\": 0}"),
    { "\"camera.view_angle\"", "[0.5, 179]" });
  expectFailure("camera position of 2",
    Scene(Cage("", Box), ", \"camera\": {\"position\": [0, 1]}"),
    { "\"camera.position\"", "3 numbers" });
  expectFailure("unknown interpolation",
    Scene(Cage("", Box), ", \"interpolation\": \"cubic\""),
    { "\"interpolation\"", "expected \"linear\" or \"catmull-rom\", found the string \"cubic\"" });
  expectFailure("interpolation not a string",
    Scene(Cage("", Box), ", \"interpolation\": 1"),
    { "\"interpolation\"" });
  expectFailure("keyframes without a cage",
    "{\"format\": \"lfd-scene\", \"version\": 1, \"keyframes\": [{\"time\": 0, \"points\": []}]}",
    { "\"keyframes\"", "no cage" });

  // Failed reads changed nothing.
  lfdtest::CheckEqual(std::string(scene->GetFileName()), valid, "scene file after failed reads");
  lfdtest::CheckEqual(
    scene->GetCage()->GetNumberOfCells(), vtkIdType(1), "boxes after failed reads");

  // A failed write (keyframe of the wrong size) leaves the existing file.
  const std::string before = lfdtest::ReadText(valid);
  vtkNew<vtkPoints> three;
  three->SetNumberOfPoints(3);
  scene->AddKeyframe(1.0, three);
  catcher->Clear();
  const bool ok = scene->Write(valid.c_str());
  lfdtest::CheckFailure("write a keyframe of 3 points",
    !ok,
    catcher->GetErrorMessage(),
    { valid, "keyframe 0 has 3 points, the cage has 8" });
  lfdtest::Check(lfdtest::ReadText(valid) == before, "the existing file is unchanged");
  scene->RemoveAllKeyframes();
  catcher->Clear();
  const bool blocked = scene->Write((folder + "/missing/dir/scene.json").c_str());
  lfdtest::CheckFailure("write into a missing folder",
    !blocked,
    catcher->GetErrorMessage(),
    { folder + "/missing/dir/scene.json: cannot create the file" });
  lfdtest::CheckEqual(lfdtest::CountEntries(folder, "valid.tmp-"), 0, "temporary files left");

  // Write() reads the cage through vtkDeformationCage: a grid without labels
  // is refused by its check; one without rest positions is written at rest.
  vtkNew<vtkUnstructuredGrid> plain;
  plain->DeepCopy(scene->GetCage());
  plain->GetPointData()->RemoveArray("RestPosition");
  plain->GetPoints()->SetPoint(6, 1.5, 1.5, 1.5);
  scene->SetCage(plain);
  const std::string atRest = folder + "/at-rest.json";
  lfdtest::Check(scene->Write(atRest.c_str()), "a cage without rest positions is written");
  lfdtest::Check(scene->Read(atRest.c_str()), "and reads back");
  vtkNew<vtkDeformationCage> read;
  read->InitializeFromGrid(scene->GetCage());
  double rest[3];
  read->GetRestPoint(6, rest);
  lfdtest::Check(!read->IsDeformed() && rest[0] == 1.5, "at rest: rest = points");
  plain->GetCellData()->RemoveArray("Label");
  scene->SetCage(plain);
  const std::string unlabelled = folder + "/unlabelled.json";
  catcher->Clear();
  const bool unlabelledWritten = scene->Write(unlabelled.c_str());
  lfdtest::CheckFailure("write a cage without labels",
    !unlabelledWritten,
    catcher->GetErrorMessage(),
    { unlabelled + ": the cage has no cell array \"Label\"" });
  return lfdtest::Result();
}
