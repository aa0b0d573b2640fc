// What vtkLightFieldRenderer keeps from one frame to the next (the label
// hull's screen tiles, the rig's layout, cameras and projections) follows
// everything it depends on: one renderer taken through a sequence of frames
// of the fish (vtkLightFieldCapture, a ring of 3 x 24 views of 64 x 64, its
// Label pass from its parts) gives, frame after frame, exactly the frame of
// a new renderer. The sequence changes the lens (the fish small in the
// image, then filling it: the tiles the hull skips differ), refocuses,
// swims the cage and poses it again (the drag the caches are for), leaves
// the view nearest the eye out, takes it back and turns it (a change of the
// rig alone: vtkLightField::GetMTime covers its rig); each step changes the
// image. Needs OpenGL (xvfb-run).
#include "lfdPinholeCamera.h"
#include "lfdTestChecks.h"
#include "vtkCagePoseFilter.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldRenderer.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using lfdtest::Expect;

int TestLightFieldRendererFrames(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> fish;
  fish->SetObjectToFish();
  fish->Update();
  auto* mesh = vtkPolyData::SafeDownCast(fish->GetOutputDataObject(0));
  double bounds[6];
  mesh->GetBounds(bounds);
  const double centre[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double reach = 0.5 * (bounds[1] - bounds[0]); // the fish lies along X
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double heights[3] = { -0.2 * reach, 0.0, 0.2 * reach };
  vtkNew<vtkCameraRig> rig;
  rig->MakeCylinder(centre, axis, 4.0 * reach, 24, 3, heights, 64, 64, 30.0);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(fish->GetOutputPort(0));
  capture->SetTextureConnection(fish->GetOutputPort(1));
  capture->SetRig(rig);
  capture->CaptureDepthOff();
  capture->Update();
  vtkLightField* lightField = capture->GetOutput();

  vtkNew<vtkPartCageSource> parts;
  parts->SetInputConnection(fish->GetOutputPort(0));
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(parts->GetOutputPort());
  pose->SetModeToSwim();
  pose->SetTurnAxis(0.0, 0.0, 1.0);

  // One eye 2.5 reaches in front of the fish, with a wide lens (the fish
  // small in the image: the label hull skips the tiles around it) and a
  // narrow one (the fish fills the image).
  vtkNew<vtkCamera> wide, narrow;
  for (vtkCamera* eye : { wide.Get(), narrow.Get() })
  {
    eye->SetPosition(centre[0], centre[1] + 0.3 * reach, centre[2] + 2.5 * reach);
    eye->SetFocalPoint(centre);
    eye->SetViewUp(0.0, 1.0, 0.0);
  }
  wide->SetViewAngle(80.0);
  narrow->SetViewAngle(30.0);
  // The view nearest the eye: its rays sample it most.
  const glm::dvec3 eye(wide->GetPosition()[0], wide->GetPosition()[1], wide->GetPosition()[2]);
  int nearest = 0;
  for (int v = 1; v < rig->GetNumberOfViews(); ++v)
  {
    if (glm::distance(rig->GetCamera(v).Center(), eye) <
      glm::distance(rig->GetCamera(nearest).Center(), eye))
    {
      nearest = v;
    }
  }

  struct Step
  {
    const char* What;
    vtkCamera* Eye;
    double Focal;  // vtkLightFieldRenderer::FocalDistance, in reaches
    double Swim;   // the cage's swim angle (0: no cage)
    int Excluded;  // a view left out (-1: none)
    bool TurnView; // the view nearest the eye turned before the frame
  };
  const Step steps[] = { { "the fish through a wide lens", wide, 0.0, 0.0, -1, false },
    { "through a narrow one", narrow, 0.0, 0.0, -1, false },
    { "through the wide one again", wide, 0.0, 0.0, -1, false },
    { "focused 0.2 reach nearer", narrow, -0.2, 0.0, -1, false },
    { "swimming", narrow, -0.2, 20.0, -1, false },
    { "swimming further", narrow, -0.2, 35.0, -1, false },
    { "the view nearest the eye left out", narrow, -0.2, 35.0, nearest, false },
    { "every view again", narrow, -0.2, 35.0, -1, false },
    { "the nearest turned by 2 degrees", narrow, -0.2, 35.0, -1, true } };
  const int size = 256;
  auto frame = [&](vtkLightFieldRenderer* renderer, const Step& step)
  {
    renderer->SetInputData(lightField);
    renderer->SetWidth(size);
    renderer->SetHeight(size);
    renderer->SetCamera(step.Eye);
    renderer->SetFocalDistance(step.Focal * reach);
    renderer->RemoveAllExcludedViews();
    if (step.Excluded >= 0)
    {
      renderer->AddExcludedView(step.Excluded);
    }
    vtkSmartPointer<vtkDeformationCage> cage;
    if (step.Swim > 0.0)
    {
      pose->SetAngle(step.Swim);
      pose->Update();
      cage = pose->GetOutput();
    }
    renderer->SetCageData(cage);
    renderer->Update();
    auto* pixels =
      vtkUnsignedCharArray::SafeDownCast(renderer->GetOutput()->GetPointData()->GetScalars());
    return std::vector<unsigned char>(pixels->GetPointer(0), pixels->GetPointer(3 * size * size));
  };
  vtkNew<vtkLightFieldRenderer> renderer; // kept from frame to frame
  std::vector<unsigned char> previous;
  int changed = 0, fishPixels = 0;
  for (const Step& step : steps)
  {
    if (step.TurnView)
    {
      // Turned by 2 degrees about its own y axis, its centre kept (t = -R C).
      vtkCameraRig* captured = lightField->GetRig();
      lfd::PinholeCamera camera = captured->GetCamera(nearest);
      const glm::dvec3 centreOfView = camera.Center();
      const double angle = 2.0 * vtkMath::Pi() / 180.0;
      // (glm is column-major: the rotation about y, column by column.)
      const glm::dmat3 turn(std::cos(angle),
        0.0,
        -std::sin(angle),
        0.0,
        1.0,
        0.0,
        std::sin(angle),
        0.0,
        std::cos(angle));
      camera.R = turn * camera.R;
      camera.t = -(camera.R * centreOfView);
      captured->SetView(nearest, camera);
      captured->FitCylinder(); // (any change of a view drops the fit)
    }
    vtkNew<vtkLightFieldRenderer> fresh;
    const std::vector<unsigned char> kept = frame(renderer, step);
    const std::vector<unsigned char> truth = frame(fresh, step);
    int differ = 0;
    for (std::size_t i = 0; i < kept.size(); ++i)
    {
      differ += kept[i] != truth[i];
    }
    Expect(differ == 0, std::string(step.What) + ": bytes unlike a new renderer's frame", differ);
    if (!previous.empty() && kept == previous)
    {
      std::cout << "unchanged: " << step.What << "\n";
    }
    changed += !previous.empty() && kept != previous;
    previous = kept;
    fishPixels = 0;
    for (int i = 0; i < size * size; ++i)
    {
      fishPixels += kept[3 * i] != 0 || kept[3 * i + 1] != 0 || kept[3 * i + 2] != 0;
    }
  }
  Expect(changed == 8, "steps that change the image (of 8)", changed);
  Expect(fishPixels > 2000, "pixels of the fish in the last frame (> 2000)", fishPixels);
  return lfdtest::Result();
}
