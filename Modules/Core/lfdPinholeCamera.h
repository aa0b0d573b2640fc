/**
 * @file   lfdPinholeCamera.h
 * @brief  Pinhole camera kernel in the OpenCV convention `x ~ K [R | t] X`.
 *
 * Pixel coordinates have their origin at the centre of the top-left pixel,
 * x grows to the right and y downwards (OpenCV, Middlebury). The camera frame
 * has x right, y down and z forward; the camera centre is `C = -R^T t`.
 *
 * Plain C++17 + GLM: no VTK here, so that the renderers, the tests and any
 * later GPU shader share one definition (DESIGN.md section 3).
 */
#ifndef lfdPinholeCamera_h
#define lfdPinholeCamera_h

#include <glm/glm.hpp>

namespace lfd
{

struct PinholeCamera
{
  glm::dmat3 K{ 1.0 }; // intrinsics
  glm::dmat3 R{ 1.0 }; // world -> camera rotation
  glm::dvec3 t{ 0.0 }; // world -> camera translation

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
   * Projects a world point. Returns false when the point is not in front of
   * the camera (then `pixel` is left untouched).
   */
  bool Project(const glm::dvec3& X, glm::dvec2& pixel) const
  {
    const glm::dvec3 x = this->K * (this->R * X + this->t);
    if (!(x.z > 0.0))
    {
      return false;
    }
    pixel = glm::dvec2(x.x / x.z, x.y / x.z);
    return true;
  }

  /**
   * Matrix `R^T K^-1` that maps a homogeneous pixel `(x, y, 1)` to a world
   * direction (not normalised). Renderers compute it once per frame.
   */
  glm::dmat3 PixelToDirection() const { return glm::transpose(this->R) * glm::inverse(this->K); }

  /// Unit world-space direction of the ray through a pixel.
  glm::dvec3 RayDirection(const glm::dvec2& pixel) const
  {
    return glm::normalize(this->PixelToDirection() * glm::dvec3(pixel, 1.0));
  }
};

} // namespace lfd

#endif
