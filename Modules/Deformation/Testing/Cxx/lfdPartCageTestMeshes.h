/**
 * @file   lfdPartCageTestMeshes.h
 * @brief  Labelled meshes for the vtkPartCageSource and vtkCagePoseFilter tests.
 */
#ifndef lfdPartCageTestMeshes_h
#define lfdPartCageTestMeshes_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <vector>

namespace lfdtest
{

/// Appends the cells of `part` (points mapped by `place`) to `mesh` with
/// label `label`.
template<typename Place>
inline void AppendPart(vtkPolyData* mesh, vtkPolyData* part, int label, Place place)
{
  vtkPoints* points = mesh->GetPoints();
  const vtkIdType base = points->GetNumberOfPoints();
  for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    part->GetPoint(i, p);
    place(p, q);
    points->InsertNextPoint(q);
  }
  auto* labels = vtkIntArray::SafeDownCast(mesh->GetCellData()->GetArray("Label"));
  for (vtkIdType c = 0; c < part->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    part->GetCellPoints(c, n, ids);
    std::vector<vtkIdType> shifted(ids, ids + n);
    for (vtkIdType& id : shifted)
    {
      id += base;
    }
    mesh->GetPolys()->InsertNextCell(n, shifted.data());
    labels->InsertNextValue(label);
  }
}

/// An empty polygonal mesh with points, polygons and a "Label" cell array.
inline vtkSmartPointer<vtkPolyData> MakeLabelledMesh()
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  mesh->SetPolys(polys);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  mesh->GetCellData()->AddArray(labels);
  return mesh;
}

/// The fish of the paper's Fig. 13 along +x as three overlapping ellipsoids:
/// tail (label 3) x in [-0.62, -0.30], body (2) [-0.36, 0.36], head (1)
/// [0.20, 0.60]; the body is the widest: y in about [-0.2, 0.2], z in about
/// [-0.1, 0.1].
inline vtkSmartPointer<vtkPolyData> MakeFishMesh()
{
  vtkNew<vtkSphereSource> sphere; // radius 0.5, poles on z
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  sphere->Update();
  auto mesh = MakeLabelledMesh();
  struct Part
  {
    int Label;
    double Min, Max, RadiusY, RadiusZ;
  };
  const Part parts[3] = {
    { 3, -0.62, -0.30, 0.15, 0.03 }, { 2, -0.36, 0.36, 0.2, 0.1 }, { 1, 0.20, 0.60, 0.12, 0.08 }
  };
  for (const Part& part : parts)
  {
    // The sphere's poles become the part's ends along x.
    AppendPart(mesh,
      sphere->GetOutput(),
      part.Label,
      [&](const double p[3], double q[3])
      {
        q[0] = 0.5 * (part.Min + part.Max) + (part.Max - part.Min) * p[2];
        q[1] = 2.0 * part.RadiusY * p[1];
        q[2] = 2.0 * part.RadiusZ * p[0];
      });
  }
  return mesh;
}

/// Three separated unit cubes (6 quads each) stacked along y: label 2 at
/// y in [0, 1], label 3 at [1.5, 2.5], label 1 at [3, 4]; x, z in [0, 1].
inline vtkSmartPointer<vtkPolyData> MakeSeparatedPartsMesh()
{
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = {
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
  };
  for (const auto& face : faces)
  {
    quads->InsertNextCell(4, face);
  }
  cube->SetPoints(points);
  cube->SetPolys(quads);
  auto mesh = MakeLabelledMesh();
  const int labels[3] = { 2, 3, 1 };
  const double offsets[3] = { 0.0, 1.5, 3.0 };
  for (int k = 0; k < 3; ++k)
  {
    AppendPart(mesh,
      cube,
      labels[k],
      [&](const double p[3], double q[3])
      {
        q[0] = p[0];
        q[1] = p[1] + offsets[k];
        q[2] = p[2];
      });
  }
  return mesh;
}

} // namespace lfdtest

#endif
