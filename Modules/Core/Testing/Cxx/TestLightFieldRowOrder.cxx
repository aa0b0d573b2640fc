// vtkLightField's documented row order: pixel (x, y) of view v, OpenCV
// coordinates (top-left origin), is point (x, H - 1 - y, v); pass arrays
// have the documented types; copies keep (shallow) or duplicate (deep) the rig.
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkLightField.h"
#include "vtkNew.h"

#include <cstdlib>
#include <iostream>

#define CHECK(cond)                                                                                \
  if (!(cond))                                                                                     \
  {                                                                                                \
    std::cout << "FAIL line " << __LINE__ << ": " #cond "\n";                                      \
    return EXIT_FAILURE;                                                                           \
  }

int TestLightFieldRowOrder(int, char*[])
{
  vtkNew<vtkLightField> lf;
  lf->SetLayout(5, 4, 3);
  CHECK(lf->GetWidth() == 5 && lf->GetHeight() == 4 && lf->GetNumberOfViews() == 3);
  CHECK(lf->GetNumberOfPoints() == 60);

  // Top-left pixel of view 1 is the first point of the last row of slice 1.
  CHECK(lf->GetPointIndex(1, 0, 0) == 1 * 20 + 3 * 5);
  // Bottom-right pixel of view 2 is the last point of the first row of slice 2.
  CHECK(lf->GetPointIndex(2, 4, 3) == 2 * 20 + 4);
  double point[3];
  lf->GetPoint(lf->GetPointIndex(2, 1, 0), point);
  CHECK(point[0] == 1.0 && point[1] == 3.0 && point[2] == 2.0);

  vtkDataArray* coaxial = lf->AllocatePass(vtkLightField::COAXIAL);
  vtkDataArray* depth = lf->AllocatePass(vtkLightField::DEPTH);
  CHECK(coaxial && coaxial->GetNumberOfComponents() == 3 &&
    coaxial->GetDataType() == VTK_UNSIGNED_CHAR && coaxial->GetNumberOfTuples() == 60);
  CHECK(depth && depth->GetNumberOfComponents() == 1 && depth->GetDataType() == VTK_FLOAT);
  CHECK(lf->GetPass(vtkLightField::LABEL) == nullptr);
  CHECK(vtkLightField::GetPassFromName("label") == vtkLightField::LABEL);
  CHECK(vtkLightField::GetPassFromName("Coaxial") == vtkLightField::COAXIAL);
  CHECK(vtkLightField::GetPassFromName("nonsense") == -1);

  lf->GetRig()->SetNumberOfViews(3);
  vtkNew<vtkLightField> shallow;
  shallow->ShallowCopy(lf);
  CHECK(shallow->GetRig() == lf->GetRig());
  CHECK(shallow->GetPass(vtkLightField::DEPTH) == depth);
  vtkNew<vtkLightField> deep;
  deep->DeepCopy(lf);
  CHECK(deep->GetRig() != lf->GetRig() && deep->GetRig()->GetNumberOfViews() == 3);
  CHECK(deep->GetPass(vtkLightField::DEPTH) != depth);

  lf->SetLayout(2, 2, 1);
  CHECK(lf->GetPass(vtkLightField::COAXIAL) == nullptr);
  std::cout << "row order and passes as documented\n";
  return EXIT_SUCCESS;
}
