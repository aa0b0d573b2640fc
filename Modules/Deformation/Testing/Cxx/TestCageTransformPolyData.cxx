// A VTK filter deforms a mesh with the cage map: the ground truth of the
// renderer tests (DESIGN.md 4.5). A sphere inside a box twisted by 45
// degrees keeps its vertex count and every vertex lands on the closed-form
// twist.
#include "lfdDeformationTestUtilities.h"

#include "vtkCageTransform.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cstdlib>

int TestCageTransformPolyData(int, char*[])
{
  const double angle = vtkMath::Pi() / 4;
  auto cage = lfdtest::MakeTwistedBox(angle);
  vtkNew<vtkCageTransform> transform;
  transform->SetCage(cage);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.1, 0, 1);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);

  vtkNew<vtkTransformPolyDataFilter> warp;
  warp->SetInputConnection(sphere->GetOutputPort());
  warp->SetTransform(transform);
  warp->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  warp->Update();

  vtkPolyData* input = sphere->GetOutput();
  vtkPolyData* output = warp->GetOutput();
  const vtkIdType count = input->GetNumberOfPoints();
  double maxError = 0.0, maxDisplacement = 0.0;
  for (vtkIdType i = 0; i < count && i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], expected[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    lfdtest::TwistPoint(angle, p, expected);
    maxError = std::max(maxError, std::sqrt(vtkMath::Distance2BetweenPoints(q, expected)));
    maxDisplacement = std::max(maxDisplacement, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  std::printf("sphere: %lld vertices in, %lld out, %lld cells in, %lld out; max displacement %g, "
              "max error vs closed-form twist %g\n",
    static_cast<long long>(count),
    static_cast<long long>(output->GetNumberOfPoints()),
    static_cast<long long>(input->GetNumberOfCells()),
    static_cast<long long>(output->GetNumberOfCells()),
    maxDisplacement,
    maxError);

  bool ok = lfdtest::Check(output->GetNumberOfPoints() == count, "vertex count kept");
  ok &= lfdtest::Check(output->GetNumberOfCells() == input->GetNumberOfCells(), "cell count kept");
  ok &= lfdtest::Check(maxDisplacement > 0.3, "the vertices moved");
  ok &= lfdtest::Check(maxError < 1e-12, "every vertex follows the twist");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
