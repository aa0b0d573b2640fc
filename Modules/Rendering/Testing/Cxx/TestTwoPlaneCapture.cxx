// A synthetic two-plane light field (Levoy and Hanrahan 1996): the fish
// (head, body, tail: its Label pass splits it) captured by
// vtkLightFieldCapture from a 5 x 5 grid of cameras 0.1 apart on the plane
// z = 3, looking along -Z, 64 x 64 pixels. Rendered by vtkLightFieldRenderer
// at a captured camera (its photo, exactly) and at a novel camera on the plane
// between four cameras, focused on the fish's centre plane, against the mesh
// captured from there (PSNR over the object); then under the cage of its
// parts swimming, against the mesh moved by the same map (vtkCageTransform):
// the two-plane lookup runs through the same RENDER_VIEW as a ring. Needs
// OpenGL (xvfb-run).
#include "lfdTestChecks.h"
#include "vtkCagePoseFilter.h"
#include "vtkCageTransform.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <iostream>
#include <vector>

using lfdtest::Expect;

namespace TestTwoPlaneCaptureHelpers
{
constexpr int Size = 64;
const double Forward[3] = { 0.0, 0.0, -1.0 };
const double Up[3] = { 0.0, 1.0, 0.0 };

/// The light field of `mesh` from a `side` x `side` grid centred on `centre`
/// (one view: a single camera there).
vtkSmartPointer<vtkLightField> Capture(vtkPolyData* mesh, const double centre[3], int side)
{
  vtkNew<vtkCameraRig> rig;
  rig->MakePlaneGrid(centre, Forward, Up, side, side, 0.1, Size, Size, 30.0);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputData(mesh);
  capture->SetRig(rig);
  capture->CaptureDepthOff();
  capture->Update();
  return capture->GetOutput();
}

/// The render of `lightField` from view 0 of `eye`, focused at depth 3
/// (the plane z = 0), through `cage` when given.
vtkSmartPointer<vtkImageData> Render(vtkLightField* lightField,
  vtkLightField* eye,
  vtkDeformationCage* cage)
{
  double K[9], R[9], t[3];
  eye->GetRig()->GetIntrinsics(0, K);
  eye->GetRig()->GetRotation(0, R);
  eye->GetRig()->GetTranslation(0, t);
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(lightField);
  renderer->SetCageData(cage);
  renderer->SetPinhole(K, R, t);
  renderer->SetWidth(Size);
  renderer->SetHeight(Size);
  renderer->SetFocalDepth(3.0);
  renderer->Update();
  return renderer->GetOutput();
}

/// PSNR of a render against view 0 of a capture, over the pixels where
/// either shows the object.
double ObjectPSNR(vtkImageData* render, vtkLightField* truth)
{
  auto* rendered = vtkUnsignedCharArray::SafeDownCast(render->GetPointData()->GetScalars());
  auto* renderedLabels =
    vtkUnsignedCharArray::SafeDownCast(render->GetPointData()->GetArray("Label"));
  auto* captured = vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::COAXIAL));
  auto* capturedLabels = vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::LABEL));
  std::vector<unsigned char> mask(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    mask[i] = renderedLabels->GetValue(i) > 0 || capturedLabels->GetValue(i) > 0;
  }
  return vtkLeaveOneOutEvaluator::ComputePSNR(
    rendered->GetPointer(0), captured->GetPointer(0), mask.data(), Size * Size);
}
}

int TestTwoPlaneCapture(int, char*[])
{
  using namespace TestTwoPlaneCaptureHelpers;
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  source->SetResolution(24);
  source->Update();
  vtkPolyData* fish = source->GetOutput();

  const double gridCentre[3] = { 0.0, 0.0, 3.0 };
  vtkSmartPointer<vtkLightField> lightField = Capture(fish, gridCentre, 5);
  Expect(lightField->GetRig()->IsTwoPlane(), "the captured grid is a two-plane rig", 1);

  // At a captured camera, the render is its photo: all the weight on it,
  // the focal point projected back onto the pixel it came from.
  const double ownCentre[3] = { 0.1, -0.1, 3.0 };
  vtkSmartPointer<vtkLightField> own = Capture(fish, ownCentre, 1);
  const double captured = ObjectPSNR(Render(lightField, own, nullptr), own);
  Expect(captured == 100.0, "at captured view 18's camera, object PSNR dB (100: equal)", captured);
  // A novel camera on the plane, between four cameras. (Measured 19.9 dB,
  // most of the loss on the fish's silhouette: each of its pixels is the fish
  // in one image and background in the other; 64 x 64 pixels are coarse.)
  const double eyeCentre[3] = { 0.05, 0.04, 3.0 };
  vtkSmartPointer<vtkLightField> truth = Capture(fish, eyeCentre, 1);
  const double novel = ObjectPSNR(Render(lightField, truth, nullptr), truth);
  Expect(novel > 19.0, "novel view vs the mesh captured there, object PSNR dB (> 19)", novel);

  // The cage of its 3 parts (a box per label), swimming (a 20 degree wave
  // about Z: the parts turn in the image plane, the tail over the body).
  vtkNew<vtkPartCageSource> parts;
  parts->SetInputData(fish);
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(parts->GetOutputPort());
  pose->SetModeToSwim();
  pose->SetAngle(20.0);
  pose->SetPhase(1.0);
  pose->SetTurnAxis(0.0, 0.0, 1.0);
  pose->Update();
  vtkDeformationCage* cage = pose->GetOutput();
  vtkNew<vtkCageTransform> map;
  map->SetCage(cage);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(fish);
  moved->SetTransform(map);
  moved->Update();
  vtkSmartPointer<vtkLightField> movedTruth = Capture(moved->GetOutput(), eyeCentre, 1);
  const double deformed = ObjectPSNR(Render(lightField, truth, cage), movedTruth);
  const double unmoved = ObjectPSNR(Render(lightField, truth, nullptr), movedTruth);
  Expect(deformed > 20.0,
    "swimming parts vs the mesh swum by the same map, object PSNR dB (> 20)",
    deformed);
  Expect(unmoved < deformed - 3.0, "without the cage vs the swum mesh (3 dB lower)", unmoved);
  return lfdtest::Result();
}
