// Coaxial versus scene-fixed light on the checkerboard (Chen et al. 2005,
// Fig. 5). The white checks are compared pixel by pixel with the shading
// model 255 (a + (1 - a) max(0, n . l)), n facing the camera, l towards the
// lamp: the lamp at the camera (coaxial) or at the centre of view 0 (fixed).
// Under coaxial light the board looks the same from the front (view 1, 45
// degrees) and from behind (view 3, 135 degrees); under the fixed light the
// back of the board gets ambient light only.
#include "lfdSynthesisTestUtilities.h"

#include <cmath>

namespace
{
constexpr int Size = 96;
constexpr double Ambient = 0.1;

// Mean red value of the white checks in a view and the mean absolute
// difference from the shading model.
void MeasureWhite(vtkLightField* lightField, int view, bool fixedLight, double& mean, double& error)
{
  vtkCameraRig* rig = lightField->GetRig();
  vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
  double lamp[3], eye[3];
  rig->GetCameraCenter(fixedLight ? 0 : view, lamp);
  rig->GetCameraCenter(view, eye);
  double sum = 0.0;
  double sumError = 0.0;
  int count = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      double hit[3];
      if (!lfdtest::HitCheckerboardPlane(rig, view, x, y, hit) || std::abs(hit[0]) >= 0.5 ||
        std::abs(hit[1]) >= 0.5)
      {
        continue;
      }
      // Keep pixels well inside a white check (checks are 1/8 wide).
      const double u = 8.0 * (hit[0] + 0.5);
      const double v = 8.0 * (hit[1] + 0.5);
      const int i = static_cast<int>(u);
      const int j = static_cast<int>(v);
      if ((i + j) % 2 != 0 || u - i < 0.25 || u - i > 0.75 || v - j < 0.25 || v - j > 0.75)
      {
        continue;
      }
      const double normal[3] = { 0.0, 0.0, eye[2] > 0.0 ? 1.0 : -1.0 };
      double toLamp[3];
      vtkMath::Subtract(lamp, hit, toLamp);
      vtkMath::Normalize(toLamp);
      const double model =
        255.0 * (Ambient + (1.0 - Ambient) * std::max(0.0, vtkMath::Dot(normal, toLamp)));
      const double red = coaxial->GetComponent(lightField->GetPointIndex(view, x, y), 0);
      sum += red;
      sumError += std::abs(red - model);
      ++count;
    }
  }
  mean = count ? sum / count : 0.0;
  error = count ? sumError / count : 1e9;
}
}

int TestCoaxialVersusSceneLight(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToCheckerboard();
  auto capture = lfdtest::RingCapture(source, Size);
  capture->SetAmbient(Ambient);
  capture->CaptureLabelOff();
  capture->CaptureDepthOff();

  double coaxial[4], fixed[4];
  for (bool fixedLight : { false, true })
  {
    capture->SetSceneFixedLight(fixedLight);
    capture->Update();
    for (int view : { 0, 1, 3 })
    {
      double mean, error;
      MeasureWhite(capture->GetOutput(), view, fixedLight, mean, error);
      (fixedLight ? fixed : coaxial)[view] = mean;
      std::cout << (fixedLight ? "fixed  " : "coaxial") << " view " << view << ": white mean "
                << mean << "\n";
      lfdtest::Check(error < 3.0, "mean |white - Lambert model|", error, 3.0);
    }
  }
  // Coaxial: oblique views front and back look alike, at cos(45 deg).
  const double oblique = 255.0 * (Ambient + (1.0 - Ambient) * std::sqrt(0.5));
  lfdtest::Check(std::abs(coaxial[1] - oblique) < 5.0,
    "coaxial view 1 near 255 (a + (1-a) cos 45)",
    coaxial[1],
    oblique);
  lfdtest::Check(std::abs(coaxial[1] - coaxial[3]) < 2.0,
    "coaxial |view 1 - view 3|",
    std::abs(coaxial[1] - coaxial[3]),
    2.0);
  // Fixed: the same face-on image at view 0; front lit, back dark.
  lfdtest::Check(std::abs(coaxial[0] - fixed[0]) < 0.5,
    "view 0 identical under both lights",
    std::abs(coaxial[0] - fixed[0]),
    0.5);
  lfdtest::Check(fixed[1] > coaxial[1] + 30.0,
    "fixed light brighter on the front at 45 deg",
    fixed[1] - coaxial[1],
    30.0);
  lfdtest::Check(fixed[3] < coaxial[3] - 100.0,
    "fixed light darker on the back at 135 deg",
    coaxial[3] - fixed[3],
    100.0);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
