// Regression image of the textured figure captured under coaxial light:
// views 0 (from +Z) and 1 (45 degrees) side by side. The texture reaches
// the capture through input port 1. Prefiltered (Supersample 2), a 64 x 64
// capture is exactly the 2 x 2 means of the 128 x 128 one, with the
// point-sampled Label pass of a plain 64 x 64 capture; its projector passes
// (Coded, Flood) are the 2 x 2 means too, within rounding.
#include "lfdSynthesisTestUtilities.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

#include <cstring>
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

  // Two projectors of 64 x 64 painting the 3 parts (the same masks at
  // every capture size).
  vtkNew<vtkUnsignedCharArray> palette;
  palette->SetNumberOfComponents(3);
  const unsigned char colours[4][3] = {
    { 0, 0, 0 }, { 230, 40, 30 }, { 30, 200, 60 }, { 40, 60, 220 }
  };
  for (const auto& colour : colours)
  {
    palette->InsertNextTypedTuple(colour);
  }
  const auto project = [&](vtkLightFieldCapture* projected)
  {
    projected->SetPalette(palette);
    projected->SetNumberOfProjectors(2);
    projected->SetProjectorWidth(64);
    projected->SetProjectorHeight(64);
  };
  auto capture = lfdtest::RingCapture(source);
  capture->SetTextureConnection(source->GetOutputPort(1));
  capture->CaptureDepthOff();
  project(capture);
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

  auto prefiltered = lfdtest::RingCapture(source, 64);
  prefiltered->SetTextureConnection(source->GetOutputPort(1));
  prefiltered->CaptureDepthOff();
  prefiltered->SetSupersample(2);
  project(prefiltered);
  prefiltered->Update();
  auto pointSampled = lfdtest::RingCapture(source, 64);
  pointSampled->CaptureCoaxialOff();
  pointSampled->CaptureDepthOff();
  pointSampled->Update();
  vtkDataArray* mean = prefiltered->GetOutput()->GetPass(vtkLightField::COAXIAL);
  vtkDataArray* meanLabel = prefiltered->GetOutput()->GetPass(vtkLightField::LABEL);
  vtkDataArray* plainLabel = pointSampled->GetOutput()->GetPass(vtkLightField::LABEL);
  int wrongMeans = 0;
  int wrongLabels = 0;
  int wrongProjected = 0;
  const int projected[2] = { vtkLightField::CODED, vtkLightField::FLOOD };
  for (vtkIdType view = 0; view < 8; ++view)
  {
    for (vtkIdType y = 0; y < 64; ++y)
    {
      for (vtkIdType x = 0; x < 64; ++x)
      {
        const vtkIdType p = view * 64 * 64 + y * 64 + x;
        const vtkIdType fine = view * 128 * 128 + 2 * y * 128 + 2 * x;
        for (int c = 0; c < 3; ++c)
        {
          const int sum =
            static_cast<int>(coaxial->GetComponent(fine, c) + coaxial->GetComponent(fine + 1, c) +
              coaxial->GetComponent(fine + 128, c) + coaxial->GetComponent(fine + 129, c));
          wrongMeans += static_cast<int>(mean->GetComponent(p, c)) != (sum + 2) / 4 ? 1 : 0;
        }
        wrongLabels += meanLabel->GetComponent(p, 0) != plainLabel->GetComponent(p, 0) ? 1 : 0;
        // Each 128 x 128 pixel was rounded before this mean: 1 level apart at most.
        for (int pass : projected)
        {
          vtkDataArray* full = lightField->GetPass(pass);
          vtkDataArray* half = prefiltered->GetOutput()->GetPass(pass);
          for (int c = 0; c < 3; ++c)
          {
            const double sum = full->GetComponent(fine, c) + full->GetComponent(fine + 1, c) +
              full->GetComponent(fine + 128, c) + full->GetComponent(fine + 129, c);
            wrongProjected += std::abs(half->GetComponent(p, c) - sum / 4.0) > 1.0 ? 1 : 0;
          }
        }
      }
    }
  }
  lfdtest::Check(wrongMeans == 0, "prefiltered pixels that are not the 2 x 2 mean", wrongMeans, 0);
  lfdtest::Check(
    wrongLabels == 0, "prefiltered Label pixels not the point-sampled ones", wrongLabels, 0);
  lfdtest::Check(wrongProjected == 0,
    "prefiltered Coded and Flood values more than 1 level from the 2 x 2 mean",
    wrongProjected,
    0);
  const char* provenance = prefiltered->GetOutput()->GetProvenance();
  lfdtest::Check(provenance && std::strstr(provenance, "\"supersample\": 2"),
    "provenance records \"supersample\": 2",
    provenance ? 1 : 0,
    1);

  auto montage = lfdtest::CoaxialMontage(lightField, { 0, 1 });
  const bool matches = lfdtest::MatchesBaseline(argc, argv, montage, 0.05);
  return matches && lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
