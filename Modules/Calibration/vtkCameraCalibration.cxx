#include "vtkCameraCalibration.h"

#include "lfdCalibrationImages.h"
#include "lfdFileUtilities.h"
#include "lfdJsonFields.h"
#include "lfdPinholeCamera.h"

#include "vtkCameraRig.h"
#include "vtkCharucoBoard.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCameraCalibration);
vtkCxxSetObjectMacro(vtkCameraCalibration, Board, vtkCharucoBoard);

namespace
{
/// Views a calibration of the intrinsics needs: two fix a planar target's
/// focal lengths and principal point only without noise.
constexpr int MinimumIntrinsicViews = 3;
}

struct vtkCameraCalibration::Internals
{
  struct View
  {
    vtkSmartPointer<vtkImageData> Image;
    std::string Name;
    lfd::calibration::BoardCorners Corners;
    double Rms = 0.0;
    double R[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    double t[3] = { 0, 0, 0 };
  };
  std::vector<View> Views;

  /// "image 3 (file.png)" or "image 3".
  std::string Describe(int i) const
  {
    const std::string& name = this->Views[i].Name;
    return "image " + std::to_string(i) + (name.empty() ? "" : " (" + name + ")");
  }
};

//------------------------------------------------------------------------------
vtkCameraCalibration::vtkCameraCalibration()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCameraCalibration::~vtkCameraCalibration()
{
  this->SetBoard(nullptr);
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::AddImage(vtkImageData* image, const char* name)
{
  Internals::View view;
  view.Image = image;
  view.Name = name ? name : "";
  this->Internal->Views.push_back(std::move(view));
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::RemoveAllImages()
{
  this->Internal->Views.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraCalibration::GetNumberOfImages() const
{
  return static_cast<int>(this->Internal->Views.size());
}

//------------------------------------------------------------------------------
const char* vtkCameraCalibration::GetImageName(int i) const
{
  return i >= 0 && i < this->GetNumberOfImages() ? this->Internal->Views[i].Name.c_str() : "";
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::SetIntrinsics(const double K[9])
{
  std::copy(K, K + 9, this->Intrinsics);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::GetIntrinsics(double K[9]) const
{
  std::copy(this->Intrinsics, this->Intrinsics + 9, K);
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::SetDistortion(const double coefficients[5])
{
  std::copy(coefficients, coefficients + 5, this->Distortion);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::GetDistortion(double coefficients[5]) const
{
  std::copy(this->Distortion, this->Distortion + 5, coefficients);
}

//------------------------------------------------------------------------------
bool vtkCameraCalibration::DetectBoards()
{
  if (!this->Board)
  {
    vtkErrorMacro("camera calibration: no board set");
    return false;
  }
  const std::string boardProblem = this->Board->Check();
  if (!boardProblem.empty())
  {
    vtkErrorMacro("ChArUco board: " << boardProblem);
    return false;
  }
  auto& views = this->Internal->Views;
  if (views.empty())
  {
    vtkErrorMacro("camera calibration: no images");
    return false;
  }
  const auto board = lfd::calibration::MakeBoard(this->Board);
  for (size_t i = 0; i < views.size(); ++i)
  {
    const int index = static_cast<int>(i);
    cv::Mat grey;
    std::string problem;
    if (!views[i].Image || !lfd::calibration::ToGrey(views[i].Image, grey, problem))
    {
      vtkErrorMacro(<< this->Internal->Describe(index) << ": "
                    << (problem.empty() ? std::string("missing") : problem));
      return false;
    }
    if (i == 0 && this->FixIntrinsics && this->ImageSize[0] > 0 &&
      (grey.cols != this->ImageSize[0] || grey.rows != this->ImageSize[1]))
    {
      vtkErrorMacro(<< this->Internal->Describe(index) << ": " << grey.cols << " x " << grey.rows
                    << " pixels, the fixed intrinsics are for " << this->ImageSize[0] << " x "
                    << this->ImageSize[1]);
      return false;
    }
    if (i == 0)
    {
      this->ImageSize[0] = grey.cols;
      this->ImageSize[1] = grey.rows;
    }
    else if (grey.cols != this->ImageSize[0] || grey.rows != this->ImageSize[1])
    {
      vtkErrorMacro(<< this->Internal->Describe(index) << ": " << grey.cols << " x " << grey.rows
                    << " pixels, " << this->Internal->Describe(0) << " is " << this->ImageSize[0]
                    << " x " << this->ImageSize[1] << " (one camera takes every image)");
      return false;
    }
    views[i].Corners = lfd::calibration::DetectCorners(grey, board);
    const int found = static_cast<int>(views[i].Corners.Ids.size());
    if (found < this->MinimumCorners)
    {
      vtkErrorMacro(<< this->Internal->Describe(index) << ": " << found
                    << " ChArUco corners found, at least " << this->MinimumCorners
                    << " needed (is the board in view, lit and in focus?)");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCameraCalibration::Calibrate()
{
  if (!this->DetectBoards())
  {
    return false;
  }
  auto& views = this->Internal->Views;
  const auto board = lfd::calibration::MakeBoard(this->Board);
  cv::Mat K = lfd::calibration::MatrixFromArray(this->Intrinsics, 3, 3);
  cv::Mat distortion = lfd::calibration::MatrixFromArray(this->Distortion, 1, 5);
  std::vector<cv::Mat> rvecs(views.size());
  std::vector<cv::Mat> tvecs(views.size());
  if (this->FixIntrinsics)
  {
    if (!(this->Intrinsics[0] > 0.0 && this->Intrinsics[4] > 0.0))
    {
      vtkErrorMacro("camera calibration: the fixed intrinsics need fx, fy > 0");
      return false;
    }
    for (size_t i = 0; i < views.size(); ++i)
    {
      cv::solvePnP(lfd::calibration::CornerPositions(board, views[i].Corners.Ids),
        views[i].Corners.Pixels,
        K,
        distortion,
        rvecs[i],
        tvecs[i]);
    }
  }
  else
  {
    if (static_cast<int>(views.size()) < MinimumIntrinsicViews)
    {
      vtkErrorMacro("camera calibration: " << views.size() << " images, at least "
                                           << MinimumIntrinsicViews
                                           << " (tilted differently) needed for the intrinsics");
      return false;
    }
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<std::vector<int>> ids;
    for (const auto& view : views)
    {
      corners.push_back(view.Corners.Pixels);
      ids.push_back(view.Corners.Ids);
    }
    cv::aruco::calibrateCameraCharuco(corners,
      ids,
      board,
      cv::Size(this->ImageSize[0], this->ImageSize[1]),
      K,
      distortion,
      rvecs,
      tvecs,
      lfd::calibration::DistortionFlags(this->DistortionModel));
    lfd::calibration::ArrayFromMatrix(K, this->Intrinsics);
    lfd::calibration::DistortionFromMatrix(distortion, this->Distortion);
  }

  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < views.size(); ++i)
  {
    const auto points = lfd::calibration::CornerPositions(board, views[i].Corners.Ids);
    views[i].Rms = lfd::calibration::ReprojectionRms(
      points, views[i].Corners.Pixels, rvecs[i], tvecs[i], K, distortion);
    sum += views[i].Rms * views[i].Rms * points.size();
    count += points.size();
    lfd::calibration::RotationFromVector(rvecs[i], views[i].R);
    lfd::calibration::ArrayFromMatrix(tvecs[i], views[i].t);
  }
  this->Rms = std::sqrt(sum / static_cast<double>(count));
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
double vtkCameraCalibration::GetViewRms(int i) const
{
  return i >= 0 && i < this->GetNumberOfImages() ? this->Internal->Views[i].Rms : 0.0;
}

//------------------------------------------------------------------------------
int vtkCameraCalibration::GetNumberOfCorners(int i) const
{
  return i >= 0 && i < this->GetNumberOfImages()
    ? static_cast<int>(this->Internal->Views[i].Corners.Ids.size())
    : 0;
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::GetViewRotation(int i, double R[9]) const
{
  const auto& view = this->Internal->Views.at(i);
  std::copy(view.R, view.R + 9, R);
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::GetViewTranslation(int i, double t[3]) const
{
  const auto& view = this->Internal->Views.at(i);
  std::copy(view.t, view.t + 3, t);
}

//------------------------------------------------------------------------------
bool vtkCameraCalibration::WriteCameraFile(const char* fileName)
{
  const std::string file = fileName ? fileName : "";
  const auto& views = this->Internal->Views;
  if (file.empty() || views.empty() || this->ImageSize[0] < 1)
  {
    vtkErrorMacro(<< (file.empty() ? std::string("camera file: no file name")
                                   : file + ": nothing calibrated to write (Calibrate first)"));
    return false;
  }
  lfd::io::Json document;
  document["format"] = "lfd-camera";
  document["version"] = 1;
  document["width"] = this->ImageSize[0];
  document["height"] = this->ImageSize[1];
  document["K"] = std::vector<double>(this->Intrinsics, this->Intrinsics + 9);
  document["distortion"] = std::vector<double>(this->Distortion, this->Distortion + 5);
  document["rms"] = this->Rms;
  if (this->Board)
  {
    document["board"] = { { "squares", { this->Board->GetSquaresX(), this->Board->GetSquaresY() } },
      { "square", this->Board->GetSquareLength() },
      { "marker", this->Board->GetMarkerLength() },
      { "dictionary", this->Board->GetDictionary() } };
  }
  lfd::io::Json list = lfd::io::Json::array();
  for (const auto& view : views)
  {
    list.push_back({ { "name", view.Name },
      { "corners", static_cast<int>(view.Corners.Ids.size()) },
      { "rms", view.Rms } });
  }
  document["views"] = list;
  std::string error;
  if (!lfd::io::WriteFileAtomically(file, document.dump(2) + "\n", error))
  {
    vtkErrorMacro(<< file << ": " << error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCameraCalibration::ReadCameraFile(const char* fileName)
{
  const std::string file = fileName ? fileName : "";
  lfd::io::Json document;
  std::string error;
  if (!lfd::io::ParseJsonFile(file, document, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  try
  {
    const std::string format =
      lfd::io::GetString(lfd::io::RequireMember(document, "", "format"), "format");
    if (format != "lfd-camera")
    {
      throw lfd::io::FieldError("format", "expected \"lfd-camera\", found \"" + format + "\"");
    }
    lfd::io::GetInteger(lfd::io::RequireMember(document, "", "version"), "version", 1, 1);
    const int width = static_cast<int>(
      lfd::io::GetInteger(lfd::io::RequireMember(document, "", "width"), "width", 1, 1048576));
    const int height = static_cast<int>(
      lfd::io::GetInteger(lfd::io::RequireMember(document, "", "height"), "height", 1, 1048576));
    const std::vector<double> K =
      lfd::io::GetNumbers(lfd::io::RequireMember(document, "", "K"), "K", 9);
    std::vector<double> distortion(5, 0.0);
    if (const lfd::io::Json* coefficients = lfd::io::FindMember(document, "", "distortion"))
    {
      distortion = lfd::io::GetNumbers(*coefficients, "distortion", 5);
    }
    // The checks every camera of a dataset passes (lfdPinholeCamera.h).
    const double R[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    const double t[3] = { 0, 0, 0 };
    std::string field;
    std::string problem;
    if (!lfd::CheckPinhole(K.data(), R, t, distortion.data(), width, height, field, problem))
    {
      throw lfd::io::FieldError(field, problem);
    }
    this->SetIntrinsics(K.data());
    this->SetDistortion(distortion.data());
    this->ImageSize[0] = width;
    this->ImageSize[1] = height;
  }
  catch (const lfd::io::FieldError& failure)
  {
    vtkErrorMacro(<< file << ": " << failure.what());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::GetRig(vtkCameraRig* rig) const
{
  const auto& views = this->Internal->Views;
  rig->SetNumberOfViews(static_cast<int>(views.size()));
  rig->SetImageSize(this->ImageSize[0], this->ImageSize[1]);
  for (size_t i = 0; i < views.size(); ++i)
  {
    const int index = static_cast<int>(i);
    rig->SetView(index, this->Intrinsics, views[i].R, views[i].t);
    rig->SetDistortion(index, this->Distortion);
    rig->SetViewName(index, views[i].Name.c_str());
  }
}

//------------------------------------------------------------------------------
void vtkCameraCalibration::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Board: " << this->Board << "\n";
  os << indent << "Images: " << this->GetNumberOfImages() << "\n";
  os << indent << "DistortionModel: " << this->DistortionModel << "\n";
  os << indent << "MinimumCorners: " << this->MinimumCorners << "\n";
  os << indent << "FixIntrinsics: " << this->FixIntrinsics << "\n";
  os << indent << "Intrinsics:";
  for (double value : this->Intrinsics)
  {
    os << " " << value;
  }
  os << "\n" << indent << "Distortion:";
  for (double value : this->Distortion)
  {
    os << " " << value;
  }
  os << "\n"
     << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "Rms: " << this->Rms << "\n";
}
