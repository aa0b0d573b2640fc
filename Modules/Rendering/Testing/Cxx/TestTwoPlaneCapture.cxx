// A synthetic two-plane light field (Levoy and Hanrahan 1996): the fish
// captured by vtkLightFieldCapture from a 5 x 5 grid of cameras 0.1 apart
// on the plane z = 3, looking along -Z, 64 x 64 pixels (one part: the mesh's
// labels removed). Rendered by vtkLightFieldRenderer at a novel camera on the
// plane between the cameras, focused on the fish's centre plane, against the
// mesh itself captured from that camera (PSNR over the object); then under a
// one-box cage that moves the fish, against the mesh moved by the same map
// (vtkCageTransform): the two-plane lookup runs through the same RENDER_VIEW
// as a ring. Needs OpenGL (xvfb-run).
#include "vtkCageTransform.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
int failures = 0;

void Expect(bool ok, const char* what, double value)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << "\n";
  failures += ok ? 0 : 1;
}

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
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  source->SetResolution(24);
  source->Update();
  vtkNew<vtkPolyData> fish;
  fish->DeepCopy(source->GetOutput());
  fish->GetCellData()->RemoveArray("Label");

  const double gridCentre[3] = { 0.0, 0.0, 3.0 };
  vtkSmartPointer<vtkLightField> lightField = Capture(fish, gridCentre, 5);
  Expect(lightField->GetRig()->IsTwoPlane(), "the captured grid is a two-plane rig", 1);

  // At a captured camera, the render is its photo: all the weight on it,
  // the focal point projected back onto the pixel it came from.
  const double ownCentre[3] = { 0.1, -0.1, 3.0 };
  vtkSmartPointer<vtkLightField> own = Capture(fish, ownCentre, 1);
  const double captured = ObjectPSNR(Render(lightField, own, nullptr), own);
  Expect(captured == 100.0, "at captured view 18's camera, object PSNR dB (100: equal)", captured);
  // A novel camera on the plane, between four cameras. (Measured 20.0 dB:
  // 26.0 over the pixels where both show the fish, the rest is the 38
  // pixels of its silhouette, each the fish or background in one image.)
  const double eyeCentre[3] = { 0.05, 0.04, 3.0 };
  vtkSmartPointer<vtkLightField> truth = Capture(fish, eyeCentre, 1);
  const double novel = ObjectPSNR(Render(lightField, truth, nullptr), truth);
  Expect(novel > 19.0, "novel view vs the mesh captured there, object PSNR dB (> 19)", novel);

  // One box around the fish, moved by (0.08, -0.05, 0.1).
  double bounds[6];
  fish->GetBounds(bounds);
  vtkNew<vtkDeformationCage> cage;
  const double move[3] = { 0.08, -0.05, 0.1 };
  vtkIdType corners[8];
  for (int c = 0; c < 8; ++c)
  {
    // VTK hexahedron order: 0-3 the bottom face counter-clockwise, 4-7 above.
    const int x = ((c & 3) == 1 || (c & 3) == 2) ? 1 : 0;
    const int y = (c & 3) >= 2 ? 1 : 0;
    const int z = c >= 4 ? 1 : 0;
    const double rest[3] = { bounds[x] + (x ? 0.05 : -0.05),
      bounds[2 + y] + (y ? 0.05 : -0.05),
      bounds[4 + z] + (z ? 0.05 : -0.05) };
    const double deformed[3] = { rest[0] + move[0], rest[1] + move[1], rest[2] + move[2] };
    corners[c] = cage->AddPoint(rest, deformed);
  }
  cage->AddBox(corners, 1);
  vtkNew<vtkCageTransform> map;
  map->SetCage(cage);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(fish);
  moved->SetTransform(map);
  moved->Update();
  vtkSmartPointer<vtkLightField> movedTruth = Capture(moved->GetOutput(), eyeCentre, 1);
  const double deformed = ObjectPSNR(Render(lightField, truth, cage), movedTruth);
  const double unmoved = ObjectPSNR(Render(lightField, truth, nullptr), movedTruth);
  // (Measured 21.3 dB.)
  Expect(deformed > 20.0, "under the moved box vs the moved mesh, object PSNR dB (> 20)", deformed);
  Expect(unmoved < deformed - 6.0, "without the cage vs the moved mesh (6 dB lower)", unmoved);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
