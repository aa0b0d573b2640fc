/**
 * @file   lfdLabelMorphology.h
 * @brief  Morphological clean-up of label images, shared by the splitters.
 *
 * OpenCV is used behind this interface only, so no wrapped header sees it.
 */
#ifndef lfdLabelMorphology_h
#define lfdLabelMorphology_h

#include <vector>

namespace lfd
{
namespace segmentation
{

/**
 * Cleans one label image of `width` x `height` pixels (labels 0..`labels`)
 * in place: per label, an opening with a disc of `radius` pixels removes
 * specks (they become 0), then a closing fills holes of unlabelled pixels
 * (only where `fillable` is non-zero, when given). Radius 0 does nothing.
 */
void CleanLabels(unsigned char* image,
  const unsigned char* fillable,
  int width,
  int height,
  int labels,
  int radius);

/**
 * The object pixels of one RGB view: mean of the channels above `threshold`
 * (1, else 0), cleaned by an opening and a closing of `radius` pixels and
 * its holes filled (FillObjectHoles), into `mask` (width x height bytes).
 * Radius 0 leaves the thresholded pixels as they are.
 */
void ObjectMask(const unsigned char* rgb,
  int width,
  int height,
  double threshold,
  int radius,
  unsigned char* mask);

/**
 * Fills the holes of an object `mask` (width x height bytes, non-zero =
 * object) of the RGB view `rgb` that are the object's own dark pixels, not
 * the backdrop seen through it. A hole is a background region (4-connected)
 * that does not reach the image border once openings of a few pixels are
 * sealed (a closing by a disc of a 120th of the image); it is the backdrop
 * seen through the object when at least a fifth of its pixels are darker
 * than a sixth of `threshold` (mean of RGB) or at least half of them darker
 * than a third of it, else it is filled. Grooves and shadowed recesses
 * darker than the object threshold are holes that the label pass and the
 * visual hull must not have: a ray through one votes background and the
 * proxy has no depth there.
 */
void FillObjectHoles(const unsigned char* rgb,
  int width,
  int height,
  double threshold,
  unsigned char* mask);

/**
 * Distance in pixels from every pixel of a `width` x `height` mask to the
 * nearest non-zero pixel (0 on the mask), into `distance` (resized).
 */
void DistanceToMask(const unsigned char* mask, int width, int height, std::vector<float>& distance);

/**
 * Robust sensor-noise sigma of a grey 8-bit image (Immerkaer, "Fast noise
 * variance estimation", CVIU 1996): the median absolute response of the
 * 3x3 Laplacian-difference mask over unclipped pixels, / (0.6745 x 6).
 * Returns -1 when no pixel qualifies.
 */
double EstimateNoise(const std::vector<unsigned char>& grey, int width, int height);

} // namespace segmentation
} // namespace lfd

#endif
