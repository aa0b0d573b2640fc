// vtkLatticeCageFilter (Sederberg and Parry, SIGGRAPH 1986, sampled into
// boxes): a lattice at rest gives the rest points exactly and keeps the
// input's point ids; a 2 x 2 x 2 lattice is the trilinear map of its region
// (compared with vtkCageTransform of that one box); an affine displacement
// of the control points is reproduced exactly (linear precision); a bend
// validates and its boxes' error against the FFD at their centres falls as
// the subdivision grows; points outside an explicit region stay; a control
// point outside the lattice is refused.
#include "lfdDeformationTestUtilities.h"

#include "vtkCageTransform.h"
#include "vtkCommand.h"
#include "vtkLatticeCageFilter.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace TestLatticeCageFilterHelpers
{
using lfdtest::Check;
using lfdtest::Near;

/// Two boxes [-0.5, 0.5]^2 x [0, 1] and [-0.5, 0.5]^2 x [1, 2] sharing the
/// 4 points at z = 1; labels 1 and 2.
vtkSmartPointer<vtkDeformationCage> MakeColumn()
{
  auto cage = vtkSmartPointer<vtkDeformationCage>::New();
  for (int layer = 0; layer < 3; ++layer)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double p[3] = {
        lfd::HexCorner[c][0] - 0.5, lfd::HexCorner[c][1] - 0.5, static_cast<double>(layer)
      };
      cage->AddPoint(p);
    }
  }
  for (int box = 0; box < 2; ++box)
  {
    vtkIdType ids[8];
    for (int c = 0; c < 8; ++c)
    {
      ids[c] = 4 * (box + c / 4) + c % 4;
    }
    cage->AddBox(ids, box + 1);
  }
  return cage;
}

/// Largest distance between an output point's deformed position and
/// `expected` of its rest position.
template<typename Map>
double MaxError(vtkDeformationCage* cage, Map expected)
{
  double error = 0.0;
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    double r[3], d[3], e[3];
    cage->GetRestPoint(i, r);
    cage->GetDeformedPoint(i, d);
    expected(r, e);
    error = std::max(error, std::sqrt(vtkMath::Distance2BetweenPoints(d, e)));
  }
  return error;
}

/// Largest distance, over the output boxes, between the deformed box's
/// centre (the mean of its corners: the trilinear map at (1/2, 1/2, 1/2))
/// and the FFD of the rest box's centre.
double CentreError(vtkLatticeCageFilter* filter)
{
  vtkDeformationCage* cage = filter->GetOutput();
  double error = 0.0;
  for (vtkIdType b = 0; b < cage->GetNumberOfBoxes(); ++b)
  {
    double rest[24], deformed[24];
    cage->GetRestCorners(b, rest);
    cage->GetDeformedCorners(b, deformed);
    double r[3] = { 0, 0, 0 }, d[3] = { 0, 0, 0 }, truth[3];
    for (int c = 0; c < 8; ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        r[a] += rest[3 * c + a] / 8.0;
        d[a] += deformed[3 * c + a] / 8.0;
      }
    }
    filter->EvaluateDeformation(r, truth);
    error = std::max(error, std::sqrt(vtkMath::Distance2BetweenPoints(d, truth)));
  }
  return error;
}

bool TestIdentity()
{
  bool ok = true;
  auto column = MakeColumn();
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(column);
  lattice->SetLatticeDimensions(3, 4, 5);
  lattice->Update();
  vtkDeformationCage* out = lattice->GetOutput();
  ok &= Near("k = 1: points", out->GetNumberOfPoints(), 12, 0);
  ok &= Near("k = 1: boxes", out->GetNumberOfBoxes(), 2, 0);
  ok &= Near("k = 1: deformed = rest",
    MaxError(out, [](const double r[3], double e[3]) { std::copy(r, r + 3, e); }),
    0.0,
    0.0);
  double inputMoved = 0.0;
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double a[3], b[3];
    column->GetRestPoint(i, a);
    out->GetRestPoint(i, b);
    inputMoved = std::max(inputMoved, vtkMath::Distance2BetweenPoints(a, b));
  }
  ok &= Near("the input's points keep their ids", inputMoved, 0.0, 0.0);

  lattice->SetSubdivision(3);
  lattice->Update();
  ok &= Near("k = 3: points (4 x 4 x 7 shared)", out->GetNumberOfPoints(), 112, 0);
  ok &= Near("k = 3: boxes", out->GetNumberOfBoxes(), 54, 0);
  ok &= Near("k = 3: deformed = rest",
    MaxError(out, [](const double r[3], double e[3]) { std::copy(r, r + 3, e); }),
    0.0,
    0.0);
  ok &= Near("k = 3: label of the last sub-box", out->GetBoxLabel(53), 2, 0);
  ok &= lfdtest::CheckValid(out, "k = 3 at rest validates");
  return ok;
}

bool TestTrilinear()
{
  // A 2 x 2 x 2 lattice over the column's bounds with random displacements
  // is the trilinear map of the box whose corners are the moved control points.
  const double lo[3] = { -0.5, -0.5, 0.0 }, hi[3] = { 0.5, 0.5, 2.0 };
  auto box = lfdtest::MakeBoxCage(lo, hi);
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(MakeColumn());
  lattice->SetSubdivision(3);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (int c = 0; c < 8; ++c)
  {
    const int* h = lfd::HexCorner[c];
    const double d[3] = { jitter(random), jitter(random), jitter(random) };
    lattice->SetControlPointDisplacement(h[0], h[1], h[2], d);
    double p[3];
    box->GetRestPoint(c, p);
    const double q[3] = { p[0] + d[0], p[1] + d[1], p[2] + d[2] };
    box->SetDeformedPoint(c, q);
  }
  lattice->Update();
  vtkNew<vtkCageTransform> transform;
  transform->SetCage(box);
  return Near("2 x 2 x 2 lattice = trilinear map of its region",
    MaxError(lattice->GetOutput(),
      [&](const double r[3], double e[3]) { transform->TransformPoint(r, e); }),
    0.0,
    1e-12);
}

bool TestLinearPrecision()
{
  // D_ijk = A P_ijk + b at the rest control points P_ijk of the region.
  const double A[3][3] = { { 0.1, -0.2, 0.05 }, { 0.3, 0.02, -0.1 }, { -0.07, 0.15, 0.2 } };
  const double b[3] = { 0.3, -0.4, 0.25 };
  const double region[6] = { -0.5, 0.5, -0.5, 0.5, 0.0, 2.0 };
  auto affine = [&](const double p[3], double q[3])
  {
    for (int r = 0; r < 3; ++r)
    {
      q[r] = p[r] + A[r][0] * p[0] + A[r][1] * p[1] + A[r][2] * p[2] + b[r];
    }
  };
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(MakeColumn());
  lattice->SetLatticeDimensions(3, 4, 5);
  lattice->SetRegion(region);
  lattice->SetSubdivision(2);
  for (int k = 0; k < 5; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        const double p[3] = { region[0] + i / 2.0 * (region[1] - region[0]),
          region[2] + j / 3.0 * (region[3] - region[2]),
          region[4] + k / 4.0 * (region[5] - region[4]) };
        double q[3];
        affine(p, q);
        lattice->SetControlPointDisplacement(i, j, k, q[0] - p[0], q[1] - p[1], q[2] - p[2]);
      }
    }
  }
  lattice->Update();
  return Near("affine displacement of a 3 x 4 x 5 lattice reproduced",
    MaxError(lattice->GetOutput(), affine),
    0.0,
    1e-12);
}

bool TestBend()
{
  // A degree-4 lattice along the column bows its middle sideways by 0.5 and
  // turns its ends: the sampled cage curves.
  bool ok = true;
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(MakeColumn());
  lattice->SetLatticeDimensions(2, 2, 5);
  const double bow[5] = { 0.0, 0.4, 0.8, 0.4, 0.0 };
  for (int k = 0; k < 5; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        lattice->SetControlPointDisplacement(i, j, k, bow[k], 0.0, 0.0);
      }
    }
  }
  std::vector<double> errors;
  for (int k : { 1, 2, 4, 8 })
  {
    lattice->SetSubdivision(k);
    lattice->Update();
    const std::string what = "bend, k = " + std::to_string(k) + " validates";
    ok &= lfdtest::CheckValid(lattice->GetOutput(), what.c_str());
    errors.push_back(CentreError(lattice));
    std::printf("bend, k = %d: %lld boxes, largest error at box centres %.3g\n",
      k,
      static_cast<long long>(lattice->GetOutput()->GetNumberOfBoxes()),
      errors.back());
  }
  double bowed[3];
  const double middle[3] = { 0.0, 0.0, 1.0 };
  lattice->EvaluateDeformation(middle, bowed);
  // Eq. (3) at t = 1/2: B^4 = (1, 4, 6, 4, 1) / 16.
  ok &= Near("the middle moves by 0.4 x 8/16 + 0.8 x 6/16 = 0.5", bowed[0], 0.5, 1e-12);
  for (size_t n = 1; n < errors.size(); ++n)
  {
    // Trilinear interpolation of a smooth map: the error falls as 1 / k^2
    // (measured 0.106, 0.0348, 0.0092, 0.00233: ratios 0.33, 0.26, 0.25).
    ok &= Check(errors[n] < 0.35 * errors[n - 1], "doubling k cuts the centre error below 0.35x");
  }
  ok &= Check(errors[0] > 1e-3, "k = 1 misses the curve");
  return ok;
}

bool TestRegionAndErrors()
{
  bool ok = true;
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(MakeColumn());
  const double region[6] = { -1.0, 1.0, -1.0, 1.0, 0.0, 1.0 };
  lattice->SetRegion(region);
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2; ++j)
    {
      lattice->SetControlPointDisplacement(i, j, 1, 0.0, 0.0, 0.0);
      lattice->SetControlPointDisplacement(i, j, 0, 0.2, 0.0, 0.0);
    }
  }
  lattice->Update();
  vtkDeformationCage* out = lattice->GetOutput();
  double moved = 0.0, kept = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double r[3], d[3];
    out->GetRestPoint(i, r);
    out->GetDeformedPoint(i, d);
    (r[2] > 1.0 ? kept : moved) += std::abs(d[0] - r[0]);
  }
  ok &= Near("points above the region stay", kept, 0.0, 0.0);
  ok &= Near("points at its bottom move by 0.2 (4 of them)", moved, 0.8, 1e-12);

  vtkNew<vtkTest::ErrorObserver> observer;
  lattice->AddObserver(vtkCommand::ErrorEvent, observer);
  lattice->SetControlPointDisplacement(2, 0, 0, 1.0, 0.0, 0.0);
  const std::string message = lfdtest::ErrorText(observer->GetErrorMessage());
  std::printf("control point (2, 0, 0): error \"%s\"\n", message.c_str());
  ok &= Check(observer->GetError() && message.find("outside the lattice") != std::string::npos,
    "a control point outside the lattice is refused");
  return ok;
}
}

int TestLatticeCageFilter(int, char*[])
{
  using namespace TestLatticeCageFilterHelpers;
  bool ok = TestIdentity();
  ok &= TestTrilinear();
  ok &= TestLinearPrecision();
  ok &= TestBend();
  ok &= TestRegionAndErrors();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
