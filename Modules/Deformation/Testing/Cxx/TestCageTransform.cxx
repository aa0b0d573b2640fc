// vtkCageTransform against closed forms: the identity, a box twisted by 45
// degrees about its vertical axis, the Newton inverse, the derivative, and
// C0 continuity across a face shared by two boxes.
#include "lfdDeformationTestUtilities.h"

#include "vtkCageTransform.h"
#include "vtkMinimalStandardRandomSequence.h"

#include <algorithm>
#include <cstdlib>

namespace TestCageTransformHelpers
{
double Distance(const double a[3], const double b[3])
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}

/// A point uniformly in [lo, hi].
void RandomPoint(vtkMinimalStandardRandomSequence* random,
  const double lo[3],
  const double hi[3],
  double p[3])
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = random->GetNextRangeValue(lo[k], hi[k]);
  }
}

bool TestIdentity(vtkMinimalStandardRandomSequence* random)
{
  // Two boxes at rest sharing a face.
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  auto cage = lfdtest::MakeBoxCage(lo, hi);
  const double lo2[3] = { 1, 0, 0 }, hi2[3] = { 2, 1.5, 1 };
  vtkIdType ids[8];
  lfdtest::AddBoxPoints(cage, lo2, hi2, ids);
  cage->AddBox(ids, 2);
  vtkNew<vtkCageTransform> transform;
  transform->SetCage(cage);

  const double sampleLo[3] = { -0.5, -0.5, -0.5 }, sampleHi[3] = { 2.5, 2, 1.5 };
  double maxError = 0.0;
  for (int i = 0; i < 1000; ++i)
  {
    double p[3], q[3];
    RandomPoint(random, sampleLo, sampleHi, p);
    transform->TransformPoint(p, q);
    maxError = std::max(maxError, Distance(p, q));
  }
  std::printf("identity: max |T(p) - p| over 1000 points = %g\n", maxError);
  return lfdtest::Check(maxError == 0.0, "a cage at rest maps every point to itself exactly");
}

bool TestTwist(vtkMinimalStandardRandomSequence* random)
{
  bool ok = true;
  const double angle = vtkMath::Pi() / 4;
  auto cage = lfdtest::MakeTwistedBox(angle);
  vtkNew<vtkCageTransform> transform;
  transform->SetCage(cage);

  // Corners go to the deformed corners.
  double cornerError = 0.0;
  for (vtkIdType i = 0; i < 8; ++i)
  {
    double rest[3], deformed[3], q[3];
    cage->GetRestPoint(i, rest);
    cage->GetDeformedPoint(i, deformed);
    transform->TransformPoint(rest, q);
    cornerError = std::max(cornerError, Distance(q, deformed));
  }
  std::printf("twist: max corner error %g\n", cornerError);
  ok &= lfdtest::Check(cornerError < 1e-12, "rest corners map to the deformed corners");

  // The centre goes to the deformed centre (the mean of the deformed corners).
  double centre[3] = { 0, 0, 1 }, deformedCentre[3] = { 0, 0, 0 }, q[3];
  for (vtkIdType i = 0; i < 8; ++i)
  {
    double d[3];
    cage->GetDeformedPoint(i, d);
    for (int k = 0; k < 3; ++k)
    {
      deformedCentre[k] += d[k] / 8;
    }
  }
  transform->TransformPoint(centre, q);
  std::printf("twist: centre -> (%g %g %g), deformed centre (%g %g %g)\n",
    q[0],
    q[1],
    q[2],
    deformedCentre[0],
    deformedCentre[1],
    deformedCentre[2]);
  ok &=
    lfdtest::Check(Distance(q, deformedCentre) < 1e-12, "the centre maps to the deformed centre");

  // Inside: the closed form of the twist.
  const double insideLo[3] = { -1, -1, 0 }, insideHi[3] = { 1, 1, 2 };
  double twistError = 0.0;
  for (int i = 0; i < 1000; ++i)
  {
    double p[3], expected[3];
    RandomPoint(random, insideLo, insideHi, p);
    transform->TransformPoint(p, q);
    lfdtest::TwistPoint(angle, p, expected);
    twistError = std::max(twistError, Distance(q, expected));
  }
  const double face[3] = { 1, 0, 1 };
  double faceExpected[3];
  lfdtest::TwistPoint(angle, face, faceExpected);
  transform->TransformPoint(face, q);
  std::printf("twist: max error vs closed form over 1000 inside points %g; face centre (1 0 1) -> "
              "(%.6f %.6f %.6f)\n",
    twistError,
    q[0],
    q[1],
    q[2]);
  ok &= lfdtest::Check(twistError < 1e-12, "inside points follow the closed-form twist");
  ok &= lfdtest::Check(Distance(q, faceExpected) < 1e-12 && std::abs(q[0] - 0.853553) < 1e-6,
    "face centre (1,0,1) -> (0.853553, 0.353553, 1)");

  // Outside: unchanged.
  const double outside[2][3] = { { 3, 0, 1 }, { 0.5, 0.5, 2.5 } };
  double outsideError = 0.0;
  for (const auto& p : outside)
  {
    transform->TransformPoint(p, q);
    outsideError = std::max(outsideError, Distance(p, q));
  }
  std::printf("twist: outside points moved by %g\n", outsideError);
  ok &= lfdtest::Check(outsideError == 0.0, "points outside the box stay");

  // Inverse by Newton: points whose image stays in the rest box (|x|,|y| <=
  // 0.6, so the image is inside too and the inverse is unique).
  transform->SetInverseTolerance(1e-10);
  vtkAbstractTransform* inverse = transform->GetInverse();
  const double innerLo[3] = { -0.6, -0.6, 0.1 }, innerHi[3] = { 0.6, 0.6, 1.9 };
  double roundTrip = 0.0;
  for (int i = 0; i < 200; ++i)
  {
    double p[3], back[3];
    RandomPoint(random, innerLo, innerHi, p);
    transform->TransformPoint(p, q);
    inverse->TransformPoint(q, back);
    roundTrip = std::max(roundTrip, Distance(p, back));
  }
  std::printf("twist: inverse round trip max error over 200 points %g\n", roundTrip);
  ok &= lfdtest::Check(roundTrip < 1e-6, "the inverse undoes the map to 1e-6");

  // Derivative against central differences, inside and outside.
  transform->Update();
  double derivativeError = 0.0;
  const double h = 1e-6;
  for (int i = 0; i < 101; ++i)
  {
    double p[3], jacobian[3][3];
    if (i < 100)
    {
      RandomPoint(random, innerLo, innerHi, p);
    }
    else
    {
      p[0] = 3;
      p[1] = p[2] = 0.5;
    }
    transform->InternalTransformDerivative(p, q, jacobian);
    for (int j = 0; j < 3; ++j)
    {
      double plus[3] = { p[0], p[1], p[2] }, minus[3] = { p[0], p[1], p[2] }, qp[3], qm[3];
      plus[j] += h;
      minus[j] -= h;
      transform->InternalTransformPoint(plus, qp);
      transform->InternalTransformPoint(minus, qm);
      for (int k = 0; k < 3; ++k)
      {
        derivativeError =
          std::max(derivativeError, std::abs((qp[k] - qm[k]) / (2 * h) - jacobian[k][j]));
      }
    }
    if (i == 100)
    {
      ok &= lfdtest::Check(jacobian[0][0] == 1 && jacobian[0][1] == 0 && jacobian[2][2] == 1,
        "the derivative outside is the identity");
    }
  }
  std::printf("twist: derivative vs central differences max error %g\n", derivativeError);
  ok &= lfdtest::Check(derivativeError < 1e-6, "the derivative matches finite differences");

  // Moving the cage updates the transform (GetMTime includes the cage).
  cage->SetPointsToRest();
  transform->TransformPoint(face, q);
  std::printf("twist undone: face centre -> (%g %g %g)\n", q[0], q[1], q[2]);
  ok &= lfdtest::Check(Distance(q, face) == 0.0, "the transform follows the cage");
  return ok;
}

/// A cage with the points of `cage` and its box `box` only.
vtkSmartPointer<vtkDeformationCage> OneBoxOf(vtkDeformationCage* cage, vtkIdType box)
{
  auto single = vtkSmartPointer<vtkDeformationCage>::New();
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    double rest[3], deformed[3];
    cage->GetRestPoint(i, rest);
    cage->GetDeformedPoint(i, deformed);
    single->AddPoint(rest, deformed);
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  cage->GetCellPoints(box, count, ids);
  single->AddBox(ids, cage->GetBoxLabel(box));
  return single;
}

bool TestSharedFace(vtkMinimalStandardRandomSequence* random)
{
  // Boxes [0,1]^3 and [1,2]x[0,1]^2 share the face x = 1; every corner moved.
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  auto cage = lfdtest::MakeBoxCage(lo, hi, 1);
  const double far[4][3] = { { 2, 0, 0 }, { 2, 1, 0 }, { 2, 1, 1 }, { 2, 0, 1 } };
  vtkIdType f[4];
  for (int i = 0; i < 4; ++i)
  {
    f[i] = cage->AddPoint(far[i]);
  }
  const vtkIdType second[8] = { 1, f[0], f[1], 2, 5, f[3], f[2], 6 };
  cage->AddBox(second, 2);
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cage->GetRestPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] += random->GetNextRangeValue(-0.15, 0.15);
    }
    cage->SetDeformedPoint(i, p);
  }
  bool ok = lfdtest::CheckValid(cage, "shared face: the cage validates");

  // One cage per box, over the same points: the map of each side alone.
  auto left = OneBoxOf(cage, 0);
  auto right = OneBoxOf(cage, 1);
  vtkNew<vtkCageTransform> both, fromLeft, fromRight;
  both->SetCage(cage);
  fromLeft->SetCage(left);
  fromRight->SetCage(right);
  std::printf("shared face: left boxes %lld (label %d), right boxes %lld (label %d)\n",
    static_cast<long long>(left->GetNumberOfBoxes()),
    left->GetBoxLabel(0),
    static_cast<long long>(right->GetNumberOfBoxes()),
    right->GetBoxLabel(0));
  ok &= lfdtest::Check(left->GetNumberOfBoxes() == 1 && right->GetNumberOfBoxes() == 1 &&
      left->GetBoxLabel(0) == 1 && right->GetBoxLabel(0) == 2,
    "one box per side");

  double sideError = 0.0, jumpError = 0.0, moved = 0.0;
  for (int i = 0; i < 500; ++i)
  {
    const double p[3] = { 1.0, random->GetNextRangeValue(0, 1), random->GetNextRangeValue(0, 1) };
    double a[3], b[3], c[3];
    fromLeft->TransformPoint(p, a);
    fromRight->TransformPoint(p, b);
    both->TransformPoint(p, c);
    sideError = std::max({ sideError, Distance(a, b), Distance(a, c) });
    moved = std::max(moved, Distance(p, a));
    const double before[3] = { 1.0 - 1e-9, p[1], p[2] }, after[3] = { 1.0 + 1e-9, p[1], p[2] };
    both->TransformPoint(before, a);
    both->TransformPoint(after, b);
    jumpError = std::max(jumpError, Distance(a, b));
  }
  std::printf("shared face: 500 face points moved up to %g; left vs right map max difference "
              "%g; jump across the face (x = 1 -+ 1e-9) max %g\n",
    moved,
    sideError,
    jumpError);
  ok &= lfdtest::Check(moved > 0.01, "the shared face moved");
  ok &= lfdtest::Check(sideError < 1e-12, "both boxes map the shared face identically");
  ok &= lfdtest::Check(jumpError < 1e-8, "the map is continuous across the face");
  return ok;
}
} // namespace

int TestCageTransform(int, char*[])
{
  using namespace TestCageTransformHelpers;
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(2005);
  bool ok = TestIdentity(random);
  ok &= TestTwist(random);
  ok &= TestSharedFace(random);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
