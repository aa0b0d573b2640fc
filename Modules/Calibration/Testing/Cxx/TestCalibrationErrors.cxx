// Bad calibration input gives one clear error each, naming the image or
// pose: no images, too few corners, images of different sizes, too few
// images for intrinsics, an unknown dictionary, a refused camera file, images
// of another size than the fixed intrinsics', a missing Gray-code image, too
// few poses, captures the projector did not light.
#include "lfdCalibrationTestUtilities.h"
#include "vtkCameraCalibration.h"
#include "vtkDataArray.h"
#include "vtkGrayCodePattern.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkPointData.h"
#include "vtkProjectorCalibration.h"
#include <vtksys/SystemTools.hxx>

#include <cstdio>
#include <fstream>
#include <string>

namespace
{
/// Runs `calibrate` on `object` and checks it fails with exactly one error, `expected`.
template<typename Calibration>
void ExpectError(Calibration* object, const std::string& expected)
{
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(object);
  const bool calibrated = object->Calibrate();
  errors->StopObserving();
  const std::string message = errors->HasError() ? errors->GetErrorMessage() : "(none)";
  const bool ok = !calibrated && errors->GetNumberOfErrors() == 1 && message == expected;
  std::cout << (ok ? "ok   " : "FAIL ") << "error: " << message << "\n";
  if (!ok)
  {
    std::cout << "     expected: " << expected << "\n";
    lfdtest::Failures() += 1;
  }
}

vtkSmartPointer<vtkImageData> Blank(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  image->GetPointData()->GetScalars()->Fill(128);
  return image;
}
}

int TestCalibrationErrors(int, char*[])
{
  auto board = lfdtest::Board();
  const double K[9] = { 800.0, 0.0, 319.5, 0.0, 800.0, 239.5, 0.0, 0.0, 1.0 };
  const lfdtest::Camera camera = lfdtest::LookAt(K,
    lfdtest::BoardCentre(board) + glm::dvec3(0.0, 0.0, -0.45),
    lfdtest::BoardCentre(board),
    glm::dvec3(0.0, -1.0, 0.0));
  auto good = lfdtest::Render(board, camera, 1);

  vtkNew<vtkCameraCalibration> calibration;
  calibration->SetBoard(board);
  ExpectError(calibration.Get(), "camera calibration: no images");

  calibration->AddImage(good, "a.png");
  calibration->AddImage(Blank(640, 480), "b.png");
  ExpectError(calibration.Get(),
    "image 1 (b.png): 0 ChArUco corners found, at least 8 needed (is the board in view, lit and "
    "in focus?)");

  calibration->RemoveAllImages();
  calibration->AddImage(good, "a.png");
  calibration->AddImage(lfdtest::Render(board, camera, 2, 320, 240), "c.png");
  ExpectError(calibration.Get(),
    "image 1 (c.png): 320 x 240 pixels, image 0 (a.png) is 640 x 480 (one camera takes every "
    "image)");

  calibration->RemoveAllImages();
  calibration->AddImage(good, "a.png");
  calibration->AddImage(good, "b.png");
  ExpectError(calibration.Get(),
    "camera calibration: 2 images, at least 3 (tilted differently) needed for the intrinsics");

  calibration->AddImage(nullptr, "gone.png");
  ExpectError(calibration.Get(), "image 2 (gone.png): missing");

  vtkNew<vtkCharucoBoard> unknown;
  unknown->SetDictionary("DICT_9X9_1");
  calibration->SetBoard(unknown);
  ExpectError(calibration.Get(),
    "ChArUco board: unknown marker dictionary 'DICT_9X9_1' (expected an OpenCV name such as "
    "DICT_5X5_100)");

  // Camera files: one refused field, and images of another size than the
  // fixed intrinsics'.
  const std::string folder = vtksys::SystemTools::GetCurrentWorkingDirectory();
  const std::string bad = folder + "/TestCalibrationErrors_camera.json";
  {
    std::ofstream file(bad);
    file << R"({"format": "lfd-camera", "version": 1, "width": 320, "height": 240,
      "K": [800, 0, 160, 0, -800, 120, 0, 0, 1]})";
  }
  vtkNew<vtkCameraCalibration> fixed;
  fixed->SetBoard(board);
  {
    vtkNew<vtkLightFieldErrorObserver> errors;
    errors->Observe(fixed);
    const bool read = fixed->ReadCameraFile(bad.c_str());
    const std::string expected =
      bad + ": field \"K\": focal lengths fx = K[0] and fy = K[4] must be positive";
    lfdtest::Check(!read && errors->GetNumberOfErrors() == 1 &&
        std::string(errors->GetErrorMessage()) == expected,
      ("camera file refused: " + std::string(errors->GetErrorMessage())).c_str(),
      errors->GetNumberOfErrors(),
      1);
  }
  {
    std::ofstream file(bad);
    file << R"({"format": "lfd-camera", "version": 1, "width": 320, "height": 240,
      "K": [400, 0, 160, 0, 400, 120, 0, 0, 1]})";
  }
  lfdtest::Check(fixed->ReadCameraFile(bad.c_str()), "camera file read", 1, 1);
  fixed->FixIntrinsicsOn();
  fixed->AddImage(good, "a.png");
  ExpectError(
    fixed.Get(), "image 0 (a.png): 640 x 480 pixels, the fixed intrinsics are for 320 x 240");
  std::remove(bad.c_str());

  // Projectors: too few poses, then a missing Gray-code image.
  vtkNew<vtkProjectorCalibration> projector;
  projector->SetBoard(board);
  projector->SetCamera(K, camera.D);
  projector->SetProjectorSize(64, 32);
  projector->SetNumberOfPoses(2);
  ExpectError(projector.Get(), "projector calibration: 2 board poses, at least 3 needed");
  projector->SetNumberOfPoses(3);
  vtkNew<vtkGrayCodePattern> sequence;
  sequence->SetProjectorSize(64, 32);
  for (int p = 0; p < 3; ++p)
  {
    for (int i = 0; i < sequence->GetNumberOfPatterns(); ++i)
    {
      if (p != 0 || i != 4)
      {
        projector->SetImage(p, i, good);
      }
    }
  }
  ExpectError(projector.Get(),
    "pose 0: Gray-code image 4 missing (a projector of 64 x 32 needs 24 images: 22 codes, white, "
    "black)");
  // Unchanging images decode nothing: the projector lit no pixel.
  projector->SetImage(0, 4, good);
  ExpectError(projector.Get(),
    "pose 0: 24 ChArUco corners found, 0 of them decoded in the projector, at least 8 needed (is "
    "the board in view and lit by the whole sequence?)");
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
