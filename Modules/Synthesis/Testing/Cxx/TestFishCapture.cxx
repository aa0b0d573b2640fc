// Regression image of the fish captured under coaxial light: the side view
// (view 0, from +Z) and the view from 45 degrees, side by side.
#include "lfdSynthesisTestUtilities.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>

#include <set>

int TestFishCapture(int argc, char* argv[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  auto capture = lfdtest::RingCapture(source);
  capture->CaptureDepthOff();
  capture->Update();

  // The mesh: normals, three labelled parts, about unit size at the origin.
  vtkPolyData* mesh = source->GetOutput();
  double range[2] = { -1, -1 };
  if (vtkDataArray* parts = mesh->GetCellData()->GetArray("Label"))
  {
    parts->GetRange(range);
  }
  lfdtest::Check(mesh->GetPointData()->GetNormals() != nullptr, "fish has normals", 1, 1);
  lfdtest::Check(range[0] == 1 && range[1] == 3, "fish labels span [1, 3]", range[1], 3);
  double bounds[6];
  mesh->GetBounds(bounds);
  lfdtest::Check(bounds[1] - bounds[0] > 1.0 && bounds[1] - bounds[0] < 1.5,
    "fish length",
    bounds[1] - bounds[0],
    1.5);
  lfdtest::Check(std::abs(bounds[0] + bounds[1]) < 0.2,
    "fish centred along X",
    0.5 * (bounds[0] + bounds[1]),
    0.1);
  lfdtest::Check(source->GetTextureOutput()->GetNumberOfPoints() == 1,
    "1 x 1 texture for a vertex-coloured object",
    source->GetTextureOutput()->GetNumberOfPoints(),
    1);
  vtkLightField* lightField = capture->GetOutput();

  // The fish is textured, not flat: its side view has many distinct colours.
  vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
  vtkDataArray* label = lightField->GetPass(vtkLightField::LABEL);
  std::set<int> colors;
  for (vtkIdType p = 0; p < 128 * 128; ++p)
  {
    if (label->GetComponent(p, 0) > 0)
    {
      colors.insert((static_cast<int>(coaxial->GetComponent(p, 0)) / 16) * 256 +
        static_cast<int>(coaxial->GetComponent(p, 1)) / 16 * 16 +
        static_cast<int>(coaxial->GetComponent(p, 2)) / 16);
    }
  }
  lfdtest::Check(colors.size() >= 20,
    "distinct colour bins on the fish, view 0",
    static_cast<double>(colors.size()),
    20);

  auto montage = lfdtest::CoaxialMontage(lightField, { 0, 1 });
  const bool matches = lfdtest::MatchesBaseline(argc, argv, montage, 0.05);
  return matches && lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
