#include "vtkSimulatedProjector.h"

#include "vtkCameraRig.h"
#include "vtkObjectFactory.h"
#include "vtkSimulatedRigCamera.h"

vtkStandardNewMacro(vtkSimulatedProjector);
vtkCxxSetObjectMacro(vtkSimulatedProjector, Camera, vtkSimulatedRigCamera);

//------------------------------------------------------------------------------
vtkSimulatedProjector::vtkSimulatedProjector() = default;

//------------------------------------------------------------------------------
vtkSimulatedProjector::~vtkSimulatedProjector()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
bool vtkSimulatedProjector::PrepareDevice()
{
  if (!this->Camera)
  {
    vtkErrorMacro("Projector " << (this->Name ? this->Name : "(unnamed)")
                               << ": no simulated camera to light (SetCamera).");
    return false;
  }
  vtkCameraRig* projectors = this->Camera->GetProjectors();
  if (this->Resolution[0] == 0 && this->Resolution[1] == 0 && projectors)
  {
    this->SetResolution(projectors->GetImageSize());
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSimulatedProjector::ShowPattern(vtkImageData* pattern)
{
  return this->PrepareDevice() && this->CheckPattern(pattern) &&
    this->Camera->SetProjectorPattern(this->ProjectorIndex, pattern);
}

//------------------------------------------------------------------------------
void vtkSimulatedProjector::Off()
{
  if (this->PrepareDevice())
  {
    this->Camera->SetProjectorPattern(this->ProjectorIndex, nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkSimulatedProjector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << (this->Camera ? "set" : "(none)") << "\n";
}
