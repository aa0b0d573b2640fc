// The faults of issue 12 that TestCaptureSession does not run, through
// vtkCaptureSession with the real peers of lfdCaptureTestRig.h (gantry
// simulator over Modbus TCP with the lamp on its coil 0, simulated GigE
// camera, simulated projectors): a drive fault, a limit switch and the
// connection dropped during a move, a move too slow for its deadline,
// frames damaged until the camera gives up, the lamp's relay stuck. Each
// capture of 4 views x 3 passes fails with exactly one error naming the
// view and the device; the dataset lists exactly the views completed before
// (their images once, no temporary); the gantry stands still, quick-stopped
// by the session; the lamp and projectors are off. Once the fault is gone,
// Resume() completes the capture: every view exactly once, matching the
// render.
#include "lfdCaptureTestRig.h"
#include "lfdMotionProfile.h"

#include <sstream>

using namespace lfd::test;

namespace
{
/// One fault: armed once `View` views are complete, so view `View` fails.
struct FaultCase
{
  std::string Name;
  int View;
  std::function<void(CaptureRig&)> Arm;
  /// The session's one error, exactly.
  std::string Message;
  /// The fault code the controller shows afterwards.
  int FaultCode;
  /// What the user does before resuming (nothing when empty).
  std::function<void(CaptureRig&)> Repair;
};

bool RunFault(CaptureRig& rig, const FaultCase& fault, vtkLightField* reference)
{
  const std::string directory = std::string(LFD_TEST_TEMP_DIR) + "/session-" + fault.Name + ".lf";
  lfd::io::RemoveQuietly(directory);
  rig.AfterView = [&rig, &fault](int complete)
  {
    if (complete == fault.View)
    {
      fault.Arm(rig);
    }
  };
  const int quickStops = rig.Gantry.Simulator->GetNumberOfQuickStops();
  bool ok = Check(!rig.Run(directory, false), fault.Name + ": the capture fails", "");
  ok &= CheckError(rig.Errors, fault.Message);
  ok &= GantryStopped(rig, fault.FaultCode, fault.Name);
  ok &= Check(rig.Gantry.Simulator->GetNumberOfQuickStops() > quickStops,
    fault.Name + ": the gantry was quick-stopped (commands)",
    rig.Gantry.Simulator->GetNumberOfQuickStops() - quickStops);
  ok &= LightsOff(rig, fault.Name);
  ok &= CheckDataset(directory, fault.View, reference, fault.Name);

  rig.AfterView = nullptr;
  if (fault.Repair)
  {
    fault.Repair(rig);
  }
  ok &= Check(rig.Run(directory, true) &&
      rig.Session->GetNumberOfViewsTaken() == PlannedViews - fault.View && !rig.Errors->HasError(),
    fault.Name + ": resumed, views taken without error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage()
                           : std::to_string(rig.Session->GetNumberOfViewsTaken()));
  rig.Errors->Clear();
  ok &= CheckDataset(directory, PlannedViews, reference, fault.Name + ": resumed");
  return ok;
}

/// The deadline vtkModbusGantry gives a move of `degrees` from rest, as its
/// message prints it.
std::string Deadline(vtkModbusGantry* gantry, double degrees)
{
  const double duration =
    lfd::MotionProfile::Trapezoid(
      0.0, 0.0, degrees, gantry->GetVelocity(), gantry->GetAcceleration())
      .GetDuration();
  std::ostringstream text;
  text << gantry->GetDeadlineFactor() * duration + gantry->GetDeadlineMargin();
  return text.str();
}
}

int TestCaptureSessionFaults(int, char*[])
{
  CaptureRig rig;
  if (!rig.Start())
  {
    std::cerr << rig.Errors->GetErrorMessage() << rig.Gantry.Errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkLightField> reference = rig.Scene.Reference({ 0, 1, 2, 3 });
  const std::string gantry = rig.Gantry.Gantry->GetDeviceName() + ": ";
  const std::string lamp = rig.Lamp->GetDeviceName() + ": ";
  const auto arm = [](int mode) { return [mode](CaptureRig& r) { r.Gantry.Simulator->ArmFault(mode); }; };
  const auto disarm = arm(lfd::gantry::NoFaultMode);
  const FaultCase faults[] = {
    { "drive",
      1,
      arm(lfd::gantry::DriveFaultMode),
      "view 1 of 4 (gantry angle 10): " + gantry +
        "drive fault 1 (amplifier over-current) during the move to 10 deg",
      lfd::gantry::DriveFault,
      nullptr },
    { "limit",
      2,
      arm(lfd::gantry::LimitSwitchMode),
      "view 2 of 4 (gantry angle 20): " + gantry +
        "drive fault 3 (limit switch tripped) during the move to 20 deg",
      lfd::gantry::LimitSwitch,
      nullptr },
    // The client reconnects and reads why the controller stopped.
    { "drop",
      3,
      arm(lfd::gantry::DropConnectionMode),
      "view 3 of 4 (gantry angle 30): " + gantry +
        "drive fault 5 (connection lost) during the move to 30 deg",
      lfd::gantry::ConnectionLost,
      nullptr },
    // Slow runs until disarmed: the mechanics repaired.
    { "slow",
      1,
      arm(lfd::gantry::SlowMode),
      "view 1 of 4 (gantry angle 10): " + gantry + "the move to 10 deg was not in position within " +
        "its deadline of " + Deadline(rig.Gantry.Gantry, 10.0) + " s; quick-stopped",
      lfd::gantry::NoFault,
      disarm },
    // Two damaged frames: the camera's two attempts at the Coaxial pass.
    { "frames",
      2,
      [](CaptureRig& r) { r.Simulated->DamageFrames(2); },
      "view 2 of 4 (gantry angle 20), Coaxial pass: Camera 127.0.0.1: no good frame after 2 "
      "attempts (last: FRAME_STATUS)",
      lfd::gantry::NoFault,
      nullptr },
    // The lamp's relay does not switch: stuck until repaired.
    { "lamp",
      1,
      arm(lfd::gantry::StuckCoilsMode),
      "view 1 of 4 (gantry angle 10), Coaxial pass: " + lamp +
        "switched on, but the coil reads back off (a relay or output that does not switch, or "
        "the wrong coil)",
      lfd::gantry::NoFault,
      disarm },
  };
  bool ok = true;
  for (const FaultCase& fault : faults)
  {
    ok &= RunFault(rig, fault, reference);
  }

  // A damaged frame is triggered again: the capture goes on.
  const std::string retried = std::string(LFD_TEST_TEMP_DIR) + "/session-retried.lf";
  lfd::io::RemoveQuietly(retried);
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 1)
    {
      rig.Simulated->DamageFrames(1);
    }
  };
  ok &= Check(rig.Run(retried, false) && rig.Camera->GetNumberOfRetries() == 1 &&
      !rig.Errors->HasError(),
    "a damaged frame: retried once, the capture completes",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage()
                           : std::to_string(rig.Camera->GetNumberOfRetries()));
  ok &= CheckDataset(retried, PlannedViews, reference, "retried");
  rig.AfterView = nullptr;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
