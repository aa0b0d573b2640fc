// The rig view of the fish capture (2 rows of 12 cameras, 2 projectors):
// frusta coloured by row, projector frusta, fitted axis and rings, the cage
// and the object bounds; a recorded click on a camera frustum selects that
// view (ViewSelectedEvent), a click on the background selects none.
#include "lfdWidgetsTestUtilities.h"

#include "lfdPinholeCamera.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraFrustumSource.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRigView.h"

#include <cmath>
#include <sstream>

namespace
{
std::string Click(int x, int y)
{
  std::ostringstream events;
  events << "MouseMoveEvent " << x << " " << y << " 0 0 0 0 0\n"
         << "LeftButtonPressEvent " << x << " " << y << " 0 0 0 0 0\n"
         << "LeftButtonReleaseEvent " << x << " " << y << " 0 0 0 0 0\n";
  return events.str();
}
}

int TestRigView(int argc, char* argv[])
{
  lfdtest::Fish fish;
  lfdtest::MakeFish(fish, 2);
  vtkCameraRig* rig = fish.LightField->GetRig();

  // The frusta: 5 polygons per view, cell data naming the view and its row.
  vtkNew<vtkCameraFrustumSource> frusta;
  frusta->SetRig(rig);
  frusta->Update();
  vtkPolyData* polygons = frusta->GetOutput();
  lfdtest::Check(
    polygons->GetNumberOfCells() == 5 * 24, "frustum polygons", polygons->GetNumberOfCells(), 120);
  vtkDataArray* rows = polygons->GetCellData()->GetArray("Row");
  vtkDataArray* viewIds = polygons->GetCellData()->GetArray("View");
  int rowErrors = 0;
  for (vtkIdType cell = 0; cell < polygons->GetNumberOfCells(); ++cell)
  {
    const int v = static_cast<int>(viewIds->GetComponent(cell, 0));
    rowErrors += v == cell / 5 && rows->GetComponent(cell, 0) == rig->GetRow(v) ? 0 : 1;
  }
  lfdtest::Check(rowErrors == 0, "cells with the wrong View or Row", rowErrors, 0);
  lfdtest::Check(rig->GetNumberOfRows() == 2, "rows", rig->GetNumberOfRows(), 2);
  // The apex is the camera centre (to float precision), the base at the
  // used depth.
  const glm::dvec3 centre = rig->GetCamera(5).Center();
  double apex[3];
  polygons->GetPoint(5 * 5, apex);
  lfdtest::Check(glm::length(glm::dvec3(apex[0], apex[1], apex[2]) - centre) < 1e-6,
    "apex of view 5 at its centre",
    glm::length(glm::dvec3(apex[0], apex[1], apex[2]) - centre),
    1e-6);
  lfdtest::Check(std::abs(frusta->GetUsedDepth() - 0.25 * rig->GetRadius()) < 1e-12,
    "depth = radius / 4",
    frusta->GetUsedDepth(),
    0.25 * rig->GetRadius());

  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->Initialize();

  vtkNew<vtkRigView> view;
  view->SetRenderer(renderer);
  view->SetLightField(fish.LightField);
  view->SetCage(fish.Cage);
  double bounds[6];
  fish.Source->GetOutput()->GetBounds(bounds);
  view->SetObjectBounds(bounds);
  view->SetInteractor(interactor);
  view->On();
  view->ResetCamera();
  window->Render();

  int selected = -100;
  vtkNew<vtkCallbackCommand> onSelect;
  onSelect->SetClientData(&selected);
  onSelect->SetCallback([](vtkObject*, unsigned long, void* client, void* data)
    { *static_cast<int*>(client) = *static_cast<int*>(data); });
  view->AddObserver(vtkRigView::ViewSelectedEvent, onSelect);

  // Click inside the frustum of the camera nearest the eye: the projection
  // of a point on its optical axis, half way to the base.
  const double* eye = renderer->GetActiveCamera()->GetPosition();
  int nearest = 0;
  for (int v = 1; v < rig->GetNumberOfViews(); ++v)
  {
    const glm::dvec3 e(eye[0], eye[1], eye[2]);
    if (glm::length(rig->GetCamera(v).Center() - e) <
      glm::length(rig->GetCamera(nearest).Center() - e))
    {
      nearest = v;
    }
  }
  const lfd::PinholeCamera& camera = rig->GetCamera(nearest);
  const glm::dvec3 inside = camera.Unproject(glm::dvec2(63.5, 63.5), 0.5 * frusta->GetUsedDepth());
  renderer->SetWorldPoint(inside.x, inside.y, inside.z, 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  const int x = static_cast<int>(std::lround(display[0]));
  const int y = static_cast<int>(std::lround(display[1]));
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(interactor);
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(Click(x, y).c_str());
  recorder->Play();
  lfdtest::Check(selected == nearest, "view selected by the click", selected, nearest);
  lfdtest::Check(
    view->GetCurrentView() == nearest, "current view", view->GetCurrentView(), nearest);

  // The background (a corner of the window) selects nothing.
  selected = -100;
  recorder->SetInputString(Click(3, 3).c_str());
  recorder->Play();
  lfdtest::Check(selected == -100, "no event for a background click", selected, -100);
  lfdtest::Check(
    view->PickView(3, 3) == -1, "PickView on the background", view->PickView(3, 3), -1);

  window->Render();
  const int result = vtkRegressionTestImage(window);
  return (lfdtest::Failures() == 0 && result != vtkRegressionTester::FAILED) ? 0 : 1;
}
