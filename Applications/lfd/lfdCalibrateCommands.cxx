// `lfd calibrate board|patterns|camera|ring|projector`: calibration with
// OpenCV (Modules/Calibration), results into a camera file or a dataset's rig.
#include "lfdCommands.h"

#include "vtkCameraCalibration.h"
#include "vtkCameraRig.h"
#include "vtkCharucoBoard.h"
#include "vtkGrayCodePattern.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkProjectorCalibration.h"
#include "vtkSmartPointer.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
struct CalibrateOptions
{
  // The board.
  std::vector<int> Squares = { 7, 5 };
  double Square = 0.03;
  double Marker = 0.022;
  std::string Dictionary = "DICT_5X5_100";
  // Inputs and outputs.
  std::vector<std::string> Inputs;
  std::string Camera;
  std::string Dataset;
  std::string Out;
  // Options of the steps.
  std::string Distortion = "radial-tangential";
  int MinimumCorners = 8;
  int PixelsPerSquare = 100;
  std::vector<int> Size = { 1024, 768 };
  int Window = 20;
  int View = 0;
  int Index = -1;
};

const std::vector<std::string> DistortionNames = { "none", "radial", "radial-tangential", "full" };

/// The board the options describe, refused with its reason when OpenCV cannot make it.
vtkSmartPointer<vtkCharucoBoard> MakeBoard(const CalibrateOptions& options)
{
  auto board = vtkSmartPointer<vtkCharucoBoard>::New();
  board->SetSquaresX(options.Squares[0]);
  board->SetSquaresY(options.Squares[1]);
  board->SetSquareLength(options.Square);
  board->SetMarkerLength(options.Marker);
  board->SetDictionary(options.Dictionary.c_str());
  const std::string problem = board->Check();
  if (!problem.empty())
  {
    Fail("--board: " + problem);
  }
  return board;
}

/// Runs one calibration step, failing with its first error.
template<typename Calibration>
void RunCalibration(Calibration* calibration)
{
  StepErrors errors;
  errors->Observe(calibration);
  const bool done = calibration->Calibrate();
  errors.FailOnError();
  if (!done)
  {
    Fail("calibration failed");
  }
}

/// The camera calibration of `options.Inputs`, with the intrinsics of
/// `options.Camera` fixed when given.
vtkSmartPointer<vtkCameraCalibration> CalibrateImages(const CalibrateOptions& options)
{
  auto calibration = vtkSmartPointer<vtkCameraCalibration>::New();
  calibration->SetBoard(MakeBoard(options));
  calibration->SetMinimumCorners(options.MinimumCorners);
  for (size_t model = 0; model < DistortionNames.size(); ++model)
  {
    if (options.Distortion == DistortionNames[model])
    {
      calibration->SetDistortionModel(static_cast<int>(model));
    }
  }
  if (!options.Camera.empty())
  {
    StepErrors errors;
    errors->Observe(calibration);
    calibration->ReadCameraFile(options.Camera.c_str());
    errors.FailOnError("--camera: ");
    calibration->FixIntrinsicsOn();
  }
  for (const std::string& file : options.Inputs)
  {
    calibration->AddImage(ReadImage(file), file.c_str());
  }
  RunCalibration(calibration.Get());
  return calibration;
}

/// The per-view report of a camera calibration.
void PrintViews(vtkCameraCalibration* calibration, vtkCameraRig* rig)
{
  for (int i = 0; i < calibration->GetNumberOfImages(); ++i)
  {
    std::printf("  %-28s %3d corners  RMS %.3f px",
      calibration->GetImageName(i),
      calibration->GetNumberOfCorners(i),
      calibration->GetViewRms(i));
    if (rig && rig->HasCylinder())
    {
      std::printf("  azimuth %7.2f deg  height %+.4f  row %d",
        vtkMath::DegreesFromRadians(rig->GetAzimuth(i)),
        rig->GetHeight(i),
        rig->GetRow(i));
    }
    std::printf("\n");
  }
  std::printf("reprojection RMS: %.3f px over %d images\n",
    calibration->GetRms(),
    calibration->GetNumberOfImages());
}

void CalibrateBoard(const CalibrateOptions& options)
{
  auto board = MakeBoard(options);
  vtkNew<vtkImageData> image;
  StepErrors errors;
  errors->Observe(board);
  board->DrawImage(options.PixelsPerSquare, image);
  errors.FailOnError();
  WriteImage(image, options.Out);
  std::printf("wrote %s: %d x %d squares of %g, markers of %g (%s), %d pixels per square\n",
    options.Out.c_str(),
    options.Squares[0],
    options.Squares[1],
    options.Square,
    options.Marker,
    options.Dictionary.c_str(),
    options.PixelsPerSquare);
}

void CalibratePatterns(const CalibrateOptions& options)
{
  vtkNew<vtkGrayCodePattern> sequence;
  sequence->SetProjectorSize(options.Size[0], options.Size[1]);
  StagedFolder folder(options.Out, "lfd calibrate patterns", { "pattern_*.png" });
  vtkNew<vtkImageData> pattern;
  for (int i = 0; i < sequence->GetNumberOfPatterns(); ++i)
  {
    StepErrors errors;
    errors->Observe(sequence);
    sequence->GetPattern(i, pattern);
    errors.FailOnError();
    char name[32];
    std::snprintf(name, sizeof(name), "/pattern_%02d.png", i);
    WriteImage(pattern, folder.GetPath() + name);
  }
  folder.Commit();
  std::printf("wrote %s: %d patterns for a %d x %d projector (%d Gray codes, white, black)\n",
    options.Out.c_str(),
    sequence->GetNumberOfPatterns(),
    options.Size[0],
    options.Size[1],
    sequence->GetNumberOfCodeImages());
}

void CalibrateCamera(const CalibrateOptions& options)
{
  auto calibration = CalibrateImages(options);
  double K[9];
  double d[5];
  calibration->GetIntrinsics(K);
  calibration->GetDistortion(d);
  PrintViews(calibration, nullptr);
  std::printf(
    "image size: %d x %d\n", calibration->GetImageSize()[0], calibration->GetImageSize()[1]);
  std::printf("K: fx %.3f fy %.3f cx %.3f cy %.3f skew %.3f\n", K[0], K[4], K[2], K[5], K[1]);
  std::printf(
    "distortion (k1 k2 p1 p2 k3): %.6g %.6g %.6g %.6g %.6g\n", d[0], d[1], d[2], d[3], d[4]);
  StepErrors errors;
  errors->Observe(calibration);
  calibration->WriteCameraFile(options.Out.c_str());
  errors.FailOnError();
  std::printf("wrote %s\n", options.Out.c_str());
}

void CalibrateRing(const CalibrateOptions& options)
{
  auto calibration = CalibrateImages(options);
  vtkNew<vtkCameraRig> rig;
  calibration->GetRig(rig);
  std::string problem;
  if (!rig->FitCylinder(problem))
  {
    Fail("no ring fits the calibrated views: " + problem);
  }
  PrintViews(calibration, rig);
  const double* axis = rig->GetAxis();
  const double* centre = rig->GetCenter();
  std::printf("ring (board frame): axis %.5f %.5f %.5f  centre %.5f %.5f %.5f\n",
    axis[0],
    axis[1],
    axis[2],
    centre[0],
    centre[1],
    centre[2]);
  std::printf("radius %.5f  fit residual %.3g  rows %d\n",
    rig->GetRadius(),
    rig->GetFitResidual(),
    rig->GetNumberOfRows());
  if (options.Dataset.empty())
  {
    return;
  }
  auto lightField = ReadLightField(options.Dataset);
  if (lightField->GetNumberOfViews() != rig->GetNumberOfViews() ||
    lightField->GetWidth() != rig->GetImageSize()[0] ||
    lightField->GetHeight() != rig->GetImageSize()[1])
  {
    Fail(options.Dataset + ": " + std::to_string(lightField->GetNumberOfViews()) + " views of " +
      std::to_string(lightField->GetWidth()) + " x " + std::to_string(lightField->GetHeight()) +
      ", the ring has " + std::to_string(rig->GetNumberOfViews()) + " images of " +
      std::to_string(rig->GetImageSize()[0]) + " x " + std::to_string(rig->GetImageSize()[1]) +
      " (give one board image per view, in view order)");
  }
  lightField->GetRig()->DeepCopy(rig);
  WriteLightField(lightField, options.Dataset);
  std::printf("wrote the calibrated rig into %s\n", options.Dataset.c_str());
}

/// Reads pose folders of pattern_NN.png into the projector calibration.
void AddPoses(vtkProjectorCalibration* calibration, const CalibrateOptions& options)
{
  vtkNew<vtkGrayCodePattern> sequence;
  sequence->SetProjectorSize(options.Size[0], options.Size[1]);
  calibration->SetNumberOfPoses(static_cast<int>(options.Inputs.size()));
  for (size_t pose = 0; pose < options.Inputs.size(); ++pose)
  {
    for (int i = 0; i < sequence->GetNumberOfPatterns(); ++i)
    {
      char name[32];
      std::snprintf(name, sizeof(name), "/pattern_%02d.png", i);
      calibration->SetImage(static_cast<int>(pose), i, ReadImage(options.Inputs[pose] + name));
    }
  }
}

/// The projector into the dataset's projectors: projector `index`
/// replaced, or a new one appended (index -1 or the number of projectors).
void StoreProjector(vtkProjectorCalibration* calibration,
  vtkLightField* lightField,
  const CalibrateOptions& options)
{
  vtkNew<vtkCameraRig> projector;
  calibration->GetProjector(projector);
  if (!lightField->GetProjectors())
  {
    vtkNew<vtkCameraRig> none;
    lightField->SetProjectors(none);
  }
  vtkCameraRig* projectors = lightField->GetProjectors();
  const int count = projectors->GetNumberOfViews();
  const int index = options.Index < 0 ? count : options.Index;
  if (index > count)
  {
    Fail("--index " + std::to_string(index) + ": " + options.Dataset + " has " +
      std::to_string(count) + " projectors (give 0 to " + std::to_string(count) +
      ", the last to add one)");
  }
  if (count > 0 &&
    (projectors->GetImageSize()[0] != options.Size[0] ||
      projectors->GetImageSize()[1] != options.Size[1]))
  {
    Fail("--size: " + options.Dataset + " holds projectors of " +
      std::to_string(projectors->GetImageSize()[0]) + " x " +
      std::to_string(projectors->GetImageSize()[1]) + " pixels");
  }
  if (index == count && lightField->GetProjectorMasks())
  {
    Fail(options.Dataset +
      ": its projectors have masks, one per projector; calibrate one of "
      "them (--index 0 to " +
      std::to_string(count - 1) + ")");
  }
  if (index == count)
  {
    projectors->SetNumberOfViews(count + 1);
    projectors->SetImageSize(options.Size[0], options.Size[1]);
  }
  double K[9];
  double R[9];
  double t[3];
  double d[5];
  projector->GetIntrinsics(0, K);
  projector->GetRotation(0, R);
  projector->GetTranslation(0, t);
  projector->GetDistortion(0, d);
  projectors->SetView(index, K, R, t);
  projectors->SetDistortion(index, d);
  projectors->SetViewName(index, ("projector_" + std::to_string(index)).c_str());
  WriteLightField(lightField, options.Dataset);
  std::printf("wrote projector %d into %s\n", index, options.Dataset.c_str());
}

void CalibrateProjector(const CalibrateOptions& options)
{
  vtkNew<vtkCameraCalibration> camera;
  {
    StepErrors errors;
    errors->Observe(camera);
    camera->ReadCameraFile(options.Camera.c_str());
    errors.FailOnError("--camera: ");
  }
  double cameraK[9];
  double cameraD[5];
  camera->GetIntrinsics(cameraK);
  camera->GetDistortion(cameraD);
  vtkNew<vtkProjectorCalibration> calibration;
  calibration->SetBoard(MakeBoard(options));
  calibration->SetProjectorSize(options.Size[0], options.Size[1]);
  calibration->SetCamera(cameraK, cameraD);
  calibration->SetWindowRadius(options.Window);
  calibration->SetMinimumCorners(options.MinimumCorners);
  vtkSmartPointer<vtkLightField> lightField;
  if (!options.Dataset.empty())
  {
    // The camera took the captures from view --view of the dataset's rig:
    // the projector's pose follows in the rig's world.
    lightField = ReadLightField(options.Dataset);
    if (options.View >= lightField->GetNumberOfViews())
    {
      Fail("--view " + std::to_string(options.View) + ": " + options.Dataset + " has " +
        std::to_string(lightField->GetNumberOfViews()) + " views");
    }
    double R[9];
    double t[3];
    lightField->GetRig()->GetRotation(options.View, R);
    lightField->GetRig()->GetTranslation(options.View, t);
    calibration->SetCameraPose(R, t);
  }
  AddPoses(calibration, options);
  RunCalibration(calibration.Get());

  for (int pose = 0; pose < calibration->GetNumberOfPoses(); ++pose)
  {
    std::printf("  %-28s %3d corners  projector RMS %.3f px\n",
      options.Inputs[pose].c_str(),
      calibration->GetNumberOfCorners(pose),
      calibration->GetPoseRms(pose));
  }
  std::printf("projector reprojection RMS: %.3f px over %d poses\n",
    calibration->GetRms(),
    calibration->GetNumberOfPoses());
  vtkNew<vtkCameraRig> projector;
  calibration->GetProjector(projector);
  double K[9];
  double centre[3];
  projector->GetIntrinsics(0, K);
  projector->GetCameraCenter(0, centre);
  std::printf("projector K: fx %.3f fy %.3f cx %.3f cy %.3f\n", K[0], K[4], K[2], K[5]);
  std::printf("projector centre (%s): %.5f %.5f %.5f\n",
    lightField ? "world" : "camera frame",
    centre[0],
    centre[1],
    centre[2]);
  if (lightField)
  {
    StoreProjector(calibration, lightField, options);
  }
}

/// The board options of a subcommand.
void AddBoardOptions(CLI::App* command, NumericOptions& numbers, CalibrateOptions& options)
{
  numbers.Add(command, "--board", options.Squares, 2, 200, "squares across and down")->expected(2);
  numbers.Add(command, "--square", options.Square, 1e-6, 1e6, "side of a square, world units");
  numbers.Add(command,
    "--marker",
    options.Marker,
    1e-6,
    1e6,
    "side of a marker, world units (smaller than --square)");
  command
    ->add_option("--dictionary",
      options.Dictionary,
      "ArUco dictionary (OpenCV name: DICT_4X4_50 .. DICT_7X7_1000, DICT_ARUCO_ORIGINAL)")
    ->capture_default_str();
}
}

void AddCalibrateCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto* calibrate = app.add_subcommand(
    "calibrate", "calibrate cameras, the ring and projectors from ChArUco images (OpenCV)");
  calibrate->require_subcommand(1);

  auto board = std::make_shared<CalibrateOptions>();
  auto* boardCommand =
    calibrate->add_subcommand("board", "write the ChArUco board as an image to print");
  AddBoardOptions(boardCommand, numbers, *board);
  numbers.Add(boardCommand,
    "--pixels-per-square",
    board->PixelsPerSquare,
    8,
    4096,
    "image pixels per square");
  boardCommand->add_option("--out", board->Out, "output image (.png)")->required();
  commands.push_back({ boardCommand, [board] { CalibrateBoard(*board); }, false });

  auto patterns = std::make_shared<CalibrateOptions>();
  auto* patternsCommand = calibrate->add_subcommand("patterns",
    "write the Gray-code sequence a projector shows for its calibration "
    "(pattern_NN.png: codes, then white, then black)");
  numbers.Add(patternsCommand, "--size", patterns->Size, 2, 16384, "projector width and height")
    ->expected(2);
  patternsCommand->add_option("--out", patterns->Out, "output folder")->required();
  commands.push_back({ patternsCommand, [patterns] { CalibratePatterns(*patterns); }, false });

  auto camera = std::make_shared<CalibrateOptions>();
  auto* cameraCommand = calibrate->add_subcommand("camera",
    "camera intrinsics and lens distortion from ChArUco images (the board seen from varied, "
    "tilted directions); prints the reprojection RMS per image, writes a camera file");
  cameraCommand->add_option("IMAGES", camera->Inputs, "board images of one camera")->required();
  AddBoardOptions(cameraCommand, numbers, *camera);
  cameraCommand
    ->add_option("--distortion",
      camera->Distortion,
      "coefficients estimated: none, radial (k1 k2), radial-tangential (k1 k2 p1 p2), full (+k3)")
    ->capture_default_str()
    ->check(CLI::IsMember(DistortionNames));
  numbers.Add(cameraCommand,
    "--min-corners",
    camera->MinimumCorners,
    4,
    100000,
    "fewest ChArUco corners an image must show");
  cameraCommand->add_option("--out", camera->Out, "output camera file (.json, lfd-camera)")
    ->required();
  commands.push_back({ cameraCommand, [camera] { CalibrateCamera(*camera); }, false });

  auto ring = std::make_shared<CalibrateOptions>();
  auto* ringCommand = calibrate->add_subcommand("ring",
    "the ring of views from one board image per camera position (intrinsics fixed): per-view "
    "poses, then the rig's cylinder fit (axis, centre, radius, azimuths, rows)");
  ringCommand->add_option("IMAGES", ring->Inputs, "one board image per view, in view order")
    ->required();
  ringCommand->add_option("--camera", ring->Camera, "camera file of `lfd calibrate camera`")
    ->required();
  AddBoardOptions(ringCommand, numbers, *ring);
  numbers.Add(ringCommand,
    "--min-corners",
    ring->MinimumCorners,
    4,
    100000,
    "fewest ChArUco corners an image must show");
  ringCommand->add_option("--dataset",
    ring->Dataset,
    "light-field dataset whose views (one per image) receive K, R, t and the distortion");
  commands.push_back({ ringCommand, [ring] { CalibrateRing(*ring); }, false });

  auto projector = std::make_shared<CalibrateOptions>();
  auto* projectorCommand = calibrate->add_subcommand("projector",
    "a projector's intrinsics and pose from Gray-code captures of the board (Moreno and Taubin "
    "2012): one folder per board pose holding pattern_NN.png, the camera's image of each "
    "pattern of `lfd calibrate patterns`");
  projectorCommand
    ->add_option("POSES", projector->Inputs, "folders, one per board pose (at least 3)")
    ->required();
  projectorCommand
    ->add_option("--camera", projector->Camera, "camera file of the camera that took the images")
    ->required();
  numbers.Add(projectorCommand, "--size", projector->Size, 2, 16384, "projector width and height")
    ->expected(2);
  AddBoardOptions(projectorCommand, numbers, *projector);
  numbers.Add(projectorCommand,
    "--window",
    projector->Window,
    2,
    200,
    "half side of a local homography's window, camera pixels");
  numbers.Add(projectorCommand,
    "--min-corners",
    projector->MinimumCorners,
    4,
    100000,
    "fewest decoded corners a pose must give");
  projectorCommand->add_option("--dataset",
    projector->Dataset,
    "light-field dataset that receives the projector (pose in its world)");
  numbers.Add(projectorCommand,
    "--view",
    projector->View,
    0,
    100000,
    "the dataset's view the camera took the captures from");
  numbers.Add(projectorCommand,
    "--index",
    projector->Index,
    -1,
    1000,
    "the dataset's projector to replace (-1: add one)");
  commands.push_back({ projectorCommand, [projector] { CalibrateProjector(*projector); }, false });
}
}
