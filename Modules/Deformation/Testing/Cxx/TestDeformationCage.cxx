// The cage's data model: shared corners, rest and deformed positions,
// labels, and InitializeFromGrid() on the grids a scene holds.
#include "lfdDeformationTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdlib>

namespace
{
using lfdtest::Check;

/// Two unit boxes side by side along x sharing the face x = 1 (12 points):
/// the accessors, then a move of a shared corner and back to rest.
bool TestSharedCorners()
{
  bool ok = true;
  vtkNew<vtkDeformationCage> cage;
  vtkIdType a[8];
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  lfdtest::AddBoxPoints(cage, lo, hi, a);
  const double far[4][3] = { { 2, 0, 0 }, { 2, 1, 0 }, { 2, 1, 1 }, { 2, 0, 1 } };
  vtkIdType f[4];
  for (int i = 0; i < 4; ++i)
  {
    f[i] = cage->AddPoint(far[i]);
  }
  const vtkIdType b[8] = { a[1], f[0], f[1], a[2], a[5], f[3], f[2], a[6] };
  const int first = cage->AddBox(a, 3);
  const int second = cage->AddBox(b, 7);
  std::printf("points %lld boxes %lld labels %d %d\n",
    static_cast<long long>(cage->GetNumberOfPoints()),
    static_cast<long long>(cage->GetNumberOfBoxes()),
    cage->GetBoxLabel(0),
    cage->GetBoxLabel(1));
  ok &= Check(first == 0 && second == 1, "AddBox returns the box index");
  ok &= Check(cage->GetNumberOfPoints() == 12, "shared corners are shared points (12)");
  ok &= Check(cage->GetNumberOfBoxes() == 2, "2 boxes");
  ok &= Check(cage->GetCellType(1) == VTK_HEXAHEDRON, "boxes are VTK_HEXAHEDRON cells");
  ok &= Check(cage->GetBoxLabel(0) == 3 && cage->GetBoxLabel(1) == 7, "labels 3 and 7");
  ok &= Check(cage->GetBoxLabel(2) == 0, "label of a missing box is 0");
  ok &= Check(vtkIntArray::SafeDownCast(cage->GetCellData()->GetArray("Label")) != nullptr,
    "Label is an int cell array");
  ok &= Check(vtkDoubleArray::SafeDownCast(cage->GetRestPositions()) != nullptr &&
      cage->GetRestPositions()->GetNumberOfTuples() == 12,
    "RestPosition is a double point array, one tuple per point");

  double rest[24], deformed[24];
  ok &= Check(cage->GetRestCorners(1, rest), "rest corners of box 1");
  ok &= Check(rest[0] == 1 && rest[3] == 2 && rest[6] == 2 && rest[7] == 1 && rest[20] == 1,
    "box 1 rest corners in VTK order");
  ok &= Check(!cage->GetRestCorners(2, rest) && !cage->GetDeformedCorners(-1, deformed),
    "no corners for a missing box");
  ok &=
    Check(!cage->IsDeformed() && cage->GetLargestDisplacement() == 0.0, "a new cage is at rest");
  ok &= lfdtest::CheckValid(cage, "two boxes at rest validate");

  // Move the shared corner a[6] = (1,1,1): both boxes see it.
  const double moved[3] = { 1.25, 1.5, 1.75 };
  cage->SetDeformedPoint(a[6], moved);
  ok &= Check(cage->IsDeformed(), "moving a point deforms the cage");
  // (0.25, 0.5, 0.75) from its rest position: sqrt(0.875).
  ok &= Check(std::abs(cage->GetLargestDisplacement() - std::sqrt(0.875)) < 1e-15,
    "the largest displacement is the moved corner's");
  double deformedFirst[24];
  cage->GetDeformedCorners(0, deformedFirst);
  const bool inFirst =
    deformedFirst[18] == 1.25 && deformedFirst[19] == 1.5 && deformedFirst[20] == 1.75;
  cage->GetDeformedCorners(1, deformed);
  const bool inSecond = deformed[21] == 1.25 && deformed[22] == 1.5 && deformed[23] == 1.75;
  cage->GetRestCorners(0, rest);
  std::printf("moved corner: box 0 corner 6 (%g %g %g), box 1 corner 7 (%g %g %g), rest (%g %g "
              "%g)\n",
    deformedFirst[18],
    deformedFirst[19],
    deformedFirst[20],
    deformed[21],
    deformed[22],
    deformed[23],
    rest[18],
    rest[19],
    rest[20]);
  ok &= Check(inFirst && inSecond, "the shared corner moves in both boxes");
  ok &= Check(rest[18] == 1 && rest[19] == 1 && rest[20] == 1, "the rest corner stays");
  ok &= lfdtest::CheckValid(cage, "the moved shared corner validates");
  cage->SetPointsToRest();
  ok &= Check(!cage->IsDeformed(), "SetPointsToRest undoes the deformation");
  double p[3];
  cage->GetDeformedPoint(a[6], p);
  ok &= Check(p[0] == 1 && p[1] == 1 && p[2] == 1, "point back at rest");
  return ok;
}

/// InitializeFromGrid() on the grids a scene holds: without RestPosition
/// (undeformed), with a byte Label and a float RestPosition, copied, emptied.
bool TestFromGrid()
{
  bool ok = true;
  // A scene grid without RestPosition is undeformed; its Label may be any type.
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  const vtkIdType a[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  for (vtkIdType i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(lfd::HexCorner[i][0], lfd::HexCorner[i][1], lfd::HexCorner[i][2]);
  }
  grid->SetPoints(points);
  grid->AllocateEstimate(1, 8);
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, a);
  vtkNew<vtkUnsignedCharArray> byteLabels;
  byteLabels->SetName("Label");
  byteLabels->InsertNextValue(5);
  grid->GetCellData()->AddArray(byteLabels);

  vtkNew<vtkDeformationCage> fromGrid;
  fromGrid->InitializeFromGrid(grid);
  std::printf("from grid: points %lld boxes %lld label %d deformed %d\n",
    static_cast<long long>(fromGrid->GetNumberOfPoints()),
    static_cast<long long>(fromGrid->GetNumberOfBoxes()),
    fromGrid->GetBoxLabel(0),
    fromGrid->IsDeformed() ? 1 : 0);
  ok &= Check(
    fromGrid->GetNumberOfPoints() == 8 && fromGrid->GetNumberOfBoxes() == 1, "the grid is copied");
  ok &= Check(fromGrid->GetBoxLabel(0) == 5 &&
      vtkIntArray::SafeDownCast(fromGrid->GetCellData()->GetArray("Label")),
    "the label becomes an int array");
  ok &= Check(!fromGrid->IsDeformed() && fromGrid->GetRestPositions() &&
      fromGrid->GetRestPositions()->GetNumberOfTuples() == 8,
    "missing RestPosition: rest = points");
  ok &= lfdtest::CheckValid(fromGrid, "a grid without RestPosition validates");

  // With a float RestPosition different from the points: deformed, stored as doubles.
  vtkNew<vtkFloatArray> restPositions;
  restPositions->SetName("RestPosition");
  restPositions->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 8; ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    x[2] -= 0.5;
    restPositions->InsertNextTuple(x);
  }
  grid->GetPointData()->AddArray(restPositions);
  fromGrid->InitializeFromGrid(grid);
  double rest[24], deformed[24];
  fromGrid->GetRestCorners(0, rest);
  fromGrid->GetDeformedCorners(0, deformed);
  std::printf("from grid with RestPosition: rest z %g %g, deformed z %g %g\n",
    rest[2],
    rest[14],
    deformed[2],
    deformed[14]);
  ok &= Check(fromGrid->IsDeformed(), "RestPosition differs from the points: deformed");
  ok &= Check(vtkDoubleArray::SafeDownCast(fromGrid->GetRestPositions()) != nullptr,
    "RestPosition converted to doubles");
  ok &= Check(rest[2] == -0.5 && rest[14] == 0.5 && deformed[2] == 0 && deformed[14] == 1,
    "rest and deformed corners read from their arrays");
  fromGrid->SetPointsToRest();
  ok &= Check(!fromGrid->IsDeformed(), "SetPointsToRest on a scene cage");

  // The grid given is copied, not shared.
  points->SetPoint(0, 9, 9, 9);
  double p[3];
  fromGrid->GetDeformedPoint(0, p);
  ok &= Check(p[0] == 0, "InitializeFromGrid copies");

  fromGrid->InitializeFromGrid(nullptr);
  ok &= Check(fromGrid->GetNumberOfBoxes() == 0 && fromGrid->GetNumberOfPoints() == 0,
    "a null grid empties the cage");
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(fromGrid, lo, hi, ids);
  ok &= Check(fromGrid->AddBox(ids, 1) == 0, "an emptied cage takes new boxes");
  ok &= lfdtest::CheckValid(fromGrid, "the new box validates");
  return ok;
}

/// CheckGridArrays(): what the modules reading a cage from an input port
/// refuse; GetRestBounds(): the rest box's extent.
bool TestGridArrays()
{
  const auto expect = [](vtkUnstructuredGrid* grid, const std::string& expected, const char* what)
  {
    const std::string why = vtkDeformationCage::CheckGridArrays(grid);
    std::printf("%s: \"%s\"\n", what, why.c_str());
    return Check(why == expected, what);
  };
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 2, 3 };
  auto cage = lfdtest::MakeBoxCage(lo, hi);
  bool ok = expect(cage, "", "a cage passes");
  ok &= expect(nullptr, "the cage is missing", "no grid");
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(cage);
  grid->GetPointData()->RemoveArray("RestPosition");
  ok &= expect(grid, "", "a grid without RestPosition passes (at rest)");
  vtkNew<vtkFloatArray> flat;
  flat->SetName("RestPosition");
  flat->SetNumberOfComponents(2);
  flat->SetNumberOfTuples(8);
  grid->GetPointData()->AddArray(flat);
  ok &= expect(grid,
    "the cage's point array \"RestPosition\" has 8 tuples of 2 components; expected 8 tuples of 3",
    "RestPosition of 2 components");
  grid->GetPointData()->RemoveArray("RestPosition");
  grid->GetCellData()->RemoveArray("Label");
  ok &= expect(grid,
    "the cage has no cell array \"Label\" of one value per box (the label of its part)",
    "no Label");

  double bounds[6];
  ok &= Check(cage->GetRestBounds(0, bounds) && bounds[0] == 0 && bounds[1] == 1 &&
      bounds[2] == 0 && bounds[3] == 2 && bounds[4] == 0 && bounds[5] == 3,
    "GetRestBounds of the box [0,1] x [0,2] x [0,3]");
  const double moved[3] = { 5, 5, 5 };
  cage->SetDeformedPoint(6, moved);
  ok &= Check(cage->GetRestBounds(0, bounds) && bounds[1] == 1, "the rest bounds ignore the move");
  ok &= Check(!cage->GetRestBounds(1, bounds), "no bounds for a missing box");
  return ok;
}
} // namespace

int TestDeformationCage(int, char*[])
{
  bool ok = TestSharedCorners();
  ok &= TestFromGrid();
  ok &= TestGridArrays();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
