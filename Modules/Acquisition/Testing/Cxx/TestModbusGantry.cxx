// vtkModbusGantry against vtkGantrySimulator served on 127.0.0.1: the
// refusals before homing, homing, a move sampled against its trapezoidal
// profile, a stop, the soft limits on both sides, and the register map
// itself (read-only registers, refused values, a fault armed by register).
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"
#include "lfdMotionProfile.h"

#include <modbus/modbus.h>

#include <cerrno>
#include <cmath>

namespace
{
namespace gantry = lfd::gantry;
using lfd::test::Check;
using lfd::test::CheckError;
using lfd::test::Now;

/**
 * Samples a move to 40 degrees from 10 and checks every actual position lies
 * within the profile's positions over the times the sample may have been
 * taken at: the move started between the start request's send and answer,
 * each sample was read between its request's send and answer.
 */
bool CheckProfileTiming(lfd::test::GantryRig& rig)
{
  vtkModbusGantry* device = rig.Gantry;
  const lfd::MotionProfile profile = lfd::MotionProfile::Trapezoid(0.0, 10.0, 40.0, 60.0, 240.0);
  const double sent = Now();
  bool ok = device->StartMove(40.0);
  const double answered = Now();
  int samples = 0;
  int outside = 0;
  double worst = 0.0;
  while (ok && samples < 1000)
  {
    const double before = Now();
    ok = device->UpdateState();
    const double after = Now();
    if (!ok || !device->IsMoving())
    {
      break;
    }
    double earliest, latest, velocity;
    profile.Evaluate(before - answered, earliest, velocity);
    profile.Evaluate(after - sent, latest, velocity);
    const double p = device->GetActualAngle();
    // Positions are whole thousandths of a degree.
    const double excess = std::max(earliest - 0.0005 - p, p - latest - 0.0005);
    worst = std::max(worst, excess);
    outside += excess > 0.0 ? 1 : 0;
    ++samples;
    lfd::test::Sleep(0.01);
  }
  ok &= device->WaitInPosition();
  bool passed = Check(ok && outside == 0 && samples >= 10,
    "move 10 -> 40 deg: every sample within the profile's bracket",
    std::to_string(samples) + " samples, " + std::to_string(outside) + " outside (worst by " +
      std::to_string(worst) + " deg)");
  passed &= Check(device->IsInPosition() && !device->IsMoving() &&
      std::fabs(device->GetActualAngle() - 40.0) < 1e-9,
    "in position at 40 deg",
    device->GetActualAngle());
  return passed;
}

/// A stop decelerates at the acceleration and leaves the axis short of its target.
bool CheckStop(lfd::test::GantryRig& rig)
{
  vtkModbusGantry* device = rig.Gantry;
  bool ok = device->StartMove(100.0);
  // Cruising after 0.3 s (reading the state refreshes the watchdog).
  const double cruising = Now() + 0.3;
  while (ok && Now() < cruising)
  {
    ok = device->UpdateState();
    lfd::test::Sleep(0.02);
  }
  ok = ok && device->Stop() && rig.WaitStill();
  const double at = device->GetActualAngle();
  return Check(
    ok && !device->IsInPosition() && at > 40.0 && at < 100.0 && device->GetFaultCode() == 0,
    "stopped mid-move, between 40 and 100 deg, not in position, no fault",
    at);
}

/// Requests the client never sends, answered with Modbus exceptions.
bool CheckRegisterMap(lfd::test::GantryRig& rig)
{
  modbus_t* raw = modbus_new_tcp("127.0.0.1", rig.Simulator->GetBoundPort());
  const bool connected = modbus_connect(raw) == 0;
  bool ok =
    Check(connected, "a second client connects", connected ? "yes" : modbus_strerror(errno));
  uint16_t identity[2] = { 0, 0 };
  ok &= Check(modbus_read_registers(raw, gantry::Identity, 2, identity) == 2 &&
      identity[0] == 0x4C46 && identity[1] == 1,
    "identity 0x4C46, map version 1",
    identity[0]);
  const struct
  {
    int Address;
    int Value;
    int Error;
    const char* What;
  } refusals[] = {
    { gantry::StatusWord, 0, EMBXILADD, "write to the status word" },
    { gantry::ActualPosition + 1, 5, EMBXILADD, "write to the actual position" },
    { gantry::Identity, 1, EMBXILADD, "write to the identity" },
    { gantry::RegisterCount, 1, EMBXILADD, "write past the map" },
    { gantry::Velocity, 0, EMBXILVAL, "velocity 0" },
    { gantry::SimulatorFault, gantry::FaultModeCount, EMBXILVAL, "unknown fault mode" },
  };
  for (const auto& refusal : refusals)
  {
    const int rc = modbus_write_register(raw, refusal.Address, refusal.Value);
    const int error = errno;
    ok &= Check(rc == -1 && error == refusal.Error,
      std::string(refusal.What) + " refused",
      rc == -1 ? modbus_strerror(error) : "accepted");
  }
  // The simulator refuses a target beyond its soft limits with fault 6.
  uint16_t target[2];
  gantry::SetInt32(target, 400000);
  ok &= Check(modbus_write_registers(raw, gantry::TargetPosition, 2, target) == 2 &&
      modbus_write_register(raw, gantry::ControlWord, gantry::EnableBit | gantry::StartBit) == 1,
    "start towards 400 deg sent",
    "yes");
  ok &= Check(rig.Simulator->GetFaultCode() == gantry::SoftLimit,
    "a start beyond the soft limits: fault 6",
    rig.Simulator->GetFaultCode());
  // A fault armed through the register fires in the client's next move.
  ok &= Check(modbus_write_register(raw, gantry::SimulatorFault, gantry::DriveFaultMode) == 1,
    "drive fault armed by register",
    "yes");
  modbus_close(raw);
  modbus_free(raw);
  ok &= rig.Gantry->ResetFault() && rig.Gantry->Enable();
  ok &= Check(!rig.Gantry->MoveTo(20.0), "the move with the armed fault fails", "failed");
  ok &= CheckError(
    rig.Errors, rig.Device() + "drive fault 1 (amplifier over-current) during the move to 20 deg");
  return ok;
}
}

int TestModbusGantry(int, char*[])
{
  lfd::test::GantryRig rig;
  bool ok = rig.Start(false);
  vtkModbusGantry* device = rig.Gantry;
  const std::string name = rig.Device();

  ok &= Check(!device->MoveTo(20.0), "a move before homing fails", "failed");
  ok &= CheckError(rig.Errors,
    name + "cannot start the move to 20 deg: the axis is not homed (call Home() first)");
  ok &= Check(device->UpdateState() && std::fabs(device->GetActualAngle() - 10.0) < 1e-9 &&
      !device->IsHomed(),
    "unhomed at the power-up position 10 deg",
    device->GetActualAngle());

  const bool homed = device->Home() && device->IsHomed() && device->IsInPosition();
  ok &= Check(homed && device->GetActualAngle() == 0.0, "homed at 0 deg", device->GetActualAngle());
  const bool moved = device->MoveTo(10.0);
  ok &=
    Check(moved && device->GetActualAngle() == 10.0, "moved to 10 deg", device->GetActualAngle());
  ok &= CheckProfileTiming(rig);
  ok &= CheckStop(rig);

  ok &= Check(!device->MoveTo(400.0), "a move beyond the soft limits fails", "failed");
  ok &= CheckError(rig.Errors,
    name + "cannot start the move to 400 deg: outside the soft limits [-360 deg, 360 deg]");
  device->SetSoftLimits(-5.0, 90.0);
  ok &= device->Enable();
  ok &= Check(!device->MoveTo(-10.0), "a move below new soft limits fails", "failed");
  ok &= CheckError(rig.Errors,
    name + "cannot start the move to -10 deg: outside the soft limits [-5 deg, 90 deg]");

  device->SetSoftLimits(-360.0, 360.0);
  ok &= device->Enable() && CheckRegisterMap(rig);
  ok &= Check(!rig.Errors->HasError(),
    "no other error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "none");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
