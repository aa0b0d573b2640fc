#include "lfdCalibrationImages.h"

#include "vtkCameraCalibration.h"
#include "vtkCharucoBoard.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace lfd
{
namespace calibration
{
namespace
{
const std::pair<const char*, int> Dictionaries[] = {
  { "DICT_4X4_50", cv::aruco::DICT_4X4_50 },
  { "DICT_4X4_100", cv::aruco::DICT_4X4_100 },
  { "DICT_4X4_250", cv::aruco::DICT_4X4_250 },
  { "DICT_4X4_1000", cv::aruco::DICT_4X4_1000 },
  { "DICT_5X5_50", cv::aruco::DICT_5X5_50 },
  { "DICT_5X5_100", cv::aruco::DICT_5X5_100 },
  { "DICT_5X5_250", cv::aruco::DICT_5X5_250 },
  { "DICT_5X5_1000", cv::aruco::DICT_5X5_1000 },
  { "DICT_6X6_50", cv::aruco::DICT_6X6_50 },
  { "DICT_6X6_100", cv::aruco::DICT_6X6_100 },
  { "DICT_6X6_250", cv::aruco::DICT_6X6_250 },
  { "DICT_6X6_1000", cv::aruco::DICT_6X6_1000 },
  { "DICT_7X7_50", cv::aruco::DICT_7X7_50 },
  { "DICT_7X7_100", cv::aruco::DICT_7X7_100 },
  { "DICT_7X7_250", cv::aruco::DICT_7X7_250 },
  { "DICT_7X7_1000", cv::aruco::DICT_7X7_1000 },
  { "DICT_ARUCO_ORIGINAL", cv::aruco::DICT_ARUCO_ORIGINAL },
};
}

int DictionaryId(const std::string& name)
{
  for (const auto& entry : Dictionaries)
  {
    if (name == entry.first)
    {
      return entry.second;
    }
  }
  return -1;
}

std::string CheckBoard(const vtkCharucoBoard* board)
{
  auto* description = const_cast<vtkCharucoBoard*>(board);
  const char* name = description->GetDictionary();
  const int id = DictionaryId(name ? name : "");
  if (id < 0)
  {
    return std::string("unknown marker dictionary '") + (name ? name : "") +
      "' (expected an OpenCV name such as DICT_5X5_100)";
  }
  if (!(description->GetMarkerLength() < description->GetSquareLength()))
  {
    return "the marker (" + std::to_string(description->GetMarkerLength()) +
      ") must be smaller than the square (" + std::to_string(description->GetSquareLength()) + ")";
  }
  // Half the squares hold a marker, each with its own code.
  const int markers = description->GetSquaresX() * description->GetSquaresY() / 2;
  const int codes = cv::aruco::getPredefinedDictionary(id)->bytesList.rows;
  if (markers > codes)
  {
    return "a board of " + std::to_string(description->GetSquaresX()) + " x " +
      std::to_string(description->GetSquaresY()) + " squares needs " + std::to_string(markers) +
      " markers, " + name + " holds " + std::to_string(codes);
  }
  return std::string();
}

cv::Ptr<cv::aruco::CharucoBoard> MakeBoard(const vtkCharucoBoard* board)
{
  auto* description = const_cast<vtkCharucoBoard*>(board);
  return cv::aruco::CharucoBoard::create(description->GetSquaresX(),
    description->GetSquaresY(),
    static_cast<float>(description->GetSquareLength()),
    static_cast<float>(description->GetMarkerLength()),
    cv::aruco::getPredefinedDictionary(DictionaryId(description->GetDictionary())));
}

bool ToGrey(vtkImageData* image, cv::Mat& grey, std::string& problem)
{
  int dimensions[3];
  image->GetDimensions(dimensions);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (dimensions[0] < 1 || dimensions[1] < 1 || !scalars ||
    scalars->GetNumberOfTuples() < static_cast<vtkIdType>(dimensions[0]) * dimensions[1])
  {
    problem = "expected an 8-bit grey or colour image";
    return false;
  }
  const int width = dimensions[0];
  const int height = dimensions[1];
  const int components = scalars->GetNumberOfComponents();
  const cv::Mat stored(height, width, CV_8UC(components), scalars->GetPointer(0));
  cv::Mat flipped;
  cv::flip(stored, flipped, 0);
  if (components == 1)
  {
    grey = flipped;
  }
  else if (components == 3 || components == 4)
  {
    cv::cvtColor(flipped, grey, components == 3 ? cv::COLOR_RGB2GRAY : cv::COLOR_RGBA2GRAY);
  }
  else
  {
    problem = "expected 1, 3 or 4 channels, found " + std::to_string(components);
    return false;
  }
  return true;
}

void FromGrey(const cv::Mat& grey, vtkImageData* image)
{
  image->SetDimensions(grey.cols, grey.rows, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  cv::Mat stored(grey.rows, grey.cols, CV_8UC1, scalars->GetPointer(0));
  cv::flip(grey, stored, 0);
}

BoardCorners DetectCorners(const cv::Mat& grey, const cv::Ptr<cv::aruco::CharucoBoard>& board)
{
  std::vector<std::vector<cv::Point2f>> markerCorners;
  std::vector<int> markerIds;
  cv::aruco::detectMarkers(grey, board->dictionary, markerCorners, markerIds);
  BoardCorners corners;
  if (markerIds.empty())
  {
    return corners;
  }
  cv::aruco::interpolateCornersCharuco(
    markerCorners, markerIds, grey, board, corners.Pixels, corners.Ids);
  // OpenCV 4.6 refines the interpolated corners in a window that reaches
  // the markers, which biases them by up to half a pixel (measured on
  // synthetic images, vtkCalibrationImageSource). Refine them again within
  // the chessboard squares only: a window of an eighth of a square (the
  // markers start a sixth of a square from the corner on a 30/22 board),
  // the square's size in pixels taken from the markers' mean side.
  double side = 0.0;
  for (const auto& marker : markerCorners)
  {
    for (int k = 0; k < 4; ++k)
    {
      side += cv::norm(marker[k] - marker[(k + 1) % 4]);
    }
  }
  side /= 4.0 * markerCorners.size();
  const double squarePixels = side * board->getSquareLength() / board->getMarkerLength();
  const int half = std::clamp(static_cast<int>(std::lround(squarePixels / 12.0)), 2, 12);
  if (!corners.Pixels.empty())
  {
    cv::cornerSubPix(grey,
      corners.Pixels,
      cv::Size(half, half),
      cv::Size(-1, -1),
      cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4));
  }
  return corners;
}

std::vector<cv::Point3f> CornerPositions(const cv::Ptr<cv::aruco::CharucoBoard>& board,
  const std::vector<int>& ids)
{
  std::vector<cv::Point3f> points;
  points.reserve(ids.size());
  for (int id : ids)
  {
    points.push_back(board->chessboardCorners[id]);
  }
  return points;
}

double ReprojectionRms(const std::vector<cv::Point3f>& points,
  const std::vector<cv::Point2f>& pixels,
  const cv::Mat& rvec,
  const cv::Mat& tvec,
  const cv::Mat& K,
  const cv::Mat& distortion)
{
  if (points.empty())
  {
    return 0.0;
  }
  std::vector<cv::Point2f> projected;
  cv::projectPoints(points, rvec, tvec, K, distortion, projected);
  double sum = 0.0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const cv::Point2f d = projected[i] - pixels[i];
    sum += d.dot(d);
  }
  return std::sqrt(sum / static_cast<double>(points.size()));
}

cv::Mat MatrixFromArray(const double* values, int rows, int cols)
{
  cv::Mat matrix(rows, cols, CV_64F);
  for (int i = 0; i < rows * cols; ++i)
  {
    matrix.at<double>(i / cols, i % cols) = values[i];
  }
  return matrix;
}

void ArrayFromMatrix(const cv::Mat& matrix, double* values)
{
  cv::Mat doubles;
  matrix.convertTo(doubles, CV_64F);
  for (int i = 0; i < doubles.rows * doubles.cols; ++i)
  {
    values[i] = doubles.at<double>(i / doubles.cols, i % doubles.cols);
  }
}

void DistortionFromMatrix(const cv::Mat& distortion, double coefficients[5])
{
  cv::Mat doubles;
  distortion.convertTo(doubles, CV_64F);
  const int count = static_cast<int>(doubles.total());
  for (int i = 0; i < 5; ++i)
  {
    coefficients[i] = i < count ? doubles.at<double>(i) : 0.0;
  }
}

int DistortionFlags(int model)
{
  switch (model)
  {
    case vtkCameraCalibration::NO_DISTORTION:
      return cv::CALIB_FIX_K1 | cv::CALIB_FIX_K2 | cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST;
    case vtkCameraCalibration::RADIAL:
      return cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST;
    case vtkCameraCalibration::RADIAL_TANGENTIAL:
      return cv::CALIB_FIX_K3;
    default:
      return 0;
  }
}

void RotationFromVector(const cv::Mat& rvec, double R[9])
{
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  ArrayFromMatrix(rotation, R);
}
}
}
