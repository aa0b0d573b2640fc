// Regression image of the checkerboard captured under coaxial light from
// a ring of 8 views: view 0 (face-on) and view 1 (45 degrees) side by side.
#include "lfdSynthesisTestUtilities.h"
#include "vtkCellData.h"
#include "vtkPolyData.h"

int TestCheckerboardCapture(int argc, char* argv[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToCheckerboard();
  auto capture = lfdtest::RingCapture(source);
  capture->CaptureLabelOff();
  capture->CaptureDepthOff();
  capture->Update();

  // 8 x 8 checks of ceil(48 / 8) = 6 x 6 quads, two triangles each.
  vtkPolyData* mesh = source->GetOutput();
  lfdtest::Check(mesh->GetNumberOfCells() == 2 * 48 * 48,
    "checkerboard triangles",
    mesh->GetNumberOfCells(),
    2 * 48 * 48);
  lfdtest::Check(mesh->GetCellData()->GetArray("RGB") != nullptr &&
      mesh->GetCellData()->GetArray("Label") != nullptr,
    "cell arrays RGB and Label",
    1,
    1);
  vtkLightField* lightField = capture->GetOutput();

  // Face-on under coaxial light: white checks show their albedo, black
  // checks stay black, so the board averages about half white.
  vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
  const vtkIdType pixels = 128 * 128;
  int white = 0;
  int black = 0;
  int board = 0;
  for (int y = 0; y < 128; ++y)
  {
    for (int x = 0; x < 128; ++x)
    {
      double hit[3];
      if (!lfdtest::HitCheckerboardPlane(lightField->GetRig(), 0, x, y, hit) ||
        std::abs(hit[0]) > 0.47 || std::abs(hit[1]) > 0.47)
      {
        continue;
      }
      ++board;
      const double red = coaxial->GetComponent(lightField->GetPointIndex(0, x, y), 0);
      white += red > 240.0 ? 1 : 0;
      black += red < 5.0 ? 1 : 0;
    }
  }
  lfdtest::Check(board > pixels / 10, "board pixels in view 0", board, pixels / 10);
  lfdtest::Check(std::abs(white - black) < board / 10,
    "white minus black pixels, view 0",
    white - black,
    board / 10);
  lfdtest::Check(
    white + black > 0.9 * board, "pure white or black pixels, view 0", white + black, 0.9 * board);

  auto montage = lfdtest::CoaxialMontage(lightField, { 0, 1 });
  const bool matches = lfdtest::MatchesBaseline(argc, argv, montage, 0.05);
  return matches && lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
