// vtkLabelAccuracy (the figures of `lfd split --truth`): accuracy and
// confusion counted exactly on a 4 x 2 x 2 light field, background pixels
// of the truth ignored, and the refusals said as one line.
#include "lfdTestChecks.h"
#include "vtkLabelAccuracy.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>
#include <string>

using lfdtest::CheckEqual;

namespace
{
void FillLabels(vtkLightField* lightField, const unsigned char* labels)
{
  lightField->SetLayout(4, 2, 2);
  auto* pass = vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::LABEL));
  for (vtkIdType i = 0; i < pass->GetNumberOfTuples(); ++i)
  {
    pass->SetValue(i, labels[i]);
  }
}
}

int TestLabelAccuracy(int, char*[])
{
  // 16 pixels: 13 object pixels of the truth, 10 of them labelled the same.
  const unsigned char truthLabels[16] = { 0, 1, 1, 1, 2, 2, 2, 2, 0, 0, 3, 3, 1, 1, 1, 2 };
  const unsigned char splitLabels[16] = { 5, 1, 1, 0, 2, 2, 1, 2, 0, 3, 3, 3, 1, 1, 2, 2 };
  vtkNew<vtkLightField> truth, split, unlabelled;
  FillLabels(truth, truthLabels);
  FillLabels(split, splitLabels);
  vtkNew<vtkLabelAccuracy> accuracy;
  CheckEqual(accuracy->Compute(split, truth), std::string(), "compared");
  CheckEqual(accuracy->GetObjectPixels(), static_cast<vtkIdType>(13), "object pixels");
  CheckEqual(accuracy->GetCorrectPixels(), static_cast<vtkIdType>(10), "correct pixels");
  CheckEqual(accuracy->GetAccuracy(), 100.0 * 10 / 13, "accuracy (%)");
  CheckEqual(accuracy->GetMaximumLabel(), 3, "largest label (background pixels ignored)");
  CheckEqual(accuracy->GetConfusion(1, 0), static_cast<vtkIdType>(1), "truth 1 left unlabelled");
  CheckEqual(accuracy->GetConfusion(1, 2), static_cast<vtkIdType>(1), "truth 1 found as 2");
  CheckEqual(accuracy->GetConfusion(2, 1), static_cast<vtkIdType>(1), "truth 2 found as 1");
  CheckEqual(accuracy->GetConfusion(3, 3), static_cast<vtkIdType>(2), "truth 3 found as 3");
  CheckEqual(accuracy->GetConfusion(0, 5), static_cast<vtkIdType>(0), "background is not counted");

  unlabelled->SetLayout(4, 2, 2);
  CheckEqual(accuracy->Compute(split, unlabelled),
    std::string("has no Label pass to compare with"),
    "a truth without labels");
  CheckEqual(accuracy->GetObjectPixels(), static_cast<vtkIdType>(0), "figures after a refusal");
  vtkNew<vtkLightField> small;
  small->SetLayout(2, 2, 2);
  small->AllocatePass(vtkLightField::LABEL);
  CheckEqual(accuracy->Compute(split, small),
    std::string("its Label pass has another size than the split light field's"),
    "a truth of another size");
  return lfdtest::Result();
}
