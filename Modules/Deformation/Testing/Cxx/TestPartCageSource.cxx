// vtkPartCageSource: the fish of the paper's Fig. 13 (three overlapping
// labelled ellipsoids along x) gives 3 slab boxes on 16 shared points with
// the boundaries at the middle of the overlaps; a mesh of separated parts
// along y is caged with every cell inside its own box; meshes without labels
// or cells are refused with a clear error.
#include "lfdDeformationTestUtilities.h"
#include "lfdPartCageTestMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"
#include "vtkPartCageSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using lfdtest::ErrorText;
using lfdtest::Near;

/// The fraction of the labelled cells of `mesh` whose centroid lies in a
/// box (rest corners 0 and 6 are its min and max) of their own label,
/// counting only cells whose centroid x is outside the intervals
/// `skip[2i]..skip[2i+1]` (i < skipped).
double FractionInOwnBox(vtkPolyData* mesh,
  vtkDeformationCage* cage,
  const double* skip = nullptr,
  int skipped = 0)
{
  vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
  vtkIdType inside = 0, counted = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double sum[3] = { 0, 0, 0 };
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    mesh->GetCellPoints(c, n, ids);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      mesh->GetPoint(ids[i], p);
      for (int a = 0; a < 3; ++a)
      {
        sum[a] += p[a] / n;
      }
    }
    bool skipCell = false;
    for (int i = 0; i < skipped; ++i)
    {
      skipCell |= sum[0] >= skip[2 * i] && sum[0] <= skip[2 * i + 1];
    }
    if (skipCell)
    {
      continue;
    }
    ++counted;
    const int label = static_cast<int>(labels->GetComponent(c, 0));
    for (vtkIdType b = 0; b < cage->GetNumberOfBoxes(); ++b)
    {
      double corners[24];
      cage->GetRestCorners(b, corners);
      bool in = cage->GetBoxLabel(b) == label;
      for (int a = 0; a < 3 && in; ++a)
      {
        in = sum[a] >= corners[a] && sum[a] <= corners[18 + a];
      }
      if (in)
      {
        ++inside;
        break;
      }
    }
  }
  return static_cast<double>(inside) / counted;
}

/// Runs `source` on `mesh` expecting a refusal whose message holds `fragment`.
bool ExpectError(const char* what, vtkPolyData* mesh, const char* fragment)
{
  vtkNew<vtkPartCageSource> source;
  source->SetInputData(mesh);
  vtkNew<vtkTest::ErrorObserver> observer;
  source->AddObserver(vtkCommand::ErrorEvent, observer);
  vtkNew<vtkTest::ErrorObserver> pipelineObserver;
  source->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineObserver);
  source->Update();
  const std::string message = ErrorText(observer->GetErrorMessage());
  std::printf("%s: boxes %lld, error \"%s\"\n",
    what,
    static_cast<long long>(source->GetOutput()->GetNumberOfBoxes()),
    message.c_str());
  bool ok = lfdtest::Check(observer->GetError(), "an error is reported");
  ok &= lfdtest::Check(message.find(fragment) != std::string::npos, fragment);
  ok &= lfdtest::Check(source->GetOutput()->GetNumberOfBoxes() == 0, "the output is empty");
  return ok;
}
}

int TestPartCageSource(int, char*[])
{
  bool ok = true;

  // The fish: tail 3, body 2, head 1 along +x.
  vtkSmartPointer<vtkPolyData> fish = lfdtest::MakeFishMesh();
  vtkNew<vtkPartCageSource> source;
  source->SetInputData(fish);
  source->Update();
  vtkDeformationCage* cage = source->GetOutput();
  std::printf("fish: %lld boxes, %lld points, axis %d\n",
    static_cast<long long>(cage->GetNumberOfBoxes()),
    static_cast<long long>(cage->GetNumberOfPoints()),
    source->GetUsedAxis());
  ok &= lfdtest::Check(cage->GetNumberOfBoxes() == 3, "3 boxes");
  ok &= lfdtest::Check(cage->GetNumberOfPoints() == 16, "16 points (shared boundaries)");
  ok &= lfdtest::Check(source->GetUsedAxis() == 0, "the longest axis is x");
  if (cage->GetNumberOfBoxes() != 3)
  {
    return EXIT_FAILURE;
  }
  const int expectedLabels[3] = { 3, 2, 1 };
  for (int b = 0; b < 3; ++b)
  {
    std::printf("box %d: label %d\n", b, cage->GetBoxLabel(b));
    ok &= lfdtest::Check(cage->GetBoxLabel(b) == expectedLabels[b], "labels in axis order");
  }
  double bounds[6];
  fish->GetBounds(bounds);
  const double pad = 0.05 * 1.22;
  ok &= Near("fish length", bounds[1] - bounds[0], 1.22);
  const double faces[4] = { -0.62 - pad, -0.33, 0.28, 0.60 + pad };
  for (int b = 0; b < 3; ++b)
  {
    double corners[24];
    cage->GetRestCorners(b, corners);
    ok &= Near("box min x", corners[0], faces[b]);
    ok &= Near("box max x", corners[18], faces[b + 1]);
    ok &= Near("box min y", corners[1], bounds[2] - pad);
    ok &= Near("box max z", corners[20], bounds[5] + pad);
  }
  // Consecutive boxes share the 4 points of their common face.
  vtkIdType shared = 0;
  for (int b = 0; b + 1 < 3; ++b)
  {
    vtkIdType n = 0;
    const vtkIdType *a = nullptr, *c = nullptr;
    cage->GetCellPoints(b, n, a);
    std::vector<vtkIdType> first(a, a + 8);
    cage->GetCellPoints(b + 1, n, c);
    for (int i = 0; i < 8; ++i)
    {
      for (int j = 0; j < 8; ++j)
      {
        shared += first[i] == c[j] ? 1 : 0;
      }
    }
  }
  std::printf("shared corners: %lld\n", static_cast<long long>(shared));
  ok &= lfdtest::Check(shared == 8, "4 shared corners per boundary");
  ok &= lfdtest::Check(!cage->IsDeformed(), "the cage is at rest");
  ok &= lfdtest::CheckValid(cage, "the fish cage validates");
  const double fishInside = FractionInOwnBox(fish, cage);
  std::printf(
    "fish: %.4f of the cells have their centroid in their own box (parts overlap)\n", fishInside);
  // Outside the overlaps of the parts' extents, every cell is in its box.
  const double overlaps[4] = { -0.36, -0.30, 0.20, 0.36 };
  const double fishOutsideOverlaps = FractionInOwnBox(fish, cage, overlaps, 2);
  std::printf(
    "fish: %.4f of the cells outside the overlaps are in their own box\n", fishOutsideOverlaps);
  ok &= lfdtest::Check(fishOutsideOverlaps == 1.0, "cells outside the overlaps are in their box");

  // Separated parts along y, labels out of order; the cage follows y.
  vtkSmartPointer<vtkPolyData> column = lfdtest::MakeSeparatedPartsMesh();
  source->SetInputData(column);
  source->SetMargin(0.1);
  source->Update();
  cage = source->GetOutput();
  std::printf("column: %lld boxes, axis %d\n",
    static_cast<long long>(cage->GetNumberOfBoxes()),
    source->GetUsedAxis());
  ok &= lfdtest::Check(source->GetUsedAxis() == 1, "the longest axis is y");
  ok &= lfdtest::Check(
    cage->GetNumberOfBoxes() == 3 && cage->GetNumberOfPoints() == 16, "3 boxes on 16 points");
  ok &= lfdtest::Check(
    cage->GetBoxLabel(0) == 2 && cage->GetBoxLabel(1) == 3 && cage->GetBoxLabel(2) == 1,
    "labels 2, 3, 1 in axis order");
  double corners[24];
  cage->GetRestCorners(1, corners);
  ok &= Near("gap boundary 1", corners[1], 0.5 * (1.0 + 1.5));
  ok &= Near("gap boundary 2", corners[19], 0.5 * (2.5 + 3.0));
  ok &= lfdtest::CheckValid(cage, "the column cage validates");
  const double columnInside = FractionInOwnBox(column, cage);
  std::printf("column: %.4f of the cells have their centroid in their own box\n", columnInside);
  ok &= lfdtest::Check(columnInside == 1.0, "every cell lies in its own box");

  // A single labelled triangle is a cage of one box; Axis forced to z
  // gives it a thickness from the margin.
  vtkNew<vtkPolyData> triangle;
  {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    points->InsertNextPoint(0, 2, 0);
    vtkNew<vtkCellArray> polys;
    const vtkIdType ids[3] = { 0, 1, 2 };
    polys->InsertNextCell(3, ids);
    triangle->SetPoints(points);
    triangle->SetPolys(polys);
    vtkNew<vtkIntArray> labels;
    labels->SetName("Label");
    labels->InsertNextValue(7);
    triangle->GetCellData()->AddArray(labels);
  }
  source->SetInputData(triangle);
  source->SetAxis(2);
  source->Update();
  cage = source->GetOutput();
  std::printf("triangle: %lld boxes, %lld points, label %d\n",
    static_cast<long long>(cage->GetNumberOfBoxes()),
    static_cast<long long>(cage->GetNumberOfPoints()),
    cage->GetBoxLabel(0));
  ok &= lfdtest::Check(
    cage->GetNumberOfBoxes() == 1 && cage->GetNumberOfPoints() == 8 && cage->GetBoxLabel(0) == 7,
    "one box of label 7");
  ok &= lfdtest::CheckValid(cage, "the triangle's cage validates");

  // Refusals.
  vtkNew<vtkPolyData> unlabelled;
  unlabelled->DeepCopy(triangle);
  unlabelled->GetCellData()->RemoveArray("Label");
  ok &= ExpectError("no Label", unlabelled, "\"Label\"");
  vtkNew<vtkPolyData> empty;
  {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    empty->SetPoints(points);
    vtkNew<vtkIntArray> labels;
    labels->SetName("Label");
    empty->GetCellData()->AddArray(labels);
  }
  ok &= ExpectError("no cells", empty, "no cells");

  std::printf("%s\n", ok ? "PASSED" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
