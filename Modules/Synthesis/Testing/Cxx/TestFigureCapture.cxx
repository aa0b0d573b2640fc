// Regression image of the textured figure captured under coaxial light:
// views 0 (from +Z) and 1 (45 degrees) side by side. The texture reaches
// the capture through input port 1.
#include "lfdSynthesisTestUtilities.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <set>

int TestFigureCapture(int argc, char* argv[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFigure();
  source->Update();
  const int textureSize = source->GetTextureOutput()->GetDimensions()[0];
  lfdtest::Check(textureSize == vtkProceduralObjectSource::GetTextureSize(),
    "texture image side",
    textureSize,
    vtkProceduralObjectSource::GetTextureSize());
  lfdtest::Check(source->GetOutput()->GetPointData()->GetTCoords() != nullptr,
    "figure has texture coordinates",
    1,
    1);

  auto capture = lfdtest::RingCapture(source);
  capture->SetTextureConnection(source->GetOutputPort(1));
  capture->CaptureDepthOff();
  capture->Update();
  vtkLightField* lightField = capture->GetOutput();

  // All three parts are seen, and the texture's red checks and navy bands
  // both show on the figure.
  vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
  vtkDataArray* label = lightField->GetPass(vtkLightField::LABEL);
  std::set<int> labels;
  int reddish = 0;
  int bluish = 0;
  for (vtkIdType p = 0; p < 128 * 128; ++p)
  {
    labels.insert(static_cast<int>(label->GetComponent(p, 0)));
    const double r = coaxial->GetComponent(p, 0);
    const double b = coaxial->GetComponent(p, 2);
    reddish += (label->GetComponent(p, 0) > 0 && r > 2.0 * b + 20) ? 1 : 0;
    bluish += (label->GetComponent(p, 0) > 0 && b > 1.5 * r + 20) ? 1 : 0;
  }
  lfdtest::Check(labels == std::set<int>{ 0, 1, 2, 3 },
    "labels seen in view 0 are {0,1,2,3}",
    static_cast<double>(labels.size()),
    4);
  lfdtest::Check(reddish > 50, "red texture pixels, view 0", reddish, 50);
  lfdtest::Check(bluish > 20, "navy texture pixels, view 0", bluish, 20);

  auto montage = lfdtest::CoaxialMontage(lightField, { 0, 1 });
  const bool matches = lfdtest::MatchesBaseline(argc, argv, montage, 0.05);
  return matches && lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
