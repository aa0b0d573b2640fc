// The rig of vtkLightFieldCapture: layout, automatic framing and row
// spacing, progress events, pass selection and capture from a given rig
// (refused when it has lens distortion).
#include "lfdSynthesisTestUtilities.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"

#include <string>

#include <vector>

namespace
{
void RecordProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData));
}

// Pixels of the Label pass with a label on the image border, over all views.
int BorderLabels(vtkLightField* lightField)
{
  vtkDataArray* label = lightField->GetPass(vtkLightField::LABEL);
  const int w = lightField->GetWidth();
  const int h = lightField->GetHeight();
  int count = 0;
  for (int view = 0; view < lightField->GetNumberOfViews(); ++view)
  {
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const bool border = x == 0 || y == 0 || x == w - 1 || y == h - 1;
        count += (border && label->GetComponent(lightField->GetPointIndex(view, x, y), 0) > 0);
      }
    }
  }
  return count;
}
}

int TestLightFieldCaptureRig(int, char*[])
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  source->SetResolution(16);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(source->GetOutputPort());
  capture->SetViewsPerRing(6);
  capture->SetNumberOfRows(2);
  capture->SetWidth(40);
  capture->SetHeight(30);
  capture->CaptureDepthOff();
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(RecordProgress);
  observer->SetClientData(&progress);
  capture->AddObserver(vtkCommand::ProgressEvent, observer);
  capture->Update();
  vtkLightField* lightField = capture->GetOutput();

  int dims[3];
  lightField->GetDimensions(dims);
  lfdtest::Check(dims[0] == 40 && dims[1] == 30 && dims[2] == 12,
    "dimensions 40 x 30 x 12",
    dims[0] * 10000 + dims[1] * 100 + dims[2],
    403012);
  lfdtest::Check(
    lightField->GetPass(vtkLightField::DEPTH) == nullptr, "no Depth pass when off", 0, 0);

  // One progress event per view (the executive adds 0 and 1 around them),
  // never decreasing, ending at 1.
  int decreasing = 0;
  for (size_t i = 1; i < progress.size(); ++i)
  {
    decreasing += progress[i] < progress[i - 1] ? 1 : 0;
  }
  lfdtest::Check(
    progress.size() >= 12, "progress events", static_cast<double>(progress.size()), 12);
  lfdtest::Check(decreasing == 0, "progress steps that decrease", decreasing, 0);
  lfdtest::Check(!progress.empty() && progress.back() == 1.0,
    "last progress",
    progress.empty() ? -1.0 : progress.back(),
    1.0);

  // The cylinder: 2 rows, 0.05 x radius apart, and the fish framed in every
  // view (no label on the image border).
  vtkCameraRig* rig = lightField->GetRig();
  lfdtest::Check(
    rig->HasCylinder() && rig->GetNumberOfRows() == 2, "fitted rows", rig->GetNumberOfRows(), 2);
  const double spacing = rig->GetRowHeight(1) - rig->GetRowHeight(0);
  lfdtest::Check(std::abs(spacing - 0.05 * rig->GetRadius()) < 1e-6 * rig->GetRadius(),
    "row spacing - 0.05 radius",
    spacing - 0.05 * rig->GetRadius(),
    1e-6);
  const int border = BorderLabels(lightField);
  lfdtest::Check(border == 0, "label pixels on the image border", border, 0);
  lfdtest::Check(
    rig->GetRadius() > 1.0 && rig->GetRadius() < 5.0, "automatic radius", rig->GetRadius(), 5.0);

  // Capture from a given rig: its views and image size win.
  vtkNew<vtkCameraRig> given;
  const double center[3] = { 0.0, 0.0, 0.0 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double heights[1] = { 0.2 };
  given->MakeCylinder(center, axis, 3.0, 5, 1, heights, 24, 20, 35.0);
  capture->SetRig(given);
  capture->Update();
  lightField->GetDimensions(dims);
  lfdtest::Check(dims[0] == 24 && dims[1] == 20 && dims[2] == 5,
    "dimensions from the given rig",
    dims[0] * 10000 + dims[1] * 100 + dims[2],
    242005);
  double c0[3], c1[3];
  given->GetCameraCenter(3, c0);
  lightField->GetRig()->GetCameraCenter(3, c1);
  lfdtest::Check(std::sqrt(vtkMath::Distance2BetweenPoints(c0, c1)) < 1e-12,
    "camera 3 of the output rig is the given one",
    std::sqrt(vtkMath::Distance2BetweenPoints(c0, c1)),
    1e-12);

  // A rig with lens distortion is refused: the views are rendered as ideal
  // pinholes, which would not be the images its calibration describes.
  const double lens[5] = { -0.2, 0.05, 1e-3, -5e-4, 0.0 };
  given->SetDistortion(2, lens);
  vtkNew<vtkLightFieldErrorObserver> lensErrors;
  lensErrors->Observe(capture);
  capture->Modified();
  capture->Update();
  const bool lensRefused = lensErrors->HasError() &&
    std::string(lensErrors->GetErrorMessage())
        .find("The rig has lens distortion; vtkLightFieldCapture renders "
              "ideal pinhole views only") != std::string::npos;
  lfdtest::Check(lensRefused, "rig with lens distortion refused", lensRefused, 1);

  // An empty mesh is refused with an error that says so.
  vtkNew<vtkLightFieldCapture> refusing;
  vtkNew<vtkPolyData> empty;
  refusing->SetInputData(empty);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(refusing);
  refusing->Update();
  const bool refused = std::string(errors->GetErrorMessage()) == "The input mesh has no cells.";
  lfdtest::Check(refused, "empty mesh refused with \"no cells\"", refused, 1);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
