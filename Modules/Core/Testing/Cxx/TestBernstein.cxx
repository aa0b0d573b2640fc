// Bernstein polynomials and the lattice free-form deformation (lfdBernstein.h;
// Sederberg and Parry, SIGGRAPH 1986): the de Casteljau basis equals the
// closed form C(n,i) (1-t)^(n-i) t^i, sums to 1 and reproduces t (linear
// precision); a lattice of zero displacements is the identity, a lattice
// displaced by an affine map reproduces it, and points outside the region
// do not move.
#include "lfdBernstein.h"
#include "lfdTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

using lfdtest::Expect;

namespace
{
double Binomial(int n, int i)
{
  double c = 1.0;
  for (int k = 1; k <= i; ++k)
  {
    c = c * (n - i + k) / k;
  }
  return c;
}
}

int TestBernstein(int, char*[])
{
  double basisError = 0.0, unityError = 0.0, precisionError = 0.0;
  for (int n = 0; n <= lfd::MaxLatticeDegree; ++n)
  {
    for (double t : { 0.0, 0.1, 0.37, 0.5, 0.81, 1.0 })
    {
      double b[lfd::MaxLatticeDegree + 1];
      lfd::BernsteinBasis(n, t, b);
      double sum = 0.0, mean = 0.0;
      for (int i = 0; i <= n; ++i)
      {
        const double closed = Binomial(n, i) * std::pow(1.0 - t, n - i) * std::pow(t, i);
        basisError = std::max(basisError, std::abs(b[i] - closed));
        sum += b[i];
        mean += n > 0 ? b[i] * i / n : 0.0;
      }
      unityError = std::max(unityError, std::abs(sum - 1.0));
      precisionError = std::max(precisionError, n > 0 ? std::abs(mean - t) : 0.0);
    }
  }
  Expect("basis vs C(n,i) (1-t)^(n-i) t^i, degrees 0..15", basisError, 0.0, 1e-13);
  Expect("partition of unity", unityError, 0.0, 1e-13);
  Expect("linear precision: sum B_i^n(t) i/n = t", precisionError, 0.0, 1e-13);

  lfd::Lattice lattice;
  lattice.Degree = glm::ivec3(3, 2, 4);
  lattice.Origin = glm::dvec3(-1.0, 0.5, 2.0);
  lattice.Size = glm::dvec3(2.0, 1.5, 3.0);
  lattice.Displacements.assign(4 * 3 * 5, glm::dvec3(0.0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double identityError = 0.0;
  for (int trial = 0; trial < 100; ++trial)
  {
    const glm::dvec3 x =
      lattice.Origin + glm::dvec3(unit(random), unit(random), unit(random)) * lattice.Size;
    identityError = std::max(identityError, glm::length(lfd::FreeFormDeformation(lattice, x) - x));
  }
  Expect("zero displacements: identity", identityError, 0.0, 0.0);

  // D_ijk = A P_ijk + b at the rest control points P_ijk.
  const glm::dmat3 A(0.1, -0.2, 0.05, 0.3, 0.02, -0.1, -0.07, 0.15, 0.2);
  const glm::dvec3 b(0.3, -0.4, 0.25);
  for (int k = 0; k <= 4; ++k)
  {
    for (int j = 0; j <= 2; ++j)
    {
      for (int i = 0; i <= 3; ++i)
      {
        const glm::dvec3 p = lattice.Origin + glm::dvec3(i / 3.0, j / 2.0, k / 4.0) * lattice.Size;
        lattice.Displacements[lattice.Index(i, j, k)] = A * p + b;
      }
    }
  }
  double affineError = 0.0;
  for (int trial = 0; trial < 100; ++trial)
  {
    const glm::dvec3 x =
      lattice.Origin + glm::dvec3(unit(random), unit(random), unit(random)) * lattice.Size;
    affineError =
      std::max(affineError, glm::length(lfd::FreeFormDeformation(lattice, x) - (x + A * x + b)));
  }
  Expect("affine displacement reproduced", affineError, 0.0, 1e-13);
  const glm::dvec3 outside(1.5, 1.0, 3.0);
  Expect("a point outside the region does not move",
    glm::length(lfd::FreeFormDeformation(lattice, outside) - outside),
    0.0,
    0.0);
  return lfdtest::Result();
}
