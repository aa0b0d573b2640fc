#include "vtkLabelAccuracy.h"

#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkLabelAccuracy);

//------------------------------------------------------------------------------
vtkLabelAccuracy::vtkLabelAccuracy()
  : Confusion(256 * 256, 0)
{
}

//------------------------------------------------------------------------------
vtkLabelAccuracy::~vtkLabelAccuracy() = default;

//------------------------------------------------------------------------------
std::string vtkLabelAccuracy::Compute(vtkLightField* split, vtkLightField* truth)
{
  this->ObjectPixels = 0;
  this->CorrectPixels = 0;
  this->MaximumLabel = 0;
  std::fill(this->Confusion.begin(), this->Confusion.end(), 0);
  this->Modified();
  auto* expected =
    truth ? vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::LABEL)) : nullptr;
  auto* found =
    split ? vtkUnsignedCharArray::SafeDownCast(split->GetPass(vtkLightField::LABEL)) : nullptr;
  if (!found)
  {
    return "the split light field has no Label pass";
  }
  if (!expected)
  {
    return "has no Label pass to compare with";
  }
  if (expected->GetNumberOfTuples() != found->GetNumberOfTuples())
  {
    return "its Label pass has another size than the split light field's";
  }
  for (vtkIdType i = 0; i < expected->GetNumberOfTuples(); ++i)
  {
    const int e = expected->GetValue(i);
    const int f = found->GetValue(i);
    if (e == 0)
    {
      continue;
    }
    ++this->ObjectPixels;
    this->CorrectPixels += e == f ? 1 : 0;
    ++this->Confusion[256 * e + f];
    this->MaximumLabel = std::max({ this->MaximumLabel, e, f });
  }
  return std::string();
}

//------------------------------------------------------------------------------
double vtkLabelAccuracy::GetAccuracy() const
{
  return this->ObjectPixels ? 100.0 * this->CorrectPixels / this->ObjectPixels : 0.0;
}

//------------------------------------------------------------------------------
vtkIdType vtkLabelAccuracy::GetConfusion(int truthLabel, int foundLabel) const
{
  if (truthLabel < 1 || truthLabel > 255 || foundLabel < 0 || foundLabel > 255)
  {
    return 0;
  }
  return this->Confusion[256 * truthLabel + foundLabel];
}

//------------------------------------------------------------------------------
void vtkLabelAccuracy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ObjectPixels: " << this->ObjectPixels << "\n";
  os << indent << "CorrectPixels: " << this->CorrectPixels << "\n";
  os << indent << "Accuracy: " << this->GetAccuracy() << " %\n";
  os << indent << "MaximumLabel: " << this->MaximumLabel << "\n";
}
