#include "vtkCalibrationView.h"

#include "vtkCallbackCommand.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <vector>

struct vtkCalibrationView::Internals
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkLightField> LightField;
  std::vector<vtkSmartPointer<vtkProp>> Props;
  std::vector<unsigned long> Events;
  vtkNew<vtkCallbackCommand> BeforeRender;
  unsigned long BeforeRenderTag = 0;
};

//------------------------------------------------------------------------------
vtkCalibrationView::vtkCalibrationView()
  : Internal(new Internals)
{
  this->EventCallbackCommand->SetCallback(vtkCalibrationView::ProcessEvents);
  this->Priority = 0.5;
  this->Internal->BeforeRender->SetClientData(this);
  this->Internal->BeforeRender->SetCallback([](vtkObject*, unsigned long, void* self, void*)
    { static_cast<vtkCalibrationView*>(self)->Refresh(); });
}

//------------------------------------------------------------------------------
vtkCalibrationView::~vtkCalibrationView()
{
  if (this->Internal->Renderer)
  {
    this->Internal->Renderer->RemoveObserver(this->Internal->BeforeRenderTag);
  }
}

//------------------------------------------------------------------------------
void vtkCalibrationView::SetRenderer(vtkRenderer* renderer)
{
  Internals& internal = *this->Internal;
  if (internal.Renderer == renderer)
  {
    return;
  }
  if (internal.Renderer)
  {
    internal.Renderer->RemoveObserver(internal.BeforeRenderTag);
    for (vtkProp* prop : internal.Props)
    {
      internal.Renderer->RemoveViewProp(prop);
    }
  }
  internal.Renderer = renderer;
  if (renderer)
  {
    internal.BeforeRenderTag = renderer->AddObserver(vtkCommand::StartEvent, internal.BeforeRender);
    for (vtkProp* prop : internal.Props)
    {
      renderer->AddViewProp(prop);
    }
  }
  this->SetDefaultRenderer(renderer);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkRenderer* vtkCalibrationView::GetRenderer()
{
  return this->Internal->Renderer;
}

//------------------------------------------------------------------------------
void vtkCalibrationView::SetLightField(vtkLightField* lightField)
{
  this->Internal->LightField = lightField;
  this->LightFieldChanged();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkLightField* vtkCalibrationView::GetLightField()
{
  return this->Internal->LightField;
}

//------------------------------------------------------------------------------
void vtkCalibrationView::AddViewProp(vtkProp* prop)
{
  this->Internal->Props.emplace_back(prop);
  if (this->Internal->Renderer)
  {
    this->Internal->Renderer->AddViewProp(prop);
  }
}

//------------------------------------------------------------------------------
void vtkCalibrationView::SetHandledEvents(std::initializer_list<unsigned long> events)
{
  this->Internal->Events.assign(events.begin(), events.end());
}

//------------------------------------------------------------------------------
void vtkCalibrationView::SetEnabled(int enabling)
{
  if (!this->Interactor || (enabling != 0) == (this->Enabled != 0))
  {
    return;
  }
  this->Enabled = enabling;
  if (enabling)
  {
    for (unsigned long event : this->Internal->Events)
    {
      this->Interactor->AddObserver(event, this->EventCallbackCommand, this->Priority);
    }
    this->InvokeEvent(vtkCommand::EnableEvent);
  }
  else
  {
    this->Interactor->RemoveObserver(this->EventCallbackCommand);
    this->InvokeEvent(vtkCommand::DisableEvent);
  }
}

//------------------------------------------------------------------------------
void vtkCalibrationView::ProcessEvents(vtkObject*, unsigned long event, void* self, void*)
{
  auto* view = static_cast<vtkCalibrationView*>(self);
  const int* position = view->Interactor->GetEventPosition();
  if (view->HandleEvent(event, position[0], position[1]))
  {
    view->EventCallbackCommand->SetAbortFlag(1);
    view->Interactor->Render();
  }
}

//------------------------------------------------------------------------------
void vtkCalibrationView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Internal->Renderer.Get() << "\n";
  os << indent << "LightField: " << this->Internal->LightField.Get() << "\n";
}
