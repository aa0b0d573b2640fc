#include "vtkRigView.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraFrustumSource.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellPicker.h"
#include "vtkDataSetMapper.h"
#include "vtkDeformationCage.h"
#include "vtkIntArray.h"
#include "vtkLightField.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutlineSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkRigView);

namespace
{
// The fitted cylinder: its axis through the rows and one ring per row.
void BuildCylinder(vtkCameraRig* rig, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  output->Initialize();
  if (!rig || !rig->HasCylinder())
  {
    return;
  }
  const double* axis = rig->GetAxis();
  const double* centre = rig->GetCenter();
  const double radius = rig->GetRadius();
  double zero[3], quarter[3];
  rig->GetAzimuthFrame(zero, quarter);
  double extent = 0.5 * radius;
  for (int row = 0; row < rig->GetNumberOfRows(); ++row)
  {
    extent = std::max(extent, std::abs(rig->GetRowHeight(row)) + 0.5 * radius);
  }
  for (double sign : { -1.0, 1.0 })
  {
    points->InsertNextPoint(centre[0] + sign * extent * axis[0],
      centre[1] + sign * extent * axis[1],
      centre[2] + sign * extent * axis[2]);
  }
  const vtkIdType axisLine[2] = { 0, 1 };
  lines->InsertNextCell(2, axisLine);
  constexpr int segments = 96;
  for (int row = 0; row < rig->GetNumberOfRows(); ++row)
  {
    const double height = rig->GetRowHeight(row);
    lines->InsertNextCell(segments + 1);
    const vtkIdType first = points->GetNumberOfPoints();
    for (int s = 0; s < segments; ++s)
    {
      const double phi = 2.0 * vtkMath::Pi() * s / segments;
      double p[3];
      for (int c = 0; c < 3; ++c)
      {
        p[c] = centre[c] + height * axis[c] +
          radius * (std::cos(phi) * zero[c] + std::sin(phi) * quarter[c]);
      }
      lines->InsertCellPoint(points->InsertNextPoint(p));
    }
    lines->InsertCellPoint(first);
  }
  output->SetPoints(points);
  output->SetLines(lines);
}

vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithmOutput* port, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->LightingOff();
  actor->PickableOff();
  return actor;
}
}

struct vtkRigView::Internals
{
  vtkSmartPointer<vtkDeformationCage> Cage;
  vtkNew<vtkCameraFrustumSource> Cameras;
  vtkNew<vtkCameraFrustumSource> Projectors;
  vtkNew<vtkCameraFrustumSource> Highlight;
  vtkNew<vtkPolyData> Cylinder;
  vtkNew<vtkOutlineSource> Outline;
  vtkNew<vtkLookupTable> RowColours;
  vtkNew<vtkActor> CameraActor;
  vtkSmartPointer<vtkActor> ProjectorActor;
  vtkSmartPointer<vtkActor> HighlightActor;
  vtkSmartPointer<vtkActor> OutlineActor;
  vtkNew<vtkActor> CylinderActor;
  vtkNew<vtkActor> CageActor;
  vtkNew<vtkDataSetMapper> CageMapper;
  vtkNew<vtkCellPicker> Picker;

  Internals()
  {
    vtkNew<vtkPolyDataMapper> cameraMapper;
    cameraMapper->SetInputConnection(this->Cameras->GetOutputPort());
    cameraMapper->SetScalarModeToUseCellFieldData();
    cameraMapper->SelectColorArray("Row");
    cameraMapper->SetLookupTable(this->RowColours);
    cameraMapper->UseLookupTableScalarRangeOn();
    this->CameraActor->SetMapper(cameraMapper);
    this->CameraActor->GetProperty()->EdgeVisibilityOn();
    this->CameraActor->GetProperty()->SetEdgeColor(0.1, 0.1, 0.1);
    this->ProjectorActor = MakeActor(this->Projectors->GetOutputPort(), 0.9, 0.2, 0.8);
    this->ProjectorActor->GetProperty()->SetRepresentationToWireframe();
    this->ProjectorActor->GetProperty()->SetLineWidth(2.0);
    this->HighlightActor = MakeActor(this->Highlight->GetOutputPort(), 1.0, 0.9, 0.1);
    this->HighlightActor->GetProperty()->SetRepresentationToWireframe();
    this->HighlightActor->GetProperty()->SetLineWidth(3.0);
    this->OutlineActor = MakeActor(this->Outline->GetOutputPort(), 1.0, 0.9, 0.1);
    this->OutlineActor->VisibilityOff();
    vtkNew<vtkPolyDataMapper> cylinderMapper;
    cylinderMapper->SetInputData(this->Cylinder);
    this->CylinderActor->SetMapper(cylinderMapper);
    this->CylinderActor->GetProperty()->SetColor(0.6, 0.6, 0.6);
    this->CylinderActor->GetProperty()->LightingOff();
    this->CylinderActor->PickableOff();
    this->CageMapper->ScalarVisibilityOff();
    this->CageActor->SetMapper(this->CageMapper);
    this->CageActor->GetProperty()->SetRepresentationToWireframe();
    this->CageActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    this->CageActor->GetProperty()->LightingOff();
    this->CageActor->PickableOff();
    this->Picker->PickFromListOn();
    this->Picker->AddPickList(this->CameraActor);
    this->Picker->SetTolerance(0.0);
  }
};

//------------------------------------------------------------------------------
vtkRigView::vtkRigView()
  : Internal(new Internals)
{
  Internals& internal = *this->Internal;
  vtkProp* props[] = { internal.CameraActor,
    internal.ProjectorActor,
    internal.HighlightActor,
    internal.OutlineActor,
    internal.CylinderActor,
    internal.CageActor };
  for (vtkProp* prop : props)
  {
    this->AddViewProp(prop);
  }
  this->SetHandledEvents({ vtkCommand::LeftButtonPressEvent });
}

//------------------------------------------------------------------------------
vtkRigView::~vtkRigView() = default;

//------------------------------------------------------------------------------
void vtkRigView::LightFieldChanged()
{
  this->UpdateRig();
}

//------------------------------------------------------------------------------
void vtkRigView::SetCage(vtkDeformationCage* cage)
{
  this->Internal->Cage = cage;
  this->Internal->CageMapper->SetInputData(cage);
  this->Internal->CageActor->SetVisibility(cage != nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkRigView::GetCage()
{
  return this->Internal->Cage;
}

//------------------------------------------------------------------------------
void vtkRigView::SetObjectBounds(const double bounds[6])
{
  this->Internal->Outline->SetBounds(
    bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  this->Internal->OutlineActor->VisibilityOn();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRigView::ClearObjectBounds()
{
  this->Internal->OutlineActor->VisibilityOff();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRigView::SetCurrentView(int view)
{
  if (this->CurrentView == view)
  {
    return;
  }
  this->CurrentView = view;
  this->UpdateRig();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRigView::UpdateRig()
{
  Internals& internal = *this->Internal;
  vtkLightField* lightField = this->GetLightField();
  vtkCameraRig* rig = lightField ? lightField->GetRig() : nullptr;
  vtkCameraRig* projectors = lightField ? lightField->GetProjectors() : nullptr;
  internal.Cameras->SetRig(rig);
  internal.Highlight->SetRig(rig);
  internal.Projectors->SetRig(projectors);
  const int views = rig ? rig->GetNumberOfViews() : 0;
  const bool highlight = this->CurrentView >= 0 && this->CurrentView < views;
  internal.Highlight->SetView(highlight ? this->CurrentView : -1);
  internal.HighlightActor->SetVisibility(highlight);
  BuildCylinder(rig, internal.Cylinder);
  const int rows = rig && rig->HasCylinder() ? std::max(1, rig->GetNumberOfRows()) : 1;
  // Rows from blue (lowest) to green (highest); the highlight is yellow.
  internal.RowColours->SetNumberOfTableValues(rows);
  internal.RowColours->SetTableRange(0, std::max(1, rows - 1));
  internal.RowColours->SetHueRange(0.6, 0.35);
  internal.RowColours->SetSaturationRange(0.6, 0.6);
  internal.RowColours->SetValueRange(0.85, 0.85);
  internal.RowColours->ForceBuild();
  // The projector frusta reach further than the cameras' so that both show.
  internal.Cameras->Update();
  internal.Highlight->SetDepth(internal.Cameras->GetUsedDepth());
  internal.Projectors->SetDepth(1.5 * internal.Cameras->GetUsedDepth());
  internal.ProjectorActor->SetVisibility(projectors && projectors->GetNumberOfViews() > 0);
}

//------------------------------------------------------------------------------
void vtkRigView::ResetCamera()
{
  vtkRenderer* renderer = this->GetRenderer();
  if (!renderer)
  {
    return;
  }
  vtkLightField* lightField = this->GetLightField();
  vtkCameraRig* rig = lightField ? lightField->GetRig() : nullptr;
  vtkCamera* camera = renderer->GetActiveCamera();
  if (rig && rig->HasCylinder())
  {
    const double* axis = rig->GetAxis();
    const double* centre = rig->GetCenter();
    double zero[3], quarter[3];
    rig->GetAzimuthFrame(zero, quarter);
    const double r = 3.0 * rig->GetRadius();
    camera->SetFocalPoint(centre[0], centre[1], centre[2]);
    camera->SetPosition(centre[0] + r * (0.8 * zero[0] + 0.3 * quarter[0] + 0.6 * axis[0]),
      centre[1] + r * (0.8 * zero[1] + 0.3 * quarter[1] + 0.6 * axis[1]),
      centre[2] + r * (0.8 * zero[2] + 0.3 * quarter[2] + 0.6 * axis[2]));
    camera->SetViewUp(axis[0], axis[1], axis[2]);
  }
  renderer->ResetCamera();
}

//------------------------------------------------------------------------------
int vtkRigView::PickView(int x, int y)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = this->GetRenderer();
  if (!renderer || !internal.Picker->Pick(x, y, 0.0, renderer))
  {
    return -1;
  }
  vtkPolyData* frusta = internal.Cameras->GetOutput();
  auto* views = vtkIntArray::SafeDownCast(frusta->GetCellData()->GetArray("View"));
  const vtkIdType cell = internal.Picker->GetCellId();
  return views && cell >= 0 && cell < views->GetNumberOfTuples() ? views->GetValue(cell) : -1;
}

//------------------------------------------------------------------------------
bool vtkRigView::HandleEvent(unsigned long, int x, int y)
{
  vtkRenderer* renderer = this->GetRenderer();
  int picked = renderer && renderer->IsInViewport(x, y) ? this->PickView(x, y) : -1;
  if (picked < 0)
  {
    return false;
  }
  this->SetCurrentView(picked);
  this->InvokeEvent(ViewSelectedEvent, &picked);
  return true;
}

//------------------------------------------------------------------------------
void vtkRigView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CurrentView: " << this->CurrentView << "\n";
  os << indent << "Cage: " << this->Internal->Cage.Get() << "\n";
}
