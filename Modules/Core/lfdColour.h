/**
 * @file   lfdColour.h
 * @brief  Colour distances as a camera sees them: sRGB (8-bit) to CIELAB.
 *
 * Label colours are chosen and recognised by their CIE 1976 L*a*b* distance
 * (Delta E*ab), a perceptual space in which a Euclidean distance of about 2
 * is just noticeable. The 8-bit values are taken as sRGB-encoded (IEC
 * 61966-2-1), white point D65. Plain C++17 + GLM, no VTK.
 */
#ifndef lfdColour_h
#define lfdColour_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lfd
{

/// Linear-light value in [0, 1] of an sRGB-encoded value in [0, 255].
inline double SrgbToLinear(double value)
{
  const double v = std::min(std::max(value / 255.0, 0.0), 1.0);
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

/// CIELAB (L* in [0, 100]) of an sRGB colour given in [0, 255] per channel.
inline glm::dvec3 SrgbToLab(const glm::dvec3& rgb)
{
  const glm::dvec3 linear(SrgbToLinear(rgb.x), SrgbToLinear(rgb.y), SrgbToLinear(rgb.z));
  // sRGB primaries to XYZ, normalised by the D65 white (Xn, Yn, Zn).
  const double x = (0.4124564 * linear.x + 0.3575761 * linear.y + 0.1804375 * linear.z) / 0.95047;
  const double y = 0.2126729 * linear.x + 0.7151522 * linear.y + 0.0721750 * linear.z;
  const double z = (0.0193339 * linear.x + 0.1191920 * linear.y + 0.9503041 * linear.z) / 1.08883;
  auto f = [](double t)
  {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const double fx = f(x), fy = f(y), fz = f(z);
  return glm::dvec3(116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz));
}

/**
 * Eq. (1) of Chen et al. 2005 (section 4.1), one channel: the coded
 * capture B normalised by the flood capture W, B' = 256 B / W, which cancels
 * albedo and shading and leaves the projector mask's colour (clamped to
 * 255). `flood` must be positive: the callers decide which channels are too
 * dark to carry information.
 */
inline double NormaliseByFlood(double coded, double flood)
{
  return std::min(255.0, 256.0 * coded / flood);
}

/// Delta E*ab (CIE 1976) between two sRGB colours in [0, 255].
inline double ColourDistance(const glm::dvec3& a, const glm::dvec3& b)
{
  return glm::length(SrgbToLab(a) - SrgbToLab(b));
}

} // namespace lfd

#endif
