/**
 * @file   lfdCalibrationImages.h
 * @brief  What the calibration classes share behind their VTK interfaces:
 *         images as OpenCV matrices, the OpenCV board of a vtkCharucoBoard,
 *         corner detection, matrix conversions and reprojection errors.
 *
 * OpenCV is used behind this interface only, so no wrapped header sees it.
 */
#ifndef lfdCalibrationImages_h
#define lfdCalibrationImages_h

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

class vtkCharucoBoard;
class vtkImageData;

namespace lfd
{
namespace calibration
{

/// The predefined dictionary called `name` ("DICT_5X5_100"), or -1.
int DictionaryId(const std::string& name);

/// "" when OpenCV can make `board`, else the reason.
std::string CheckBoard(const vtkCharucoBoard* board);

/// OpenCV's board of a description that CheckBoard() accepted.
cv::Ptr<cv::aruco::CharucoBoard> MakeBoard(const vtkCharucoBoard* board);

/**
 * `image` as an 8-bit grey matrix with the top image row first (VTK stores
 * the bottom row first): one channel is taken as it is, RGB(A) as its luma.
 * Returns false with `problem` for an empty image or one whose scalars are
 * not unsigned char.
 */
bool ToGrey(vtkImageData* image, cv::Mat& grey, std::string& problem);

/// An 8-bit grey matrix (top row first) into `image` (bottom row first).
void FromGrey(const cv::Mat& grey, vtkImageData* image);

/// The ChArUco corners found in one image: ids and pixel positions.
struct BoardCorners
{
  std::vector<int> Ids;
  std::vector<cv::Point2f> Pixels;
};

/**
 * Detects the board's markers in `grey`, then interpolates its chessboard
 * corners from them (local homographies, refined to sub-pixel).
 */
BoardCorners DetectCorners(const cv::Mat& grey, const cv::Ptr<cv::aruco::CharucoBoard>& board);

/// Board-frame positions of the corners `ids`.
std::vector<cv::Point3f> CornerPositions(const cv::Ptr<cv::aruco::CharucoBoard>& board,
  const std::vector<int>& ids);

/// Root mean square distance, in pixels, between `pixels` and the
/// projections of `points` through the pose and the camera.
double ReprojectionRms(const std::vector<cv::Point3f>& points,
  const std::vector<cv::Point2f>& pixels,
  const cv::Mat& rvec,
  const cv::Mat& tvec,
  const cv::Mat& K,
  const cv::Mat& distortion);

///@{
/// Conversions between row-major arrays and OpenCV matrices (CV_64F).
cv::Mat MatrixFromArray(const double* values, int rows, int cols);
void ArrayFromMatrix(const cv::Mat& matrix, double* values);
///@}

/// The five coefficients (k1, k2, p1, p2, k3) of an OpenCV distortion vector
/// of any length (missing ones are 0).
void DistortionFromMatrix(const cv::Mat& distortion, double coefficients[5]);

/// The `calibrateCamera` flags that estimate the coefficients of a
/// vtkCameraCalibration::DistortionModels value only.
int DistortionFlags(int model);

/// Row-major rotation matrix of a Rodrigues vector.
void RotationFromVector(const cv::Mat& rvec, double R[9]);
}
}

#endif
