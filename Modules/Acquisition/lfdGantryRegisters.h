/**
 * @file   lfdGantryRegisters.h
 * @brief  The gantry's Modbus register map, shared by the client
 *         (vtkModbusGantry) and the simulator (vtkGantrySimulator).
 *
 * Modelled on the motion controllers that drive real turntables and ring
 * gantries (CiA-402 control/status words, Oriental Motor AZ direct data
 * operation, Leadshine PR mode): a control word of commands, a status word,
 * a fault code, 32-bit target and actual positions, velocity, acceleration,
 * soft limits and a watchdog. All are holding registers (function codes 3,
 * 6 and 16), 0-based addresses; a 32-bit value takes two registers, high word
 * first (signed, two's complement). Besides the registers, the controller's
 * digital outputs are coils 0 .. CoilCount - 1 (function codes 1, 5 and 15),
 * e.g. the coaxial lamp (vtkModbusLight). Data/README.md documents the map
 * for users wiring a real controller.
 */
#ifndef lfdGantryRegisters_h
#define lfdGantryRegisters_h

#include <cstdint>

namespace lfd
{
namespace gantry
{
/// Register addresses.
enum Register : int
{
  ControlWord = 0,       ///< commands (ControlBits), read back as the Enable bit only
  StatusWord = 1,        ///< read-only (StatusBits)
  FaultCodeRegister = 2, ///< read-only (FaultCode)
  ActualPosition = 3,    ///< read-only, 2 registers, 0.001 degree
  TargetPosition = 5,    ///< 2 registers, 0.001 degree
  Velocity = 7,          ///< 0.01 degree/s, unsigned
  Acceleration = 8,      ///< 0.1 degree/s^2, unsigned (deceleration too)
  SoftLimitMinimum = 9,  ///< 2 registers, 0.001 degree
  SoftLimitMaximum = 11, ///< 2 registers, 0.001 degree
  WatchdogTimeout = 13,  ///< milliseconds, 0 = off
  Watchdog = 14,         ///< any write refreshes the watchdog
  Identity = 15,         ///< read-only, IdentityValue
  MapVersion = 16,       ///< read-only, MapVersionValue
  SimulatorFault = 17,   ///< simulator only: the fault (FaultMode) armed for the next move
  RegisterCount = 18
};

/// Control word bits. Enable is a level; the others are commands carried
/// out when a write sets them (they read back as 0).
enum ControlBits : uint16_t
{
  EnableBit = 1u << 0,
  StartBit = 1u << 1,     ///< move to TargetPosition (needs Ready and Homed)
  HomeBit = 1u << 2,      ///< search the home sensor; position 0 there
  StopBit = 1u << 3,      ///< decelerate at Acceleration
  QuickStopBit = 1u << 4, ///< decelerate at QuickStopFactor x Acceleration
  FaultResetBit = 1u << 7
};

/// Status word bits.
enum StatusBits : uint16_t
{
  ReadyBit = 1u << 0, ///< enabled, no fault
  MovingBit = 1u << 1,
  InPositionBit = 1u << 2, ///< at the target of the last move or homing
  HomedBit = 1u << 3,
  FaultBit = 1u << 4,
  EmergencyStopBit = 1u << 5,
  LimitSwitchBit = 1u << 6
};

/// Fault codes (FaultCodeRegister). A fault quick-stops the axis and
/// disables it: FaultResetBit clears it, then Enable again.
enum FaultCode : uint16_t
{
  NoFault = 0,
  DriveFault = 1,      ///< amplifier fault (over-current)
  EmergencyStop = 2,   ///< the e-stop circuit opened
  LimitSwitch = 3,     ///< a hardware limit switch tripped
  WatchdogExpired = 4, ///< no watchdog write within WatchdogTimeout during a move
  ConnectionLost = 5,  ///< the controlling connection closed during a move
  SoftLimit = 6        ///< Start with a target outside the soft limits
};

/// The simulator's faults on demand (SimulatorFault register, `lfd
/// gantry-sim --fault`): armed, each but Slow and StuckCoils fires half-way
/// through the next move (by time) and disarms; those two last until another
/// mode is armed.
enum FaultMode : uint16_t
{
  NoFaultMode = 0,
  SilentMode = 1,         ///< stops answering for the simulator's SilentTime
  DriveFaultMode = 2,     ///< DriveFault
  EmergencyStopMode = 3,  ///< EmergencyStop
  LimitSwitchMode = 4,    ///< LimitSwitch
  SlowMode = 5,           ///< every move at SlowFactor of its velocity, until disarmed
  DropConnectionMode = 6, ///< closes every connection (ConnectionLost)
  StuckCoilsMode = 7, ///< the coils ignore writes (a relay that does not switch), until disarmed
  FaultModeCount = 8
};

/// The controller's digital outputs (coils 0 .. CoilCount - 1), e.g. the
/// coaxial lamp's relay.
constexpr int CoilCount = 8;

constexpr uint16_t IdentityValue = 0x4C46; // "LF"
constexpr uint16_t MapVersionValue = 1;
/// Quick-stop deceleration in units of the Acceleration register.
constexpr double QuickStopFactor = 4.0;
/// The register scales: 1 register unit in degrees (per second, per second^2).
constexpr double PositionUnit = 0.001;
constexpr double VelocityUnit = 0.01;
constexpr double AccelerationUnit = 0.1;

/// What a fault code means, for messages ("emergency stop").
inline const char* DescribeFault(int code)
{
  switch (code)
  {
    case NoFault:
      return "no fault";
    case DriveFault:
      return "amplifier over-current";
    case EmergencyStop:
      return "emergency stop";
    case LimitSwitch:
      return "limit switch tripped";
    case WatchdogExpired:
      return "watchdog expired";
    case ConnectionLost:
      return "connection lost";
    case SoftLimit:
      return "target outside the soft limits";
    default:
      return "unknown fault";
  }
}

/// The fault modes' names (`lfd gantry-sim --fault NAME`), indexed by FaultMode.
inline const char* FaultModeName(int mode)
{
  static const char* const names[FaultModeCount] = {
    "none", "silent", "drive", "estop", "limit", "slow", "drop", "stuck"
  };
  return mode >= 0 && mode < FaultModeCount ? names[mode] : "unknown";
}

///@{
/// A 32-bit value in two registers, high word first.
inline int32_t GetInt32(const uint16_t* registers)
{
  return static_cast<int32_t>((static_cast<uint32_t>(registers[0]) << 16) | registers[1]);
}
inline void SetInt32(uint16_t* registers, int32_t value)
{
  registers[0] = static_cast<uint16_t>(static_cast<uint32_t>(value) >> 16);
  registers[1] = static_cast<uint16_t>(static_cast<uint32_t>(value) & 0xFFFFu);
}
///@}
}
}

#endif
