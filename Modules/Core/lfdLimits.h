/**
 * @file   lfdLimits.h
 * @brief  The documented limits of lfd's inputs (Data/README.md, "Limits and errors").
 *
 * Readers, importers, the renderer and the command line check against these
 * constants before they allocate, so that a malformed file ends in one error
 * line instead of an out-of-memory abort or a stack overflow.
 */
#ifndef lfdLimits_h
#define lfdLimits_h

#include <cstdint>
#include <sstream>
#include <string>

namespace lfd
{
/// Largest rendered image side (scene camera.width/height), pixels.
constexpr int MaximumRenderSize = 16384;

/// Largest light field in memory: W x H x views x bytes per pixel of the passes.
constexpr std::uint64_t MaximumLightFieldBytes = std::uint64_t(4) << 30;

/// Largest camera translation |t| (world units) a calibration may hold.
constexpr double MaximumTranslation = 1e6;

/// Deepest nesting of arrays and objects in a JSON file we read.
constexpr int MaximumJsonDepth = 64;

///@{
/// Range of the scene's render.subdivision (k x k x k sub-boxes per box).
constexpr int MinimumSubdivision = 1;
constexpr int MaximumSubdivision = 16;
///@}

/// Largest number of sub-boxes of a whole tessellated cage: every ray tests
/// every sub-box, about 1.1 ms per sub-box for a 256 x 256 frame on 2 cores,
/// so this budget bounds a 512 x 512 frame to about 18 s. One box at the
/// maximum subdivision fills it. (A ray keeps every segment it meets:
/// lfdRenderView.h.)
constexpr int MaximumSubBoxes = MaximumSubdivision * MaximumSubdivision * MaximumSubdivision;

///@{
/// Range of a view angle, degrees (a smaller angle is a degenerate camera).
constexpr double MinimumViewAngle = 0.5;
constexpr double MaximumViewAngle = 179.0;
///@}

/**
 * Empty when a light field of `width` x `height` pixels, `views` views and
 * `bytesPerPixel` bytes per pixel (over all its passes) fits within
 * MaximumLightFieldBytes; otherwise the problem in words.
 */
inline std::string CheckLightFieldSize(std::int64_t width,
  std::int64_t height,
  std::int64_t views,
  std::int64_t bytesPerPixel)
{
  // Long double: the product of four values up to 2^31 must not wrap.
  const long double bytes = static_cast<long double>(width) * height * views * bytesPerPixel;
  if (bytes <= static_cast<long double>(MaximumLightFieldBytes))
  {
    return std::string();
  }
  std::ostringstream problem;
  problem.precision(3);
  problem << width << "x" << height << " pixels x " << views << " views x " << bytesPerPixel
          << " bytes per pixel need " << static_cast<double>(bytes / (1024.0L * 1024 * 1024))
          << " GiB, more than the " << (MaximumLightFieldBytes >> 30) << " GiB limit";
  return problem.str();
}
}

#endif
