// Frames lost on the way from the simulated camera: a dropped frame (never
// sent) and a damaged one (half its packets lost) are triggered again and
// the next good frame is returned; a late frame (the trigger given up on,
// answered after the retry's) is discarded by the next Acquire(); a camera whose frames keep
// getting lost gives one error after MaximumAttempts.
#include "lfdCameraTestScene.h"
#include "vtkAravisCamera.h"
#include "vtkLightFieldErrorObserver.h"

int TestCameraRetries(int, char*[])
{
  lfdtest::CameraScene scene;
  vtkNew<vtkSimulatedRigCamera> simulated;
  scene.SetUp(simulated);
  simulated->SetCoaxialLight(true);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(simulated);
  vtkNew<vtkAravisCamera> camera;
  camera->SetAddress("127.0.0.1");
  // Long enough for a render on a loaded machine: a dropped frame costs
  // this long.
  camera->SetFrameTimeout(5000);
  errors->Observe(camera);
  if (!simulated->Start() || !camera->Open())
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkLightField> reference = scene.Reference({ 0 });
  vtkNew<vtkImageData> frame;

  simulated->DropFrames(1);
  const bool dropped = camera->Acquire(frame);
  lfdtest::Check(dropped && camera->GetNumberOfRetries() == 1,
    "retries after a dropped frame",
    camera->GetNumberOfRetries(),
    1);
  const double afterDrop = dropped ? lfdtest::FramePSNR(frame, reference, 0, 0) : 0.0;
  lfdtest::Check(afterDrop > 60.0, "PSNR of the frame after the dropped one (dB)", afterDrop, 60.0);

  simulated->DamageFrames(1);
  const bool damaged = camera->Acquire(frame);
  lfdtest::Check(damaged && camera->GetNumberOfRetries() == 2,
    "retries after a damaged frame (total)",
    camera->GetNumberOfRetries(),
    2);
  const double afterDamage = damaged ? lfdtest::FramePSNR(frame, reference, 0, 0) : 0.0;
  lfdtest::Check(
    afterDamage > 60.0, "PSNR of the frame after the damaged one (dB)", afterDamage, 60.0);
  lfdtest::Check(!errors->HasError(), "errors so far", errors->HasError(), 0);

  // A slow camera: the first frame comes after its attempt gave up, so the
  // retry's trigger is answered as well, later. The next Acquire() waits for
  // that frame and discards it instead of taking it for its own (on a rig,
  // a frame exposed under the previous pass's lights).
  // (The fake camera answers no control packet while it fills a frame, so
  // the retry's trigger returns once the late frame is sent, and that
  // attempt takes it. Two budgets bound the render R of a frame, several
  // times slower under the sanitizers on a loaded machine: the retry's own
  // frame must come within the frame timeout of the next Acquire (R <
  // 1200 ms), and the delay plus a render must stay under the fake
  // camera's 3 s heartbeat timeout, past which it drops its controller
  // (R < 1600 ms); 1000 / 1800 ms left R < 1000 and 1200 ms, and failed
  // under ASan at load 4.)
  camera->SetFrameTimeout(1200);
  simulated->DelayFrames(1, 1400);
  const int retriesBefore = camera->GetNumberOfRetries();
  const int renderedBefore = simulated->GetNumberOfFramesRendered();
  const bool slow = camera->Acquire(frame);
  lfdtest::Check(slow && camera->GetNumberOfRetries() == retriesBefore + 1,
    "retries after a late frame (total)",
    camera->GetNumberOfRetries(),
    retriesBefore + 1);
  const bool next = camera->Acquire(frame);
  lfdtest::Check(next && camera->GetNumberOfLateFrames() == 1,
    "late frames discarded by the next Acquire",
    camera->GetNumberOfLateFrames(),
    1);
  lfdtest::Check(simulated->GetNumberOfFramesRendered() - renderedBefore == 3,
    "frames sent for 3 triggers",
    simulated->GetNumberOfFramesRendered() - renderedBefore,
    3);
  const double afterLate = next ? lfdtest::FramePSNR(frame, reference, 0, 0) : 0.0;
  lfdtest::Check(afterLate > 60.0, "PSNR of the frame after the late one (dB)", afterLate, 60.0);

  camera->SetMaximumAttempts(3);
  camera->SetFrameTimeout(300);
  simulated->DropFrames(3);
  const bool failed = !camera->Acquire(frame);
  const std::string expected =
    "Camera 127.0.0.1: no good frame after 3 attempts (last: no frame within 300 ms)";
  const std::string message = errors->GetErrorMessage();
  std::cout << "error: " << message << "\n";
  lfdtest::Check(
    failed && message == expected, "exact error after 3 dropped frames", message == expected, 1);
  errors->Clear();

  // A gantry that cannot tell its angle: the simulated camera sends nothing.
  simulated->SetAngleSource([](double&) { return false; });
  camera->SetMaximumAttempts(1);
  const bool noAngle = !camera->Acquire(frame);
  const std::string angleError =
    "Simulated camera 127.0.0.1: the angle source gave no gantry angle; the frame is dropped.";
  std::cout << "errors: " << errors->GetErrorMessage() << " | "
            << (errors->GetNumberOfErrors() > 1 ? errors->GetError(1) : "") << "\n";
  lfdtest::Check(noAngle && errors->GetNumberOfErrors() == 2 &&
      errors->GetErrorMessage() == angleError &&
      std::string(errors->GetError(1)) ==
        "Camera 127.0.0.1: no good frame after 1 attempt (last: no frame within 300 ms)",
    "exact errors without a gantry angle",
    errors->GetNumberOfErrors(),
    2);
  camera->Close();
  simulated->Stop();
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
