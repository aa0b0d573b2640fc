// The scene logic's projector-mask command (issue 10, projector view): a
// painted mask replaces one projector's slice of the light field's masks as
// one undoable command invoking ProjectorMasksModifiedEvent; undo and redo
// restore the bytes exactly; a missing mask stack, a projector out of range
// and a mask of the wrong size are refused with one line and change nothing.
#include "lfdIOTestUtilities.h"
#include "lfdSceneTestUtilities.h"

#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

using lfdtest::Check;
using lfdtest::CheckEqual;
using lfdtest::CheckFailure;
using lfdtest::LastError;

namespace
{
using Logic = vtkLightFieldSceneLogic;

// A width x height x slices RGB image whose byte b is (seed + b) % 251.
vtkSmartPointer<vtkImageData> MakeMasks(int width, int height, int slices, int seed)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, slices);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("Mask");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType b = 0; b < rgb->GetNumberOfValues(); ++b)
  {
    rgb->SetValue(b, static_cast<unsigned char>((seed + b) % 251));
  }
  image->GetPointData()->AddArray(rgb);
  return image;
}

std::vector<unsigned char> Bytes(vtkImageData* image)
{
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetArray("Mask"));
  return std::vector<unsigned char>(
    rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
}

}

int TestSceneLogicProjectorMask(int, char*[])
{
  vtkNew<Logic> logic;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(logic);
  vtkNew<vtkLightField> lightField;
  lightField->SetLayout(4, 4, 1);
  logic->SetLightField(lightField);
  auto painted = MakeMasks(3, 2, 1, 100);
  bool applied = logic->SetProjectorMask(0, painted);
  CheckFailure("painting without masks",
    !applied,
    LastError(errors),
    { "SetProjectorMask: the light field has no projector masks to paint" });

  auto masks = MakeMasks(3, 2, 2, 7);
  lightField->SetProjectorMasks(masks);
  const std::vector<unsigned char> original = Bytes(masks);
  lfdtest::EventCounter events(logic);
  Check(logic->SetProjectorMask(1, painted), "mask of projector 1 painted");
  CheckEqual(events[Logic::ProjectorMasksModifiedEvent], 1, "ProjectorMasksModifiedEvent");
  CheckEqual(events[vtkCommand::ModifiedEvent], 1, "ModifiedEvent");
  CheckEqual(events[Logic::UndoStackModifiedEvent], 1, "UndoStackModifiedEvent");
  CheckEqual(logic->GetUndoName(), std::string("Paint projector mask"), "undo name");
  std::vector<unsigned char> expected = original;
  const std::vector<unsigned char> stroke = Bytes(painted);
  std::copy(stroke.begin(), stroke.end(), expected.begin() + 18);
  Check(Bytes(masks) == expected, "slice 1 replaced, slice 0 untouched");

  events.Reset();
  Check(logic->Undo(), "undo");
  Check(Bytes(masks) == original, "undo restores the masks byte for byte");
  CheckEqual(events[Logic::ProjectorMasksModifiedEvent], 1, "undo's ProjectorMasksModifiedEvent");
  Check(logic->Redo(), "redo");
  Check(Bytes(masks) == expected, "redo paints it again");

  const int commands = logic->GetNumberOfCommands();
  applied = logic->SetProjectorMask(2, painted);
  CheckFailure("projector 2 of 2",
    !applied,
    LastError(errors),
    { "SetProjectorMask: projector 2 does not exist (the light field has 2)" });
  auto wrongSize = MakeMasks(2, 2, 1, 0);
  applied = logic->SetProjectorMask(0, wrongSize);
  CheckFailure("a 2 x 2 mask",
    !applied,
    LastError(errors),
    { "the mask of projector 0 must be an RGB uint8 image of 3 x 2 pixels" });
  CheckEqual(logic->GetNumberOfCommands(), commands, "refused paints push no command");
  Check(Bytes(masks) == expected, "refused paints change nothing");
  return lfdtest::Result();
}
