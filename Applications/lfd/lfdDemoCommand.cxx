// `lfd demo`: the built-in scenes, synthesised, deformed and animated.
#include "lfdCommands.h"

#include "vtkCagePoseFilter.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldScene.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtksys/SystemTools.hxx"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
/**
 * A built-in scene of `lfd demo`: an object, its cage at rest, keyframes of
 * a pose, and the light(s) it is captured under.
 */
struct DemoScene
{
  const char* Object; ///< the built-in object
  const char* Name;   ///< the scene file's name (and the light field's, see below)
  const char* Motion; ///< what the keyframes do, for the report
  bool SingleBox;     ///< one box (label 1) around the whole object, as in Fig. 1
  int Axis;           ///< the slab axis of the cage and of the pose
  int Mode;           ///< vtkCagePoseFilter mode
  double Angle;       ///< the pose's angle (degrees)
  bool Wave;          ///< keyframes run the swim's phase over a cycle, else ramp the angle
  bool BothLights;    ///< also capture under a scene-fixed light (Figs. 4 and 5)
  double TurnAxis[3];
};

/// The demos: the swimming fish (Fig. 13), the single-box twist of the
/// figure (Fig. 1) and the twisted checkerboard under coaxial and scene-fixed
/// light (Figs. 4 and 5).
const DemoScene DemoScenes[] = {
  { "fish", "swim", "swim", false, -1, vtkCagePoseFilter::SWIM, 20.0, true, false, { 0, 0, 1 } },
  { "figure",
    "twist",
    "twist 0-90 degrees",
    true,
    1,
    vtkCagePoseFilter::TWIST,
    90.0,
    false,
    false,
    { 0, 1, 0 } },
  { "checkerboard",
    "checkerboard",
    "top twisted 0-60 degrees",
    true,
    1,
    vtkCagePoseFilter::TWIST,
    60.0,
    false,
    true,
    { 0, 1, 0 } },
};

/// What `lfd demo` writes into its folder: light fields, scenes, frame
/// folders and contact sheets.
const std::vector<std::string> DemoFiles = { "*.lf",
  "*.json",
  "frames",
  "frames_*",
  "contact_sheet*.png" };

/// The object's mesh with every cell in part 1: one sub-light field for one box.
vtkSmartPointer<vtkPolyData> SinglePart(vtkPolyData* mesh)
{
  auto single = vtkSmartPointer<vtkPolyData>::New();
  single->ShallowCopy(mesh);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  labels->SetNumberOfTuples(mesh->GetNumberOfCells());
  labels->FillValue(1);
  single->GetCellData()->AddArray(labels); // replaces the parts' labels
  return single;
}

/**
 * A demo's animation in its staged folder `staged` (to be known as `out`):
 * frames`suffix`/ and contact_sheet`suffix`.png.
 */
void AnimateDemo(vtkLightFieldScene* scene,
  vtkLightField* lightField,
  int frames,
  const std::string& staged,
  const std::string& out,
  const std::string& suffix)
{
  const double start = vtkTimerLog::GetUniversalTime();
  const std::string frameDir = "/frames" + suffix;
  vtkNew<vtkLightFieldSceneLogic> logic;
  logic->SetScene(scene);
  const auto contactSheet = RenderAnimation(logic, lightField, frames, staged + frameDir);
  PrintAnimation(logic, frames, Seconds(start), staged + frameDir, out + frameDir);
  const std::string sheet = "/contact_sheet" + suffix + ".png";
  WriteImage(contactSheet, staged + sheet);
  std::printf("sheet     %s%s\n", out.c_str(), sheet.c_str());
}

/**
 * `lfd demo`: captures the scene's object (under each light), writes the
 * light field, a scene with the cage and its keyframes, the animation's
 * frames and a contact sheet. A second light writes its files with the
 * suffix "_fixed_light".
 */
void Demo(const std::string& sceneName,
  const std::string& out,
  int frames,
  int size,
  const SynthOptions& capture)
{
  const DemoScene* demo = nullptr;
  for (const DemoScene& candidate : DemoScenes)
  {
    if (sceneName == candidate.Name || sceneName == candidate.Object)
    {
      demo = &candidate;
    }
  }
  StagedFolder folder(out, "lfd demo", DemoFiles);
  const std::string& staged = folder.GetPath();
  vtkSmartPointer<vtkImageData> texture;
  vtkSmartPointer<vtkPolyData> mesh = SourceMesh(demo->Object, texture);
  if (demo->SingleBox)
  {
    mesh = SinglePart(mesh);
  }
  vtkNew<vtkPartCageSource> parts;
  parts->SetInputData(mesh);
  parts->SetAxis(demo->Axis);
  Run(parts.Get(), "building the cage");
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(parts->GetOutputPort());
  pose->SetMode(demo->Mode);
  pose->SetAxis(parts->GetUsedAxis());
  pose->SetAngle(demo->Angle);
  pose->SetTurnAxis(demo->TurnAxis);
  const int keyframes = 8;
  std::vector<vtkSmartPointer<vtkPoints>> poses;
  for (int k = 0; k <= keyframes; ++k)
  {
    const double t = static_cast<double>(k) / keyframes;
    if (demo->Wave)
    {
      pose->SetPhase(2.0 * vtkMath::Pi() * t);
    }
    else
    {
      pose->SetAngle(demo->Angle * t);
    }
    Run(pose.Get(), "posing the cage");
    poses.push_back(vtkSmartPointer<vtkPoints>::New());
    poses.back()->DeepCopy(pose->GetOutput()->GetPoints());
  }

  for (const bool sceneFixedLight : { false, true })
  {
    if (sceneFixedLight && !demo->BothLights)
    {
      continue;
    }
    const std::string suffix = sceneFixedLight ? "_fixed_light" : "";
    double start = vtkTimerLog::GetUniversalTime();
    SynthOptions options = capture;
    options.Object = demo->Object;
    options.SceneFixedLight = sceneFixedLight;
    auto lightField = Capture(mesh, texture, options);
    const double captureTime = Seconds(start);
    start = vtkTimerLog::GetUniversalTime();
    const std::string lightFieldName = std::string(demo->Object) + suffix + ".lf";
    WriteLightField(lightField, staged + "/" + lightFieldName);
    const double writeTime = Seconds(start);

    vtkNew<vtkLightFieldScene> scene;
    scene->SetLightFieldPath(lightFieldName.c_str());
    scene->SetCage(parts->GetOutput());
    for (int k = 0; k <= keyframes; ++k)
    {
      scene->AddKeyframe(k, poses[k]);
    }
    vtkCameraRig* rig = lightField->GetRig();
    const double step = 2.0 * vtkMath::Pi() / rig->GetNumberOfViews() * rig->GetNumberOfRows();
    // Half-way between two captured views, further out than the ring. For
    // the fish, swimming about the camera's viewing axis keeps the motion in
    // the picture (a ring light field has horizontal parallax only).
    vtkLightFieldSceneLogic::OrbitCamera(
      rig, 0.5 * step, 1.15, 0.0, 0.7 * rig->GetViewAngle(0), scene->GetCamera());
    scene->SetWidth(size);
    scene->SetHeight(size);
    const std::string sceneName = std::string(demo->Name) + suffix + ".json";
    WriteScene(scene, staged + "/" + sceneName);

    std::printf("capture   %d views of %dx%d%s in %.2f s; written to %s/%s in %.2f s\n",
      lightField->GetNumberOfViews(),
      lightField->GetWidth(),
      lightField->GetHeight(),
      sceneFixedLight ? " under a scene-fixed light" : "",
      captureTime,
      out.c_str(),
      lightFieldName.c_str(),
      writeTime);
    std::printf("scene     %s/%s (%lld boxes, %d keyframes: %s)\n",
      out.c_str(),
      sceneName.c_str(),
      static_cast<long long>(parts->GetOutput()->GetNumberOfBoxes()),
      keyframes + 1,
      demo->Motion);
    AnimateDemo(scene, lightField, frames, staged, out, suffix);
  }
  folder.Commit();
}

/**
 * `lfd demo --scene temple`: Fig. 1 on real data. The Middlebury templeRing
 * (47 photographs, no split) is one part in one box around the temple, whose
 * top turns 0-60 degrees about the vertical: the renderer finds the object
 * pixels (brighter than 60: the cloth behind the temple reaches about 45)
 * and the box moves them. `dataDir` holds templeR_par.txt; empty: look in
 * ../shared/data/templeRing, then in the configured shared data folder.
 */
void DemoTemple(const std::string& dataDir, const std::string& out, int frames, int size)
{
  std::vector<std::string> candidates;
  if (!dataDir.empty())
  {
    candidates.push_back(dataDir);
  }
  else
  {
    candidates = { "../shared/data/templeRing", LFD_SHARED_DATA_DIR "/templeRing" };
  }
  std::string par;
  for (const std::string& folder : candidates)
  {
    if (par.empty() && vtksys::SystemTools::FileExists(folder + "/templeR_par.txt", true))
    {
      par = folder + "/templeR_par.txt";
    }
  }
  if (par.empty())
  {
    Fail("templeRing not found (no templeR_par.txt in " + candidates.front() +
      (candidates.size() > 1 ? " nor " + candidates.back() : std::string()) +
      "): download templeRing.zip from https://vision.middlebury.edu/mview/data/, unzip it and "
      "pass its folder with --data DIR");
  }
  StagedFolder folder(out, "lfd demo", DemoFiles);
  const std::string& staged = folder.GetPath();
  ImportMiddlebury(par, staged + "/temple.lf", out + "/temple.lf");
  auto lightField = ReadLightField(staged + "/temple.lf");

  // The box: the dataset's published tight bounding box (templeRing
  // README.txt), 1 cm wider, its bottom face on the temple's base so the
  // cloth under it stays out. World y is the temple's vertical.
  const double low[3] = { -0.023121 - 0.01, -0.038009 - 0.002, -0.091940 - 0.01 };
  const double high[3] = { 0.078626 + 0.01, 0.121636 + 0.01, -0.017395 + 0.01 };
  vtkNew<vtkDeformationCage> cage;
  vtkIdType corners[8];
  for (int c = 0; c < 8; ++c)
  {
    // VTK hexahedron order: the bottom face counter-clockwise seen from +y.
    const bool x = c % 4 == 2 || c % 4 == 3, z = c % 4 == 1 || c % 4 == 2;
    const double corner[3] = {
      x ? high[0] : low[0], c < 4 ? low[1] : high[1], z ? high[2] : low[2]
    };
    corners[c] = cage->AddPoint(corner);
  }
  cage->AddBox(corners, 1);
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputData(cage);
  pose->SetModeToTwist();
  pose->SetAxis(1);
  const int keyframes = 8;
  vtkNew<vtkLightFieldScene> scene;
  scene->SetLightFieldPath("temple.lf");
  scene->SetCage(cage);
  for (int k = 0; k <= keyframes; ++k)
  {
    pose->SetAngle(60.0 * k / keyframes);
    Run(pose.Get(), "posing the cage");
    scene->AddKeyframe(k, pose->GetOutput()->GetPoints());
  }
  vtkCameraRig* rig = lightField->GetRig();
  if (!rig->HasCylinder()) // the importer fits the rig it builds
  {
    Fail(par + ": no ring could be fitted to the cameras");
  }
  vtkLightFieldSceneLogic::OrbitCamera(rig,
    vtkMath::Pi() / rig->GetNumberOfViews(),
    1.15,
    0.0,
    0.8 * rig->GetViewAngle(0),
    scene->GetCamera());
  scene->GetCamera()->SetFocalPoint(
    0.5 * (low[0] + high[0]), 0.5 * (low[1] + high[1]), 0.5 * (low[2] + high[2]));
  scene->SetWidth(size);
  scene->SetHeight(size);
  scene->SetObjectThreshold(60.0);
  WriteScene(scene, staged + "/temple.json");
  std::printf("scene     %s/temple.json (1 box over the unsplit light field, %d keyframes: top "
              "twisted 0-60 degrees)\n",
    out.c_str(),
    keyframes + 1);
  AnimateDemo(scene, lightField, frames, staged, out, "");
  folder.Commit();
}

}

void AddDemoCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  struct DemoOptions
  {
    std::string Scene = "fish";
    std::string Data;
    std::string Out;
    int Frames = 36;
    int Size = 512;
    SynthOptions Capture;
  };
  auto demo = std::make_shared<DemoOptions>();
  vtkNew<vtkLightFieldCapture> captureLimits;
  const int largestImage = captureLimits->GetWidthMaxValue();
  auto* demoCommand = app.add_subcommand("demo",
    "synthesise a built-in scene (default: the fish, in a cage of 3 boxes, swimming) and render "
    "its animation into the folder OUT: light field(s) *.lf, scene file(s) *.json, frames*/, "
    "contact_sheet*.png (MP4s with ffmpeg); replaces OUT when complete (an existing OUT may hold "
    "only such files); needs an X display (xvfb-run -a)");
  demoCommand
    ->add_option("--scene",
      demo->Scene,
      "fish: swimming, 3 boxes (Fig. 13); twist: the figure in one box, its top turned (Fig. 1); "
      "checkerboard: its top turned, captured under coaxial and under scene-fixed light (Figs. 4, "
      "5); temple: the real templeRing, unsplit, its top turned in one box (Fig. 1, see --data)")
    ->check(CLI::IsMember({ "fish", "twist", "checkerboard", "temple" }))
    ->capture_default_str();
  demoCommand->add_option("--data",
    demo->Data,
    "--scene temple: the templeRing folder (templeR_par.txt; default ../shared/data/templeRing, "
    "then " LFD_SHARED_DATA_DIR "/templeRing)");
  demoCommand->add_option(
    "--out", demo->Out, "output folder (default: lfd-demo, or lfd-demo-SCENE for the others)");
  numbers.Add(demoCommand, "--frames", demo->Frames, 1, MaximumFrames, "number of frames");
  numbers.Add(demoCommand, "--size", demo->Size, 1, largestImage, "frame width and height");
  numbers.Add(demoCommand,
    "--views",
    demo->Capture.Views,
    captureLimits->GetViewsPerRingMinValue(),
    captureLimits->GetViewsPerRingMaxValue(),
    "captured views per ring");
  numbers.Add(demoCommand,
    "--rows",
    demo->Capture.Rows,
    captureLimits->GetNumberOfRowsMinValue(),
    captureLimits->GetNumberOfRowsMaxValue(),
    "captured rings");
  numbers.Add(demoCommand,
    "--capture-size",
    demo->Capture.Width,
    captureLimits->GetWidthMinValue(),
    largestImage,
    "captured views' width and height");
  commands.push_back({ demoCommand,
    [demo]
    {
      demo->Capture.Height = demo->Capture.Width;
      if (demo->Scene == "temple")
      {
        DemoTemple(
          demo->Data, demo->Out.empty() ? "lfd-demo-temple" : demo->Out, demo->Frames, demo->Size);
        return;
      }
      const std::string out = !demo->Out.empty() ? demo->Out
        : demo->Scene == "fish"                  ? "lfd-demo"
                                                 : "lfd-demo-" + demo->Scene;
      Demo(demo->Scene, out, demo->Frames, demo->Size, demo->Capture);
    },
    true });
}
}
