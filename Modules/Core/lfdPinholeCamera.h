/**
 * @file   lfdPinholeCamera.h
 * @brief  Pinhole camera kernel in the OpenCV convention `x ~ K [R | t] X`.
 *
 * Pixel coordinates have their origin at the centre of the top-left pixel,
 * x grows to the right and y downwards (OpenCV, Middlebury). The camera frame
 * has x right, y down and z forward; the camera centre is `C = -R^T t`.
 *
 * A camera may carry lens distortion (lfdLensDistortion.h, OpenCV's k1, k2,
 * p1, p2, k3): Project() applies it between the camera frame and K, the
 * pixel-to-ray direction (Unproject(), RayDirection()) removes it. With all
 * coefficients 0 both are the plain pinhole, without the polynomial.
 *
 * Plain C++17 + GLM: no VTK here, so that the renderers, the tests and any
 * later GPU shader share one definition (DESIGN.md section 3).
 */
#ifndef lfdPinholeCamera_h
#define lfdPinholeCamera_h

#include "lfdLensDistortion.h"
#include "lfdLimits.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lfd
{

struct PinholeCamera
{
  glm::dmat3 K{ 1.0 }; // intrinsics
  glm::dmat3 R{ 1.0 }; // world -> camera rotation
  glm::dvec3 t{ 0.0 }; // world -> camera translation
  LensDistortion Lens; // none by default

  /// Builds a camera from row-major 3x3 arrays (the file and VTK API order).
  static PinholeCamera FromRowMajor(const double k[9], const double r[9], const double tr[3])
  {
    PinholeCamera camera;
    for (int row = 0; row < 3; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        camera.K[col][row] = k[3 * row + col]; // GLM is column-major
        camera.R[col][row] = r[3 * row + col];
      }
      camera.t[row] = tr[row];
    }
    return camera;
  }

  /**
   * A camera at `position` looking along `forward` with its image "up" as
   * close to `up` as the view allows (camera rows: right, down, forward).
   */
  static PinholeCamera LookAt(const glm::dmat3& k,
    const glm::dvec3& position,
    glm::dvec3 forward,
    glm::dvec3 up)
  {
    forward = glm::normalize(forward);
    up = glm::normalize(up - glm::dot(up, forward) * forward);
    const glm::dvec3 down = -up;
    const glm::dvec3 right = glm::cross(down, forward);
    PinholeCamera camera;
    camera.K = k;
    camera.R = glm::transpose(glm::dmat3(right, down, forward)); // rows
    camera.t = -(camera.R * position);
    return camera;
  }

  glm::dvec3 Center() const { return -glm::transpose(this->R) * this->t; }

  /// Unit viewing direction (camera +z) in world space.
  glm::dvec3 Forward() const { return glm::dvec3(R[0][2], R[1][2], R[2][2]); }

  /// Unit "up" of the image in world space (camera -y).
  glm::dvec3 Up() const { return -glm::dvec3(R[0][1], R[1][1], R[2][1]); }

  /**
   * Projects a world point, through the lens distortion when there is one.
   * Returns false when the point is not in front of the camera (then `pixel`
   * is left untouched).
   */
  bool Project(const glm::dvec3& X, glm::dvec2& pixel) const
  {
    double z;
    return this->Project(X, pixel, z);
  }

  /**
   * Project() that also gives the point's camera z (its depth along
   * Forward(), dot(Forward(), X) + t.z to the bit), set even when the point
   * is not in front of the camera.
   */
  bool Project(const glm::dvec3& X, glm::dvec2& pixel, double& z) const
  {
    const glm::dvec3 c = this->R * X + this->t;
    z = c.z;
    if (!(c.z > 0.0))
    {
      return false;
    }
    if (!this->Lens.Active)
    {
      const glm::dvec3 x = this->K * c;
      pixel = glm::dvec2(x.x / x.z, x.y / x.z);
      return true;
    }
    // K's last row is (0, 0, 1) (CheckPinhole): the distorted normalised
    // point maps to the pixel without a division.
    const glm::dvec3 x =
      this->K * glm::dvec3(this->Lens.Apply(glm::dvec2(c.x / c.z, c.y / c.z)), 1.0);
    pixel = glm::dvec2(x.x, x.y);
    return true;
  }

  /**
   * Matrix `R^T K^-1` that maps a homogeneous pixel `(x, y, 1)` to a world
   * direction (not normalised) of an undistorted camera. Renderers compute it
   * once per frame for their (ideal) view camera.
   */
  glm::dmat3 PixelToDirection() const { return glm::transpose(this->R) * glm::inverse(this->K); }

  /**
   * Back-projection of pixels with their depth (the distance along the
   * optical axis, camera z, as the Depth pass stores it): the world point
   * `C + depth R^T (x', y', 1)` where (x', y') are the pixel's undistorted
   * normalised coordinates (`K^-1 (x, y, 1)` without distortion). Built once
   * per camera, applied per pixel.
   */
  struct Unprojection
  {
    glm::dvec3 Center;
    glm::dmat3 PixelToDirection; // R^T K^-1
    glm::dmat3 InverseK;
    glm::dmat3 RotationT;
    LensDistortion Lens;

    /// World direction (camera z component 1, not normalised) of a pixel's ray.
    glm::dvec3 Direction(const glm::dvec2& pixel) const
    {
      if (!this->Lens.Active)
      {
        return this->PixelToDirection * glm::dvec3(pixel, 1.0);
      }
      const glm::dvec3 distorted = this->InverseK * glm::dvec3(pixel, 1.0);
      return this->RotationT * glm::dvec3(this->Lens.Remove(glm::dvec2(distorted)), 1.0);
    }

    glm::dvec3 operator()(const glm::dvec2& pixel, double depth) const
    {
      return this->Center + depth * this->Direction(pixel);
    }
  };
  Unprojection GetUnprojection() const
  {
    return { this->Center(),
      this->PixelToDirection(),
      glm::inverse(this->K),
      glm::transpose(this->R),
      this->Lens };
  }

  /// The world point seen at `pixel` at `depth` (camera z); see Unprojection.
  glm::dvec3 Unproject(const glm::dvec2& pixel, double depth) const
  {
    return this->GetUnprojection()(pixel, depth);
  }

  /// Unit world-space direction of the ray through a pixel.
  glm::dvec3 RayDirection(const glm::dvec2& pixel) const
  {
    return glm::normalize(this->GetUnprojection().Direction(pixel));
  }
};

/**
 * An undistorted pinhole camera's projection as one 3x4 matrix P = K [R | t]
 * (Hartley and Zisserman, Multiple View Geometry, Sec. 6.1), built once per
 * camera: a point projects with one matrix product and one division instead
 * of PinholeCamera::Project's two 3x3 products and two divisions. The
 * pixel's rounding differs from Project's in the last bits; the test of the
 * camera side is Project's to the bit (K's last row is (0, 0, 1), so P's
 * last row is R's last row and t.z). No lens distortion: a camera with one
 * keeps PinholeCamera::Project.
 */
struct ProjectionMatrix
{
  /// P's first two rows column by column, (P(0, k), P(1, k)) at Pixel[k]:
  /// the pixel's two numerators are computed as one pair (two lanes of SSE2,
  /// each lane the scalar sum in its order).
  alignas(16) double Pixel[4][2];
  /// P's last row: the camera z of a point.
  double Depth[4];

  explicit ProjectionMatrix(const PinholeCamera& camera)
  {
    for (int row = 0; row < 2; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        // (K R)[row][col]; GLM is column-major: K[k][row] is K's (row, k).
        this->Pixel[col][row] = camera.K[0][row] * camera.R[col][0] +
          camera.K[1][row] * camera.R[col][1] + camera.K[2][row] * camera.R[col][2];
      }
      this->Pixel[3][row] = camera.K[0][row] * camera.t[0] + camera.K[1][row] * camera.t[1] +
        camera.K[2][row] * camera.t[2];
    }
    // Exactly R's last row and t.z (K's last row is (0, 0, 1)).
    for (int col = 0; col < 3; ++col)
    {
      this->Depth[col] = camera.R[col][2];
    }
    this->Depth[3] = camera.t.z;
  }

  /// PinholeCamera::Project without lens distortion: false (pixel untouched)
  /// for a point not in front of the camera.
  bool Project(const glm::dvec3& X, glm::dvec2& pixel) const
  {
    double z;
    return this->Project(X, pixel, z);
  }

  /// Project() that also gives the point's camera z, the homogeneous w
  /// (PinholeCamera's to the bit: the same products, summed in the same
  /// order), set even when the point is not in front of the camera.
  bool Project(const glm::dvec3& X, glm::dvec2& pixel, double& z) const
  {
    z = this->CameraZ(X);
    if (!(z > 0.0))
    {
      return false;
    }
    pixel = this->PixelAt(X, 1.0 / z);
    return true;
  }

  /// The camera z of X: Project()'s homogeneous w (it is in front for z > 0).
  double CameraZ(const glm::dvec3& X) const
  {
    return this->Depth[0] * X.x + this->Depth[1] * X.y + this->Depth[2] * X.z + this->Depth[3];
  }

#if defined(__SSE2__)
  /// CameraZ() of X for the cameras `a` and `b` as the two lanes of one
  /// vector, each lane the scalar sum in its order.
  static __m128d CameraZPair(const ProjectionMatrix& a,
    const ProjectionMatrix& b,
    const glm::dvec3& X)
  {
    const auto column = [&](int k) { return _mm_set_pd(b.Depth[k], a.Depth[k]); };
    return _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(column(0), _mm_set1_pd(X.x)),
                                   _mm_mul_pd(column(1), _mm_set1_pd(X.y))),
                        _mm_mul_pd(column(2), _mm_set1_pd(X.z))),
      column(3));
  }
#endif

  /**
   * Project()'s pixel of X from `inverse`, 1 / CameraZ(X): the second half
   * of Project(), for a caller that takes the reciprocals of several
   * points' z at once (LightFieldSampler::ProjectViews(): two a division).
   */
  glm::dvec2 PixelAt(const glm::dvec3& X, double inverse) const
  {
#if defined(__SSE2__)
    const __m128d sum =
      _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_load_pd(this->Pixel[0]), _mm_set1_pd(X.x)),
                              _mm_mul_pd(_mm_load_pd(this->Pixel[1]), _mm_set1_pd(X.y))),
                   _mm_mul_pd(_mm_load_pd(this->Pixel[2]), _mm_set1_pd(X.z))),
        _mm_load_pd(this->Pixel[3]));
    const __m128d scaled = _mm_mul_pd(sum, _mm_set1_pd(inverse));
    return glm::dvec2(_mm_cvtsd_f64(scaled), _mm_cvtsd_f64(_mm_unpackhi_pd(scaled, scaled)));
#else
    glm::dvec2 pixel;
    for (int row = 0; row < 2; ++row)
    {
      pixel[row] = (this->Pixel[0][row] * X.x + this->Pixel[1][row] * X.y +
                     this->Pixel[2][row] * X.z + this->Pixel[3][row]) *
        inverse;
    }
    return pixel;
#endif
  }
};

/**
 * Largest distance of an image corner (pixel centres at integers, so the
 * corners at -0.5 and size - 0.5) from the principal point, in normalised
 * coordinates K^-1 (x, y, 1): the extent of a `width` x `height` image that a
 * lens distortion must keep one-to-one. K is row-major and upper triangular.
 */
inline double NormalisedImageRadius(const double K[9], int width, int height)
{
  double radius = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double u = (corner & 1) ? width - 0.5 : -0.5;
    const double v = (corner & 2) ? height - 0.5 : -0.5;
    const double y = (v - K[5]) / K[4];
    const double x = (u - K[2] - K[1] * y) / K[0];
    radius = std::max(radius, std::sqrt(x * x + y * y));
  }
  return radius;
}

/**
 * The one validation of a calibrated camera, shared by every reader,
 * importer and writer: R a rotation (R R^T = I to 1e-3, det R = +1), K upper
 * triangular with K[8] = 1, finite positive focal lengths fx, fy, finite
 * skew and principal point, t finite with |t| < MaximumTranslation, and the
 * lens distortion (k1, k2, p1, p2, k3; null = none) finite and monotonic
 * over the `width` x `height` image (lfd::CheckLensMonotonic). Returns false
 * with the offending field ("K", "R", "t" or "distortion") in `field` and
 * the problem in words.
 */
inline bool CheckPinhole(const double K[9],
  const double R[9],
  const double t[3],
  const double distortion[5],
  int width,
  int height,
  std::string& field,
  std::string& problem)
{
  for (int i = 0; i < 9; ++i)
  {
    if (!std::isfinite(K[i]) || !std::isfinite(R[i]))
    {
      field = std::isfinite(K[i]) ? "R" : "K";
      problem = "has a non-finite entry";
      return false;
    }
  }
  if (K[3] != 0.0 || K[6] != 0.0 || K[7] != 0.0 || K[8] != 1.0)
  {
    field = "K";
    problem = "not an intrinsic matrix (expected [fx s cx, 0 fy cy, 0 0 1])";
    return false;
  }
  if (!(K[0] > 0.0) || !(K[4] > 0.0))
  {
    field = "K";
    problem = "focal lengths fx = K[0] and fy = K[4] must be positive";
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      const double dot =
        R[3 * a] * R[3 * b] + R[3 * a + 1] * R[3 * b + 1] + R[3 * a + 2] * R[3 * b + 2];
      if (std::abs(dot - (a == b ? 1.0 : 0.0)) > 1e-3)
      {
        field = "R";
        problem = "not a rotation matrix (R R^T != I)";
        return false;
      }
    }
  }
  const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
    R[2] * (R[3] * R[7] - R[4] * R[6]);
  if (!(det > 0.0))
  {
    field = "R";
    problem = "not a rotation matrix (det R = -1: a reflection)";
    return false;
  }
  const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  if (!(length < MaximumTranslation))
  {
    field = "t";
    problem = "|t| must be finite and below 1e6 world units";
    return false;
  }
  if (distortion)
  {
    field = "distortion";
    for (int i = 0; i < 5; ++i)
    {
      if (!std::isfinite(distortion[i]))
      {
        problem = "has a non-finite coefficient (expected [k1, k2, p1, p2, k3])";
        return false;
      }
    }
    const char* fold = CheckLensMonotonic(
      LensDistortion::FromArray(distortion), NormalisedImageRadius(K, width, height));
    if (fold)
    {
      problem = fold;
      return false;
    }
    field.clear();
  }
  return true;
}

/**
 * The one validation of a look-at camera (a scene's view camera): the
 * position differs from the focal point, view_up is not parallel to the
 * viewing direction, and the vertical view angle is within
 * [MinimumViewAngle, MaximumViewAngle] degrees. Returns false with the
 * offending field ("focal_point", "view_up" or "view_angle") and the problem.
 */
inline bool CheckLookAt(const double position[3],
  const double focalPoint[3],
  const double viewUp[3],
  double viewAngle,
  std::string& field,
  std::string& problem)
{
  const glm::dvec3 forward(
    focalPoint[0] - position[0], focalPoint[1] - position[1], focalPoint[2] - position[2]);
  const glm::dvec3 up(viewUp[0], viewUp[1], viewUp[2]);
  const double distance = glm::length(forward);
  if (!(distance > 0.0) || !std::isfinite(distance))
  {
    field = "focal_point";
    problem = "must differ from the camera position (no viewing direction)";
    return false;
  }
  const double upLength = glm::length(up);
  // sin of the angle between view_up and the viewing direction: below 1e-6
  // the image "up" is undefined.
  if (!(upLength > 0.0) || !std::isfinite(upLength) ||
    glm::length(glm::cross(forward / distance, up / upLength)) < 1e-6)
  {
    field = "view_up";
    problem = "must not be zero or parallel to the viewing direction";
    return false;
  }
  if (!(viewAngle >= MinimumViewAngle && viewAngle <= MaximumViewAngle))
  {
    field = "view_angle";
    problem = "expected degrees in [0.5, 179]";
    return false;
  }
  return true;
}
} // namespace lfd

#endif
