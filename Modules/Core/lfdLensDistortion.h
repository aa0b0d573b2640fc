/**
 * @file   lfdLensDistortion.h
 * @brief  Lens distortion of a calibrated camera, OpenCV's five-coefficient model.
 *
 * The Brown-Conrady model (D. C. Brown, "Decentering distortion of lenses",
 * Photogrammetric Engineering 32(3), 1966) in the convention of OpenCV's
 * `projectPoints` (OpenCV docs, "Camera Calibration and 3D Reconstruction"):
 * a camera-space point (x, y, z) has the normalised coordinates
 * x' = x / z, y' = y / z, r^2 = x'^2 + y'^2, and is seen at
 *
 *     x'' = x' (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x' y' + p2 (r^2 + 2 x'^2)
 *     y'' = y' (1 + k1 r^2 + k2 r^4 + k3 r^6) + p1 (r^2 + 2 y'^2) + 2 p2 x' y'
 *
 * before the intrinsics K map (x'', y'', 1) to the pixel. The coefficients are
 * stored in OpenCV's order (k1, k2, p1, p2, k3).
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdLensDistortion_h
#define lfdLensDistortion_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lfd
{

struct LensDistortion
{
  /// OpenCV's order: k1, k2, p1, p2, k3.
  double Coefficients[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
  /// False when every coefficient is 0: cameras then skip the polynomial
  /// (the renderer's hot path stays a plain pinhole).
  bool Active = false;

  /// The model of five coefficients (k1, k2, p1, p2, k3).
  static LensDistortion FromArray(const double coefficients[5])
  {
    LensDistortion lens;
    for (int i = 0; i < 5; ++i)
    {
      lens.Coefficients[i] = coefficients[i];
      lens.Active = lens.Active || coefficients[i] != 0.0;
    }
    return lens;
  }

  /// Distorted normalised coordinates (x'', y'') of undistorted ones (x', y').
  glm::dvec2 Apply(const glm::dvec2& n) const
  {
    const double k1 = this->Coefficients[0], k2 = this->Coefficients[1];
    const double p1 = this->Coefficients[2], p2 = this->Coefficients[3];
    const double k3 = this->Coefficients[4];
    const double r2 = n.x * n.x + n.y * n.y;
    const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
    return glm::dvec2(n.x * radial + 2.0 * p1 * n.x * n.y + p2 * (r2 + 2.0 * n.x * n.x),
      n.y * radial + p1 * (r2 + 2.0 * n.y * n.y) + 2.0 * p2 * n.x * n.y);
  }

  /// Jacobian d(x'', y'') / d(x', y') (GLM column-major: column j = d/d(n_j)).
  glm::dmat2 Jacobian(const glm::dvec2& n) const
  {
    const double k1 = this->Coefficients[0], k2 = this->Coefficients[1];
    const double p1 = this->Coefficients[2], p2 = this->Coefficients[3];
    const double k3 = this->Coefficients[4];
    const double r2 = n.x * n.x + n.y * n.y;
    const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
    const double slope = k1 + r2 * (2.0 * k2 + 3.0 * r2 * k3); // d radial / d r^2
    const double cross = 2.0 * n.x * n.y * slope + 2.0 * p1 * n.x + 2.0 * p2 * n.y;
    return glm::dmat2(radial + 2.0 * n.x * n.x * slope + 2.0 * p1 * n.y + 6.0 * p2 * n.x,
      cross,
      cross,
      radial + 2.0 * n.y * n.y * slope + 6.0 * p1 * n.y + 2.0 * p2 * n.x);
  }

  /**
   * Undistorted normalised coordinates of distorted ones: the inverse of
   * Apply(), which has no closed form. OpenCV's `undistortPoints` iterates a
   * fixed point; Newton's method on the 2 x 2 system converges quadratically
   * from the same start (the distorted point itself), so a bounded number of
   * steps reaches the residual |Apply(n) - d| < 1e-12 (normalised units)
   * wherever the model is monotonic, which CheckPinhole() guarantees over
   * the image. Stops early at a singular Jacobian (outside the image).
   */
  glm::dvec2 Remove(const glm::dvec2& d) const
  {
    constexpr int MaximumSteps = 20;
    constexpr double Tolerance = 1e-12;
    glm::dvec2 n = d;
    for (int step = 0; step < MaximumSteps; ++step)
    {
      const glm::dvec2 residual = this->Apply(n) - d;
      if (std::max(std::abs(residual.x), std::abs(residual.y)) < Tolerance)
      {
        break;
      }
      const glm::dmat2 J = this->Jacobian(n);
      const double det = glm::determinant(J);
      if (!(std::abs(det) > 1e-300))
      {
        break;
      }
      n -= glm::inverse(J) * residual;
    }
    return n;
  }
};

/**
 * Empty when the distortion keeps the image one-to-one: along rays from the
 * principal point in 64 directions, the map from undistorted to distorted
 * normalised coordinates keeps a positive Jacobian determinant until it
 * leaves the image, whose extent in distorted normalised coordinates is
 * `imageRadius` (the largest distance of an image corner from the principal
 * point, divided by the focal length). Otherwise the problem in words.
 * Non-monotonic models fold the image: two directions would share a pixel
 * and the iterative removal would have no unique answer.
 */
inline const char* CheckLensMonotonic(const LensDistortion& lens, double imageRadius)
{
  constexpr int Directions = 64;
  constexpr int StepsPerRadius = 256;
  constexpr int MaximumSteps = 16 * StepsPerRadius; // undistorted radius up to 16x the image's
  if (!lens.Active || !(imageRadius > 0.0))
  {
    return nullptr;
  }
  const double step = imageRadius / StepsPerRadius;
  for (int k = 0; k < Directions; ++k)
  {
    const double angle = 6.283185307179586476925286766559 * k / Directions;
    const glm::dvec2 direction(std::cos(angle), std::sin(angle));
    int i = 0;
    for (; i <= MaximumSteps; ++i)
    {
      const glm::dvec2 n = (i * step) * direction;
      if (!(glm::determinant(lens.Jacobian(n)) > 0.0))
      {
        return "folds the image (the distortion is not monotonic up to the image border)";
      }
      if (glm::length(lens.Apply(n)) > imageRadius)
      {
        break;
      }
    }
    if (i > MaximumSteps)
    {
      return "does not reach the image border (the distortion compresses the image too much)";
    }
  }
  return nullptr;
}

} // namespace lfd

#endif
