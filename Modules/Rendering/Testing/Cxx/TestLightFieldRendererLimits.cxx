// The renderer's documented limits (lfdLimits.h): an output size above
// lfd::MaximumRenderSize, a subdivision above lfd::MaximumSubdivision and a
// tessellation above lfd::MaximumSubBoxes are refused with one line naming
// the setting, the number of boxes and the cost; "auto" (subdivision 0)
// lowers its largest k until the cage fits the budget instead.
#include "lfdLimits.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkCommand.h"
#include "vtkDeformationCage.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using lfdtest::Expect;

namespace TestLightFieldRendererLimitsHelpers
{
/// `columns` x `columns` boxes of side 0.4 side by side in the plane y = 0,
/// each with its own corners, the top face turned by `degrees` about y.
vtkSmartPointer<vtkDeformationCage> Boxes(int columns, double degrees)
{
  auto cage = vtkSmartPointer<vtkDeformationCage>::New();
  const double side = 0.4, turn = degrees * 3.14159265358979323846 / 180.0;
  for (int i = 0; i < columns; ++i)
  {
    for (int j = 0; j < columns; ++j)
    {
      const double cx = (i - 0.5 * (columns - 1)) * side, cz = (j - 0.5 * (columns - 1)) * side;
      vtkIdType ids[8];
      for (int c = 0; c < 8; ++c)
      {
        // VTK hexahedron order, counter-clockwise seen from +y.
        const double u = (c % 4 == 2 || c % 4 == 3) ? 0.5 : -0.5;
        const double w = (c % 4 == 1 || c % 4 == 2) ? 0.5 : -0.5;
        const double y = c < 4 ? -0.5 * side : 0.5 * side;
        const double a = c < 4 ? 0.0 : turn;
        const double rest[3] = { cx + u * side, y, cz + w * side };
        const double deformed[3] = { cx + side * (u * std::cos(a) + w * std::sin(a)),
          y,
          cz + side * (w * std::cos(a) - u * std::sin(a)) };
        ids[c] = cage->AddPoint(rest, deformed);
      }
      cage->AddBox(ids, 1);
    }
  }
  return cage;
}

/// Renders and returns the error text ("" when it succeeded).
std::string Render(vtkLightFieldRenderer* renderer)
{
  vtkNew<vtkTest::ErrorObserver> observer, pipeline;
  const unsigned long tag = renderer->AddObserver(vtkCommand::ErrorEvent, observer);
  // The executive's own "returned failure" line repeats the refusal.
  vtkExecutive* executive = renderer->GetExecutive();
  const unsigned long pipelineTag = executive->AddObserver(vtkCommand::ErrorEvent, pipeline);
  renderer->Update();
  renderer->RemoveObserver(tag);
  executive->RemoveObserver(pipelineTag);
  return observer->GetError() ? observer->GetErrorMessage() : std::string();
}

void ExpectRefusal(vtkLightFieldRenderer* renderer,
  const std::string& what,
  const std::string& text)
{
  const std::string message = Render(renderer);
  Expect(message.find(text) != std::string::npos,
    what + " is refused with \"" + text + "\"",
    message.empty() ? "(no error)" : message);
}

std::vector<unsigned char> Image(vtkLightFieldRenderer* renderer)
{
  auto* rgb =
    vtkUnsignedCharArray::SafeDownCast(renderer->GetOutput()->GetPointData()->GetScalars());
  return std::vector<unsigned char>(
    rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
}
}

int TestLightFieldRendererLimits(int, char*[])
{
  using namespace TestLightFieldRendererLimitsHelpers;
  // A ring of 36 views of 32 x 32 pixels seeing a uniform grey object.
  const int size = 32, views = 36;
  const double center[3] = { 0.0, 0.0, 0.0 }, axis[3] = { 0.0, 1.0, 0.0 }, height = 0.0;
  vtkNew<vtkLightField> lightField;
  lightField->SetLayout(size, size, views);
  lightField->GetRig()->MakeCylinder(center, axis, 4.0, views, 1, &height, size, size, 40.0);
  lightField->AllocatePass(vtkLightField::COAXIAL)->Fill(200.0);

  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(lightField);
  renderer->SetWidth(lfd::MaximumRenderSize + 1);
  renderer->SetHeight(size);
  ExpectRefusal(renderer,
    "a width of 16385",
    "Output size 16385 x 32 is outside the render size limits: width and height in [1, 16384]");
  renderer->SetWidth(size);
  renderer->SetHeight(0);
  ExpectRefusal(renderer, "a height of 0", "Output size 32 x 0 is outside");
  renderer->SetHeight(size);
  Expect(Render(renderer).empty(), "32 x 32 renders", "ok");

  renderer->SetCageData(Boxes(1, 30.0));
  renderer->SetSubdivision(lfd::MaximumSubdivision + 1);
  ExpectRefusal(renderer,
    "subdivision 17",
    "Subdivision 17 (render.subdivision) is outside [1, 16] (0 = auto): one box at k 16 already "
    "makes 4096 sub-boxes, the budget of a cage (lfd::MaximumSubBoxes).");
  renderer->SetSubdivision(-1);
  ExpectRefusal(renderer, "subdivision -1", "Subdivision -1 (render.subdivision) is outside");
  renderer->SetSubdivision(lfd::MaximumSubdivision);
  Expect(Render(renderer).empty(), "one box at subdivision 16 (4096 sub-boxes) renders", "ok");

  renderer->SetCageData(Boxes(3, 30.0));
  renderer->SetSubdivision(8);
  ExpectRefusal(renderer,
    "9 boxes at subdivision 8",
    "Subdivision 8 (render.subdivision) splits the cage's 9 boxes into 4608 sub-boxes, above the "
    "budget of 4096 (every ray tests every sub-box): lower it.");
  renderer->SetSubdivision(7);
  Expect(Render(renderer).empty(), "9 boxes at subdivision 7 (3087 sub-boxes) render", "ok");

  // Auto on 16 boxes that each want k = 8 (a tolerance no k meets): 16 x 8^3
  // and 16 x 7^3 are over the budget, so every box gets k = 6 (3456).
  renderer->SetCageData(Boxes(4, 30.0));
  renderer->SetSubdivisionTolerance(1e-9);
  renderer->SetSubdivision(6);
  Expect(Render(renderer).empty(), "16 boxes at subdivision 6 render", "ok");
  const std::vector<unsigned char> six = Image(renderer);
  renderer->SetSubdivision(0);
  const std::string automatic = Render(renderer);
  Expect(
    automatic.empty(), "16 boxes at subdivision auto render", automatic.empty() ? "ok" : automatic);
  Expect(Image(renderer) == six, "auto on 16 boxes renders as subdivision 6", "compared");

  renderer->SetCageData(Boxes(65, 0.0));
  ExpectRefusal(renderer,
    "4225 boxes at subdivision auto",
    "Subdivision auto (render.subdivision) splits the cage's 4225 boxes into 4225 sub-boxes, above "
    "the budget of 4096 (every ray tests every sub-box): use fewer boxes.");

  return lfdtest::Result();
}
