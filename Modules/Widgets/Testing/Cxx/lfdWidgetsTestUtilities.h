// Shared by the Widgets view tests: checks that print their numbers, and the
// fish captured with projectors and caged by part (the paper's Fig. 13
// object), small enough for a test.
#ifndef lfdWidgetsTestUtilities_h
#define lfdWidgetsTestUtilities_h

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

#include <iostream>

namespace lfdtest
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline void Check(bool ok, const char* what, double value, double limit)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (limit " << limit << ")\n";
  Failures() += ok ? 0 : 1;
}

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
