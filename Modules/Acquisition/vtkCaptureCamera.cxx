#include "vtkCaptureCamera.h"

vtkCaptureCamera::vtkCaptureCamera() = default;

vtkCaptureCamera::~vtkCaptureCamera()
{
  this->SetAddress(nullptr);
}

void vtkCaptureCamera::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Address: " << (this->Address ? this->Address : "(none)") << "\n";
  os << indent << "ExposureTime: " << this->ExposureTime << " us\n";
  os << indent << "Gain: " << this->Gain << " dB\n";
}
