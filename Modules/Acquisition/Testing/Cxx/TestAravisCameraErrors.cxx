// One readable error for each way a camera cannot be used: no address, an
// address where no camera answers, a setting outside the camera's range
// (the fake camera's gain is 0..10), Acquire() before Open(); a simulated
// camera on an address already served or not local.
#include "lfdCameraTestScene.h"
#include "vtkAravisCamera.h"
#include "vtkLightFieldErrorObserver.h"

namespace
{
void ExpectError(vtkLightFieldErrorObserver* errors, const std::string& expected)
{
  const std::string message = errors->GetErrorMessage();
  std::cout << "error: " << message << "\n";
  lfdtest::Check(message == expected, "exact error \"" + expected + "\"", message == expected, 1);
  lfdtest::Check(
    errors->GetNumberOfErrors() == 1, "number of errors", errors->GetNumberOfErrors(), 1);
  errors->Clear();
}
}

int TestAravisCameraErrors(int, char*[])
{
  vtkNew<vtkLightFieldErrorObserver> errors;
  vtkNew<vtkAravisCamera> camera;
  errors->Observe(camera);
  vtkNew<vtkImageData> frame;

  lfdtest::Check(!camera->Open(), "Open() without an address fails", 0, 0);
  ExpectError(errors, "Camera: no Address set (an IP address or an Aravis device id).");

  camera->SetAddress("127.0.0.2");
  lfdtest::Check(!camera->Acquire(frame), "Acquire() before Open() fails", 0, 0);
  ExpectError(errors, "Camera 127.0.0.2: not open; call Open() first.");
  lfdtest::Check(!camera->Open(), "Open() of an address without a camera fails", 0, 0);
  ExpectError(
    errors, "Camera 127.0.0.2: cannot connect: Can't connect to device at address '127.0.0.2'");

  lfdtest::CameraScene scene;
  vtkNew<vtkSimulatedRigCamera> simulated;
  scene.SetUp(simulated);
  if (!simulated->Start())
  {
    return EXIT_FAILURE;
  }
  // The simulated camera: a second one on the same address, and an
  // address that is not this machine's.
  vtkNew<vtkSimulatedRigCamera> second;
  scene.SetUp(second);
  errors->Observe(second);
  lfdtest::Check(!second->Start(), "a second simulated camera on 127.0.0.1 fails", 0, 0);
  ExpectError(errors,
    "Simulated camera 127.0.0.1: the GVCP port 3956 of this address is taken (another camera "
    "serves there).");
  second->SetAddress("10.9.9.9");
  lfdtest::Check(!second->Start(), "a simulated camera on 10.9.9.9 fails", 0, 0);
  ExpectError(errors,
    "Simulated camera 10.9.9.9: cannot serve GigE Vision there (not a local IPv4 address).");

  camera->SetAddress("127.0.0.1");
  camera->SetGain(20.0);
  lfdtest::Check(!camera->Open(), "Open() with a gain the camera refuses fails", 0, 0);
  ExpectError(errors, "Camera 127.0.0.1: refuses Gain = 20 dB: its range is [0, 10] dB");
  camera->SetGain(5.0);
  camera->SetPixelFormat(vtkAravisCamera::MONO8);
  lfdtest::Check(camera->Open(), "Open() with a gain the camera accepts", 1, 1);
  lfdtest::Check(!errors->HasError(), "errors", errors->HasError(), 0);
  camera->Close();
  simulated->Stop();
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
