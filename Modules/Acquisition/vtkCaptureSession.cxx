#include "vtkCaptureSession.h"

#include "vtkCaptureCamera.h"
#include "vtkCaptureLight.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkIncrementalLightFieldWriter.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkModbusGantry.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkVariant.h"

#include <chrono>

vtkStandardNewMacro(vtkCaptureSession);
vtkCxxSetObjectMacro(vtkCaptureSession, Gantry, vtkModbusGantry);
vtkCxxSetObjectMacro(vtkCaptureSession, Camera, vtkCaptureCamera);

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
}

//------------------------------------------------------------------------------
vtkCaptureSession::vtkCaptureSession()
  : Writer(vtkSmartPointer<vtkIncrementalLightFieldWriter>::New())
  , DeviceErrors(vtkSmartPointer<vtkLightFieldErrorObserver>::New())
{
}

//------------------------------------------------------------------------------
vtkCaptureSession::~vtkCaptureSession()
{
  this->SetGantry(nullptr);
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
void vtkCaptureSession::AddLight(vtkCaptureLight* light)
{
  if (light)
  {
    this->Lights.emplace_back(light);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCaptureSession::RemoveAllLights()
{
  this->Lights.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCaptureSession::GetNumberOfLights() const
{
  return static_cast<int>(this->Lights.size());
}

//------------------------------------------------------------------------------
vtkIncrementalLightFieldWriter* vtkCaptureSession::GetWriter()
{
  return this->Writer;
}

//------------------------------------------------------------------------------
void vtkCaptureSession::Abort()
{
  this->AbortRequested = 1;
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::Capture()
{
  return this->Run(false);
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::Resume()
{
  return this->Run(true);
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::Run(bool resume)
{
  this->AbortRequested = 0;
  this->Aborted = false;
  this->NumberOfViewsTaken = 0;
  this->DeviceSeconds = 0.0;
  this->OverheadSeconds = 0.0;
  this->SecondsRemaining = 0.0;
  if (!this->Gantry || !this->Camera)
  {
    vtkErrorMacro(<< "capture session: no " << (this->Gantry ? "camera" : "gantry") << " set");
    return false;
  }
  // Device errors are collected, not shown: the session reports the first.
  this->DeviceErrors->Clear();
  this->DeviceErrors->Observe(this->Gantry);
  this->DeviceErrors->Observe(this->Camera);
  this->DeviceErrors->Observe(this->Writer);
  for (vtkCaptureLight* light : this->Lights)
  {
    this->DeviceErrors->Observe(light);
  }
  // A new dataset is created once the devices are ready (an unreachable
  // device leaves nothing behind); a resumed one is checked first.
  bool ok = !resume || this->Writer->Resume() || this->Fail(std::string());
  ok = ok && this->PrepareDevices();
  ok = ok && (resume || this->Writer->Start() || this->Fail(std::string()));
  const int planned = this->Writer->GetNumberOfPlannedViews();
  const Clock::time_point start = Clock::now();
  for (int view = this->Writer->GetNumberOfCompleteViews(); ok && view < planned; ++view)
  {
    if (this->AbortRequested)
    {
      this->Aborted = true;
      break;
    }
    ok = this->TakeView(view);
    if (ok)
    {
      ++this->NumberOfViewsTaken;
      const double elapsed = SecondsSince(start);
      this->OverheadSeconds = elapsed - this->DeviceSeconds;
      this->SecondsRemaining = elapsed / this->NumberOfViewsTaken * (planned - view - 1);
      double fraction = (view + 1.0) / planned;
      this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
    }
  }
  if (ok)
  {
    for (vtkCaptureLight* light : this->Lights)
    {
      light->Off();
    }
    this->Camera->Close();
    this->Gantry->Disconnect();
  }
  this->DeviceErrors->StopObserving();
  return ok;
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::PrepareDevices()
{
  vtkModbusGantry* gantry = this->Gantry;
  bool ok = gantry->Connect() && gantry->UpdateState();
  // A fault left by the run that failed is cleared: resuming is the user's
  // decision to go on.
  ok = ok && (gantry->GetFaultCode() == 0 || gantry->ResetFault());
  ok = ok && gantry->Enable() && (gantry->IsHomed() || gantry->Home());
  if (!ok)
  {
    return this->Fail("preparing the gantry");
  }
  if (!this->Camera->Open())
  {
    return this->Fail("opening the camera");
  }
  for (vtkCaptureLight* light : this->Lights)
  {
    if (!light->Prepare())
    {
      return this->Fail("preparing the lights");
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::TakeView(int view)
{
  const int planned = this->Writer->GetNumberOfPlannedViews();
  const double angle = this->FirstAngle + view * this->AngleStep;
  const std::string where = "view " + std::to_string(view) + " of " + std::to_string(planned) +
    " (gantry angle " + vtkVariant(angle).ToString() + ")";
  Clock::time_point start = Clock::now();
  if (!this->Gantry->MoveTo(angle))
  {
    return this->Fail(where);
  }
  this->DeviceSeconds += SecondsSince(start);
  for (int i = 0; i < this->Writer->GetNumberOfPasses(); ++i)
  {
    const int pass = this->Writer->GetPass(i);
    const std::string photograph = where + ", " + vtkLightField::GetPassName(pass) + " pass";
    for (vtkCaptureLight* light : this->Lights)
    {
      if (!light->Apply(pass))
      {
        return this->Fail(photograph);
      }
    }
    vtkNew<vtkImageData> frame;
    start = Clock::now();
    if (!this->Camera->Acquire(frame))
    {
      return this->Fail(photograph);
    }
    this->DeviceSeconds += SecondsSince(start);
    if (!this->Writer->SetViewFrame(pass, frame))
    {
      return this->Fail(where);
    }
  }
  return this->Writer->CommitView() || this->Fail(where);
}

//------------------------------------------------------------------------------
bool vtkCaptureSession::Fail(const std::string& context)
{
  // The first device error is the cause; what stopping the devices says
  // (a silent gantry does not answer the quick stop either) is not.
  const std::string cause =
    this->DeviceErrors->HasError() ? this->DeviceErrors->GetErrorMessage() : std::string();
  if (this->Gantry->IsConnected())
  {
    this->Gantry->QuickStop();
  }
  for (vtkCaptureLight* light : this->Lights)
  {
    light->Off();
  }
  this->Camera->Close();
  this->Gantry->Disconnect();
  this->DeviceErrors->StopObserving();
  vtkErrorMacro(<< (context.empty() ? cause : context + ": " + cause));
  return false;
}

//------------------------------------------------------------------------------
void vtkCaptureSession::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Gantry: " << this->Gantry << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Lights: " << this->Lights.size() << "\n";
  os << indent << "FirstAngle: " << this->FirstAngle << "\n";
  os << indent << "AngleStep: " << this->AngleStep << "\n";
  os << indent << "Aborted: " << this->Aborted << "\n";
  os << indent << "NumberOfViewsTaken: " << this->NumberOfViewsTaken << "\n";
  os << indent << "DeviceSeconds: " << this->DeviceSeconds << "\n";
  os << indent << "OverheadSeconds: " << this->OverheadSeconds << "\n";
  os << indent << "SecondsRemaining: " << this->SecondsRemaining << "\n";
}
