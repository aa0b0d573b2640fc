/**
 * @file   lfdLimits.h
 * @brief  The documented limits of the renderer (Data/README.md, "Limits").
 *
 * Inputs above these are refused with an error naming the setting, never
 * clamped: a value a user wrote is either honoured or reported.
 */
#ifndef lfdLimits_h
#define lfdLimits_h

namespace lfd
{

/// Largest rendered image width or height in pixels: 16384^2 pixels already
/// take 2 GiB of output arrays (RGB, label and float depth per pixel).
constexpr int MaximumRenderSize = 16384;

/// Largest tessellation k of a box (k^3 sub-boxes, DESIGN.md 4.4): a ray
/// crosses at most 3k - 2 sub-boxes of one box, which stays under the 64
/// segments a ray keeps.
constexpr int MaximumSubdivision = 16;

/// Largest number of sub-boxes of a whole tessellated cage: every ray tests
/// every sub-box, about 1.1 ms per sub-box for a 256 x 256 frame on 2 cores,
/// so this budget bounds a 512 x 512 frame to about 18 s. One box at the
/// maximum subdivision fills it.
constexpr int MaximumSubBoxes = MaximumSubdivision * MaximumSubdivision * MaximumSubdivision;

} // namespace lfd

#endif
