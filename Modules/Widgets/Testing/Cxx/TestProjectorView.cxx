// Painting a projector mask of the fish capture: a recorded stroke in the
// projector view changes exactly the mask pixels within the brush radius of
// its path (to the brush label's palette colour), as one undoable command of
// the scene logic that undo restores byte for byte; the coded view is
// re-rendered from the fish with the painted mask; the mask saves as a PNG
// that reads back equal. Regression image: mask beside the coded view.
#include "lfdWidgetsTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkImageFileReader.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleImage.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkPointData.h"
#include "vtkProjectorView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTesting.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<unsigned char> MaskBytes(vtkImageData* masks)
{
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(masks->GetPointData()->GetArray("Mask"));
  return std::vector<unsigned char>(
    rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
}

// Display position of mask pixel (i, j) (VTK rows) and back: what a mouse
// event at that position means in the image.
void ToDisplay(vtkRenderer* renderer, double i, double j, int position[2], double image[2])
{
  renderer->SetWorldPoint(i, j, 0.0, 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  position[0] = static_cast<int>(std::lround(display[0]));
  position[1] = static_cast<int>(std::lround(display[1]));
  renderer->SetDisplayPoint(position[0], position[1], 0.0);
  renderer->DisplayToWorld();
  const double* world = renderer->GetWorldPoint();
  image[0] = world[0] / world[3];
  image[1] = world[1] / world[3];
}

double SegmentDistance(double x, double y, const double a[2], const double b[2])
{
  const double d[2] = { b[0] - a[0], b[1] - a[1] };
  const double length2 = d[0] * d[0] + d[1] * d[1];
  const double f = length2 > 0.0
    ? std::min(1.0, std::max(0.0, ((x - a[0]) * d[0] + (y - a[1]) * d[1]) / length2))
    : 0.0;
  return std::hypot(x - a[0] - f * d[0], y - a[1] - f * d[1]);
}

// The painted mask of projector 1 (`painted`: every mask's RGB bytes, `slice`
// pixels each) saves as a PNG that reads back equal; a projector the light
// field has no mask for is refused with one error.
void CheckWrittenMask(vtkProjectorView* view,
  const std::vector<unsigned char>& painted,
  vtkIdType slice)
{
  const std::string file = std::string(LFD_TEST_TEMP_DIR) + "/TestProjectorView-mask1.png";
  lfdtest::Check(view->WriteMask(1, file.c_str()), "mask written", 1, 1);
  vtkNew<vtkImageFileReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataArray* read = reader->GetOutput()->GetPointData()->GetScalars();
  int readErrors = read && read->GetNumberOfTuples() == slice ? 0 : 1;
  for (vtkIdType q = 0; readErrors == 0 && q < slice; ++q)
  {
    for (int c = 0; c < 3; ++c)
    {
      readErrors += read->GetComponent(q, c) == painted[3 * (slice + q) + c] ? 0 : 1;
    }
  }
  lfdtest::Check(readErrors == 0, "PNG bytes different from the mask", readErrors, 0);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(view);
  const bool written = view->WriteMask(5, file.c_str());
  lfdtest::Check(!written &&
      std::string(errors->GetErrorMessage()).find("the light field has no mask for projector 5") !=
        std::string::npos,
    "projector 5 refused",
    written,
    0);
}
}

int TestProjectorView(int argc, char* argv[])
{
  lfdtest::Fish fish;
  lfdtest::MakeFish(fish);
  vtkLightField* lightField = fish.LightField;
  vtkImageData* masks = lightField->GetProjectorMasks();
  const std::vector<unsigned char> original = MaskBytes(masks);

  vtkNew<vtkLightFieldSceneLogic> logic;
  logic->SetLightField(lightField);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(480, 160);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleImage> style;
  interactor->SetInteractorStyle(style);
  interactor->Initialize();

  vtkNew<vtkProjectorView> view;
  view->SetRenderer(renderer);
  view->SetLightField(lightField);
  view->SetProjector(1);
  view->SetBrushRadius(3.0);
  view->SetBrushLabel(2);
  view->SetSimulationMesh(fish.Source->GetOutput());
  view->SetSimulationView(12);
  view->SetInteractor(interactor);
  view->On();
  view->ResetCamera();
  window->Render();
  vtkNew<vtkImageData> before;
  before->DeepCopy(view->GetSimulatedImage());
  std::cout << "coded view re-rendered in " << view->GetLastSimulationTime() << " ms\n";

  // Each stroke is applied through the scene logic.
  struct Applied
  {
    vtkLightFieldSceneLogic* Logic;
    vtkProjectorView* View;
    int Strokes = 0;
  } applied{ logic, view };
  vtkNew<vtkCallbackCommand> apply;
  apply->SetClientData(&applied);
  apply->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* data)
    {
      auto* a = static_cast<Applied*>(client);
      a->Strokes += a->Logic->SetProjectorMask(*static_cast<int*>(data), a->View->GetStrokeMask());
    });
  view->AddObserver(vtkProjectorView::MaskStrokeEvent, apply);

  // A stroke from mask pixel (10, 30) through (30, 20) to (50, 24).
  const double path[3][2] = { { 10, 30 }, { 30, 20 }, { 50, 24 } };
  int positions[3][2];
  double image[3][2];
  std::ostringstream events;
  for (int k = 0; k < 3; ++k)
  {
    ToDisplay(renderer, path[k][0], path[k][1], positions[k], image[k]);
    const char* what = k == 0 ? "LeftButtonPressEvent" : "MouseMoveEvent";
    if (k == 0)
    {
      events << "MouseMoveEvent " << positions[k][0] << " " << positions[k][1] << " 0 0 0 0 0\n";
    }
    events << what << " " << positions[k][0] << " " << positions[k][1] << " 0 0 0 0 0\n";
  }
  events << "LeftButtonReleaseEvent " << positions[2][0] << " " << positions[2][1]
         << " 0 0 0 0 0\n";
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(interactor);
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(events.str().c_str());
  recorder->Play();
  lfdtest::Check(applied.Strokes == 1, "strokes applied", applied.Strokes, 1);
  lfdtest::Check(
    logic->GetNumberOfCommands() == 1 && logic->GetUndoName() == "Paint projector mask",
    "one command \"Paint projector mask\"",
    logic->GetNumberOfCommands(),
    1);

  // Exactly the pixels within the radius of the path, in projector 1, are
  // the palette colour of label 2; every other byte is unchanged.
  const std::vector<unsigned char> painted = MaskBytes(masks);
  unsigned char colour[3];
  lightField->GetPalette()->GetTypedTuple(2, colour);
  const int* dims = masks->GetDimensions();
  const vtkIdType slice = static_cast<vtkIdType>(dims[0]) * dims[1];
  int wrong = 0, inBrush = 0, changed = 0;
  for (int p = 0; p < dims[2]; ++p)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        const vtkIdType at = 3 * (p * slice + static_cast<vtkIdType>(j) * dims[0] + i);
        const bool brush = p == 1 &&
          std::min(SegmentDistance(i, j, image[0], image[0]),
            std::min(SegmentDistance(i, j, image[0], image[1]),
              SegmentDistance(i, j, image[1], image[2]))) <= 3.0;
        inBrush += brush ? 1 : 0;
        for (int c = 0; c < 3; ++c)
        {
          const unsigned char expected = brush ? colour[c] : original[at + c];
          wrong += painted[at + c] == expected ? 0 : 1;
        }
        changed += std::equal(&painted[at], &painted[at] + 3, &original[at]) ? 0 : 1;
      }
    }
  }
  std::cout << "pixels under the brush: " << inBrush << ", changed: " << changed << "\n";
  lfdtest::Check(wrong == 0, "mask bytes different from the expected stroke", wrong, 0);
  lfdtest::Check(inBrush > 200 && changed > 0, "pixels under the brush", inBrush, 200);

  // The simulated coded view changed with the mask.
  window->Render();
  vtkImageData* after = view->GetSimulatedImage();
  const auto* a = static_cast<unsigned char*>(after->GetScalarPointer());
  const auto* b = static_cast<unsigned char*>(before->GetScalarPointer());
  const vtkIdType bytes = 3 * after->GetNumberOfPoints();
  const vtkIdType differing = bytes -
    std::inner_product(a,
      a + bytes,
      b,
      vtkIdType(0),
      std::plus<vtkIdType>(),
      [](unsigned char x, unsigned char y) { return x == y ? 1 : 0; });
  lfdtest::Check(differing > 0, "coded bytes changed by the stroke", differing, 0);
  std::cout << "coded view re-rendered in " << view->GetLastSimulationTime() << " ms\n";

  CheckWrittenMask(view, painted, slice);

  // Regression image with the painted stroke, then undo restores the masks
  // byte for byte, redo repaints them.
  const int result = vtkRegressionTestImage(window);
  logic->Undo();
  lfdtest::Check(MaskBytes(masks) == original, "undo restores the masks exactly", 1, 1);
  logic->Redo();
  lfdtest::Check(MaskBytes(masks) == painted, "redo repaints them", 1, 1);
  return (lfdtest::Failures() == 0 && result != vtkRegressionTester::FAILED) ? 0 : 1;
}
