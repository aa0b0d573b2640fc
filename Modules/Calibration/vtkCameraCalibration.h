/**
 * @class   vtkCameraCalibration
 * @brief   camera intrinsics, lens distortion and per-view poses from ChArUco images
 *
 * vtkCameraCalibration finds a ChArUco board (vtkCharucoBoard) in each image
 * added, then either
 *
 * - estimates the intrinsics K and the lens distortion together with every
 *   view's board pose (Zhang, "A flexible new technique for camera
 *   calibration", IEEE PAMI 22(11), 2000, as OpenCV's
 *   `aruco::calibrateCameraCharuco` implements it): images of the board
 *   seen from varied, tilted directions; or
 * - with FixIntrinsics on, keeps the given K and distortion and estimates
 *   each view's pose alone (`solvePnP`): the images of a ring gantry, one per
 *   camera position, seeing a board that stands where the object will be.
 *
 * Poses are board-to-camera, `x ~ K [R | t] X` with X in the board frame
 * (vtkCharucoBoard), so GetRig() gives a vtkCameraRig whose world is the
 * board: its FitCylinder() then gives the ring's axis, centre, radius and
 * each view's azimuth, height and row, with the rig's own fit (one
 * implementation for calibrated, imported and synthetic rigs).
 *
 * Reprojection errors are reported per view and overall (root mean square
 * distance in pixels between the detected corners and the projections of
 * the board's corners). Every refusal is one error naming the image: no
 * images, images of different sizes, an image not 8-bit, too few corners
 * found (MinimumCorners), too few images for intrinsics (3), images of
 * another size than the fixed intrinsics' (read from a camera file).
 *
 * @sa vtkCharucoBoard vtkCameraRig vtkProjectorCalibration
 */
#ifndef vtkCameraCalibration_h
#define vtkCameraCalibration_h

#include "lfdCalibrationModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkCameraRig;
class vtkCharucoBoard;
class vtkImageData;

class LFDCALIBRATION_EXPORT vtkCameraCalibration : public vtkObject
{
public:
  static vtkCameraCalibration* New();
  vtkTypeMacro(vtkCameraCalibration, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The board the images show (required).
   */
  virtual void SetBoard(vtkCharucoBoard* board);
  vtkGetObjectMacro(Board, vtkCharucoBoard);
  ///@}

  ///@{
  /**
   * The images, in view order (8-bit grey or colour, rows stored the VTK
   * way, all of one size), each with an optional name (its file) by which
   * errors and the report name it.
   */
  void AddImage(vtkImageData* image, const char* name = nullptr);
  void RemoveAllImages();
  int GetNumberOfImages() const;
  const char* GetImageName(int i) const;
  ///@}

  /**
   * Lens distortion models: the coefficients (k1, k2, p1, p2, k3) estimated.
   */
  enum DistortionModels
  {
    NO_DISTORTION = 0,     ///< none
    RADIAL = 1,            ///< k1, k2
    RADIAL_TANGENTIAL = 2, ///< k1, k2, p1, p2 (the default)
    FULL = 3               ///< k1, k2, p1, p2, k3
  };

  ///@{
  /**
   * The distortion model estimated; default RADIAL_TANGENTIAL (k3 needs
   * many views reaching the image corners to be reliable).
   */
  vtkSetClampMacro(DistortionModel, int, NO_DISTORTION, FULL);
  vtkGetMacro(DistortionModel, int);
  ///@}

  ///@{
  /**
   * Fewest corners an image must show; default 8.
   */
  vtkSetClampMacro(MinimumCorners, int, 4, 100000);
  vtkGetMacro(MinimumCorners, int);
  ///@}

  ///@{
  /**
   * When on, Calibrate() keeps the intrinsics and distortion set below and
   * estimates the poses only; default off.
   */
  vtkSetMacro(FixIntrinsics, bool);
  vtkGetMacro(FixIntrinsics, bool);
  vtkBooleanMacro(FixIntrinsics, bool);
  ///@}

  ///@{
  /**
   * The intrinsics K (row-major) and the distortion (k1, k2, p1, p2, k3):
   * the input with FixIntrinsics, else the result of Calibrate().
   */
  void SetIntrinsics(const double K[9]);
  void GetIntrinsics(double K[9]) const;
  void SetDistortion(const double coefficients[5]);
  void GetDistortion(double coefficients[5]) const;
  ///@}

  /**
   * Detects the board in every image and calibrates. Returns false, with
   * one error naming the image at fault, when the input is refused.
   */
  bool Calibrate();

  ///@{
  /**
   * Results of Calibrate(): the image size, the overall and per-view
   * reprojection RMS (pixels), the corners found per view and each view's
   * board-to-camera pose (R row-major, t in board units).
   */
  vtkGetVector2Macro(ImageSize, int);
  vtkGetMacro(Rms, double);
  double GetViewRms(int i) const;
  int GetNumberOfCorners(int i) const;
  void GetViewRotation(int i, double R[9]) const;
  void GetViewTranslation(int i, double t[3]) const;
  ///@}

  ///@{
  /**
   * The camera file (`lfd-camera`, version 1, Data/README.md): the
   * intrinsics, distortion and image size with the board and the
   * reprojection errors per view. WriteCameraFile() writes the result of
   * Calibrate() atomically (temporary name, then rename);
   * ReadCameraFile() reads the intrinsics, distortion and image size back
   * (as FixIntrinsics needs them). Both return false with one error naming
   * the file (and the field) on failure.
   */
  bool WriteCameraFile(const char* fileName);
  bool ReadCameraFile(const char* fileName);
  ///@}

  /**
   * The calibrated views as a rig whose world frame is the board's: one
   * view per image (K, R, t, distortion, name), the image size. The rig is
   * not fitted: call its FitCylinder() for a ring.
   */
  void GetRig(vtkCameraRig* rig) const;

protected:
  vtkCameraCalibration();
  ~vtkCameraCalibration() override;

  vtkCharucoBoard* Board = nullptr;
  int DistortionModel = RADIAL_TANGENTIAL;
  int MinimumCorners = 8;
  bool FixIntrinsics = false;
  double Intrinsics[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double Distortion[5] = { 0, 0, 0, 0, 0 };
  int ImageSize[2] = { 0, 0 };
  double Rms = 0.0;

private:
  vtkCameraCalibration(const vtkCameraCalibration&) = delete;
  void operator=(const vtkCameraCalibration&) = delete;

  /// Finds the board in every image: false (with the error) on a refusal.
  bool DetectBoards();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
