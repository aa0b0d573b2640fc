/**
 * @class   vtkCalibrationImageSource
 * @brief   what a calibrated camera sees of a ChArUco board, optionally lit by a projector
 *
 * vtkCalibrationImageSource renders synthetic calibration images from known
 * cameras, so that every calibration can be checked against the truth and a
 * simulated rig can show a board. The board (vtkCharucoBoard, drawn as
 * OpenCV prints it) lies in the plane z = 0 of the world frame, surrounded
 * by a white margin one square wide; nothing else is seen (grey 0). Each
 * pixel traces Supersampling x Supersampling rays through the camera,
 * lens distortion included (lfd::PinholeCamera, lfdLensDistortion.h), to the
 * plane, and averages
 *
 *     grey = 255 albedo (Ambient + pattern),  albedo = BlackAlbedo .. WhiteAlbedo
 *
 * where `pattern` (0..1) is the projector pattern's pixel that the
 * projector throws onto the board point (0 when no pattern is set or the
 * point is outside the projector's image), e.g. a vtkGrayCodePattern image.
 * Gaussian sensor noise of NoiseSigma grey levels is added (seeded, so
 * images are reproducible). The output is one channel of 8-bit grey of
 * ImageSize, rows stored the VTK way.
 *
 * The rays are traced once for a camera, board and projector: a sequence of
 * patterns seen through the same set-up (a Gray-code capture) only
 * re-shades them.
 *
 * @sa vtkCharucoBoard vtkGrayCodePattern vtkCameraCalibration vtkProjectorCalibration
 */
#ifndef vtkCalibrationImageSource_h
#define vtkCalibrationImageSource_h

#include "lfdCalibrationModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkCharucoBoard;
class vtkImageData;

class LFDCALIBRATION_EXPORT vtkCalibrationImageSource : public vtkImageAlgorithm
{
public:
  static vtkCalibrationImageSource* New();
  vtkTypeMacro(vtkCalibrationImageSource, vtkImageAlgorithm);
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
   * Output image size; default 640 x 480.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  /**
   * The camera, OpenCV convention `x ~ K [R | t] X` (row-major), and its lens
   * distortion (k1, k2, p1, p2, k3). Default: identity pose, fx = fy = 800
   * at the image centre, no distortion.
   */
  void SetCamera(const double K[9], const double R[9], const double t[3]);
  void SetDistortion(const double coefficients[5]);

  /**
   * The projector (row-major K, R, t; its image size is the pattern's) and
   * the pattern it shows: an 8-bit grey image, rows stored the VTK way, or
   * nullptr for no projector light.
   */
  void SetProjector(const double K[9], const double R[9], const double t[3]);
  virtual void SetProjectorPattern(vtkImageData* pattern);
  vtkGetObjectMacro(ProjectorPattern, vtkImageData);

  ///@{
  /**
   * Light that reaches the board besides the projector (1 = a fully lit
   * board); default 1.
   */
  vtkSetClampMacro(Ambient, double, 0.0, 10.0);
  vtkGetMacro(Ambient, double);
  ///@}

  ///@{
  /**
   * Reflectance of the board's black and white; defaults 0.1 and 0.9 (a
   * printed board: its black still reflects a projector's codes).
   */
  vtkSetClampMacro(BlackAlbedo, double, 0.0, 1.0);
  vtkGetMacro(BlackAlbedo, double);
  vtkSetClampMacro(WhiteAlbedo, double, 0.0, 1.0);
  vtkGetMacro(WhiteAlbedo, double);
  ///@}

  ///@{
  /**
   * Rays per pixel along each axis (anti-aliasing); default 3.
   */
  vtkSetClampMacro(Supersampling, int, 1, 8);
  vtkGetMacro(Supersampling, int);
  ///@}

  ///@{
  /**
   * Standard deviation of the Gaussian sensor noise in grey levels, and the
   * seed of its generator; defaults 0 and 1.
   */
  vtkSetClampMacro(NoiseSigma, double, 0.0, 64.0);
  vtkGetMacro(NoiseSigma, double);
  vtkSetMacro(NoiseSeed, int);
  vtkGetMacro(NoiseSeed, int);
  ///@}

protected:
  vtkCalibrationImageSource();
  ~vtkCalibrationImageSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkCharucoBoard* Board = nullptr;
  vtkImageData* ProjectorPattern = nullptr;
  int ImageSize[2] = { 640, 480 };
  double CameraK[9] = { 800, 0, 319.5, 0, 800, 239.5, 0, 0, 1 };
  double CameraR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double CameraT[3] = { 0, 0, 0 };
  double Distortion[5] = { 0, 0, 0, 0, 0 };
  double ProjectorK[9] = { 800, 0, 319.5, 0, 800, 239.5, 0, 0, 1 };
  double ProjectorR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double ProjectorT[3] = { 0, 0, 0 };
  double Ambient = 1.0;
  double BlackAlbedo = 0.1;
  double WhiteAlbedo = 0.9;
  int Supersampling = 3;
  double NoiseSigma = 0.0;
  int NoiseSeed = 1;

private:
  vtkCalibrationImageSource(const vtkCalibrationImageSource&) = delete;
  void operator=(const vtkCalibrationImageSource&) = delete;

  /// The traced rays of the last set-up: each sample's albedo and projector pixel.
  struct Samples;
  std::unique_ptr<Samples> Traced;
  /// Traces the rays when the set-up differs from the last one traced.
  void Trace(int patternWidth, int patternHeight);
};

#endif
