// vtkLabelCellsByBoxes on a 10 x 10 plane (200 triangles) and two boxes: an
// axis-aligned box (label 2) over columns 0-3 given by its rest positions,
// and a box rotated by 30 degrees about Z (label 5) that overlaps it. The
// expected counts come from the analytic boxes, not from vtkHexahedron.
#include "lfdSynthesisTestUtilities.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkLabelCellsByBoxes.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>

namespace
{
constexpr double Angle = vtkMath::Pi() / 6.0;
const double RotatedCenter[2] = { 5.5, 5.0 };
const double RotatedHalf[2] = { 2.0, 1.5 };

void RotatedCorner(double u, double v, double z, double x[3])
{
  x[0] = RotatedCenter[0] + u * std::cos(Angle) - v * std::sin(Angle);
  x[1] = RotatedCenter[1] + u * std::sin(Angle) + v * std::cos(Angle);
  x[2] = z;
}

bool InRotatedBox(const double x[3])
{
  const double dx = x[0] - RotatedCenter[0];
  const double dy = x[1] - RotatedCenter[1];
  const double u = dx * std::cos(Angle) + dy * std::sin(Angle);
  const double v = -dx * std::sin(Angle) + dy * std::cos(Angle);
  return std::abs(u) < RotatedHalf[0] && std::abs(v) < RotatedHalf[1];
}
}

int TestLabelCellsByBoxes(int, char*[])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(10.0, 0.0, 0.0);
  plane->SetPoint2(0.0, 10.0, 0.0);
  plane->SetResolution(10, 10);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();

  // Box 0: [0, 4] x [0, 10] x [-1, 1] in rest space; its points are moved
  // far away, so only RestPosition can label anything. Box 1: rotated.
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> rest;
  rest->SetName("RestPosition");
  rest->SetNumberOfComponents(3);
  vtkNew<vtkUnstructuredGrid> boxes;
  boxes->SetPoints(points);
  boxes->GetPointData()->AddArray(rest);
  const double square[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (int box = 0; box < 2; ++box)
  {
    vtkIdType ids[8];
    for (int corner = 0; corner < 8; ++corner)
    {
      const double z = corner < 4 ? -1.0 : 1.0;
      const double* s = square[corner % 4];
      double x[3];
      if (box == 0)
      {
        x[0] = 4.0 * s[0];
        x[1] = 10.0 * s[1];
        x[2] = z;
      }
      else
      {
        RotatedCorner(
          (2.0 * s[0] - 1.0) * RotatedHalf[0], (2.0 * s[1] - 1.0) * RotatedHalf[1], z, x);
      }
      rest->InsertNextTuple(x);
      ids[corner] = points->InsertNextPoint(x[0] + 100.0, x[1], x[2]);
    }
    boxes->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  }
  vtkNew<vtkIntArray> boxLabels;
  boxLabels->SetName("Label");
  boxLabels->InsertNextValue(2);
  boxLabels->InsertNextValue(5);
  boxes->GetCellData()->AddArray(boxLabels);

  // Expected labels: first box wins, then the rotated box, else 0.
  int expected[3] = { 0, 0, 0 };
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    mesh->GetCellPoints(cell, ids);
    double c[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      double x[3];
      mesh->GetPoint(ids->GetId(i), x);
      for (int k = 0; k < 3; ++k)
      {
        c[k] += x[k] / ids->GetNumberOfIds();
      }
    }
    expected[c[0] < 4.0 ? 1 : (InRotatedBox(c) ? 2 : 0)]++;
  }

  vtkNew<vtkLabelCellsByBoxes> labeller;
  labeller->SetInputData(mesh);
  labeller->SetBoxesData(boxes);
  labeller->Update();
  vtkDataArray* labels = labeller->GetOutput()->GetCellData()->GetArray("Label");
  int counts[3] = { 0, 0, 0 };
  int unexpected = 0;
  for (vtkIdType cell = 0; labels && cell < labels->GetNumberOfTuples(); ++cell)
  {
    const int l = static_cast<int>(labels->GetComponent(cell, 0));
    if (l == 0)
    {
      counts[0]++;
    }
    else if (l == 2)
    {
      counts[1]++;
    }
    else if (l == 5)
    {
      counts[2]++;
    }
    else
    {
      unexpected++;
    }
  }
  lfdtest::Check(labels != nullptr && labels->GetNumberOfTuples() == 200,
    "labelled triangles",
    labels ? labels->GetNumberOfTuples() : 0,
    200);
  lfdtest::Check(
    counts[1] == 80 && expected[1] == 80, "label 2 (box 0, wins the overlap)", counts[1], 80);
  lfdtest::Check(
    counts[2] == expected[2] && expected[2] > 20, "label 5 (rotated box)", counts[2], expected[2]);
  lfdtest::Check(counts[0] == expected[0], "label 0 (no box)", counts[0], expected[0]);
  lfdtest::Check(unexpected == 0, "other labels", unexpected, 0);

  // Without rest positions the boxes are the moved points: nothing inside.
  boxes->GetPointData()->RemoveArray("RestPosition");
  labeller->Modified();
  labeller->Update();
  labels = labeller->GetOutput()->GetCellData()->GetArray("Label");
  int labelled = 0;
  for (vtkIdType cell = 0; cell < labels->GetNumberOfTuples(); ++cell)
  {
    labelled += labels->GetComponent(cell, 0) != 0 ? 1 : 0;
  }
  lfdtest::Check(labelled == 0, "labelled cells with boxes at their moved points", labelled, 0);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
