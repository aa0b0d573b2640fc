// The silent fault: the controller stops answering half-way through a move.
// The client gives up after its retries with one message; the controller's
// watchdog, which the unanswered requests no longer refresh, stops the axis.
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"

#include <cmath>

int TestModbusGantrySilent(int, char*[])
{
  namespace gantry = lfd::gantry;
  using lfd::test::Check;
  lfd::test::GantryRig rig;
  rig.Simulator->SetSilentTime(1.0);
  bool ok = rig.Start(true);
  vtkModbusGantry* device = rig.Gantry;

  rig.Simulator->ArmFault(gantry::SilentMode);
  const double start = lfd::test::Now();
  ok &= Check(!device->MoveTo(90.0), "the move fails", "failed");
  const double failed = lfd::test::Now() - start;
  ok &= lfd::test::CheckError(rig.Errors,
    rig.Device() +
      "no answer within 0.2 s (Connection timed out; 3 attempts) during the move to 90 deg");
  // Half-way (0.875 s of a 1.75 s move), then 3 attempts and the
  // best-effort quick stop of 0.2 s each, with margin for a loaded machine.
  ok &= Check(failed > 1.5 && failed < 3.5, "gave up after the retries (s)", failed);

  // Answers again once the silence is over: the axis stands still, stopped
  // by the watchdog, short of the target.
  lfd::test::Sleep(std::max(0.0, 2.0 - failed));
  ok &= Check(rig.WaitStill(), "answering again, still", device->GetActualAngle());
  ok &= Check(device->GetFaultCode() == gantry::WatchdogExpired && !device->IsMoving() &&
      device->GetActualAngle() > 50.0 && device->GetActualAngle() < 85.0,
    "stopped by the watchdog (fault 4) 0.3 s after the silence, between 50 and 85 deg",
    device->GetActualAngle());
  ok &= Check(!rig.Errors->HasError(),
    "no other error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "none");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
