#include "vtkSimulatedCoaxialLight.h"

#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkSimulatedRigCamera.h"

vtkStandardNewMacro(vtkSimulatedCoaxialLight);
vtkCxxSetObjectMacro(vtkSimulatedCoaxialLight, Camera, vtkSimulatedRigCamera);

//------------------------------------------------------------------------------
vtkSimulatedCoaxialLight::vtkSimulatedCoaxialLight() = default;

//------------------------------------------------------------------------------
vtkSimulatedCoaxialLight::~vtkSimulatedCoaxialLight()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
bool vtkSimulatedCoaxialLight::Apply(int pass)
{
  if (!this->Camera)
  {
    vtkErrorMacro("Coaxial light " << (this->Name ? this->Name : "(unnamed)")
                                   << ": no simulated camera to light (SetCamera).");
    return false;
  }
  this->Camera->SetCoaxialLight(pass == vtkLightField::COAXIAL);
  return true;
}

//------------------------------------------------------------------------------
void vtkSimulatedCoaxialLight::Off()
{
  if (this->Camera)
  {
    this->Camera->SetCoaxialLight(false);
  }
}

//------------------------------------------------------------------------------
void vtkSimulatedCoaxialLight::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << (this->Camera ? "set" : "(none)") << "\n";
}
