/**
 * @file   lfdPerspectiveDepth.h
 * @brief  OpenGL window depth <-> camera-space distance of a perspective frustum.
 *
 * A perspective projection with clipping range [n, f] stores, for a point at
 * distance z along the optical axis, the window depth d = (z_ndc + 1) / 2 with
 * z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) z). Synthetic capture reads the
 * Depth pass back from the z-buffer (window -> distance); the light-field
 * mapper writes its rays' depth into the z-buffer (distance -> window), so
 * that the light field composites with other actors. One definition for both.
 *
 * Plain C++17: no VTK, no GL.
 */
#ifndef lfdPerspectiveDepth_h
#define lfdPerspectiveDepth_h

namespace lfd
{
/// Camera z of a window depth d in [0, 1) (d = 1 is the far plane or nothing).
inline double WindowDepthToDistance(double d, double n, double f)
{
  const double ndc = 2.0 * d - 1.0;
  return 2.0 * n * f / (f + n - ndc * (f - n));
}

/// Window depth of a camera z > 0 (not clamped: outside [n, f] leaves [0, 1]).
inline double DistanceToWindowDepth(double z, double n, double f)
{
  const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z);
  return 0.5 * ndc + 0.5;
}
}

#endif
