/**
 * @file   lfdTrilinear.h
 * @brief  The trilinear box map of Chen, Ofek, Shum and Levoy 2005 (Sec. 5, Eq. 2).
 *
 * A box is a hexahedron of 8 corners in VTK's corner order: corners 0-3 are
 * the bottom face counter-clockwise, 4-7 the top face above them, so corner
 * i sits at the parametric point
 *
 *   0:(0,0,0) 1:(1,0,0) 2:(1,1,0) 3:(0,1,0) 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1).
 *
 * The map is p(u,v,w) = sum_i B_i(u,v,w) c_i with the 8 trilinear basis
 * functions B_i. A deformation sends the rest box to the deformed box at
 * the same (u,v,w).
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdTrilinear_h
#define lfdTrilinear_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lfd
{

/// Parametric coordinates of the 8 corners, VTK hexahedron order.
constexpr int HexCorner[8][3] = { { 0, 0, 0 },
  { 1, 0, 0 },
  { 1, 1, 0 },
  { 0, 1, 0 },
  { 0, 0, 1 },
  { 1, 0, 1 },
  { 1, 1, 1 },
  { 0, 1, 1 } };

struct Hexahedron
{
  glm::dvec3 Corners[8];
};

/// The box of 24 values x0 y0 z0 x1 y1 z1 ... (VTK corner order), as
/// vtkDeformationCage::GetRestCorners() gives them.
inline Hexahedron HexahedronFromArray(const double corners[24])
{
  Hexahedron box;
  for (int i = 0; i < 8; ++i)
  {
    box.Corners[i] = glm::dvec3(corners[3 * i], corners[3 * i + 1], corners[3 * i + 2]);
  }
  return box;
}

/// Axis-aligned bounds of a box: those of its corners (a trilinear box lies
/// in their convex hull).
struct AxisBounds
{
  glm::dvec3 Min, Max;
};

inline AxisBounds BoxBounds(const Hexahedron& box)
{
  AxisBounds bounds{ box.Corners[0], box.Corners[0] };
  for (const glm::dvec3& c : box.Corners)
  {
    bounds.Min = glm::min(bounds.Min, c);
    bounds.Max = glm::max(bounds.Max, c);
  }
  return bounds;
}

/// Corner `k` (0..7) of axis-aligned bounds: bit a of k picks Max along axis a.
inline glm::dvec3 BoundsCorner(const AxisBounds& bounds, int k)
{
  return glm::dvec3(k & 1 ? bounds.Max.x : bounds.Min.x,
    k & 2 ? bounds.Max.y : bounds.Min.y,
    k & 4 ? bounds.Max.z : bounds.Min.z);
}

/// Slab test of the half-line o + t d (t >= 0) against axis-aligned bounds:
/// the stretch [enter, leave] of it inside them (enter 0 when o is inside);
/// false when it misses them (enter and leave then mean nothing).
inline bool RayStretchInBounds(const glm::dvec3& o,
  const glm::dvec3& d,
  const AxisBounds& bounds,
  double& enter,
  double& leave)
{
  enter = 0.0;
  leave = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < bounds.Min[a] || o[a] > bounds.Max[a])
      {
        return false;
      }
      continue;
    }
    double near = (bounds.Min[a] - o[a]) / d[a];
    double far = (bounds.Max[a] - o[a]) / d[a];
    if (near > far)
    {
      std::swap(near, far);
    }
    enter = std::max(enter, near);
    leave = std::min(leave, far);
    if (enter > leave)
    {
      return false;
    }
  }
  return true;
}

namespace detail
{
/// The term of corner i in Eq. (2): its basis function at uvw times the corner.
inline glm::dvec3 TrilinearTerm(const Hexahedron& box, const glm::dvec3& uvw, int i)
{
  const double bu = HexCorner[i][0] ? uvw.x : 1.0 - uvw.x;
  const double bv = HexCorner[i][1] ? uvw.y : 1.0 - uvw.y;
  const double bw = HexCorner[i][2] ? uvw.z : 1.0 - uvw.z;
  return (bu * bv * bw) * box.Corners[i];
}
} // namespace detail

/// Eq. (2): the point of the box at parametric coordinates uvw.
inline glm::dvec3 TrilinearMap(const Hexahedron& box, const glm::dvec3& uvw)
{
  glm::dvec3 p(0.0);
  for (int i = 0; i < 8; ++i)
  {
    p += detail::TrilinearTerm(box, uvw, i);
  }
  return p;
}

/// Of each face (VTK's hexahedron face order: 0 is u = 0, 1 is u = 1, 2 is
/// v = 0, ...): the axis it is normal to, then its two free axes, along
/// which its coordinates s and t run.
constexpr int FaceAxes[6][3] = { { 0, 1, 2 },
  { 0, 1, 2 },
  { 1, 0, 2 },
  { 1, 0, 2 },
  { 2, 0, 1 },
  { 2, 0, 1 } };

/**
 * One face of a box as Eq. (2) maps it: its points as box parametric points,
 * and their TrilinearMap, to the bit at half the cost. On the face the
 * coordinate along its axis is exactly 0 or 1, so the basis factor along
 * that axis is exactly 1 or +-0, and a product with 1 is exact: each term
 * that does not vanish is the product of its other two factors, in
 * TrilinearTerm's order, times its corner; the 4 that vanish weigh +-0, and
 * adding them to a sum that starts at +0 leaves it unchanged. The sum of
 * the 4 others, in the same order, is therefore the same point. Built once
 * per box and face, so that a caller looping over faces maps a point of any
 * face by one code path (no switch).
 */
struct FaceOfBox
{
  /// The corners of the terms that do not vanish, in TrilinearMap's order:
  /// on every face the two whose factor along t is 1 - t, then the two whose
  /// factor is t (VTK's corner order).
  glm::dvec3 Corners[4];
  /// Of each of those two pairs, where the factors along s of its two terms
  /// start in (1 - s, s, 1 - s): 0 when they are 1 - s then s, 1 when s then
  /// 1 - s.
  int Flip[2] = { 0, 0 };
  /// The face's coordinate along its axis (its side: 0 or 1).
  double Side = 0.0;
  /// Per box axis, where its coordinate is in (Side, s, t) (FaceAxes inverted).
  int From[3] = { 0, 1, 2 };

  FaceOfBox() = default;
  FaceOfBox(const Hexahedron& box, int face)
    : Side(face % 2)
  {
    const int* axes = FaceAxes[face];
    for (int j = 0; j < 3; ++j)
    {
      this->From[axes[j]] = j;
    }
    int k = 0;
    for (int i = 0; i < 8; ++i)
    {
      if (HexCorner[i][axes[0]] == face % 2)
      {
        this->Corners[k] = box.Corners[i];
        if (k % 2 == 0)
        {
          this->Flip[k / 2] = HexCorner[i][axes[1]];
        }
        ++k;
      }
    }
  }

  /// The box parametric point of the face at coordinates s, t.
  glm::dvec3 BoxPoint(double s, double t) const
  {
    const double onFace[3] = { this->Side, s, t };
    return { onFace[this->From[0]], onFace[this->From[1]], onFace[this->From[2]] };
  }

  /// TrilinearMap of the face's point at coordinates s, t (both in [0, 1]).
  /// (Always inlined: the warp maps the two hits of its interval.)
  __attribute__((always_inline)) glm::dvec3 Map(double s, double t) const
  {
    const double sFactors[3] = { 1.0 - s, s, 1.0 - s };
    const double* low = sFactors + this->Flip[0];
    const double* high = sFactors + this->Flip[1];
    glm::dvec3 p(0.0);
    p += (low[0] * (1.0 - t)) * this->Corners[0];
    p += (low[1] * (1.0 - t)) * this->Corners[1];
    p += (high[0] * t) * this->Corners[2];
    p += (high[1] * t) * this->Corners[3];
    return p;
  }
};

/// Jacobian d p / d (u,v,w) of the map; column k is the derivative along k.
inline glm::dmat3 TrilinearJacobian(const Hexahedron& box, const glm::dvec3& uvw)
{
  glm::dmat3 jacobian(0.0);
  for (int i = 0; i < 8; ++i)
  {
    const int a = HexCorner[i][0], b = HexCorner[i][1], c = HexCorner[i][2];
    const double bu = a ? uvw.x : 1.0 - uvw.x;
    const double bv = b ? uvw.y : 1.0 - uvw.y;
    const double bw = c ? uvw.z : 1.0 - uvw.z;
    const double du = a ? 1.0 : -1.0;
    const double dv = b ? 1.0 : -1.0;
    const double dw = c ? 1.0 : -1.0;
    jacobian[0] += (du * bv * bw) * box.Corners[i];
    jacobian[1] += (bu * dv * bw) * box.Corners[i];
    jacobian[2] += (bu * bv * dw) * box.Corners[i];
  }
  return jacobian;
}

/// Length of the box's longest edge-spanning diagonal: the scale for tolerances.
inline double BoxSize(const Hexahedron& box)
{
  return std::max(
    glm::distance(box.Corners[0], box.Corners[6]), glm::distance(box.Corners[1], box.Corners[7]));
}

/**
 * Inverse of the map by Newton's method from `uvw` (in: the start, out: the
 * solution). Returns true when |p(uvw) - point| fell below `tolerance` x the
 * box size. The solution may lie outside [0,1]^3: the caller decides what
 * "inside" means (see Contains).
 */
inline bool InvertTrilinear(const Hexahedron& box,
  const glm::dvec3& point,
  glm::dvec3& uvw,
  double tolerance = 1e-12,
  int iterations = 30)
{
  const double limit = tolerance * std::max(BoxSize(box), 1e-300);
  for (int k = 0; k < iterations; ++k)
  {
    const glm::dvec3 residual = TrilinearMap(box, uvw) - point;
    if (glm::length(residual) <= limit)
    {
      return true;
    }
    const glm::dmat3 jacobian = TrilinearJacobian(box, uvw);
    const double det = glm::determinant(jacobian);
    if (!(std::abs(det) > 0.0))
    {
      return false;
    }
    uvw -= glm::inverse(jacobian) * residual;
  }
  return glm::length(TrilinearMap(box, uvw) - point) <= limit;
}

/// True when `point` maps back inside the box (parametric slack `epsilon`).
inline bool Contains(const Hexahedron& box,
  const glm::dvec3& point,
  glm::dvec3& uvw,
  double epsilon = 1e-9)
{
  uvw = glm::dvec3(0.5);
  if (!InvertTrilinear(box, point, uvw))
  {
    return false;
  }
  return uvw.x >= -epsilon && uvw.x <= 1.0 + epsilon && uvw.y >= -epsilon &&
    uvw.y <= 1.0 + epsilon && uvw.z >= -epsilon && uvw.z <= 1.0 + epsilon;
}

} // namespace lfd

#endif
