#include "vtkCaptureProjector.h"

#include "lfdProjectorMasks.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cstring>

vtkCxxSetObjectMacro(vtkCaptureProjector, Masks, vtkImageData);

//------------------------------------------------------------------------------
vtkCaptureProjector::vtkCaptureProjector() = default;

//------------------------------------------------------------------------------
vtkCaptureProjector::~vtkCaptureProjector()
{
  this->SetMasks(nullptr);
}

//------------------------------------------------------------------------------
bool vtkCaptureProjector::GetPatternSize(int size[2])
{
  if (this->Resolution[0] > 0 && this->Resolution[1] > 0)
  {
    size[0] = this->Resolution[0];
    size[1] = this->Resolution[1];
    return true;
  }
  if (this->Masks)
  {
    size[0] = this->Masks->GetDimensions()[0];
    size[1] = this->Masks->GetDimensions()[1];
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
vtkImageData* vtkCaptureProjector::MakeSolidPattern(unsigned char value)
{
  int size[2];
  if (!this->GetPatternSize(size))
  {
    vtkErrorMacro("Projector " << (this->Name ? this->Name : "(unnamed)")
                               << ": no Resolution and no Masks: its image size is unknown.");
    return nullptr;
  }
  vtkImageData* pattern = vtkImageData::New();
  pattern->SetDimensions(size[0], size[1], 1);
  pattern->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memset(pattern->GetScalarPointer(), value, 3 * static_cast<size_t>(size[0]) * size[1]);
  return pattern;
}

//------------------------------------------------------------------------------
bool vtkCaptureProjector::CheckPattern(vtkImageData* pattern)
{
  int size[2] = { 0, 0 };
  const bool sized = this->GetPatternSize(size);
  vtkDataArray* scalars = pattern ? pattern->GetPointData()->GetScalars() : nullptr;
  const int* dims = pattern ? pattern->GetDimensions() : size;
  if (sized && scalars && scalars->GetDataType() == VTK_UNSIGNED_CHAR &&
    scalars->GetNumberOfComponents() == 3 && dims[0] == size[0] && dims[1] == size[1] &&
    dims[2] == 1)
  {
    return true;
  }
  vtkErrorMacro(
    "Projector " << (this->Name ? this->Name : "(unnamed)") << ": shows RGB uint8 "
                 << "patterns of " << size[0] << " x " << size[1] << " pixels; the pattern is "
                 << (pattern ? "" : "missing") << (pattern && !scalars ? "without scalars" : "")
                 << (scalars ? std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
                          std::to_string(dims[2]) + " of " +
                          std::to_string(scalars->GetNumberOfComponents()) + " components"
                             : std::string())
                 << ".");
  return false;
}

//------------------------------------------------------------------------------
bool vtkCaptureProjector::Apply(int pass)
{
  const char* name = this->Name ? this->Name : "(unnamed)";
  if (!this->PrepareDevice())
  {
    return false;
  }
  if (pass == vtkLightField::COAXIAL || pass == vtkLightField::FLOOD)
  {
    vtkSmartPointer<vtkImageData> solid;
    solid.TakeReference(this->MakeSolidPattern(pass == vtkLightField::FLOOD ? 255 : 0));
    return solid && this->ShowPattern(solid);
  }
  if (pass != vtkLightField::CODED)
  {
    vtkErrorMacro(
      "Projector " << name << ": no pattern for pass "
                   << (vtkLightField::GetPassName(pass) ? vtkLightField::GetPassName(pass)
                                                        : std::to_string(pass).c_str())
                   << "; a projector lights the Coaxial (dark), Coded and Flood "
                      "passes.");
    return false;
  }
  vtkUnsignedCharArray* colours = lfd::GetMaskColours(this->Masks);
  if (!colours || this->ProjectorIndex >= this->Masks->GetDimensions()[2])
  {
    vtkErrorMacro("Projector " << name << ": no colour mask for the Coded pass (Masks "
                               << (this->Masks ? "has no RGB uint8 slice " : "not set, slice ")
                               << this->ProjectorIndex << ").");
    return false;
  }
  const int* dims = this->Masks->GetDimensions();
  const size_t slice = 3 * static_cast<size_t>(dims[0]) * dims[1];
  vtkNew<vtkImageData> mask;
  mask->SetDimensions(dims[0], dims[1], 1);
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memcpy(mask->GetScalarPointer(), colours->GetPointer(slice * this->ProjectorIndex), slice);
  return this->ShowPattern(mask);
}

//------------------------------------------------------------------------------
void vtkCaptureProjector::Off()
{
  if (!this->PrepareDevice())
  {
    return;
  }
  vtkSmartPointer<vtkImageData> black;
  black.TakeReference(this->MakeSolidPattern(0));
  if (black)
  {
    this->ShowPattern(black);
  }
}

//------------------------------------------------------------------------------
void vtkCaptureProjector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Masks: " << (this->Masks ? "set" : "(none)") << "\n";
  os << indent << "ProjectorIndex: " << this->ProjectorIndex << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
}
