/**
 * @class   vtkProjectorCalibration
 * @brief   a projector's intrinsics and pose from Gray-code captures of a ChArUco board
 *
 * vtkProjectorCalibration follows Moreno and Taubin, "Simple, Accurate, and
 * Robust Projector-Camera Calibration" (3DIMPVT 2012). A calibrated camera
 * (its intrinsics and distortion, e.g. from vtkCameraCalibration) sees the
 * board at a few poses; at each pose the projector shows the
 * vtkGrayCodePattern sequence and the camera captures one image per
 * pattern. For each pose:
 *
 * 1. the board's corners are found in the image under white light;
 * 2. every camera pixel the projector lights (white minus black above
 *    ContrastThreshold) is decoded to the projector pixel that lit it
 *    (pattern against inverse, CodeThreshold);
 * 3. around each corner, a local homography from the decoded camera pixels
 *    of a window (2 WindowRadius + 1 pixels wide) to their projector pixels
 *    (RANSAC, then least squares on the inliers) carries the corner's
 *    sub-pixel camera position into the projector: the corner as the
 *    projector "sees" it.
 *
 * The projector is then calibrated as an inverse camera from the board
 * corners and their projector pixels (`calibrateCamera`). For its
 * pose relative to the camera the paper calibrates the stereo pair with
 * both intrinsics fixed; here every corner is instead placed in
 * the camera's frame through the board poses the calibrated camera sees,
 * and the projector's intrinsics and pose are refined together against
 * that non-planar set (one inverse-camera view), which also corrects the
 * focal length a few planar views leave uncertain (on the synthetic test:
 * projector position 0.2 mm off instead of 1.2 mm). With the camera's world
 * pose (SetCameraPose) the projector's pose is given in the world.
 *
 * Refusals are one error each naming the pose and image: too few poses (3),
 * a missing image, images of different sizes, too few corners found or
 * decoded (MinimumCorners).
 *
 * @sa vtkGrayCodePattern vtkCameraCalibration vtkCharucoBoard
 */
#ifndef vtkProjectorCalibration_h
#define vtkProjectorCalibration_h

#include "lfdCalibrationModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkCameraRig;
class vtkCharucoBoard;
class vtkDoubleArray;
class vtkImageData;

class LFDCALIBRATION_EXPORT vtkProjectorCalibration : public vtkObject
{
public:
  static vtkProjectorCalibration* New();
  vtkTypeMacro(vtkProjectorCalibration, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The board (required).
   */
  virtual void SetBoard(vtkCharucoBoard* board);
  vtkGetObjectMacro(Board, vtkCharucoBoard);
  ///@}

  ///@{
  /**
   * The projector's image size in pixels (the patterns'); default 1024 x 768.
   */
  vtkSetVector2Macro(ProjectorSize, int);
  vtkGetVector2Macro(ProjectorSize, int);
  ///@}

  /**
   * The calibrated camera that took the images: intrinsics K (row-major),
   * distortion (k1, k2, p1, p2, k3) and world-to-camera pose R, t (default
   * identity: the projector's pose is then given in the camera's frame).
   */
  void SetCamera(const double K[9], const double distortion[5]);
  void SetCameraPose(const double R[9], const double t[3]);

  ///@{
  /**
   * The captures: board poses, each with one image per vtkGrayCodePattern
   * pattern of the projector's size (8-bit, rows stored the VTK way),
   * `pattern` being the pattern's index. SetNumberOfPoses() clears them.
   */
  void SetNumberOfPoses(int poses);
  int GetNumberOfPoses() const;
  void SetImage(int pose, int pattern, vtkImageData* image);
  ///@}

  ///@{
  /**
   * Half the side of the window of a local homography, camera pixels;
   * default 20 (Moreno and Taubin use 47 x 47 on 1600 x 1200 images).
   */
  vtkSetClampMacro(WindowRadius, int, 2, 200);
  vtkGetMacro(WindowRadius, int);
  ///@}

  ///@{
  /**
   * Decoding thresholds in grey levels: white minus black (the projector
   * lights the pixel), default 10; a code against its inverse, default 5.
   */
  vtkSetClampMacro(ContrastThreshold, int, 0, 255);
  vtkGetMacro(ContrastThreshold, int);
  vtkSetClampMacro(CodeThreshold, int, 0, 255);
  vtkGetMacro(CodeThreshold, int);
  ///@}

  ///@{
  /**
   * Fewest corners a pose must give (found and decoded); default 8.
   */
  vtkSetClampMacro(MinimumCorners, int, 4, 100000);
  vtkGetMacro(MinimumCorners, int);
  ///@}

  ///@{
  /**
   * The projector's distortion model, as vtkCameraCalibration's
   * (NO_DISTORTION, RADIAL, RADIAL_TANGENTIAL, FULL); default RADIAL.
   */
  vtkSetClampMacro(DistortionModel, int, 0, 3);
  vtkGetMacro(DistortionModel, int);
  ///@}

  /**
   * Decodes every pose and calibrates. Returns false, with one error naming
   * the pose and image at fault, when the input is refused.
   */
  bool Calibrate();

  ///@{
  /**
   * Results: the projector's intrinsics, distortion and world-to-projector
   * pose (R row-major, t), its reprojection RMS (pixels) overall and per
   * pose, and the corners each pose gave.
   */
  void GetProjectorIntrinsics(double K[9]) const;
  void GetProjectorDistortion(double coefficients[5]) const;
  void GetProjectorRotation(double R[9]) const;
  void GetProjectorTranslation(double t[3]) const;
  vtkGetMacro(Rms, double);
  double GetPoseRms(int pose) const;
  int GetNumberOfCorners(int pose) const;
  ///@}

  /**
   * The corners pose `pose` gave, after Calibrate(): their board-frame
   * positions (3 components), camera pixels and projector pixels (2
   * components each, OpenCV pixel coordinates), one tuple per corner; for
   * showing the decoding and for checking it.
   */
  void GetCorners(int pose,
    vtkDoubleArray* boardPositions,
    vtkDoubleArray* cameraPixels,
    vtkDoubleArray* projectorPixels) const;

  /**
   * The projector as a rig of one view (K, R, t, distortion, image size),
   * the form vtkLightField::SetProjectors() holds.
   */
  void GetProjector(vtkCameraRig* projector) const;

protected:
  vtkProjectorCalibration();
  ~vtkProjectorCalibration() override;

  vtkCharucoBoard* Board = nullptr;
  int ProjectorSize[2] = { 1024, 768 };
  double CameraK[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double CameraDistortion[5] = { 0, 0, 0, 0, 0 };
  double CameraR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double CameraT[3] = { 0, 0, 0 };
  int WindowRadius = 20;
  int ContrastThreshold = 10;
  int CodeThreshold = 5;
  int MinimumCorners = 8;
  int DistortionModel = 1;
  double ProjectorK[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double ProjectorDistortion[5] = { 0, 0, 0, 0, 0 };
  double ProjectorR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double ProjectorT[3] = { 0, 0, 0 };
  double Rms = 0.0;

private:
  vtkProjectorCalibration(const vtkProjectorCalibration&) = delete;
  void operator=(const vtkProjectorCalibration&) = delete;

  /// Steps 1-3 above for one pose: false (with the error) on a refusal.
  bool DecodePose(int pose);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
