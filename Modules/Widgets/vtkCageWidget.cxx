#include "vtkCageWidget.h"

#include "vtkCageRepresentation.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeformationCage.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkWidgetCallbackMapper.h"
#include "vtkWidgetEvent.h"

#include <cctype>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkCageWidget);

namespace
{
enum WidgetStateType
{
  Idle = 0,
  Pressed,      // left button down on a handle, not moved yet
  PressedEmpty, // left button down on empty space, not moved yet
  Dragging,     // a handle drag in progress (interaction events fired)
  RubberBand,   // drawing the selection rectangle
  Transforming  // a G / R / S transform follows the cursor
};

// A press and release closer than this (pixels) is a click.
constexpr double ClickTolerance = 3.0;
}

//------------------------------------------------------------------------------
vtkCageWidget::vtkCageWidget()
  : RelayCommand(vtkCallbackCommand::New())
{
  this->RelayCommand->SetClientData(this);
  this->RelayCommand->SetCallback(vtkCageWidget::RelayEvent);
  this->ManagesCursor = 0;

  vtkWidgetCallbackMapper* mapper = this->CallbackMapper;
  mapper->SetCallbackMethod(
    vtkCommand::LeftButtonPressEvent, vtkWidgetEvent::Select, this, vtkCageWidget::SelectAction);
  mapper->SetCallbackMethod(vtkCommand::LeftButtonReleaseEvent,
    vtkWidgetEvent::EndSelect,
    this,
    vtkCageWidget::EndSelectAction);
  mapper->SetCallbackMethod(
    vtkCommand::MouseMoveEvent, vtkWidgetEvent::Move, this, vtkCageWidget::MoveAction);
  mapper->SetCallbackMethod(
    vtkCommand::RightButtonPressEvent, vtkWidgetEvent::Reset, this, vtkCageWidget::CancelAction);
  // Keys act on CharEvent, the event the interactor styles act on, so that a
  // key the widget uses can be kept from them (R would reset the camera).
  mapper->SetCallbackMethod(
    vtkCommand::CharEvent, vtkWidgetEvent::ModifyEvent, this, vtkCageWidget::KeyPressAction);
}

//------------------------------------------------------------------------------
vtkCageWidget::~vtkCageWidget()
{
  if (this->ObservedRepresentation)
  {
    this->ObservedRepresentation->RemoveObserver(this->RelayCommand);
  }
  this->RelayCommand->Delete();
}

//------------------------------------------------------------------------------
void vtkCageWidget::SetRepresentation(vtkCageRepresentation* rep)
{
  if (this->ObservedRepresentation && this->ObservedRepresentation != rep)
  {
    this->ObservedRepresentation->RemoveObserver(this->RelayCommand);
    this->ObservedRepresentation = nullptr;
  }
  this->Superclass::SetWidgetRepresentation(rep);
  if (rep && this->ObservedRepresentation != rep)
  {
    // The representation's API edits and selection changes reach the
    // widget's observers as the widget's own events.
    for (unsigned long event : { static_cast<unsigned long>(vtkCommand::StartInteractionEvent),
           static_cast<unsigned long>(vtkCommand::InteractionEvent),
           static_cast<unsigned long>(vtkCommand::EndInteractionEvent),
           static_cast<unsigned long>(vtkCageRepresentation::SelectionChangedEvent) })
    {
      rep->AddObserver(event, this->RelayCommand);
    }
    this->ObservedRepresentation = rep;
  }
}

//------------------------------------------------------------------------------
vtkCageRepresentation* vtkCageWidget::GetCageRepresentation()
{
  return vtkCageRepresentation::SafeDownCast(this->WidgetRep);
}

//------------------------------------------------------------------------------
void vtkCageWidget::CreateDefaultRepresentation()
{
  if (!this->WidgetRep)
  {
    vtkCageRepresentation* rep = vtkCageRepresentation::New();
    this->SetRepresentation(rep);
    rep->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkCageWidget::RelayEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  static_cast<vtkCageWidget*>(clientData)->InvokeEvent(event, callData);
}

//------------------------------------------------------------------------------
void vtkCageWidget::BeginInteraction()
{
  this->GrabFocus(this->EventCallbackCommand);
  this->StartInteraction();
  this->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
}

//------------------------------------------------------------------------------
void vtkCageWidget::FinishInteraction(bool cancel)
{
  vtkCageRepresentation* rep = this->GetCageRepresentation();
  if (cancel)
  {
    rep->CancelTransform();
    this->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  }
  else
  {
    rep->ConfirmTransform();
  }
  this->WidgetState = Idle;
  this->ReleaseFocus();
  this->EndInteraction();
  this->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  this->EventCallbackCommand->SetAbortFlag(1);
  this->Render();
}

//------------------------------------------------------------------------------
void vtkCageWidget::SelectAction(vtkAbstractWidget* w)
{
  vtkCageWidget* self = static_cast<vtkCageWidget*>(w);
  vtkCageRepresentation* rep = self->GetCageRepresentation();
  const int x = self->Interactor->GetEventPosition()[0];
  const int y = self->Interactor->GetEventPosition()[1];
  if (self->WidgetState == Transforming)
  {
    self->FinishInteraction(false);
    return;
  }
  if (self->PassingPress || self->WidgetState != Idle || !self->CurrentRenderer ||
    !self->CurrentRenderer->IsInViewport(x, y))
  {
    return;
  }
  if (self->RubberBandArmed)
  {
    self->RubberBandArmed = false;
    self->WidgetState = RubberBand;
    rep->StartRubberBand(x, y);
    self->GrabFocus(self->EventCallbackCommand);
    self->EventCallbackCommand->SetAbortFlag(1);
    self->Render();
    return;
  }
  self->PressPosition[0] = x;
  self->PressPosition[1] = y;
  if (rep->ComputeInteractionState(x, y) != vtkCageRepresentation::OnHandle)
  {
    // Empty space: a click clears the selection, a drag moves the camera.
    // The press is held back until the cursor moves, because the style
    // takes the focus on a press and the widget would never see a release.
    self->WidgetState = PressedEmpty;
    self->EventCallbackCommand->SetAbortFlag(1);
    return;
  }
  const vtkIdType id = rep->GetHoverPointId();
  const bool shift = self->Interactor->GetShiftKey() != 0;
  if (shift || !rep->IsPointSelected(id))
  {
    rep->SelectPoint(id, shift);
  }
  self->EventCallbackCommand->SetAbortFlag(1);
  if (rep->IsPointSelected(id))
  {
    self->WidgetState = Pressed;
    self->GrabFocus(self->EventCallbackCommand);
  }
  self->Render();
}

//------------------------------------------------------------------------------
void vtkCageWidget::MoveAction(vtkAbstractWidget* w)
{
  vtkCageWidget* self = static_cast<vtkCageWidget*>(w);
  vtkCageRepresentation* rep = self->GetCageRepresentation();
  const int x = self->Interactor->GetEventPosition()[0];
  const int y = self->Interactor->GetEventPosition()[1];
  switch (self->WidgetState)
  {
    case PressedEmpty:
      if (std::hypot(x - self->PressPosition[0], y - self->PressPosition[1]) > ClickTolerance)
      {
        // A drag: give the held-back press to the style, then this motion.
        self->WidgetState = Idle;
        self->PassingPress = true;
        self->Interactor->SetEventPosition(
          static_cast<int>(self->PressPosition[0]), static_cast<int>(self->PressPosition[1]));
        self->Interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent, nullptr);
        self->Interactor->SetEventPosition(x, y);
        self->PassingPress = false;
      }
      return;
    case Idle:
    {
      const vtkIdType before = rep->GetHoverPointId();
      if (self->CurrentRenderer && self->CurrentRenderer->IsInViewport(x, y))
      {
        rep->ComputeInteractionState(x, y);
      }
      if (rep->GetHoverPointId() != before)
      {
        self->Render();
      }
      return;
    }
    case Pressed:
      // The drag starts at the first motion: a click selects, nothing moves.
      if (!rep->StartTransform(
            vtkCageRepresentation::Dragging, self->PressPosition[0], self->PressPosition[1]))
      {
        self->WidgetState = Idle;
        self->ReleaseFocus();
        return;
      }
      rep->SetConstraint(vtkCageRepresentation::ConstraintNone);
      self->WidgetState = Dragging;
      self->BeginInteraction();
      VTK_FALLTHROUGH;
    case Dragging:
    case Transforming:
      rep->UpdateTransform(x, y);
      self->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
      break;
    case RubberBand:
      rep->UpdateRubberBand(x, y);
      break;
    default:
      return;
  }
  self->EventCallbackCommand->SetAbortFlag(1);
  self->Render();
}

//------------------------------------------------------------------------------
void vtkCageWidget::EndSelectAction(vtkAbstractWidget* w)
{
  vtkCageWidget* self = static_cast<vtkCageWidget*>(w);
  vtkCageRepresentation* rep = self->GetCageRepresentation();
  const int x = self->Interactor->GetEventPosition()[0];
  const int y = self->Interactor->GetEventPosition()[1];
  switch (self->WidgetState)
  {
    case Pressed:
      self->WidgetState = Idle;
      self->ReleaseFocus();
      self->EventCallbackCommand->SetAbortFlag(1);
      return;
    case Dragging:
      self->FinishInteraction(false);
      return;
    case RubberBand:
      rep->EndRubberBand(x, y, self->Interactor->GetShiftKey() != 0);
      self->WidgetState = Idle;
      self->ReleaseFocus();
      self->EventCallbackCommand->SetAbortFlag(1);
      self->Render();
      return;
    case PressedEmpty:
      self->WidgetState = Idle;
      if (!self->Interactor->GetShiftKey())
      {
        rep->ClearSelection();
        self->Render();
      }
      self->EventCallbackCommand->SetAbortFlag(1);
      return;
    default:
      return;
  }
}

//------------------------------------------------------------------------------
void vtkCageWidget::CancelAction(vtkAbstractWidget* w)
{
  vtkCageWidget* self = static_cast<vtkCageWidget*>(w);
  if (self->WidgetState == Transforming || self->WidgetState == Dragging)
  {
    self->FinishInteraction(true);
  }
}

//------------------------------------------------------------------------------
bool vtkCageWidget::HandleModalKey(const char* key, bool shift)
{
  vtkCageRepresentation* rep = this->GetCageRepresentation();
  const std::string k = key;
  if (k == "Escape")
  {
    this->FinishInteraction(true);
    return true;
  }
  if (k == "Return" || k == "KP_Enter")
  {
    if (this->WidgetState == Transforming)
    {
      this->FinishInteraction(false);
    }
    return true;
  }
  if (k.size() != 1 || std::tolower(k[0]) < 'x' || std::tolower(k[0]) > 'z')
  {
    return false;
  }
  // X / Y / Z: that axis; shift: the plane perpendicular to it; the same
  // key again: no constraint.
  const int axis = std::tolower(k[0]) - 'x';
  int constraint =
    (shift ? vtkCageRepresentation::ConstraintPlaneX : vtkCageRepresentation::ConstraintX) + axis;
  if (constraint == rep->GetConstraint())
  {
    constraint = vtkCageRepresentation::ConstraintNone;
  }
  rep->SetConstraint(constraint);
  const int* position = this->Interactor->GetEventPosition();
  rep->UpdateTransform(position[0], position[1]);
  this->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  this->Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkCageWidget::KeyPressAction(vtkAbstractWidget* w)
{
  vtkCageWidget* self = static_cast<vtkCageWidget*>(w);
  vtkCageRepresentation* rep = self->GetCageRepresentation();
  const char* keySym = self->Interactor->GetKeySym();
  if (!self->KeyboardBindings || !keySym)
  {
    return;
  }
  const bool shift = self->Interactor->GetShiftKey() != 0;
  bool used = false;
  if (self->WidgetState == Transforming || self->WidgetState == Dragging)
  {
    used = self->HandleModalKey(keySym, shift);
  }
  else if (self->WidgetState == Idle)
  {
    const std::string k = keySym;
    const int* position = self->Interactor->GetEventPosition();
    const char lower = k.size() == 1 ? static_cast<char>(std::tolower(k[0])) : '\0';
    if (lower == 'b')
    {
      self->RubberBandArmed = true;
      used = true;
    }
    else if (lower == 'a')
    {
      const vtkIdType selected = rep->GetNumberOfSelectedPoints();
      const bool all =
        selected > 0 && rep->GetCage() && selected == rep->GetCage()->GetNumberOfPoints();
      all ? rep->ClearSelection() : rep->SelectAll();
      used = true;
    }
    else if ((lower == 'g' || lower == 'r' || lower == 's') && rep->GetNumberOfSelectedPoints())
    {
      const int mode = lower == 'g'
        ? vtkCageRepresentation::Translating
        : (lower == 'r' ? vtkCageRepresentation::Rotating : vtkCageRepresentation::Scaling);
      rep->SetConstraint(vtkCageRepresentation::ConstraintNone);
      if (rep->StartTransform(mode, position[0], position[1]))
      {
        self->WidgetState = Transforming;
        self->BeginInteraction();
      }
      used = true;
    }
    else if (k == "Escape" && rep->GetNumberOfSelectedPoints())
    {
      rep->ClearSelection();
      used = true;
    }
  }
  if (used)
  {
    self->EventCallbackCommand->SetAbortFlag(1);
    self->Render();
  }
}

//------------------------------------------------------------------------------
void vtkCageWidget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KeyboardBindings: " << this->KeyboardBindings << "\n";
}
