// Shared by the Widgets view tests: the fish captured with projectors and
// caged by part (the paper's Fig. 13 object), small enough for a test; the
// checks that print their numbers are the Synthesis tests'.
#ifndef lfdWidgetsTestUtilities_h
#define lfdWidgetsTestUtilities_h

#include "lfdSynthesisTestUtilities.h"

#include "vtkDeformationCage.h"
#include "vtkLabelPalette.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

namespace lfdtest
{
struct Fish
{
  vtkNew<vtkProceduralObjectSource> Source;
  vtkSmartPointer<vtkLightField> LightField;
  vtkSmartPointer<vtkDeformationCage> Cage;
};

// The fish from `rows` rings (0.5 apart) of 24 / rows views of 128 x 128 pixels, lit by
// 2 projectors of 64 x 48 pixels, with its part cage (one box per label).
inline void MakeFish(Fish& fish, int rows = 1)
{
  fish.Source->SetObjectToFish();
  fish.Source->SetResolution(24);
  vtkNew<vtkUnsignedCharArray> palette;
  vtkNew<vtkLabelPalette> chooser;
  chooser->Build(palette);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(fish.Source->GetOutputPort());
  capture->SetViewsPerRing(24 / rows);
  capture->SetNumberOfRows(rows);
  capture->SetRowSpacing(0.5);
  capture->SetWidth(128);
  capture->SetHeight(128);
  capture->SetNumberOfProjectors(2);
  capture->SetProjectorWidth(64);
  capture->SetProjectorHeight(48);
  capture->SetPalette(palette);
  capture->Update();
  fish.LightField = capture->GetOutput();
  vtkNew<vtkPartCageSource> cage;
  cage->SetInputConnection(fish.Source->GetOutputPort());
  cage->Update();
  fish.Cage = cage->GetOutput();
}
}

#endif
