/**
 * @file   lfdBernstein.h
 * @brief  Bernstein polynomials and the lattice free-form deformation of Sederberg and Parry.
 *
 * Sederberg and Parry, "Free-Form Deformation of Solid Geometric Models",
 * SIGGRAPH 1986: a lattice of (l+1) x (m+1) x (n+1) control points P_ijk
 * spans a region X0 + s S + t T + u U, (s,t,u) in [0,1]^3 (here
 * axis-aligned: S, T, U along x, y, z), and a point of the region goes to
 *
 *   X_ffd(s,t,u) = sum_i sum_j sum_k B_i^l(s) B_j^m(t) B_k^n(u) P_ijk      (SP86, Eq. 3)
 *
 * with the Bernstein polynomials B_i^n(t) = C(n,i) (1-t)^(n-i) t^i. At rest
 * P_ijk = X0 + (i/l) S + (j/m) T + (k/n) U, and by the linear precision of
 * the Bernstein basis (sum_i B_i^n(t) i/n = t) the map is the identity. The
 * lattice here stores the displacements D_ijk = P_ijk - (rest P_ijk), so
 * X_ffd(x) = x + sum B B B D_ijk: exactly x when nothing moved, and any
 * affine displacement of the control points is reproduced exactly.
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdBernstein_h
#define lfdBernstein_h

#include <glm/glm.hpp>

#include <vector>

namespace lfd
{

/// The highest degree a lattice axis may have (MaxLatticeDegree + 1 control points).
constexpr int MaxLatticeDegree = 15;

/**
 * The n + 1 Bernstein polynomials of degree n at t, B_0^n(t) .. B_n^n(t),
 * into b[0..n], by the de Casteljau triangle (B_i^d = (1-t) B_i^(d-1) +
 * t B_(i-1)^(d-1)): no binomials, no powers, stable for any t.
 */
inline void BernsteinBasis(int n, double t, double* b)
{
  const double s = 1.0 - t;
  b[0] = 1.0;
  for (int d = 1; d <= n; ++d)
  {
    double carried = 0.0;
    for (int i = 0; i < d; ++i)
    {
      const double previous = b[i];
      b[i] = carried + s * previous;
      carried = t * previous;
    }
    b[d] = carried;
  }
}

/// A Sederberg-Parry lattice over an axis-aligned region, as control-point displacements.
struct Lattice
{
  glm::ivec3 Degree{ 1 };   ///< (l, m, n): control points per axis minus one, each >= 1
  glm::dvec3 Origin{ 0.0 }; ///< X0, the region's low corner
  glm::dvec3 Size{ 1.0 };   ///< the region's sides along x, y, z (all positive)
  std::vector<glm::dvec3> Displacements; ///< D_ijk at i + (l+1) (j + (m+1) k)

  int Index(int i, int j, int k) const
  {
    return i + (this->Degree.x + 1) * (j + (this->Degree.y + 1) * k);
  }
};

/**
 * Sum of B_i^l(s) B_j^m(t) B_k^n(u) D_ijk at the lattice coordinates stu =
 * (s, t, u): the displacement of Eq. (3). Degrees up to MaxLatticeDegree.
 */
inline glm::dvec3 LatticeDisplacement(const Lattice& lattice, const glm::dvec3& stu)
{
  double bs[MaxLatticeDegree + 1], bt[MaxLatticeDegree + 1], bu[MaxLatticeDegree + 1];
  BernsteinBasis(lattice.Degree.x, stu.x, bs);
  BernsteinBasis(lattice.Degree.y, stu.y, bt);
  BernsteinBasis(lattice.Degree.z, stu.z, bu);
  glm::dvec3 displacement(0.0);
  for (int k = 0; k <= lattice.Degree.z; ++k)
  {
    for (int j = 0; j <= lattice.Degree.y; ++j)
    {
      const double w = bt[j] * bu[k];
      for (int i = 0; i <= lattice.Degree.x; ++i)
      {
        displacement += (bs[i] * w) * lattice.Displacements[lattice.Index(i, j, k)];
      }
    }
  }
  return displacement;
}

/**
 * The free-form deformation of point x: x + the lattice displacement at its
 * lattice coordinates (x - X0) / size. Points outside the region (beyond a
 * relative slack of 1e-12) are not moved, as in SP86, where only what lies
 * inside the lattice deforms; leave the outer control points in place for a
 * map that is continuous across the region's faces.
 */
inline glm::dvec3 FreeFormDeformation(const Lattice& lattice, const glm::dvec3& x)
{
  constexpr double slack = 1e-12;
  glm::dvec3 stu = (x - lattice.Origin) / lattice.Size;
  for (int a = 0; a < 3; ++a)
  {
    if (stu[a] < -slack || stu[a] > 1.0 + slack)
    {
      return x;
    }
  }
  stu = glm::clamp(stu, glm::dvec3(0.0), glm::dvec3(1.0));
  return x + LatticeDisplacement(lattice, stu);
}

} // namespace lfd

#endif
