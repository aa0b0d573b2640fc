/**
 * @file   lfdRayWarp.h
 * @brief  The exact ray warp of Chen, Ofek, Shum and Levoy 2005 (Sec. 5).
 *
 * A view ray in *deformed* space crosses deformed boxes. Inside one box the
 * warped ray is the straight rest-space line through the rest images of the
 * points where the view ray enters and leaves the box (Sec. 5). The paper
 * found those points with a rasterised look-up table; here they are exact:
 * the faces of a trilinear box are bilinear patches, the ray is intersected
 * with each face (a quadratic in one patch parameter, Ramsey, Potter and
 * Hansen 2004; Reshetov 2019), and a hit at patch parameters (s,t) on face k
 * is the box parametric point uvw of FaceOfBox::BoxPoint, whose rest image
 * is TrilinearMap(rest, uvw) (DESIGN.md section 4.2; FaceOfBox::Map).
 *
 * A twisted box is not convex, so a ray can enter and leave it several
 * times; WarpRayThroughBox returns every interval.
 *
 * Faces follow VTK's hexahedron face numbering: 0 is u = 0, 1 is u = 1,
 * 2 is v = 0, 3 is v = 1, 4 is w = 0, 5 is w = 1. On each face the patch
 * parameter s runs along the first free box axis and t along the second
 * (face 0: s = v, t = w; face 2: s = u, t = w; face 4: s = u, t = v).
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdRayWarp_h
#define lfdRayWarp_h

#include "lfdTrilinear.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

namespace lfd
{

/// A ray / patch hit: ray parameter T and patch parameters ST = (s,t).
struct PatchHit
{
  double T;
  glm::dvec2 ST;
};

/// Slack on the patch parameters, so that a ray through a patch edge is
/// reported by both patches sharing the edge rather than by neither.
constexpr double PatchParameterSlack = 1e-9;

namespace detail
{
#if defined(__GNUC__) && defined(__x86_64__)
/**
 * fma(a, b, c) by the processor's FMA3 instruction, when HasFma3(). Built
 * for the x86-64 baseline (no -mfma), std::fma is a library call that
 * emulates the fused operation in software, about 15 ns; and a function
 * built for FMA3 (target("fma")) is not inlined into baseline code, so each
 * call saves and restores every floating-point value its caller holds in
 * registers (the x86-64 System V ABI keeps none across a call). As inline
 * assembly the one instruction inlines into any caller. It rounds once, as
 * std::fma does (IEEE 754 fusedMultiplyAdd), so the results are the same
 * bit for bit; and since only this instruction is fused, no other
 * expression is contracted differently.
 */
inline double FusedMultiplyAddFma3(double a, double b, double c)
{
  // (AT&T operand order: c = a * b + c.)
  __asm__("vfmadd231sd %[b], %[a], %[c]" : [c] "+x"(c) : [a] "x"(a), [b] "x"(b));
  return c;
}

/// Whether the processor has FMA3 (asked once).
inline bool HasFma3()
{
  static const bool has = __builtin_cpu_supports("fma");
  return has;
}
#endif

/// The index of the lowest set bit of `bits` (not 0).
inline int LowestSetBit(int bits)
{
#if defined(__GNUC__)
  return __builtin_ctz(static_cast<unsigned>(bits));
#else
  int index = 0;
  for (; !(bits & 1); bits >>= 1)
  {
    ++index;
  }
  return index;
#endif
}

/// a*b - c*d without the cancellation of the naive form (Kahan's fma trick).
inline double DifferenceOfProducts(double a, double b, double c, double d)
{
#if defined(__GNUC__) && defined(__x86_64__)
  if (HasFma3())
  {
    const double cd = c * d;
    const double error = FusedMultiplyAddFma3(-c, d, cd);
    return FusedMultiplyAddFma3(a, b, -cd) + error;
  }
#endif
  const double cd = c * d;
  const double error = std::fma(-c, d, cd);
  return std::fma(a, b, -cd) + error;
}
} // namespace detail

/**
 * A bilinear patch seen from a fixed ray origin o: the terms of the ray /
 * patch intersection that do not depend on the ray's direction. A frame's
 * view rays all leave the eye, so the renderer computes these once per face
 * and frame instead of once per ray (every ray, single or of a frame, goes
 * through this struct, so the hits are bit for bit the same either way).
 *
 * A planar patch is also intersected as its plane: a cage posed by turning
 * layers about an axis (swim, bend) has every face planar, and the ray's
 * T and t there are a dot product and a division each, instead of the
 * intersection of the ray with the line at s (IntersectPlanar).
 */
struct PatchFromOrigin
{
  glm::dvec3 P00, P10, P01, P11, O;
  glm::dvec3 Q;     ///< p00 - o
  glm::dvec3 E10;   ///< p10 - p00
  glm::dvec3 E00;   ///< p01 - p00, the t-line at s = 0
  glm::dvec3 E11;   ///< p11 - p01
  glm::dvec3 Twist; ///< (p11 - p10) - (p01 - p00), zero for a parallelogram
  /// The coefficients of f(s) (see IntersectAlongS) as linear forms of d:
  /// A = e10 x twist, B = q x twist + e10 x e00, C = q x e00, so that
  /// f(s) = (A.d) s^2 + (B.d) s + (C.d): three dot products per ray instead
  /// of two cross products and three triple products (u.(v x d) = d.(u x v)).
  glm::dvec3 A, B, C;
  /// (|q| + |e10|) (|e00| + |twist|): the vanishing scale of f(s) without |d|.
  double Scale;

  /// The patch's shape, which picks the intersection (IntersectPlanar).
  enum class Shape
  {
    Curved,       ///< a hyperbolic paraboloid: only IntersectAlongS
    Planar,       ///< 4 coplanar corners (within PlanarTolerance)
    Parallelogram ///< a twist of exactly zero, so A = 0 and f(s) is linear
  };
  Shape Form = Shape::Curved;
  /// Of a planar patch: a normal of its plane (B for a parallelogram, where
  /// B = e10 x e00; else the cross product of the diagonals), q.Normal, and
  /// 1e-9 |Normal|: rays closer than 1e-9 radians to the plane are left to
  /// IntersectAlongS, which handles a ray in (or along) the plane.
  glm::dvec3 Normal{ 0.0 };
  double QNormal = 0.0;
  double GrazingLimit = 0.0;
  /// Of a parallelogram: q x e10, so that t = (d.TForm) / (d.B) (Cramer's rule).
  glm::dvec3 TForm{ 0.0 };
  /// Of a planar patch: Across = Normal x e10, in the plane and normal to
  /// the s-edges, so that a crossing x = pa(s) + t e(s) has
  /// (x - p00).Across = t e(s).Across; with q, e00 and the twist along it.
  glm::dvec3 Across{ 0.0 };
  double QAcross = 0.0, E00Across = 0.0, TwistAcross = 0.0;
  /// Of a planar patch: 1e-10 max(|e00|, |e11|) |Across|, below which
  /// |e(s).Across| is a line at s collapsed to a point or along the s-edges,
  /// where t is undetermined (as IntersectAlongS's parallel test).
  double CollapsedLine = 0.0;

  /// Largest |n.(p10 - p00)| / (|n| |p10 - p00|), n the diagonals' cross
  /// product, of a patch intersected as a plane: corners off the plane by
  /// about the rounding of their coordinates, as a rotation about an axis
  /// leaves them.
  static constexpr double PlanarTolerance = 1e-14;

  PatchFromOrigin() = default;
  PatchFromOrigin(const glm::dvec3& p00,
    const glm::dvec3& p10,
    const glm::dvec3& p01,
    const glm::dvec3& p11,
    const glm::dvec3& o)
    : P00(p00)
    , P10(p10)
    , P01(p01)
    , P11(p11)
    , O(o)
    , Q(p00 - o)
    , E10(p10 - p00)
    , E00(p01 - p00)
    , E11(p11 - p01)
    , Twist((p11 - p10) - (p01 - p00))
    , A(glm::cross(E10, Twist))
    , B(glm::cross(Q, Twist) + glm::cross(E10, E00))
    , C(glm::cross(Q, E00))
    , Scale((glm::length(Q) + glm::length(E10)) * (glm::length(E00) + glm::length(Twist)))
  {
    if (this->Twist == glm::dvec3(0.0))
    {
      this->Form = Shape::Parallelogram;
      this->Normal = this->B;
      this->TForm = glm::cross(this->Q, this->E10);
    }
    else
    {
      // The diagonals' cross product is normal to both diagonals, so p00
      // and p11 lie in the plane through p00, and p10 and p01 at the same
      // distance from it on either side: the patch is planar when that
      // distance is zero.
      const glm::dvec3 normal = glm::cross(p11 - p00, p01 - p10);
      if (std::abs(glm::dot(normal, this->E10)) <=
        PlanarTolerance * glm::length(normal) * glm::length(this->E10))
      {
        this->Form = Shape::Planar;
        this->Normal = normal;
        this->Across = glm::cross(normal, this->E10);
        this->QAcross = glm::dot(this->Q, this->Across);
        this->E00Across = glm::dot(this->E00, this->Across);
        this->TwistAcross = glm::dot(this->Twist, this->Across);
        this->CollapsedLine = 1e-10 * std::max(glm::length(this->E00), glm::length(this->E11)) *
          glm::length(this->Across);
      }
    }
    this->QNormal = glm::dot(this->Q, this->Normal);
    this->GrazingLimit = 1e-9 * glm::length(this->Normal);
  }

  /**
   * The roots s of f(s) (see IntersectAlongS) of magnitude at most about 2,
   * into `roots`; -1 when f vanishes identically (s is undetermined).
   */
  int RootsAlongS(const glm::dvec3& d, double speed, double roots[2]) const
  {
    const double a = glm::dot(this->A, d);
    const double b = glm::dot(this->B, d);
    const double c = glm::dot(this->C, d);

    const double vanishing = 1e-12 * (this->Scale * speed);
    if (std::abs(a) <= vanishing && std::abs(b) <= vanishing && std::abs(c) <= vanishing)
    {
      return -1;
    }

    // Roots in the cancellation-free form q/a, c/q. A root is only computed
    // when its magnitude is bounded, so a tiny a (a near-parallelogram) or a
    // tiny qq never turns into a division by almost zero.
    const double discriminant = detail::DifferenceOfProducts(b, b, 4.0 * a, c);
    if (discriminant < 0.0)
    {
      return 0;
    }
    const double qq = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    int nRoots = 0;
    if (std::abs(qq) <= 2.0 * std::abs(a) && a != 0.0)
    {
      roots[nRoots++] = qq / a;
    }
    if (std::abs(c) <= 2.0 * std::abs(qq) && qq != 0.0)
    {
      const double root = c / qq;
      if (nRoots == 0 || root != roots[0])
      {
        roots[nRoots++] = root;
      }
    }
    return nRoots;
  }

  /**
   * Hits of the ray o + T d (`speed` = |d|) with the patch, solving first
   * for s. For a fixed s the patch is the segment pa(s) + t (pb(s) - pa(s)),
   * and the ray meets that line only when the two are coplanar:
   *
   *   f(s) = (pa(s) - o) . ((pb(s) - pa(s)) x d) = (A.d) s^2 + (B.d) s + (C.d) = 0
   *
   * (Reshetov 2019, Ray Tracing Gems ch. 8). Each root gives t and T as the
   * point where the two lines meet. Returns -1 when f vanishes identically
   * (every fixed-s line is coplanar with the ray: the ray is parallel to all
   * of them, or lies in the surface), so s is undetermined and the caller
   * solves for t instead; else returns the number of hits.
   */
  int IntersectAlongS(const glm::dvec3& d, double speed, PatchHit hits[2]) const
  {
    double roots[2];
    const int nRoots = this->RootsAlongS(d, speed, roots);
    if (nRoots < 0)
    {
      return -1;
    }
    int nHits = 0;
    for (int k = 0; k < nRoots; ++k)
    {
      const double s = roots[k];
      if (!(s >= -PatchParameterSlack && s <= 1.0 + PatchParameterSlack))
      {
        continue;
      }
      // The ray o + T d meets the line pa + t e where T d - t e = pa - o; with
      // m = d x e, crossing with e and with d isolates T and t.
      const glm::dvec3 pa = this->P00 + s * this->E10;
      const glm::dvec3 e = (this->P01 + s * this->E11) - pa;
      const glm::dvec3 w0 = pa - this->O;
      const glm::dvec3 m = glm::cross(d, e);
      const double mm = glm::dot(m, m);
      // This fixed-s line is parallel to the ray: it either misses it or
      // contains it (a grazing line contact); neither is a crossing.
      if (!(mm > 1e-20 * glm::dot(e, e) * glm::dot(d, d)))
      {
        continue;
      }
      const double tNumerator = glm::dot(glm::cross(w0, d), m);
      if (std::abs(tNumerator) > 2.0 * mm)
      {
        continue;
      }
      const double t = tNumerator / mm;
      if (!(t >= -PatchParameterSlack && t <= 1.0 + PatchParameterSlack))
      {
        continue;
      }
      hits[nHits].T = glm::dot(glm::cross(w0, e), m) / mm;
      hits[nHits].ST = glm::dvec2(s, t);
      ++nHits;
    }
    return nHits;
  }

  /**
   * Hits of the ray o + T d (`speed` = |d|) with a planar patch, through its
   * plane: T = (q.n) / (d.n) is where the ray crosses it. A parallelogram
   * p00 + s e10 + t e00 is then linear in (T, s, t), and Cramer's rule gives
   * s = -(C.d) / (B.d), the root of the linear f(s) to the bit, and
   * t = (TForm.d) / (B.d). A general planar patch takes s from f(s) = 0,
   * whose roots are the s-lines through the crossing (a line in the plane
   * is never parallel to a ray that crosses it), and t from the crossing's
   * component across the s-edges (Across). Returns -1 for a curved patch, a ray
   * within 1e-9 radians of the plane, or an f(s) that vanishes: the cases
   * of IntersectAlongS.
   */
  int IntersectPlanar(const glm::dvec3& d, double speed, PatchHit hits[2]) const
  {
    const double dn = glm::dot(this->Normal, d);
    if (this->Form == Shape::Curved || !(std::abs(dn) > this->GrazingLimit * speed))
    {
      return -1;
    }
    const double T = this->QNormal / dn;
    if (this->Form == Shape::Parallelogram)
    {
      const double s = glm::dot(this->C, d) / -dn;
      if (!(s >= -PatchParameterSlack && s <= 1.0 + PatchParameterSlack))
      {
        return 0;
      }
      const double t = glm::dot(this->TForm, d) / dn;
      if (!(t >= -PatchParameterSlack && t <= 1.0 + PatchParameterSlack))
      {
        return 0;
      }
      hits[0] = { T, glm::dvec2(s, t) };
      return 1;
    }
    double roots[2];
    const int nRoots = this->RootsAlongS(d, speed, roots);
    if (nRoots < 0)
    {
      return -1; // (every s-line through the crossing: a collapsed edge)
    }
    const double dAcross = glm::dot(d, this->Across);
    int nHits = 0;
    for (int k = 0; k < nRoots; ++k)
    {
      const double s = roots[k];
      if (!(s >= -PatchParameterSlack && s <= 1.0 + PatchParameterSlack))
      {
        continue;
      }
      // The crossing less p00, T d - q, is s e10 + t e(s): along Across, t e(s).
      const double across = this->E00Across + s * this->TwistAcross;
      if (!(std::abs(across) > this->CollapsedLine))
      {
        continue;
      }
      const double t = (T * dAcross - this->QAcross) / across;
      if (!(t >= -PatchParameterSlack && t <= 1.0 + PatchParameterSlack))
      {
        continue;
      }
      hits[nHits].T = T;
      hits[nHits].ST = glm::dvec2(s, t);
      ++nHits;
    }
    return nHits;
  }

  /// Every hit of the ray o + T d (`speed` = |d|), as IntersectBilinearPatch.
  int Intersect(const glm::dvec3& d, double speed, PatchHit hits[2]) const
  {
    const int planar = this->IntersectPlanar(d, speed, hits);
    if (planar >= 0)
    {
      return planar;
    }
    const int n = this->IntersectAlongS(d, speed, hits);
    if (n >= 0)
    {
      return n;
    }
    // s is undetermined along the ray; solve for t on the transposed patch.
    const int nt = PatchFromOrigin(this->P00, this->P01, this->P10, this->P11, this->O)
                     .IntersectAlongS(d, speed, hits);
    for (int k = 0; k < nt; ++k)
    {
      hits[k].ST = glm::dvec2(hits[k].ST.y, hits[k].ST.x);
    }
    return std::max(nt, 0);
  }
};

/**
 * Intersection of the ray o + T d with the bilinear patch
 *
 *   P(s,t) = (1-s)(1-t) p00 + s(1-t) p10 + (1-s)t p01 + st p11.
 *
 * Writes every hit with s,t in [0,1] (within PatchParameterSlack, values
 * are not clamped) and any T (the caller filters) to `hits`, returns their
 * number (0, 1 or 2). Planar and parallelogram patches (where the quadratic
 * degenerates to a linear equation) are handled. A ray that lies in the
 * patch's surface, or runs parallel to a planar patch, touches it along a
 * line or not at all and gets no hit.
 */
inline int IntersectBilinearPatch(const glm::dvec3& p00,
  const glm::dvec3& p10,
  const glm::dvec3& p01,
  const glm::dvec3& p11,
  const glm::dvec3& o,
  const glm::dvec3& d,
  PatchHit hits[2])
{
  return PatchFromOrigin(p00, p10, p01, p11, o).Intersect(d, glm::length(d), hits);
}

/// Corners of face k as a patch: p00, p10, p01, p11 (not VTK's cyclic order).
constexpr int HexFacePatch[6][4] = { { 0, 3, 4, 7 },
  { 1, 2, 5, 6 },
  { 0, 1, 4, 5 },
  { 3, 2, 7, 6 },
  { 0, 1, 3, 2 },
  { 4, 5, 7, 6 } };

/// Rest image of a deformed-space point: the rest map at the deformed map's
/// inverse. Returns false when the Newton inverse does not converge.
inline bool WarpPoint(const Hexahedron& rest,
  const Hexahedron& deformed,
  const glm::dvec3& point,
  glm::dvec3& restPoint,
  glm::dvec3& uvw)
{
  uvw = glm::dvec3(0.5);
  if (!InvertTrilinear(deformed, point, uvw))
  {
    return false;
  }
  restPoint = TrilinearMap(rest, uvw);
  return true;
}

/// One interval of a view ray inside a deformed box, with its warp (Sec. 5).
struct WarpedSegment
{
  double TEnter, TExit;           ///< ray parameters of the deformed entry and exit
  glm::dvec3 RestEnter, RestExit; ///< their rest-space images: the warped ray
  glm::dvec3 UvwEnter, UvwExit;   ///< their box parametric coordinates
  int FaceExit;                   ///< the face (HexFacePatch order) the ray leaves by
};

/// A ray crosses the 6 faces at most 12 times, so the interior of a box is
/// at most 6 separate intervals of the ray.
constexpr int MaxWarpedSegments = 6;

/// A deformed box seen from a fixed ray origin: its faces (HexFacePatch) as
/// PatchFromOrigin, its size, and the faces of its rest box (FaceOfBox, in
/// the face order of HexFacePatch), computed once per box and frame.
struct BoxFromOrigin
{
  PatchFromOrigin Faces[6];
  FaceOfBox RestFaces[6];
  glm::dvec3 Origin{ 0.0 };
  double Size = 0.0; ///< BoxSize of the deformed box
  /// The curved faces (bit k: Faces[k] is PatchFromOrigin::Shape::Curved),
  /// which WarpRaysThroughBox leaves to WarpRayThroughBox.
  int CurvedFaces = 0;

  BoxFromOrigin() = default;
  BoxFromOrigin(const Hexahedron& rest, const Hexahedron& deformed, const glm::dvec3& o)
    : Origin(o)
    , Size(BoxSize(deformed))
  {
    for (int face = 0; face < 6; ++face)
    {
      const int* c = HexFacePatch[face];
      this->Faces[face] = PatchFromOrigin(deformed.Corners[c[0]],
        deformed.Corners[c[1]],
        deformed.Corners[c[2]],
        deformed.Corners[c[3]],
        o);
      this->RestFaces[face] = FaceOfBox(rest, face);
      this->CurvedFaces |= (this->Faces[face].Form == PatchFromOrigin::Shape::Curved ? 1 : 0)
        << face;
    }
  }
};

/**
 * Every interval of the ray o + T d, T >= tMin, inside the deformed box,
 * sorted by T, with the entry and exit points warped into the rest box
 * (Sec. 5). Writes at most `maxSegments` (MaxWarpedSegments always
 * suffices) and returns the number written.
 *
 * All face hits are sorted and hits closer than 1e-9 x the box size merged
 * (a ray through an edge or a corner hits 2 or 3 faces at one point); each
 * stretch between consecutive hits is inside or outside the box as its
 * midpoint is, and adjacent inside stretches form one interval, so a ray
 * touching a face from inside is not split. When the point at tMin is inside
 * the box the first interval starts there, warped with the Newton inverse.
 * Intervals shorter than 1e-7 x the box size (a ray grazing a face or an
 * edge) are dropped. A ray lying in a planar face is on the closed box and
 * gets the interval along the face.
 *
 * `startsOutside` is the caller's promise that the point at tMin lies outside
 * the box (a camera outside the cage): a ray with exactly two distinct face
 * crossings is then inside between them by parity, and the Newton test of
 * that stretch is skipped.
 *
 * `box` is the box seen from the ray's origin o (box.Origin), built from
 * `rest` and `deformed`.
 * Only the faces whose bit (1 << face) is set in `faces` are intersected:
 * the caller's promise that the ray misses the others.
 *
 * `out[k]` is the k-th interval's WarpedSegment: a WarpedSegment array, or
 * an accessor that writes the intervals where the caller keeps them (see
 * FrameCage::NextSegment: a copy read back at once waits for the stores).
 */
template<typename Out>
inline int WarpRayThroughBox(const BoxFromOrigin& box,
  const Hexahedron& rest,
  const Hexahedron& deformed,
  const glm::dvec3& d,
  double tMin,
  Out&& out,
  int maxSegments,
  bool startsOutside = false,
  int faces = 0x3f)
{
  const glm::dvec3& o = box.Origin;
  const double size = box.Size;
  const double speed = glm::length(d);
  if (!(size > 0.0) || !(speed > 0.0))
  {
    return 0;
  }
  const double mergeT = 1e-9 * size / speed;
  const double shortestT = 1e-7 * size / speed;

  // The face hits from tMin on, in the order found: the face and its
  // coordinates s, t (clamped to the face). Their box points and rest images
  // (FaceOfBox::BoxPoint, Map) are found only for the hits that bound an
  // interval, straight into `out` (copied from here, they were read back
  // while their stores were in flight).
  struct FaceHit
  {
    double T;
    double S, Tp; ///< s, t on the face
    int Face;
  };
  FaceHit found[12];
  int nFound = 0;
  for (int remaining = faces & 0x3f; remaining != 0; remaining &= remaining - 1)
  {
    const int face = detail::LowestSetBit(remaining);
    PatchHit hits[2];
    const int nHits = box.Faces[face].Intersect(d, speed, hits);
    for (int k = 0; k < nHits; ++k)
    {
      if (hits[k].T >= tMin - mergeT)
      {
        FaceHit& hit = found[nFound++];
        hit.T = std::max(hits[k].T, tMin);
        hit.Face = face;
        hit.S = std::min(std::max(hits[k].ST.x, 0.0), 1.0);
        hit.Tp = std::min(std::max(hits[k].ST.y, 0.0), 1.0);
      }
    }
  }
  // A face hit's box point (the face's own coordinate exactly 0 or 1) and
  // rest image. (The rest image always inlined: as a call, it was a tenth
  // of the warp's instructions.)
  const auto boxPoint = [&box](const auto& hit)
  { return box.RestFaces[hit.Face].BoxPoint(hit.S, hit.Tp); };
  const auto restPoint = [&box](const auto& hit) __attribute__((always_inline))
  {
    return box.RestFaces[hit.Face].Map(hit.S, hit.Tp);
  };

  if (startsOutside && nFound == 2 && maxSegments > 0)
  {
    // The common case, the general walk below in short: from an outside
    // point, two distinct crossings bound the one interval (by parity).
    const bool swap = found[1].T < found[0].T;
    const FaceHit& enter = found[swap ? 1 : 0];
    const FaceHit& exit = found[swap ? 0 : 1];
    if (exit.T > enter.T + mergeT)
    {
      if (exit.T - enter.T < shortestT)
      {
        return 0;
      }
      WarpedSegment& segment = out[0];
      segment.TEnter = enter.T;
      segment.TExit = exit.T;
      segment.UvwEnter = boxPoint(enter);
      segment.UvwExit = boxPoint(exit);
      segment.FaceExit = exit.Face;
      segment.RestEnter = restPoint(enter);
      segment.RestExit = restPoint(exit);
      return 1;
    }
  }

  struct Crossing
  {
    double T;
    double S, Tp; // s, t of a face hit
    bool OnFace;  // false for the point at tMin, which is on no face
    int Face;     // the face hit (-1 for the point at tMin)
  };
  // Sorted by T, hits of equal T in the order found (the insertion sort that
  // std::sort is below 16 elements, without its calls: the 3-box swim 228.4
  // -> 226.9 M instructions per frame).
  Crossing crossings[12];
  int n = 0;
  for (int i = 0; i < nFound; ++i)
  {
    const Crossing crossing{ found[i].T, found[i].S, found[i].Tp, true, found[i].Face };
    int at = n++;
    for (; at > 0 && crossing.T < crossings[at - 1].T; --at)
    {
      crossings[at] = crossings[at - 1];
    }
    crossings[at] = crossing;
  }

  // Merge coincident hits; the point at tMin goes first unless a hit is there.
  Crossing merged[13];
  int m = 0;
  // (A point at tMin known to be outside starts no stretch that matters.)
  if (!startsOutside && std::isfinite(tMin) && (n == 0 || crossings[0].T > tMin + mergeT))
  {
    merged[m++] = { tMin, 0.0, 0.0, false, -1 };
  }
  for (int k = 0; k < n; ++k)
  {
    if (m == 0 || crossings[k].T > merged[m - 1].T + mergeT)
    {
      merged[m++] = crossings[k];
    }
  }

  int written = 0;
  int k = 0;
  while (k + 1 < m && written < maxSegments)
  {
    // Extend the run of inside stretches starting at crossing k.
    int last = k;
    glm::dvec3 firstMidUvw(0.5);
    for (int j = k; j + 1 < m; ++j)
    {
      const Crossing& a = merged[j];
      const Crossing& b = merged[j + 1];
      // Start Newton from the parametric midpoint of the bounding hits, which
      // is close to the answer; from the box centre it may converge to a
      // preimage outside [0,1]^3 of a strongly deformed box (Contains is the
      // fallback when the close start fails).
      glm::dvec3 uvw = a.OnFace ? 0.5 * (boxPoint(a) + boxPoint(b)) : boxPoint(b);
      const glm::dvec3 mid = o + (0.5 * (a.T + b.T)) * d;
      // From an outside eye every crossing is on a face (no tMin point).
      const bool inside = (startsOutside && m == 2) ||
        (InvertTrilinear(deformed, mid, uvw) &&
          glm::all(glm::greaterThanEqual(uvw, glm::dvec3(-1e-9))) &&
          glm::all(glm::lessThanEqual(uvw, glm::dvec3(1.0 + 1e-9)))) ||
        Contains(deformed, mid, uvw);
      if (!inside)
      {
        break;
      }
      if (j == k)
      {
        firstMidUvw = uvw;
      }
      last = j + 1;
    }
    if (last == k)
    {
      ++k;
      continue;
    }
    const Crossing& enter = merged[k];
    const Crossing& exit = merged[last];
    k = last;
    glm::dvec3 enterUvw;
    if (enter.OnFace)
    {
      enterUvw = boxPoint(enter);
    }
    else
    {
      // (Only the point at tMin is off the faces.)
      enterUvw = firstMidUvw;
      if (!InvertTrilinear(deformed, o + enter.T * d, enterUvw))
      {
        continue;
      }
      enterUvw = glm::clamp(enterUvw, 0.0, 1.0);
    }
    if (exit.T - enter.T < shortestT)
    {
      continue;
    }
    WarpedSegment& segment = out[written++];
    segment.TEnter = enter.T;
    segment.TExit = exit.T;
    segment.UvwEnter = enterUvw;
    segment.UvwExit = boxPoint(exit);
    segment.FaceExit = exit.Face;
    segment.RestEnter = enter.OnFace ? restPoint(enter) : TrilinearMap(rest, enterUvw);
    segment.RestExit = restPoint(exit);
  }
  return written;
}

/// The most rays WarpRaysThroughBox takes at once.
constexpr int MaximumWarpBatch = 4;

#if defined(__GNUC__) && defined(__x86_64__)
namespace detail
{
/// Four lanes of FusedMultiplyAddFma3: c = a * b + c, rounded once (the
/// processor must have FMA3; as inline assembly, in a function built for
/// AVX2 alone, no other product is contracted).
__attribute__((target("avx2"))) inline __m256d FusedMultiplyAddFma3x4(__m256d a,
  __m256d b,
  __m256d c)
{
  __asm__("vfmadd231pd %[b], %[a], %[c]" : [c] "+x"(c) : [a] "x"(a), [b] "x"(b));
  return c;
}

/// glm::dot(u, v) of a constant u with four lanes of v: (x + y) + z, as glm sums it.
__attribute__((target("avx2"))) inline __m256d Dot4(const glm::dvec3& u,
  __m256d x,
  __m256d y,
  __m256d z)
{
  return _mm256_add_pd(
    _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(u.x), x), _mm256_mul_pd(_mm256_set1_pd(u.y), y)),
    _mm256_mul_pd(_mm256_set1_pd(u.z), z));
}

/// Whether each lane of v lies in [-PatchParameterSlack, 1 + PatchParameterSlack] (all bits set).
__attribute__((target("avx2"))) inline __m256d OnPatch4(__m256d v)
{
  return _mm256_and_pd(_mm256_cmp_pd(v, _mm256_set1_pd(-PatchParameterSlack), _CMP_GE_OQ),
    _mm256_cmp_pd(v, _mm256_set1_pd(1.0 + PatchParameterSlack), _CMP_LE_OQ));
}

/// Four lanes of |v|.
__attribute__((target("avx2"))) inline __m256d Abs4(__m256d v)
{
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
}

/**
 * PatchFromOrigin::IntersectPlanar of a planar patch for four rays (the
 * same operations, lane by lane): per lane, up to two hits (T, s, t) and
 * their masks (Hit[k]: all bits set), and Undecided, the lanes where
 * IntersectPlanar returns -1 (a grazing ray, or an f(s) that vanishes).
 */
struct PlanarHits4
{
  __m256d T, S[2], Tp[2], Hit[2], Undecided;

  __attribute__((target("avx2")))
  PlanarHits4(const PatchFromOrigin& patch, __m256d dx, __m256d dy, __m256d dz, __m256d speed)
  {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d dn = Dot4(patch.Normal, dx, dy, dz);
    this->Undecided = _mm256_cmp_pd(
      Abs4(dn), _mm256_mul_pd(_mm256_set1_pd(patch.GrazingLimit), speed), _CMP_NGT_UQ);
    this->T = _mm256_div_pd(_mm256_set1_pd(patch.QNormal), dn);
    if (patch.Form == PatchFromOrigin::Shape::Parallelogram)
    {
      const __m256d s = _mm256_div_pd(Dot4(patch.C, dx, dy, dz), _mm256_sub_pd(zero, dn));
      const __m256d t = _mm256_div_pd(Dot4(patch.TForm, dx, dy, dz), dn);
      this->S[0] = s;
      this->Tp[0] = t;
      this->Hit[0] = _mm256_and_pd(OnPatch4(s), OnPatch4(t));
      this->S[1] = this->Tp[1] = this->Hit[1] = zero;
      return;
    }
    // RootsAlongS.
    const __m256d a = Dot4(patch.A, dx, dy, dz);
    const __m256d b = Dot4(patch.B, dx, dy, dz);
    const __m256d c = Dot4(patch.C, dx, dy, dz);
    const __m256d vanishing =
      _mm256_mul_pd(_mm256_set1_pd(1e-12), _mm256_mul_pd(_mm256_set1_pd(patch.Scale), speed));
    const __m256d vanishes =
      _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(Abs4(a), vanishing, _CMP_LE_OQ),
                      _mm256_cmp_pd(Abs4(b), vanishing, _CMP_LE_OQ)),
        _mm256_cmp_pd(Abs4(c), vanishing, _CMP_LE_OQ));
    this->Undecided = _mm256_or_pd(this->Undecided, vanishes);
    // DifferenceOfProducts(b, b, 4 a, c).
    const __m256d a4 = _mm256_mul_pd(_mm256_set1_pd(4.0), a);
    const __m256d cd = _mm256_mul_pd(a4, c);
    const __m256d error = FusedMultiplyAddFma3x4(_mm256_sub_pd(zero, a4), c, cd);
    const __m256d discriminant =
      _mm256_add_pd(FusedMultiplyAddFma3x4(b, b, _mm256_sub_pd(zero, cd)), error);
    const __m256d real = _mm256_cmp_pd(discriminant, zero, _CMP_NLT_UQ);
    const __m256d sign = _mm256_set1_pd(-0.0);
    const __m256d root = _mm256_sqrt_pd(discriminant);
    const __m256d signedRoot =
      _mm256_or_pd(_mm256_andnot_pd(sign, root), _mm256_and_pd(sign, b)); // copysign
    const __m256d qq = _mm256_mul_pd(_mm256_set1_pd(-0.5), _mm256_add_pd(b, signedRoot));
    const __m256d two = _mm256_set1_pd(2.0);
    const __m256d first = _mm256_and_pd(real,
      _mm256_and_pd(_mm256_cmp_pd(Abs4(qq), _mm256_mul_pd(two, Abs4(a)), _CMP_LE_OQ),
        _mm256_cmp_pd(a, zero, _CMP_NEQ_UQ)));
    const __m256d s0 = _mm256_div_pd(qq, a);
    const __m256d s1 = _mm256_div_pd(c, qq);
    __m256d second = _mm256_and_pd(real,
      _mm256_and_pd(_mm256_cmp_pd(Abs4(c), _mm256_mul_pd(two, Abs4(qq)), _CMP_LE_OQ),
        _mm256_cmp_pd(qq, zero, _CMP_NEQ_UQ)));
    second = _mm256_andnot_pd(_mm256_and_pd(first, _mm256_cmp_pd(s1, s0, _CMP_EQ_OQ)), second);
    // Each root's t from the crossing's component across the s-edges.
    const __m256d dAcross = Dot4(patch.Across, dx, dy, dz);
    const __m256d numerator =
      _mm256_sub_pd(_mm256_mul_pd(this->T, dAcross), _mm256_set1_pd(patch.QAcross));
    const __m256d roots[2] = { s0, s1 };
    const __m256d found[2] = { first, second };
    for (int k = 0; k < 2; ++k)
    {
      const __m256d across = _mm256_add_pd(_mm256_set1_pd(patch.E00Across),
        _mm256_mul_pd(roots[k], _mm256_set1_pd(patch.TwistAcross)));
      const __m256d t = _mm256_div_pd(numerator, across);
      this->S[k] = roots[k];
      this->Tp[k] = t;
      this->Hit[k] = _mm256_and_pd(_mm256_and_pd(found[k], OnPatch4(roots[k])),
        _mm256_and_pd(_mm256_cmp_pd(Abs4(across), _mm256_set1_pd(patch.CollapsedLine), _CMP_GT_OQ),
          OnPatch4(t)));
    }
  }
};

/// FaceOfBox::Map of four lanes of (s, t): the same products and sums.
__attribute__((target("avx2"))) inline void Map4(const FaceOfBox& face,
  __m256d s,
  __m256d t,
  __m256d point[3])
{
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d s1 = _mm256_sub_pd(one, s);
  const __m256d t1 = _mm256_sub_pd(one, t);
  const __m256d weights[4] = { _mm256_mul_pd(face.Flip[0] ? s : s1, t1),
    _mm256_mul_pd(face.Flip[0] ? s1 : s, t1),
    _mm256_mul_pd(face.Flip[1] ? s : s1, t),
    _mm256_mul_pd(face.Flip[1] ? s1 : s, t) };
  for (int axis = 0; axis < 3; ++axis)
  {
    __m256d sum = _mm256_setzero_pd();
    for (int k = 0; k < 4; ++k)
    {
      sum = _mm256_add_pd(sum, _mm256_mul_pd(weights[k], _mm256_set1_pd(face.Corners[k][axis])));
    }
    point[axis] = sum;
  }
}

/// WarpRaysThroughBox's lanes (the processor must have AVX2 and FMA3).
template<typename Out>
__attribute__((target("avx2"))) inline void WarpRaysThroughBoxAvx2(const BoxFromOrigin& box,
  int face0,
  int face1,
  const glm::dvec3* d,
  int count,
  Out&& out,
  int* status)
{
  alignas(32) double lanes[3][4];
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3& di = d[std::min(i, count - 1)]; // (lanes past count repeat the last ray)
    lanes[0][i] = di.x;
    lanes[1][i] = di.y;
    lanes[2][i] = di.z;
  }
  const __m256d dx = _mm256_load_pd(lanes[0]);
  const __m256d dy = _mm256_load_pd(lanes[1]);
  const __m256d dz = _mm256_load_pd(lanes[2]);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d one = _mm256_set1_pd(1.0);
  // glm::length: the root of glm::dot(d, d).
  const __m256d speed = _mm256_sqrt_pd(_mm256_add_pd(
    _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)));
  const __m256d mergeT = _mm256_div_pd(_mm256_set1_pd(1e-9 * box.Size), speed);
  const __m256d shortestT = _mm256_div_pd(_mm256_set1_pd(1e-7 * box.Size), speed);
  const PlanarHits4 hits[2] = { PlanarHits4(box.Faces[face0], dx, dy, dz, speed),
    PlanarHits4(box.Faces[face1], dx, dy, dz, speed) };
  // Per face, its hit from the ray's start on (WarpRayThroughBox keeps
  // those at T >= tMin - mergeT), and whether it has one, or two.
  const __m256d from = _mm256_sub_pd(zero, mergeT);
  __m256d T[2], S[2], Tp[2], once[2], twice[2];
  __m256d undecided = _mm256_or_pd(hits[0].Undecided, hits[1].Undecided);
  undecided = _mm256_or_pd(undecided, _mm256_cmp_pd(speed, zero, _CMP_NGT_UQ));
  for (int f = 0; f < 2; ++f)
  {
    const __m256d after = _mm256_cmp_pd(hits[f].T, from, _CMP_GE_OQ);
    const __m256d h0 = _mm256_and_pd(hits[f].Hit[0], after);
    const __m256d h1 = _mm256_and_pd(hits[f].Hit[1], after);
    once[f] = _mm256_xor_pd(h0, h1);
    twice[f] = _mm256_and_pd(h0, h1);
    T[f] = _mm256_max_pd(zero, hits[f].T); // std::max(T, tMin)
    // The clamped s, t of the face's one hit (std::min(std::max(v, 0), 1)).
    const __m256d s = _mm256_blendv_pd(hits[f].S[1], hits[f].S[0], h0);
    const __m256d t = _mm256_blendv_pd(hits[f].Tp[1], hits[f].Tp[0], h0);
    S[f] = _mm256_min_pd(one, _mm256_max_pd(zero, s));
    Tp[f] = _mm256_min_pd(one, _mm256_max_pd(zero, t));
  }
  // The two-hit path: the ray's hits ordered (the first face's first).
  const __m256d swap = _mm256_cmp_pd(T[1], T[0], _CMP_LT_OQ);
  const __m256d enterT = _mm256_blendv_pd(T[0], T[1], swap);
  const __m256d exitT = _mm256_blendv_pd(T[1], T[0], swap);
  const __m256d apart = _mm256_cmp_pd(exitT, _mm256_add_pd(enterT, mergeT), _CMP_GT_OQ);
  const __m256d longEnough = _mm256_cmp_pd(_mm256_sub_pd(exitT, enterT), shortestT, _CMP_NLT_UQ);
  __m256d points[2][3];
  Map4(box.RestFaces[face0], S[0], Tp[0], points[0]);
  Map4(box.RestFaces[face1], S[1], Tp[1], points[1]);
  alignas(32) double values[14][4];
  _mm256_store_pd(values[0], enterT);
  _mm256_store_pd(values[1], exitT);
  for (int f = 0; f < 2; ++f)
  {
    _mm256_store_pd(values[2 + f], S[f]);
    _mm256_store_pd(values[4 + f], Tp[f]);
    for (int axis = 0; axis < 3; ++axis)
    {
      _mm256_store_pd(values[6 + 3 * f + axis], points[f][axis]);
    }
  }
  const int undecidedLanes = _mm256_movemask_pd(undecided);
  const int oneEach = _mm256_movemask_pd(_mm256_and_pd(once[0], once[1]));
  const int twoAny = _mm256_movemask_pd(_mm256_or_pd(twice[0], twice[1]));
  const int oneAny = _mm256_movemask_pd(_mm256_or_pd(once[0], once[1]));
  const int swapped = _mm256_movemask_pd(swap);
  const int kept = _mm256_movemask_pd(_mm256_and_pd(apart, longEnough));
  for (int i = 0; i < count; ++i)
  {
    const int bit = 1 << i;
    if ((undecidedLanes & bit) || (twoAny & bit) || ((oneAny & bit) && !(oneEach & bit)))
    {
      // (Three hits or more, or two of one face: WarpRayThroughBox merges
      // them, or two from one ray that no plane decides.)
      status[i] = (undecidedLanes & bit) || (twoAny & bit) ? -1 : 0;
      continue;
    }
    if (!(oneEach & bit) || !(kept & bit))
    {
      status[i] = 0; // fewer than two crossings, or two too close together
      continue;
    }
    const int enter = (swapped & bit) ? 1 : 0;
    const int exit = 1 - enter;
    const FaceOfBox& enterFace = box.RestFaces[enter ? face1 : face0];
    const FaceOfBox& exitFace = box.RestFaces[exit ? face1 : face0];
    WarpedSegment& segment = out[i];
    segment.TEnter = values[0][i];
    segment.TExit = values[1][i];
    segment.UvwEnter = enterFace.BoxPoint(values[2 + enter][i], values[4 + enter][i]);
    segment.UvwExit = exitFace.BoxPoint(values[2 + exit][i], values[4 + exit][i]);
    segment.FaceExit = exit ? face1 : face0;
    segment.RestEnter =
      glm::dvec3(values[6 + 3 * enter][i], values[7 + 3 * enter][i], values[8 + 3 * enter][i]);
    segment.RestExit =
      glm::dvec3(values[6 + 3 * exit][i], values[7 + 3 * exit][i], values[8 + 3 * exit][i]);
    status[i] = 1;
  }
}
} // namespace detail
#endif

/**
 * WarpRayThroughBox for the rays o + T d[i], i < count <= MaximumWarpBatch,
 * o = box.Origin outside the box (startsOutside), tMin = 0, through the
 * two faces whose bits `faces` sets only, both planar: per
 * ray, status[i] = 1 and out[i] the one interval (`out` as
 * WarpRayThroughBox's: an array, or an accessor that writes where the
 * caller keeps the interval), 0 for none, or -1 where
 * the batch does not decide (the caller warps that ray with
 * WarpRayThroughBox). On a processor with AVX2 and FMA3, the four rays are
 * the lanes of vectors, each lane the operations of WarpRayThroughBox,
 * so that the results are the same to the bit; elsewhere every status is
 * -1. A ray through a box crosses two faces: warped one by one, each
 * crossing is a dependent chain of two divisions and a square root
 * (IntersectPlanar) waiting on the next, and the warp was a quarter of the
 * 3-box swim's frame.
 */
template<typename Out>
inline void WarpRaysThroughBox(const BoxFromOrigin& box,
  int faces,
  const glm::dvec3* d,
  int count,
  Out&& out,
  int* status)
{
  std::fill(status, status + count, -1);
#if defined(__GNUC__) && defined(__x86_64__)
  static const bool avx2 = __builtin_cpu_supports("avx2") && detail::HasFma3();
  if (avx2 && count > 0 && box.Size > 0.0 && (faces & box.CurvedFaces) == 0)
  {
    detail::WarpRaysThroughBoxAvx2(box,
      detail::LowestSetBit(faces),
      detail::LowestSetBit(faces & (faces - 1)),
      d,
      count,
      out,
      status);
  }
#endif
}

/// WarpRayThroughBox for a single ray: the box seen from o built on the spot.
inline int WarpRayThroughBox(const Hexahedron& rest,
  const Hexahedron& deformed,
  const glm::dvec3& o,
  const glm::dvec3& d,
  double tMin,
  WarpedSegment* out,
  int maxSegments,
  bool startsOutside = false)
{
  return WarpRayThroughBox(
    BoxFromOrigin(rest, deformed, o), rest, deformed, d, tMin, out, maxSegments, startsOutside);
}

} // namespace lfd

#endif
