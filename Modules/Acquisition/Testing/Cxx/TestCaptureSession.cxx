// vtkCaptureSession with real peers on 127.0.0.1: the gantry simulator
// (Modbus TCP, in this process, a free port; its coil 0 switches the
// coaxial lamp, a vtkModbusLight) and the simulated rig camera (GigE
// Vision), two simulated projectors (lfdCaptureTestRig.h). A plan of 4 ring
// views x 3 passes is captured through faults:
// - an emergency stop during the move to view 2: one error naming the
//   gantry and the fault, views 0-1 complete and readable, the axis still,
//   the lights off; then Resume() completes views 2-3, each view once,
//   matching vtkLightFieldCapture's own render of the ring views;
// - the gantry going silent before view 1, the camera gone before view 2
//   (one error each naming the device; the complete views listed, the
//   gantry still, the lights off), then the capture completed;
// - Abort() after view 0: no error, one view, resumable.
// TestCaptureSessionFaults runs the other faults.
#include "lfdCaptureTestRig.h"

using namespace lfd::test;

int TestCaptureSession(int, char*[])
{
  CaptureRig rig;
  if (!rig.Start())
  {
    std::cerr << rig.Errors->GetErrorMessage() << rig.Gantry.Errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkLightField> reference = rig.Scene.Reference({ 0, 1, 2, 3 });
  const std::string temp = LFD_TEST_TEMP_DIR;
  const std::string gantry = rig.Gantry.Gantry->GetDeviceName();
  bool ok = true;

  // Emergency stop during the move to view 2, then resumed.
  const std::string estop = temp + "/session-estop.lf";
  lfd::io::RemoveQuietly(estop);
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 2)
    {
      rig.Gantry.Simulator->ArmFault(lfd::gantry::EmergencyStopMode);
    }
  };
  const int quickStops = rig.Gantry.Simulator->GetNumberOfQuickStops();
  ok &= Check(!rig.Run(estop, false), "e-stop: the capture fails", "");
  ok &= CheckError(rig.Errors,
    "view 2 of 4 (gantry angle 20): " + gantry +
      ": drive fault 2 (emergency stop) during the move to 20 deg");
  ok &= GantryStopped(rig, lfd::gantry::EmergencyStop, "e-stop");
  ok &= Check(rig.Gantry.Simulator->GetNumberOfQuickStops() == quickStops + 1,
    "e-stop: the session quick-stopped the gantry",
    rig.Gantry.Simulator->GetNumberOfQuickStops() - quickStops);
  ok &= LightsOff(rig, "e-stop");
  ok &= CheckDataset(estop, 2, reference, "e-stop");
  rig.AfterView = nullptr;
  const bool resumed = rig.Run(estop, true);
  ok &= Check(resumed && rig.Session->GetNumberOfViewsTaken() == 2,
    "e-stop: resumed, views taken",
    rig.Session->GetNumberOfViewsTaken());
  ok &= Check(!rig.Errors->HasError(),
    "e-stop: resumed without error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "none");
  ok &= CheckDataset(estop, 4, reference, "e-stop: resumed");
  std::cout << "overhead per view " << 1000.0 * rig.Session->GetOverheadSeconds() / 2
            << " ms, devices " << 1000.0 * rig.Session->GetDeviceSeconds() / 2 << " ms\n";
  const bool again = rig.Run(estop, true);
  ok &= Check(again && rig.Session->GetNumberOfViewsTaken() == 0,
    "e-stop: resuming a complete capture takes no view",
    rig.Session->GetNumberOfViewsTaken());

  // The gantry silent before the move to view 1.
  const std::string silent = temp + "/session-silent.lf";
  lfd::io::RemoveQuietly(silent);
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 1)
    {
      rig.Gantry.Simulator->ArmFault(lfd::gantry::SilentMode);
    }
  };
  ok &= Check(!rig.Run(silent, false), "silent: the capture fails", "");
  ok &= CheckError(rig.Errors,
    "view 1 of 4 (gantry angle 10): " + gantry +
      ": no answer within 0.2 s (Connection timed out; 2 attempts) during the move to 10 deg");
  lfd::test::Sleep(1.0);
  ok &= GantryStopped(rig, lfd::gantry::NoFault, "silent");
  ok &= LightsOff(rig, "silent");
  ok &= CheckDataset(silent, 1, reference, "silent");

  // Aborted after view 0 of a new capture: no error, one view.
  const std::string aborted = temp + "/session-abort.lf";
  lfd::io::RemoveQuietly(aborted);
  rig.AfterView = [&rig](int) { rig.Session->Abort(); };
  const bool stopped = rig.Run(aborted, false);
  ok &= Check(stopped && rig.Session->GetAborted() && rig.Session->GetNumberOfViewsTaken() == 1 &&
      !rig.Errors->HasError(),
    "abort: stopped after 1 view without error",
    rig.Session->GetNumberOfViewsTaken());

  // A capture is never started over an existing one.
  ok &= Check(!rig.Run(silent, false), "an existing capture is not replaced", "");
  ok &= CheckError(rig.Errors,
    silent + ": exists; resume that capture, or choose a new name (it is never replaced)");

  // The camera gone before view 2 of the resumed silent capture.
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 2)
    {
      rig.Simulated->Stop();
    }
  };
  ok &= Check(!rig.Run(silent, true), "camera gone: the capture fails", "");
  const std::string cameraMessage = rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "";
  ok &= Check(cameraMessage.rfind(
                "view 2 of 4 (gantry angle 20), Coaxial pass: Camera 127.0.0.1: ", 0) == 0 &&
      rig.Errors->GetNumberOfErrors() == 1,
    "camera gone: one error naming the view and the camera",
    cameraMessage);
  rig.Errors->Clear();
  ok &= GantryStopped(rig, lfd::gantry::NoFault, "camera gone");
  ok &= LightsOff(rig, "camera gone");
  ok &= CheckDataset(silent, 2, reference, "camera gone");

  // The camera back: the capture completes, each view once.
  rig.AfterView = nullptr;
  const bool back = rig.Simulated->Start() && rig.Run(silent, true);
  ok &= Check(back && rig.Session->GetNumberOfViewsTaken() == 2 && !rig.Errors->HasError(),
    "camera back: resumed, views taken without error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage()
                           : std::to_string(rig.Session->GetNumberOfViewsTaken()));
  ok &= CheckDataset(silent, 4, reference, "camera back");

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
