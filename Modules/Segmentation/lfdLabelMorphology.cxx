#include "lfdLabelMorphology.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace lfd
{
namespace segmentation
{

void CleanLabels(unsigned char* image,
  const unsigned char* fillable,
  int width,
  int height,
  int labels,
  int radius)
{
  if (radius <= 0)
  {
    return;
  }
  cv::Mat labelImage(height, width, CV_8UC1, image);
  const cv::Mat disc = cv::getStructuringElement(
    cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1), cv::Point(radius, radius));
  cv::Mat original = labelImage.clone();
  cv::Mat mask, opened, closed;
  // Openings first, each from the original image, so that a label's speck
  // removal does not depend on the order of the labels.
  std::vector<cv::Mat> kept(labels + 1);
  for (int label = 1; label <= labels; ++label)
  {
    cv::compare(original, label, mask, cv::CMP_EQ);
    cv::morphologyEx(mask, kept[label], cv::MORPH_OPEN, disc);
  }
  labelImage.setTo(0);
  for (int label = 1; label <= labels; ++label)
  {
    labelImage.setTo(label, kept[label]);
  }
  // Closings fill unlabelled pixels only (and only fillable ones).
  cv::Mat holes;
  cv::compare(labelImage, 0, holes, cv::CMP_EQ);
  if (fillable)
  {
    const cv::Mat lit(height, width, CV_8UC1, const_cast<unsigned char*>(fillable));
    cv::bitwise_and(holes, lit, holes);
  }
  for (int label = 1; label <= labels; ++label)
  {
    cv::morphologyEx(kept[label], closed, cv::MORPH_CLOSE, disc);
    cv::bitwise_and(closed, holes, closed);
    labelImage.setTo(label, closed);
    cv::bitwise_and(holes, ~closed, holes);
  }
}

void ObjectMask(const unsigned char* rgb,
  int width,
  int height,
  double threshold,
  int radius,
  unsigned char* mask)
{
  const long pixels = static_cast<long>(width) * height;
  for (long p = 0; p < pixels; ++p)
  {
    mask[p] = (rgb[3 * p] + rgb[3 * p + 1] + rgb[3 * p + 2]) / 3.0 > threshold ? 1 : 0;
  }
  if (radius > 0)
  {
    CleanLabels(mask, nullptr, width, height, 1, radius);
    FillObjectHoles(rgb, width, height, threshold, mask);
  }
}

namespace
{
/// The components (4-connected) of the non-zero pixels of `image`, and
/// whether each reaches the image border.
int Components(const cv::Mat& image, cv::Mat& regions, std::vector<unsigned char>& border)
{
  cv::Mat stats, centroids;
  const int count = cv::connectedComponentsWithStats(image, regions, stats, centroids, 4);
  border.assign(count, 0);
  for (int r = 1; r < count; ++r)
  {
    const int left = stats.at<int>(r, cv::CC_STAT_LEFT);
    const int top = stats.at<int>(r, cv::CC_STAT_TOP);
    border[r] = left == 0 || top == 0 || left + stats.at<int>(r, cv::CC_STAT_WIDTH) == image.cols ||
      top + stats.at<int>(r, cv::CC_STAT_HEIGHT) == image.rows;
  }
  return count;
}
}

void FillObjectHoles(const unsigned char* rgb,
  int width,
  int height,
  double threshold,
  unsigned char* mask)
{
  // Measured on the 47 views of the templeRing at threshold 60: its holes
  // between the columns show the black backdrop (a fifth or more of their
  // pixels darker than 10) or the dark cloth behind it (half or more darker
  // than 20); its grooves, flutes and shadowed recesses (up to 2 250 pixels
  // each) have neither. The pediment's grooves open onto the backdrop
  // through gaps of a few pixels (640 x 480 views): a closing of a disc of
  // a 120th of the image seals those before the outside is found.
  constexpr double DarkLevel = 1.0 / 6.0; // of the threshold
  constexpr double DarkShare = 0.2;       // of the hole's pixels
  constexpr double DimLevel = 1.0 / 3.0;
  constexpr double DimShare = 0.5;
  const int seal = std::max(1, static_cast<int>(std::lround(std::min(width, height) / 120.0)));
  cv::Mat object(height, width, CV_8UC1, mask);
  const cv::Mat disc = cv::getStructuringElement(
    cv::MORPH_ELLIPSE, cv::Size(2 * seal + 1, 2 * seal + 1), cv::Point(seal, seal));
  cv::Mat sealed, outside, regions;
  cv::morphologyEx(object, sealed, cv::MORPH_CLOSE, disc);
  cv::compare(sealed, 0, outside, cv::CMP_EQ);
  std::vector<unsigned char> border;
  Components(outside, regions, border);
  const long pixels = static_cast<long>(width) * height;
  // The holes: background pixels that the sealed outside does not reach.
  cv::Mat holes(height, width, CV_8UC1);
  unsigned char* hole = holes.ptr<unsigned char>();
  const int* region = regions.ptr<int>();
  for (long p = 0; p < pixels; ++p)
  {
    hole[p] = !mask[p] && !border[region[p]] ? 1 : 0;
  }
  const int count = Components(holes, regions, border);
  std::vector<long> area(count, 0), dark(count, 0), dim(count, 0);
  // On the sum of R, G and B, as ObjectMask thresholds their mean.
  const double darkSum = 3.0 * DarkLevel * threshold;
  const double dimSum = 3.0 * DimLevel * threshold;
  for (long p = 0; p < pixels; ++p)
  {
    const int sum = rgb[3 * p] + rgb[3 * p + 1] + rgb[3 * p + 2];
    ++area[region[p]];
    dark[region[p]] += sum <= darkSum ? 1 : 0;
    dim[region[p]] += sum <= dimSum ? 1 : 0;
  }
  for (long p = 0; p < pixels; ++p)
  {
    const int r = region[p];
    const bool backdrop = dark[r] >= DarkShare * area[r] || dim[r] >= DimShare * area[r];
    mask[p] = mask[p] || (r > 0 && !border[r] && !backdrop) ? 1 : 0;
  }
}

void DistanceToMask(const unsigned char* mask, int width, int height, std::vector<float>& distance)
{
  distance.resize(static_cast<size_t>(width) * height);
  const cv::Mat source(height, width, CV_8UC1, const_cast<unsigned char*>(mask));
  cv::Mat outside;
  cv::compare(source, 0, outside, cv::CMP_EQ);
  cv::Mat result(height, width, CV_32FC1, distance.data());
  cv::distanceTransform(outside, result, cv::DIST_L2, cv::DIST_MASK_PRECISE);
}

double EstimateNoise(const std::vector<unsigned char>& grey, int width, int height)
{
  if (width < 3 || height < 3)
  {
    return -1.0;
  }
  const cv::Mat image(height, width, CV_8UC1, const_cast<unsigned char*>(grey.data()));
  const cv::Mat kernel = (cv::Mat_<float>(3, 3) << 1, -2, 1, -2, 4, -2, 1, -2, 1);
  cv::Mat response;
  cv::filter2D(image, response, CV_32F, kernel);
  std::vector<float> values;
  for (int y = 1; y + 1 < height; ++y)
  {
    for (int x = 1; x + 1 < width; ++x)
    {
      // Clipped pixels (black background, saturation) carry no noise.
      bool clipped = false;
      for (int dy = -1; dy <= 1 && !clipped; ++dy)
      {
        for (int dx = -1; dx <= 1 && !clipped; ++dx)
        {
          const unsigned char v = grey[(y + dy) * width + x + dx];
          clipped = v < 4 || v > 251;
        }
      }
      if (!clipped)
      {
        values.push_back(std::abs(response.at<float>(y, x)));
      }
    }
  }
  if (values.empty())
  {
    return -1.0;
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2] / (0.6745 * 6.0);
}

} // namespace segmentation
} // namespace lfd
