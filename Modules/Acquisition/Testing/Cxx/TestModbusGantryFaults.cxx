// The simulator's faults on demand, each fired half-way through a move of
// vtkModbusGantry: the exact message, the axis stopped short of its target,
// the fault's status bits; then reset and the next fault. Also the watchdog
// (no refresh during a move) and the move deadline (slow fault).
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"

#include <cmath>

namespace
{
namespace gantry = lfd::gantry;
using lfd::test::Check;
using lfd::test::CheckError;

/**
 * Arms `mode` (none: the watchdog, by not refreshing it), moves 30 degrees
 * and checks the move fails with `before` + the target + `after` (after the
 * device name), the axis stands still between its start and the target with
 * fault `code` and status bit `bit` (0: none), then resets.
 */
bool CheckFault(lfd::test::GantryRig& rig,
  int mode,
  const std::string& before,
  const std::string& after,
  int code,
  int bit)
{
  vtkModbusGantry* device = rig.Gantry;
  const std::string name = mode == gantry::NoFaultMode ? "watchdog" : gantry::FaultModeName(mode);
  bool ok = device->UpdateState();
  const double from = device->GetActualAngle();
  const double to = from + (from < 100.0 ? 30.0 : -30.0);
  rig.Simulator->ArmFault(mode);
  if (mode == gantry::NoFaultMode)
  {
    // Nothing refreshes the watchdog between these calls.
    ok &= device->StartMove(to);
    lfd::test::Sleep(0.45);
  }
  ok &= Check(!(mode == gantry::NoFaultMode ? device->WaitInPosition() : device->MoveTo(to)),
    name + ": the move fails",
    "failed");
  std::ostringstream target;
  target << to;
  ok &= CheckError(rig.Errors, rig.Device() + before + target.str() + after);
  ok &= Check(rig.WaitStill(), name + ": the axis stands still", device->GetActualAngle());
  const double at = device->GetActualAngle();
  ok &=
    Check(std::fabs(at - from) > 1.0 && std::fabs(at - to) > 1.0 && (at - from) * (to - at) > 0.0,
      name + ": stopped between " + std::to_string(from) + " and " + std::to_string(to),
      at);
  ok &= Check(device->GetFaultCode() == code && device->IsReady() == (code == 0) &&
      (bit == 0 || (device->GetStatusWord() & bit) != 0),
    name + ": fault " + std::to_string(code) + (code ? ", disabled" : ", enabled"),
    device->GetStatusWord());
  if (code != 0)
  {
    ok &= Check(device->ResetFault() && device->Enable() && device->GetFaultCode() == 0 &&
        (device->GetStatusWord() & (gantry::EmergencyStopBit | gantry::LimitSwitchBit)) == 0,
      name + ": reset and enabled",
      device->GetStatusWord());
  }
  return ok;
}
}

int TestModbusGantryFaults(int, char*[])
{
  lfd::test::GantryRig rig;
  bool ok = rig.Start(true);
  const std::string during = "during the move to ";

  ok &= CheckFault(rig,
    gantry::DriveFaultMode,
    "drive fault 1 (amplifier over-current) " + during,
    " deg",
    gantry::DriveFault,
    0);
  ok &= CheckFault(rig,
    gantry::EmergencyStopMode,
    "drive fault 2 (emergency stop) " + during,
    " deg",
    gantry::EmergencyStop,
    gantry::EmergencyStopBit);
  ok &= CheckFault(rig,
    gantry::LimitSwitchMode,
    "drive fault 3 (limit switch tripped) " + during,
    " deg",
    gantry::LimitSwitch,
    gantry::LimitSwitchBit);
  ok &= CheckFault(rig,
    gantry::NoFaultMode,
    "drive fault 4 (watchdog expired) " + during,
    " deg",
    gantry::WatchdogExpired,
    0);
  // The connection closed: the client reconnects (a retry) and finds the
  // controller's fault reaction.
  ok &= CheckFault(rig,
    gantry::DropConnectionMode,
    "drive fault 5 (connection lost) " + during,
    " deg",
    gantry::ConnectionLost,
    0);
  ok &= Check(rig.Simulator->GetNumberOfConnections() == 2,
    "drop: reconnected once",
    rig.Simulator->GetNumberOfConnections());
  // Slow: the move misses its deadline, 1.5 x 0.75 s + 0.5 s, and the client
  // quick-stops it; no fault.
  ok &= CheckFault(rig,
    gantry::SlowMode,
    "the move to ",
    " deg was not in position within its deadline of 1.625 s; quick-stopped",
    gantry::NoFault,
    0);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
