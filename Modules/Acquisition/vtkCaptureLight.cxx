#include "vtkCaptureLight.h"

vtkCaptureLight::vtkCaptureLight() = default;

vtkCaptureLight::~vtkCaptureLight()
{
  this->SetName(nullptr);
}

void vtkCaptureLight::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << (this->Name ? this->Name : "(none)") << "\n";
}
