// Links against an installed LightField Deform and renders: the fish is
// captured on a small ring (OpenGL, so run it with an X display) and a
// novel view between two captured ones is rendered from the light field.
// Prints the number of object pixels and fails when there are too few.
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>

int main()
{
  vtkNew<vtkProceduralObjectSource> fish;
  fish->SetObjectToFish();
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(fish->GetOutputPort());
  capture->SetViewsPerRing(24);
  capture->SetNumberOfRows(1);
  capture->SetWidth(64);
  capture->SetHeight(64);
  capture->Update();
  vtkLightField* lightField = vtkLightField::SafeDownCast(capture->GetOutputDataObject(0));
  if (!lightField || lightField->GetNumberOfViews() != 24)
  {
    std::cerr << "lfdConsumer: the capture failed\n";
    return 1;
  }

  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.0, 3.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewAngle(30.0);
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(lightField);
  renderer->SetCamera(camera);
  renderer->SetWidth(64);
  renderer->SetHeight(64);
  renderer->Update();
  vtkImageData* image = renderer->GetOutput();
  auto* labels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetArray("Label"));
  vtkIdType object = 0;
  for (vtkIdType i = 0; labels && i < labels->GetNumberOfValues(); ++i)
  {
    object += labels->GetValue(i) != 0 ? 1 : 0;
  }
  std::cout << "lfdConsumer: " << object << " object pixels of 64 x 64\n";
  return object > 200 ? 0 : 1;
}
