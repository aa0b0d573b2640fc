/**
 * @file   lfdDeformationTestUtilities.h
 * @brief  Cages shared by the Deformation tests.
 */
#ifndef lfdDeformationTestUtilities_h
#define lfdDeformationTestUtilities_h

#include "lfdTrilinear.h"
#include "vtkDeformationCage.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace lfdtest
{

/// Adds the 8 corner points of the axis-aligned box [lo, hi] (VTK order) to
/// `cage` and writes their ids into `ids`.
inline void AddBoxPoints(vtkDeformationCage* cage,
  const double lo[3],
  const double hi[3],
  vtkIdType ids[8])
{
  const auto& corner = lfd::HexCorner;
  for (int i = 0; i < 8; ++i)
  {
    const double p[3] = {
      corner[i][0] ? hi[0] : lo[0], corner[i][1] ? hi[1] : lo[1], corner[i][2] ? hi[2] : lo[2]
    };
    ids[i] = cage->AddPoint(p);
  }
}

/// A cage of one axis-aligned box [lo, hi] with label `label`.
inline vtkSmartPointer<vtkDeformationCage> MakeBoxCage(const double lo[3],
  const double hi[3],
  int label = 1)
{
  auto cage = vtkSmartPointer<vtkDeformationCage>::New();
  vtkIdType ids[8];
  AddBoxPoints(cage, lo, hi, ids);
  cage->AddBox(ids, label);
  return cage;
}

/// The box [-1,1]^2 x [0,2] with its top face twisted by `angle` radians
/// about the vertical (z) axis: corners 4-7 rotated.
inline vtkSmartPointer<vtkDeformationCage> MakeTwistedBox(double angle)
{
  const double lo[3] = { -1, -1, 0 }, hi[3] = { 1, 1, 2 };
  auto cage = MakeBoxCage(lo, hi);
  const double c = std::cos(angle), s = std::sin(angle);
  for (vtkIdType i = 4; i < 8; ++i)
  {
    double p[3];
    cage->GetRestPoint(i, p);
    const double q[3] = { c * p[0] - s * p[1], s * p[0] + c * p[1], p[2] };
    cage->SetDeformedPoint(i, q);
  }
  return cage;
}

/// The twist of MakeTwistedBox in closed form: at height z the section is
/// (1 - w) p + w R p with w = z / 2, since bilinear interpolation of rotated
/// corners is the rotation of the interpolation.
inline void TwistPoint(double angle, const double p[3], double q[3])
{
  const double w = p[2] / 2.0;
  const double c = std::cos(angle), s = std::sin(angle);
  q[0] = (1 - w) * p[0] + w * (c * p[0] - s * p[1]);
  q[1] = (1 - w) * p[1] + w * (s * p[0] + c * p[1]);
  q[2] = p[2];
}

/// The text of a vtkErrorMacro event without its "ERROR: In file, line"
/// header and object address, so that ctest's "ERROR: " regex stays quiet.
inline std::string ErrorText(const std::string& event)
{
  const size_t line = event.find('\n');
  const size_t text = event.find("): ", line == std::string::npos ? 0 : line);
  const std::string body = text == std::string::npos ? event : event.substr(text + 3);
  return body.substr(0, body.find('\n'));
}

inline bool Near(const char* what, double value, double expected, double tolerance = 1e-9)
{
  const bool ok = std::abs(value - expected) <= tolerance;
  std::printf("%s %s: %.12g (expected %.12g)\n", ok ? "ok  " : "FAIL", what, value, expected);
  return ok;
}

inline bool Check(bool condition, const char* what)
{
  if (!condition)
  {
    std::printf("FAILED: %s\n", what);
  }
  return condition;
}

/// Checks that `cage` validates (against `lightField` when given); prints
/// the refusal otherwise.
inline bool CheckValid(vtkDeformationCage* cage,
  const char* what,
  vtkLightField* lightField = nullptr)
{
  const std::string why = cage->Validate(lightField);
  std::printf("%s: %s\n", what, why.empty() ? "valid" : why.c_str());
  return Check(why.empty(), what);
}

} // namespace lfdtest

#endif
