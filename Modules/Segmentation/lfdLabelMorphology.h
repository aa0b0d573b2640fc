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
 * (1, else 0), cleaned by an opening and a closing of `radius` pixels, into
 * `mask` (width x height bytes).
 */
void ObjectMask(const unsigned char* rgb,
  int width,
  int height,
  double threshold,
  int radius,
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
