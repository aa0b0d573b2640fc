// The faults of issue 12 that TestCaptureSession does not run, through
// vtkCaptureSession with the real peers of lfdCaptureTestRig.h (gantry
// simulator over Modbus TCP with the lamp on its coil 0, simulated GigE
// camera, simulated projectors), each during a capture of 4 views x 3
// passes: a drive fault, a limit switch and the connection dropped during a
// move; a move too slow for its deadline, frames damaged until the camera
// gives up, the lamp's relay stuck. Each fails the run with exactly one
// error naming the view and the device; the dataset lists exactly the views
// completed so far (their images once, no temporary); the gantry stands
// still, quick-stopped by the session; the lamp and projectors are off.
// Resume() after each continues at the failed view, once the fault is gone:
// to keep the test short the faults come in two chains of three, each
// resumed run taking views up to the next fault, the last one completing
// the capture with every view exactly once, matching the render. A lamp
// that is not there stops the capture before its first move, nothing
// written.
#include "lfdCaptureTestRig.h"
#include "lfdMotionProfile.h"

#include <sstream>
#include <vector>

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
  /// Frames the camera triggered again in the failing run.
  int Retries;
};

/// Runs `faults` (in the order of their views) into one dataset `name`:
/// a new capture, then a Resume() after each fault; the last Resume()
/// completes it.
bool RunFaults(CaptureRig& rig,
  const std::string& name,
  const std::vector<FaultCase>& faults,
  vtkLightField* reference)
{
  const std::string directory = std::string(LFD_TEST_TEMP_DIR) + "/session-" + name + ".lf";
  lfd::io::RemoveQuietly(directory);
  bool ok = true;
  int complete = 0;
  for (const FaultCase& fault : faults)
  {
    rig.AfterView = [&rig, &fault](int views)
    {
      if (views == fault.View)
      {
        fault.Arm(rig);
      }
    };
    const int quickStops = rig.Gantry.Simulator->GetNumberOfQuickStops();
    const bool failed = !rig.Run(directory, complete > 0);
    ok &= Check(failed && rig.Session->GetNumberOfViewsTaken() == fault.View - complete,
      fault.Name + ": the capture fails after taking views " + std::to_string(complete) + " to " +
        std::to_string(fault.View - 1),
      rig.Session->GetNumberOfViewsTaken());
    ok &= CheckError(rig.Errors, fault.Message);
    ok &= Check(rig.Camera->GetNumberOfRetries() == fault.Retries,
      fault.Name + ": frames triggered again in the run",
      rig.Camera->GetNumberOfRetries());
    ok &= GantryStopped(rig, fault.FaultCode, fault.Name);
    ok &= Check(rig.Gantry.Simulator->GetNumberOfQuickStops() > quickStops,
      fault.Name + ": the session quick-stopped the gantry (commands)",
      rig.Gantry.Simulator->GetNumberOfQuickStops() - quickStops);
    ok &= LightsOff(rig, fault.Name);
    ok &= CheckDataset(directory, fault.View, reference, fault.Name);
    if (fault.Repair)
    {
      fault.Repair(rig);
    }
    complete = fault.View;
  }
  rig.AfterView = nullptr;
  const bool resumed = rig.Run(directory, true);
  ok &= Check(resumed && rig.Session->GetNumberOfViewsTaken() == PlannedViews - complete &&
      !rig.Errors->HasError(),
    name + ": the last Resume() takes the remaining views without error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage()
                           : std::to_string(rig.Session->GetNumberOfViewsTaken()));
  rig.Errors->Clear();
  ok &= CheckDataset(directory, PlannedViews, reference, name + ": complete");
  return ok;
}

/// The deadline vtkModbusGantry gives a move of `degrees` from rest, as its
/// message prints it.
std::string Deadline(vtkModbusGantry* gantry, double degrees)
{
  const double duration = lfd::MotionProfile::Trapezoid(
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
  const auto arm = [](int mode)
  { return [mode](CaptureRig& r) { r.Gantry.Simulator->ArmFault(mode); }; };
  const auto disarm = arm(lfd::gantry::NoFaultMode);
  // The gantry's faults; resuming resets the controller's fault.
  const std::vector<FaultCase> gantryFaults = {
    { "drive",
      1,
      arm(lfd::gantry::DriveFaultMode),
      "view 1 of 4 (gantry angle 10): " + gantry +
        "drive fault 1 (amplifier over-current) during the move to 10 deg",
      lfd::gantry::DriveFault,
      nullptr,
      0 },
    { "limit",
      2,
      arm(lfd::gantry::LimitSwitchMode),
      "view 2 of 4 (gantry angle 20): " + gantry +
        "drive fault 3 (limit switch tripped) during the move to 20 deg",
      lfd::gantry::LimitSwitch,
      nullptr,
      0 },
    // The client reconnects and reads why the controller stopped.
    { "drop",
      3,
      arm(lfd::gantry::DropConnectionMode),
      "view 3 of 4 (gantry angle 30): " + gantry +
        "drive fault 5 (connection lost) during the move to 30 deg",
      lfd::gantry::ConnectionLost,
      nullptr,
      0 },
  };
  bool ok = RunFaults(rig, "gantry-faults", gantryFaults, reference);

  // The rig's other faults, each repaired by the user before resuming.
  const std::vector<FaultCase> rigFaults = {
    // Slow runs until disarmed (the mechanics repaired).
    { "slow",
      1,
      arm(lfd::gantry::SlowMode),
      "view 1 of 4 (gantry angle 10): " + gantry +
        "the move to 10 deg was not in position within " + "its deadline of " +
        Deadline(rig.Gantry.Gantry, 10.0) + " s; quick-stopped",
      lfd::gantry::NoFault,
      disarm,
      0 },
    // Two damaged frames: both of the camera's attempts at the Coaxial pass
    // (half the packets lost: the frame never completes). Resumed with one
    // damaged frame more, which the camera triggers again.
    { "frames",
      2,
      [](CaptureRig& r) { r.Simulated->DamageFrames(2); },
      "view 2 of 4 (gantry angle 20), Coaxial pass: Camera 127.0.0.1: no good frame after 2 "
      "attempts (last: frame timeout while receiving)",
      lfd::gantry::NoFault,
      [](CaptureRig& r) { r.Simulated->DamageFrames(1); },
      1 },
    // The lamp's relay does not switch: stuck until repaired.
    { "lamp",
      3,
      arm(lfd::gantry::StuckCoilsMode),
      "view 3 of 4 (gantry angle 30), Coaxial pass: " + lamp +
        "switched on, but the coil reads back off (a relay or output that does not switch, or "
        "the wrong coil)",
      lfd::gantry::NoFault,
      disarm,
      1 },
  };
  ok &= RunFaults(rig, "rig-faults", rigFaults, reference);

  // A lamp that is not there: the capture stops before its first move and
  // writes nothing (as an unreachable gantry or camera).
  const std::string noLamp = std::string(LFD_TEST_TEMP_DIR) + "/session-no-lamp.lf";
  lfd::io::RemoveQuietly(noLamp);
  rig.Lamp->SetPort(1);
  const bool refused = !rig.Run(noLamp, false);
  ok &= Check(refused && !std::filesystem::exists(noLamp),
    "an unreachable lamp: the capture fails, nothing written",
    std::filesystem::exists(noLamp) ? "written" : "nothing");
  ok &= CheckError(rig.Errors,
    "preparing the lights: coaxial lamp 127.0.0.1:1 coil 0: cannot connect: Connection refused (2 "
    "attempts) while switching it off");
  ok &= GantryStopped(rig, lfd::gantry::NoFault, "unreachable lamp");
  rig.Lamp->SetPort(rig.Gantry.Simulator->GetBoundPort());
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
