#include "vtkLightFieldEditor.h"

#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCoordinate.h"
#include "vtkDeformationCage.h"
#include "vtkIdList.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLightField.h"
#include "vtkLightFieldActor.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTimerLog.h"
#include "vtkWeakPointer.h"

#include <cstdio>
#include <string>

vtkStandardNewMacro(vtkLightFieldEditor);

struct vtkLightFieldEditor::Internals
{
  vtkNew<vtkLightFieldMapper> Mapper;
  vtkNew<vtkLightFieldActor> Actor;
  vtkNew<vtkCageWidget> Widget;
  vtkNew<vtkTextActor> FrameTime;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkCallbackCommand> Callback;
  /// The pose ShowTime() shows (the logic's cage stays the current one).
  vtkNew<vtkDeformationCage> TimeCage;
  vtkNew<vtkIdList> MovedIds;
  vtkNew<vtkPoints> MovedPositions;
  /// The window, interactor and style of Initialize() without a given renderer.
  vtkSmartPointer<vtkRenderWindow> OwnWindow;
  vtkSmartPointer<vtkRenderWindowInteractor> OwnInteractor;
  vtkSmartPointer<vtkInteractorStyleTrackballCamera> OwnStyle;
  vtkWeakPointer<vtkRenderWindowInteractor> ObservedInteractor;
  bool Initialized = false;
  double RenderStart = 0.0;
};

namespace
{
/// Events of the logic the editor follows.
const unsigned long LogicEvents[] = { vtkLightFieldSceneLogic::CageModifiedEvent,
  vtkLightFieldSceneLogic::KeyframesModifiedEvent,
  vtkLightFieldSceneLogic::SettingsModifiedEvent,
  vtkCommand::ErrorEvent };

/// Events of the widget that bracket an edit.
const unsigned long WidgetEvents[] = { vtkCommand::StartInteractionEvent,
  vtkCommand::InteractionEvent,
  vtkCommand::EndInteractionEvent };

/// A corner text of the view: `x`, `y` in normalised viewport coordinates.
void PlaceText(vtkTextActor* text, double x, double y, bool right)
{
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* property = text->GetTextProperty();
  property->SetFontSize(14);
  property->SetFontFamilyToCourier();
  property->SetVerticalJustificationToBottom();
  if (right)
  {
    property->SetJustificationToRight();
  }
  else
  {
    property->SetJustificationToLeft();
  }
}
}

//------------------------------------------------------------------------------
vtkLightFieldEditor::vtkLightFieldEditor()
  : Internal(new Internals)
{
  Internals& in = *this->Internal;
  in.Callback->SetClientData(this);
  in.Callback->SetCallback(&vtkLightFieldEditor::OnEvent);
  in.Actor->SetMapper(in.Mapper);
  in.Widget->CreateDefaultRepresentation();
  vtkCageRepresentation* rep = in.Widget->GetCageRepresentation();
  // The logic applies (and validates) every move; the handles only propose.
  rep->ApplyToCageOff();
  // Handles the light field hides cannot be picked.
  rep->SetOccluderDepth(in.Mapper->GetDepthImage());
  for (unsigned long event : WidgetEvents)
  {
    in.Widget->AddObserver(event, in.Callback);
  }
  PlaceText(in.FrameTime, 0.99, 0.01, true);
  in.FrameTime->GetTextProperty()->SetColor(0.8, 0.9, 1.0);
  PlaceText(in.Status, 0.01, 0.01, false);
  in.Status->GetTextProperty()->SetColor(1.0, 0.55, 0.3);
  vtkNew<vtkLightFieldSceneLogic> logic;
  this->SetLogic(logic);
}

//------------------------------------------------------------------------------
vtkLightFieldEditor::~vtkLightFieldEditor()
{
  Internals& in = *this->Internal;
  in.Widget->Off();
  in.Widget->SetInteractor(nullptr);
  if (in.ObservedInteractor)
  {
    in.ObservedInteractor->RemoveObserver(in.Callback);
  }
  this->SetRenderer(nullptr);
  this->Logic->RemoveObserver(in.Callback);
  this->Logic->UnRegister(this);
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::SetLogic(vtkLightFieldSceneLogic* logic)
{
  if (!logic || logic == this->Logic)
  {
    return;
  }
  Internals& in = *this->Internal;
  if (this->Logic)
  {
    this->Logic->RemoveObserver(in.Callback);
    this->Logic->UnRegister(this);
  }
  this->Logic = logic;
  this->Logic->Register(this);
  for (unsigned long event : LogicEvents)
  {
    this->Logic->AddObserver(event, in.Callback);
  }
  this->Modified();
  if (in.Initialized)
  {
    this->Initialize();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::SetRenderer(vtkRenderer* renderer)
{
  if (renderer == this->Renderer)
  {
    return;
  }
  Internals& in = *this->Internal;
  if (this->Renderer)
  {
    this->Renderer->RemoveObserver(in.Callback);
    this->Renderer->RemoveViewProp(in.Actor);
    this->Renderer->RemoveViewProp(in.FrameTime);
    this->Renderer->RemoveViewProp(in.Status);
    this->Renderer->UnRegister(this);
  }
  this->Renderer = renderer;
  if (this->Renderer)
  {
    this->Renderer->Register(this);
    this->Renderer->AddObserver(vtkCommand::StartEvent, in.Callback);
    this->Renderer->AddObserver(vtkCommand::EndEvent, in.Callback);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::CreateWindow()
{
  Internals& in = *this->Internal;
  vtkNew<vtkRenderer> renderer;
  in.OwnWindow = vtkSmartPointer<vtkRenderWindow>::New();
  in.OwnWindow->SetSize(800, 600);
  in.OwnWindow->SetWindowName("LightField Editor");
  in.OwnWindow->SetMultiSamples(0);
  in.OwnWindow->AddRenderer(renderer);
  in.OwnInteractor = vtkSmartPointer<vtkRenderWindowInteractor>::New();
  in.OwnStyle = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  in.OwnInteractor->SetInteractorStyle(in.OwnStyle);
  in.OwnInteractor->SetRenderWindow(in.OwnWindow);
  this->SetRenderer(renderer);
}

//------------------------------------------------------------------------------
bool vtkLightFieldEditor::Initialize()
{
  Internals& in = *this->Internal;
  if (!this->Renderer)
  {
    this->CreateWindow();
  }
  vtkRenderWindowInteractor* interactor = this->GetInteractor();
  if (!interactor)
  {
    vtkErrorMacro("The editor's renderer must be in a render window with an interactor.");
    return false;
  }
  in.Initialized = true;
  this->Renderer->AddViewProp(in.Actor);
  this->Renderer->AddViewProp(in.FrameTime);
  this->Renderer->AddViewProp(in.Status);
  in.Status->SetInput("");
  in.FrameTime->SetInput("");
  this->ObserveInteractor(interactor);

  // Errors reading the light field reach the logic's observers (this one
  // included: the status line says them).
  vtkLightField* lightField = this->Logic->GetLightField();
  in.Mapper->SetInputData(lightField);
  this->ApplySettings();
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  vtkCamera* sceneCamera = this->Logic->GetScene()->GetCamera();
  camera->SetPosition(sceneCamera->GetPosition());
  camera->SetFocalPoint(sceneCamera->GetFocalPoint());
  camera->SetViewUp(sceneCamera->GetViewUp());
  camera->SetViewAngle(sceneCamera->GetViewAngle());

  in.Widget->SetInteractor(interactor);
  in.Widget->SetDefaultRenderer(this->Renderer);
  in.Widget->SetCurrentRenderer(this->Renderer);
  in.Widget->GetCageRepresentation()->SetRenderer(this->Renderer);
  this->ShowCurrentCage();
  in.Widget->On();
  this->Renderer->ResetCameraClippingRange();
  return lightField != nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::ObserveInteractor(vtkRenderWindowInteractor* interactor)
{
  Internals& in = *this->Internal;
  if (in.ObservedInteractor == interactor)
  {
    return;
  }
  if (in.ObservedInteractor)
  {
    in.ObservedInteractor->RemoveObserver(in.Callback);
  }
  in.ObservedInteractor = interactor;
  interactor->AddObserver(vtkCommand::KeyPressEvent, in.Callback);
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::ApplySettings()
{
  // The mapper sets the camera and the image size at each render; the scene
  // gives the rest of the view (focal distance, subdivision, ...).
  vtkLightFieldRenderer* view = this->Internal->Mapper->GetLightFieldRenderer();
  this->Logic->ApplyView(view);
  const double* background = this->Logic->GetScene()->GetBackground();
  view->SetBackground(background);
  if (this->Renderer)
  {
    this->Renderer->SetBackground(background[0], background[1], background[2]);
  }
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkLightFieldEditor::GetRenderWindow()
{
  return this->Renderer ? this->Renderer->GetRenderWindow() : nullptr;
}

//------------------------------------------------------------------------------
vtkRenderWindowInteractor* vtkLightFieldEditor::GetInteractor()
{
  vtkRenderWindow* window = this->GetRenderWindow();
  return window ? window->GetInteractor() : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::Render()
{
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    window->Render();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::Start()
{
  vtkRenderWindowInteractor* interactor = this->GetInteractor();
  if (!interactor)
  {
    vtkErrorMacro("Start() needs Initialize() first.");
    return;
  }
  this->Render();
  interactor->Start();
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldEditor::GetActor()
{
  return this->Internal->Actor;
}

//------------------------------------------------------------------------------
vtkLightFieldMapper* vtkLightFieldEditor::GetMapper()
{
  return this->Internal->Mapper;
}

//------------------------------------------------------------------------------
vtkCageWidget* vtkLightFieldEditor::GetWidget()
{
  return this->Internal->Widget;
}

//------------------------------------------------------------------------------
vtkTextActor* vtkLightFieldEditor::GetFrameTimeActor()
{
  return this->Internal->FrameTime;
}

//------------------------------------------------------------------------------
vtkTextActor* vtkLightFieldEditor::GetStatusActor()
{
  return this->Internal->Status;
}

//------------------------------------------------------------------------------
bool vtkLightFieldEditor::ShowTime(double time)
{
  Internals& in = *this->Internal;
  vtkLightField* lightField = vtkLightField::SafeDownCast(in.Mapper->GetInputDataObject(0, 0));
  if (!this->Logic->GetCageAtTime(time, lightField, in.TimeCage))
  {
    return false;
  }
  this->ShowingTime = true;
  this->Time = time;
  in.Mapper->SetCageData(in.TimeCage);
  vtkCageRepresentation* rep = in.Widget->GetCageRepresentation();
  if (rep->GetCage() != in.TimeCage)
  {
    rep->SetCage(in.TimeCage);
  }
  else
  {
    rep->UpdateFromCage();
  }
  // A pose between keys is not an edit of anything: look, do not touch.
  in.Widget->ProcessEventsOff();
  this->Modified();
  this->Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::ShowCurrentCage()
{
  Internals& in = *this->Internal;
  vtkDeformationCage* cage = this->Logic->GetCage();
  this->ShowingTime = false;
  in.Mapper->SetCageData(cage);
  vtkCageRepresentation* rep = in.Widget->GetCageRepresentation();
  if (rep->GetCage() != cage)
  {
    rep->SetCage(cage);
  }
  else
  {
    rep->UpdateFromCage();
  }
  in.Widget->ProcessEventsOn();
  this->Modified();
  if (in.Initialized)
  {
    this->Render();
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldEditor::EditAtTime(double time)
{
  Internals& in = *this->Internal;
  vtkLightField* lightField = vtkLightField::SafeDownCast(in.Mapper->GetInputDataObject(0, 0));
  if (!this->Logic->GetCageAtTime(time, lightField, in.TimeCage))
  {
    return false;
  }
  vtkPoints* current = this->Logic->GetCage()->GetPoints();
  vtkPoints* pose = in.TimeCage->GetPoints();
  in.MovedIds->Reset();
  for (vtkIdType id = 0; id < pose->GetNumberOfPoints(); ++id)
  {
    double a[3], b[3];
    current->GetPoint(id, a);
    pose->GetPoint(id, b);
    if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
    {
      in.MovedIds->InsertNextId(id);
    }
  }
  bool applied = true;
  if (in.MovedIds->GetNumberOfIds() > 0)
  {
    in.MovedPositions->SetNumberOfPoints(in.MovedIds->GetNumberOfIds());
    for (vtkIdType i = 0; i < in.MovedIds->GetNumberOfIds(); ++i)
    {
      in.MovedPositions->SetPoint(i, pose->GetPoint(in.MovedIds->GetId(i)));
    }
    applied = this->Logic->MovePoints(in.MovedIds, in.MovedPositions);
  }
  this->Time = time;
  this->ShowCurrentCage();
  return applied;
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::OnEvent(vtkObject* caller,
  unsigned long event,
  void* clientData,
  void* callData)
{
  auto* self = static_cast<vtkLightFieldEditor*>(clientData);
  Internals& in = *self->Internal;
  if (caller == in.Widget.Get())
  {
    self->OnWidgetEvent(event);
  }
  else if (caller == self->Logic)
  {
    self->OnLogicEvent(event, callData);
  }
  else if (caller == self->Renderer)
  {
    self->OnRenderEvent(event);
  }
  else if (event == vtkCommand::KeyPressEvent)
  {
    self->OnKeyPress();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::OnWidgetEvent(unsigned long event)
{
  Internals& in = *this->Internal;
  if (this->ShowingTime)
  {
    return;
  }
  vtkCageRepresentation* rep = in.Widget->GetCageRepresentation();
  switch (event)
  {
    case vtkCommand::StartInteractionEvent:
      this->Interacting = true;
      this->Logic->BeginInteraction();
      break;
    case vtkCommand::InteractionEvent:
      rep->GetMovedPointIds(in.MovedIds);
      rep->GetMovedPositions(in.MovedPositions);
      // The logic validates the boxes using the moved points; a fold is
      // refused and the handles go back to its cage, the last valid
      // position of the drag, so a folded box is never drawn.
      if (in.MovedIds->GetNumberOfIds() > 0 &&
        !this->Logic->MovePoints(in.MovedIds, in.MovedPositions))
      {
        rep->UpdateFromCage();
      }
      break;
    case vtkCommand::EndInteractionEvent:
      this->Logic->EndInteraction();
      this->Interacting = false;
      break;
    default:
      break;
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::OnLogicEvent(unsigned long event, void* callData)
{
  Internals& in = *this->Internal;
  switch (event)
  {
    case vtkCommand::ErrorEvent:
      in.Status->SetInput(vtkLightFieldErrorObserver::StripLocation(
        callData ? static_cast<const char*>(callData) : "")
                            .c_str());
      return;
    case vtkLightFieldSceneLogic::SettingsModifiedEvent:
      this->ApplySettings();
      break;
    case vtkLightFieldSceneLogic::CageModifiedEvent:
      in.Status->SetInput("");
      if (this->Interacting)
      {
        // The handles already show the move; the widget renders it.
        return;
      }
      if (!this->ShowingTime)
      {
        this->ShowCurrentCage();
        return;
      }
      VTK_FALLTHROUGH;
    case vtkLightFieldSceneLogic::KeyframesModifiedEvent:
      if (this->ShowingTime && !this->ShowTime(this->Time))
      {
        this->ShowCurrentCage();
      }
      return;
    default:
      return;
  }
  if (in.Initialized)
  {
    this->Render();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::OnKeyPress()
{
  vtkRenderWindowInteractor* interactor = this->Internal->ObservedInteractor;
  const char* key = interactor ? interactor->GetKeySym() : nullptr;
  if (!this->UndoKeys || this->Interacting || !key || !interactor->GetControlKey() ||
    (std::string(key) != "z" && std::string(key) != "Z"))
  {
    return;
  }
  // The logic's CageModifiedEvent (or the others) updates the view.
  if (interactor->GetShiftKey())
  {
    this->Logic->Redo();
  }
  else
  {
    this->Logic->Undo();
  }
  this->Internal->Callback->SetAbortFlag(1);
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::OnRenderEvent(unsigned long event)
{
  Internals& in = *this->Internal;
  if (event == vtkCommand::StartEvent)
  {
    in.RenderStart = vtkTimerLog::GetUniversalTime();
    return;
  }
  if (event != vtkCommand::EndEvent)
  {
    return;
  }
  this->LastFrameTime = vtkTimerLog::GetUniversalTime() - in.RenderStart;
  const int* size = this->Renderer->GetSize();
  const int* image = in.Mapper->GetLastImageSize();
  this->LastFrameCoarse = image[0] < size[0] || image[1] < size[1];
  // The text is drawn with the next frame: it tells the previous one.
  char text[96];
  std::snprintf(text,
    sizeof(text),
    "%.1f ms/frame (%.0f fps) %s",
    1000.0 * this->LastFrameTime,
    this->LastFrameTime > 0.0 ? 1.0 / this->LastFrameTime : 0.0,
    this->LastFrameCoarse ? "coarse" : "full");
  in.FrameTime->SetInput(text);
}

//------------------------------------------------------------------------------
void vtkLightFieldEditor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Logic: " << this->Logic << "\n";
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "UndoKeys: " << (this->UndoKeys ? "On" : "Off") << "\n";
  os << indent << "ShowingTime: " << (this->ShowingTime ? "On" : "Off") << "\n";
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "LastFrameTime: " << this->LastFrameTime << "\n";
  os << indent << "LastFrameCoarse: " << (this->LastFrameCoarse ? "On" : "Off") << "\n";
  os << indent << "Interacting: " << (this->Interacting ? "On" : "Off") << "\n";
}
