#include "vtkProjectorCalibration.h"

#include "lfdCalibrationImages.h"

#include "vtkCameraRig.h"
#include "vtkCharucoBoard.h"
#include "vtkDoubleArray.h"
#include "vtkGrayCodePattern.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/structured_light.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkProjectorCalibration);
vtkCxxSetObjectMacro(vtkProjectorCalibration, Board, vtkCharucoBoard);

namespace
{
/// Poses a calibration of the projector's intrinsics needs.
constexpr int MinimumPoses = 3;
}

struct vtkProjectorCalibration::Internals
{
  struct Pose
  {
    std::vector<vtkSmartPointer<vtkImageData>> Images;
    // Corners decoded at this pose: board positions, camera and projector pixels.
    std::vector<cv::Point3f> Board;
    std::vector<cv::Point2f> Camera;
    std::vector<cv::Point2f> Projector;
    double Rms = 0.0;
  };
  std::vector<Pose> Poses;
  int ImageWidth = 0;
  int ImageHeight = 0;
};

//------------------------------------------------------------------------------
vtkProjectorCalibration::vtkProjectorCalibration()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkProjectorCalibration::~vtkProjectorCalibration()
{
  this->SetBoard(nullptr);
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::SetCamera(const double K[9], const double distortion[5])
{
  std::copy(K, K + 9, this->CameraK);
  std::copy(distortion, distortion + 5, this->CameraDistortion);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::SetCameraPose(const double R[9], const double t[3])
{
  std::copy(R, R + 9, this->CameraR);
  std::copy(t, t + 3, this->CameraT);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::SetNumberOfPoses(int poses)
{
  this->Internal->Poses.assign(static_cast<size_t>(std::max(0, poses)), Internals::Pose());
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkProjectorCalibration::GetNumberOfPoses() const
{
  return static_cast<int>(this->Internal->Poses.size());
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::SetImage(int pose, int pattern, vtkImageData* image)
{
  if (pose < 0 || pose >= this->GetNumberOfPoses() || pattern < 0)
  {
    vtkErrorMacro("projector calibration: no pose " << pose << " or pattern " << pattern
                                                    << " (SetNumberOfPoses first)");
    return;
  }
  auto& images = this->Internal->Poses[pose].Images;
  if (static_cast<int>(images.size()) <= pattern)
  {
    images.resize(pattern + 1);
  }
  images[pattern] = image;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkProjectorCalibration::DecodePose(int index)
{
  Internals::Pose& pose = this->Internal->Poses[index];
  vtkNew<vtkGrayCodePattern> sequence;
  sequence->SetProjectorSize(this->ProjectorSize);
  const int patterns = sequence->GetNumberOfPatterns();
  const std::string where = "pose " + std::to_string(index);
  std::vector<cv::Mat> grey(patterns);
  for (int i = 0; i < patterns; ++i)
  {
    std::string problem;
    if (i >= static_cast<int>(pose.Images.size()) || !pose.Images[i])
    {
      vtkErrorMacro(<< where << ": Gray-code image " << i << " missing (a projector of "
                    << this->ProjectorSize[0] << " x " << this->ProjectorSize[1] << " needs "
                    << patterns << " images: " << sequence->GetNumberOfCodeImages()
                    << " codes, white, black)");
      return false;
    }
    if (!lfd::calibration::ToGrey(pose.Images[i], grey[i], problem))
    {
      vtkErrorMacro(<< where << ", image " << i << ": " << problem);
      return false;
    }
    if (index == 0 && i == 0)
    {
      this->Internal->ImageWidth = grey[i].cols;
      this->Internal->ImageHeight = grey[i].rows;
    }
    else if (grey[i].cols != this->Internal->ImageWidth ||
      grey[i].rows != this->Internal->ImageHeight)
    {
      vtkErrorMacro(<< where << ", image " << i << ": " << grey[i].cols << " x " << grey[i].rows
                    << " pixels, pose 0 image 0 is " << this->Internal->ImageWidth << " x "
                    << this->Internal->ImageHeight << " (one camera takes every image)");
      return false;
    }
  }
  const cv::Mat& white = grey[sequence->GetWhiteIndex()];
  const cv::Mat& black = grey[sequence->GetBlackIndex()];
  const std::vector<cv::Mat> codes(grey.begin(), grey.begin() + sequence->GetNumberOfCodeImages());

  // 1. The corners under the projector's white light.
  const auto board = lfd::calibration::MakeBoard(this->Board);
  const lfd::calibration::BoardCorners corners = lfd::calibration::DetectCorners(white, board);

  // 2-3. Decode a window around each corner; its local homography carries
  // the corner into the projector.
  auto decoder =
    cv::structured_light::GrayCodePattern::create(this->ProjectorSize[0], this->ProjectorSize[1]);
  decoder->setWhiteThreshold(static_cast<size_t>(this->CodeThreshold));
  const int radius = this->WindowRadius;
  // A corner on the board's black needs a quarter of its window decoded
  // (the white squares around it give that much).
  const int needed = (2 * radius + 1) * (2 * radius + 1) / 4;
  pose.Board.clear();
  pose.Camera.clear();
  pose.Projector.clear();
  for (size_t c = 0; c < corners.Ids.size(); ++c)
  {
    const cv::Point2f corner = corners.Pixels[c];
    const int cx = static_cast<int>(std::lround(corner.x));
    const int cy = static_cast<int>(std::lround(corner.y));
    std::vector<cv::Point2f> cameraPixels;
    std::vector<cv::Point2f> projectorPixels;
    for (int y = std::max(0, cy - radius); y <= std::min(white.rows - 1, cy + radius); ++y)
    {
      for (int x = std::max(0, cx - radius); x <= std::min(white.cols - 1, cx + radius); ++x)
      {
        if (white.at<unsigned char>(y, x) - black.at<unsigned char>(y, x) <=
          this->ContrastThreshold)
        {
          continue;
        }
        cv::Point projected;
        // getProjPixel returns true when the pixel cannot be decoded.
        if (decoder->getProjPixel(codes, x, y, projected))
        {
          continue;
        }
        cameraPixels.emplace_back(static_cast<float>(x), static_cast<float>(y));
        projectorPixels.emplace_back(
          static_cast<float>(projected.x), static_cast<float>(projected.y));
      }
    }
    if (static_cast<int>(cameraPixels.size()) < needed)
    {
      continue; // the corner is in a shadow or off the projector's image
    }
    const cv::Mat H = cv::findHomography(cameraPixels, projectorPixels, cv::RANSAC, 1.5);
    if (H.empty())
    {
      continue;
    }
    std::vector<cv::Point2f> mapped;
    cv::perspectiveTransform(std::vector<cv::Point2f>{ corner }, mapped, H);
    pose.Board.push_back(board->chessboardCorners[corners.Ids[c]]);
    pose.Camera.push_back(corner);
    pose.Projector.push_back(mapped[0]);
  }
  if (static_cast<int>(pose.Board.size()) < this->MinimumCorners)
  {
    vtkErrorMacro(<< where << ": " << corners.Ids.size() << " ChArUco corners found, "
                  << pose.Board.size() << " of them decoded in the projector, at least "
                  << this->MinimumCorners
                  << " needed (is the board in view and lit by the whole sequence?)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkProjectorCalibration::Calibrate()
{
  if (!this->Board)
  {
    vtkErrorMacro("projector calibration: no board set");
    return false;
  }
  const std::string boardProblem = this->Board->Check();
  if (!boardProblem.empty())
  {
    vtkErrorMacro("ChArUco board: " << boardProblem);
    return false;
  }
  if (this->ProjectorSize[0] < 2 || this->ProjectorSize[1] < 2)
  {
    vtkErrorMacro("projector calibration: projector size "
      << this->ProjectorSize[0] << " x " << this->ProjectorSize[1] << " is below 2 x 2");
    return false;
  }
  if (!(this->CameraK[0] > 0.0 && this->CameraK[4] > 0.0))
  {
    vtkErrorMacro("projector calibration: the camera's intrinsics need fx, fy > 0");
    return false;
  }
  auto& poses = this->Internal->Poses;
  if (static_cast<int>(poses.size()) < MinimumPoses)
  {
    vtkErrorMacro("projector calibration: " << poses.size() << " board poses, at least "
                                            << MinimumPoses << " needed");
    return false;
  }
  for (int i = 0; i < static_cast<int>(poses.size()); ++i)
  {
    if (!this->DecodePose(i))
    {
      return false;
    }
  }

  // 4. The projector as an inverse camera: planar views of the
  // board, the first estimate of its intrinsics.
  std::vector<std::vector<cv::Point3f>> boardPoints;
  std::vector<std::vector<cv::Point2f>> projectorPixels;
  for (const auto& pose : poses)
  {
    boardPoints.push_back(pose.Board);
    projectorPixels.push_back(pose.Projector);
  }
  const cv::Size projectorSize(this->ProjectorSize[0], this->ProjectorSize[1]);
  const int flags = lfd::calibration::DistortionFlags(this->DistortionModel);
  cv::Mat projectorK;
  cv::Mat projectorDistortion;
  std::vector<cv::Mat> rvecs;
  std::vector<cv::Mat> tvecs;
  cv::calibrateCamera(boardPoints,
    projectorPixels,
    projectorSize,
    projectorK,
    projectorDistortion,
    rvecs,
    tvecs,
    flags);

  // 5. The projector relative to the camera. Moreno and Taubin calibrate the
  // stereo pair with both intrinsics fixed, which keeps the
  // inverse camera's focal length, poorly fixed by a few planar views
  // (0.2 % off, 1.2 mm of projector position on the synthetic test).
  // Instead every corner is placed in the camera's frame through the board
  // poses the calibrated camera sees, and the projector's intrinsics and
  // pose are refined together against that non-planar set, from step 4's
  // intrinsics (0.04 %, 0.2 mm on the same images).
  const cv::Mat cameraK = lfd::calibration::MatrixFromArray(this->CameraK, 3, 3);
  const cv::Mat cameraDistortion = lfd::calibration::MatrixFromArray(this->CameraDistortion, 1, 5);
  std::vector<cv::Point3f> inCamera;
  std::vector<cv::Point2f> seen;
  std::vector<size_t> first;
  for (const auto& pose : poses)
  {
    cv::Mat rvec;
    cv::Mat tvec;
    cv::solvePnP(pose.Board, pose.Camera, cameraK, cameraDistortion, rvec, tvec);
    cv::Mat rotation;
    cv::Rodrigues(rvec, rotation);
    first.push_back(inCamera.size());
    for (size_t c = 0; c < pose.Board.size(); ++c)
    {
      const cv::Mat X = rotation * cv::Mat(cv::Point3d(pose.Board[c])) + tvec;
      inCamera.emplace_back(X);
      seen.push_back(pose.Projector[c]);
    }
  }
  first.push_back(inCamera.size());
  cv::calibrateCamera(std::vector<std::vector<cv::Point3f>>{ inCamera },
    std::vector<std::vector<cv::Point2f>>{ seen },
    projectorSize,
    projectorK,
    projectorDistortion,
    rvecs,
    tvecs,
    flags | cv::CALIB_USE_INTRINSIC_GUESS);

  // Reprojection errors of the final projector, per pose and overall.
  double sum = 0.0;
  for (size_t i = 0; i < poses.size(); ++i)
  {
    const std::vector<cv::Point3f> points(
      inCamera.begin() + first[i], inCamera.begin() + first[i + 1]);
    poses[i].Rms = lfd::calibration::ReprojectionRms(
      points, poses[i].Projector, rvecs[0], tvecs[0], projectorK, projectorDistortion);
    sum += poses[i].Rms * poses[i].Rms * points.size();
  }
  this->Rms = std::sqrt(sum / static_cast<double>(inCamera.size()));

  // World to projector = (camera to projector) o (world to camera).
  cv::Mat R;
  cv::Rodrigues(rvecs[0], R);
  const cv::Mat cameraR = lfd::calibration::MatrixFromArray(this->CameraR, 3, 3);
  const cv::Mat cameraT = lfd::calibration::MatrixFromArray(this->CameraT, 3, 1);
  lfd::calibration::ArrayFromMatrix(R * cameraR, this->ProjectorR);
  lfd::calibration::ArrayFromMatrix(R * cameraT + tvecs[0], this->ProjectorT);
  lfd::calibration::ArrayFromMatrix(projectorK, this->ProjectorK);
  lfd::calibration::DistortionFromMatrix(projectorDistortion, this->ProjectorDistortion);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetProjectorIntrinsics(double K[9]) const
{
  std::copy(this->ProjectorK, this->ProjectorK + 9, K);
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetProjectorDistortion(double coefficients[5]) const
{
  std::copy(this->ProjectorDistortion, this->ProjectorDistortion + 5, coefficients);
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetProjectorRotation(double R[9]) const
{
  std::copy(this->ProjectorR, this->ProjectorR + 9, R);
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetProjectorTranslation(double t[3]) const
{
  std::copy(this->ProjectorT, this->ProjectorT + 3, t);
}

//------------------------------------------------------------------------------
double vtkProjectorCalibration::GetPoseRms(int pose) const
{
  return pose >= 0 && pose < this->GetNumberOfPoses() ? this->Internal->Poses[pose].Rms : 0.0;
}

//------------------------------------------------------------------------------
int vtkProjectorCalibration::GetNumberOfCorners(int pose) const
{
  return pose >= 0 && pose < this->GetNumberOfPoses()
    ? static_cast<int>(this->Internal->Poses[pose].Board.size())
    : 0;
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetCorners(int pose,
  vtkDoubleArray* boardPositions,
  vtkDoubleArray* cameraPixels,
  vtkDoubleArray* projectorPixels) const
{
  boardPositions->SetNumberOfComponents(3);
  cameraPixels->SetNumberOfComponents(2);
  projectorPixels->SetNumberOfComponents(2);
  const int corners = this->GetNumberOfCorners(pose);
  boardPositions->SetNumberOfTuples(corners);
  cameraPixels->SetNumberOfTuples(corners);
  projectorPixels->SetNumberOfTuples(corners);
  for (int c = 0; c < corners; ++c)
  {
    const Internals::Pose& data = this->Internal->Poses[pose];
    boardPositions->SetTuple3(c, data.Board[c].x, data.Board[c].y, data.Board[c].z);
    cameraPixels->SetTuple2(c, data.Camera[c].x, data.Camera[c].y);
    projectorPixels->SetTuple2(c, data.Projector[c].x, data.Projector[c].y);
  }
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::GetProjector(vtkCameraRig* projector) const
{
  projector->SetNumberOfViews(1);
  projector->SetImageSize(this->ProjectorSize[0], this->ProjectorSize[1]);
  projector->SetView(0, this->ProjectorK, this->ProjectorR, this->ProjectorT);
  projector->SetDistortion(0, this->ProjectorDistortion);
}

//------------------------------------------------------------------------------
void vtkProjectorCalibration::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Board: " << this->Board << "\n";
  os << indent << "ProjectorSize: " << this->ProjectorSize[0] << " x " << this->ProjectorSize[1]
     << "\n";
  os << indent << "Poses: " << this->GetNumberOfPoses() << "\n";
  os << indent << "WindowRadius: " << this->WindowRadius << "\n";
  os << indent << "ContrastThreshold: " << this->ContrastThreshold << "\n";
  os << indent << "CodeThreshold: " << this->CodeThreshold << "\n";
  os << indent << "MinimumCorners: " << this->MinimumCorners << "\n";
  os << indent << "DistortionModel: " << this->DistortionModel << "\n";
  os << indent << "Rms: " << this->Rms << "\n";
}
