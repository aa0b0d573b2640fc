#include "vtkModbusGantry.h"

#include "lfdGantryRegisters.h"
#include "lfdJsonFields.h"
#include "lfdModbusClient.h"
#include "lfdMotionProfile.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

namespace gantry = lfd::gantry;

namespace
{
/// "30", "12.5": angles in messages, as a user would type them.
std::string Degrees(double angle)
{
  std::ostringstream text;
  text << angle << " deg";
  return text.str();
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}

/// The connection and the motion being waited for.
class vtkModbusGantry::vtkInternals
{
public:
  lfd::ModbusClient Client;
  uint16_t WatchdogCount = 0;
  /// The motion waited for: "the move to 30 deg", "homing".
  std::string Motion;
  double Deadline = 0.0;
  double DeadlineSeconds = 0.0;
};

vtkStandardNewMacro(vtkModbusGantry);

vtkModbusGantry::vtkModbusGantry()
  : Internals(new vtkInternals)
{
}

vtkModbusGantry::~vtkModbusGantry()
{
  this->SetAddress(nullptr);
}

std::string vtkModbusGantry::GetDeviceName() const
{
  return "gantry " + std::string(this->Address ? this->Address : "(no address)") + ":" +
    std::to_string(this->Port);
}

void vtkModbusGantry::Refuse(const std::string& reason)
{
  vtkErrorMacro(<< this->GetDeviceName() << ": " << reason);
}

void vtkModbusGantry::RefuseRequest(int error, const std::string& during)
{
  this->Refuse(
    this->Internals->Client.DescribeFailure(error) + (during.empty() ? "" : " during " + during));
}

namespace
{
/// The gantry's connection settings, as the Modbus client takes them.
lfd::ModbusSettings ConnectionSettings(vtkModbusGantry* gantry)
{
  lfd::ModbusSettings settings;
  settings.Address = gantry->GetAddress() ? gantry->GetAddress() : "";
  settings.Port = gantry->GetPort();
  settings.ConnectTimeout = gantry->GetConnectTimeout();
  settings.ResponseTimeout = gantry->GetResponseTimeout();
  settings.Retries = gantry->GetRetries();
  return settings;
}
}

std::string vtkModbusGantry::CheckSettings(bool fileFields)
{
  const std::string connection = lfd::CheckModbusSettings(ConnectionSettings(this), fileFields);
  if (!connection.empty())
  {
    return connection;
  }
  const lfd::SettingCheck checks[] = {
    { "Velocity",
      "velocity",
      this->Velocity,
      0.0,
      65535 * gantry::VelocityUnit,
      false,
      " degree/s" },
    { "Acceleration",
      "acceleration",
      this->Acceleration,
      0.0,
      65535 * gantry::AccelerationUnit,
      false,
      " degree/s^2" },
    { "SoftLimits[0]", "soft_limits[0]", this->SoftLimits[0], -100000.0, 100000.0, true, " deg" },
    { "SoftLimits[1]", "soft_limits[1]", this->SoftLimits[1], -100000.0, 100000.0, true, " deg" },
    { "WatchdogTimeout", "watchdog_timeout", this->WatchdogTimeout, 0.0, 65.535, true, " s" },
    { "DeadlineFactor", "deadline_factor", this->DeadlineFactor, 1.0, 100.0, true, "" },
    { "DeadlineMargin", "deadline_margin", this->DeadlineMargin, 0.0, 3600.0, true, " s" },
    { "PollInterval", "poll_interval", this->PollInterval, 0.0, 1.0, false, " s" },
  };
  const std::string motion =
    lfd::CheckSettings(checks, static_cast<int>(sizeof(checks) / sizeof(checks[0])), fileFields);
  if (!motion.empty())
  {
    return motion;
  }
  if (!(this->SoftLimits[0] < this->SoftLimits[1]))
  {
    std::ostringstream reason;
    reason << (fileFields ? "field \"soft_limits\": " : "SoftLimits ") << "[" << this->SoftLimits[0]
           << ", " << this->SoftLimits[1] << "] deg: the minimum is not below the maximum";
    return reason.str();
  }
  return std::string();
}

bool vtkModbusGantry::ReadConfiguration(const char* fileName)
{
  namespace io = lfd::io;
  const std::string path = fileName ? fileName : "";
  io::Json document;
  std::string error;
  if (!io::ParseJsonFile(path, document, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  // Read into a copy: a refused description changes nothing.
  vtkNew<vtkModbusGantry> read;
  try
  {
    const std::string format = io::GetString(io::RequireMember(document, "", "format"), "format");
    if (format != "lfd-gantry")
    {
      throw io::FieldError("format", "expected \"lfd-gantry\", found \"" + format + "\"");
    }
    if (io::GetInteger(io::RequireMember(document, "", "version"), "version", 0, VTK_INT_MAX) != 1)
    {
      throw io::FieldError("version", "unsupported version (this reader reads version 1)");
    }
    read->SetAddress(io::GetString(io::RequireMember(document, "", "address"), "address").c_str());
    read->Port =
      static_cast<int>(io::GetInteger(io::RequireMember(document, "", "port"), "port", 1, 65535));
    const struct
    {
      const char* Field;
      double vtkModbusGantry::*Value;
      double Current;
    } numbers[] = {
      { "connect_timeout", &vtkModbusGantry::ConnectTimeout, this->ConnectTimeout },
      { "response_timeout", &vtkModbusGantry::ResponseTimeout, this->ResponseTimeout },
      { "velocity", &vtkModbusGantry::Velocity, this->Velocity },
      { "acceleration", &vtkModbusGantry::Acceleration, this->Acceleration },
      { "watchdog_timeout", &vtkModbusGantry::WatchdogTimeout, this->WatchdogTimeout },
      { "deadline_factor", &vtkModbusGantry::DeadlineFactor, this->DeadlineFactor },
      { "deadline_margin", &vtkModbusGantry::DeadlineMargin, this->DeadlineMargin },
      { "poll_interval", &vtkModbusGantry::PollInterval, this->PollInterval },
    };
    for (const auto& number : numbers)
    {
      const io::Json* value = io::FindMember(document, "", number.Field);
      (*read).*number.Value = value ? io::GetNumber(*value, number.Field) : number.Current;
    }
    const io::Json* retries = io::FindMember(document, "", "retries");
    read->Retries =
      retries ? static_cast<int>(io::GetInteger(*retries, "retries", 0, 100)) : this->Retries;
    const io::Json* limits = io::FindMember(document, "", "soft_limits");
    const std::vector<double> soft = limits
      ? io::GetNumbers(*limits, "soft_limits", 2)
      : std::vector<double>(this->SoftLimits, this->SoftLimits + 2);
    read->SetSoftLimits(soft[0], soft[1]);
    const std::string refused = read->CheckSettings(true);
    if (!refused.empty())
    {
      throw std::runtime_error(refused);
    }
  }
  catch (const std::runtime_error& e)
  {
    vtkErrorMacro(<< path << ": " << e.what());
    return false;
  }
  this->SetAddress(read->Address);
  this->Port = read->Port;
  this->ConnectTimeout = read->ConnectTimeout;
  this->ResponseTimeout = read->ResponseTimeout;
  this->Retries = read->Retries;
  this->Velocity = read->Velocity;
  this->Acceleration = read->Acceleration;
  this->SetSoftLimits(read->SoftLimits);
  this->WatchdogTimeout = read->WatchdogTimeout;
  this->DeadlineFactor = read->DeadlineFactor;
  this->DeadlineMargin = read->DeadlineMargin;
  this->PollInterval = read->PollInterval;
  this->Modified();
  return true;
}

bool vtkModbusGantry::Connect()
{
  this->Disconnect();
  const std::string refused = this->CheckSettings(false);
  if (!refused.empty())
  {
    this->Refuse(refused);
    return false;
  }
  this->Internals->Client.Reset(ConnectionSettings(this));
  uint16_t identity[2] = { 0, 0 };
  const int error = this->Internals->Client.Transact([&](modbus_t* context)
    { return modbus_read_registers(context, gantry::Identity, 2, identity); },
    this->Retries);
  if (error)
  {
    this->RefuseRequest(error, "");
    this->Disconnect();
    return false;
  }
  if (identity[0] != gantry::IdentityValue || identity[1] != gantry::MapVersionValue)
  {
    std::ostringstream reason;
    reason << "not an lfd gantry controller: registers " << gantry::Identity << "-"
           << gantry::MapVersion << " read " << identity[0] << ", " << identity[1] << " (expected "
           << gantry::IdentityValue << ", " << gantry::MapVersionValue
           << ": see the register map in Data/README.md)";
    this->Refuse(reason.str());
    this->Disconnect();
    return false;
  }
  return true;
}

void vtkModbusGantry::Disconnect()
{
  this->Internals->Client.Close();
}

bool vtkModbusGantry::IsConnected() const
{
  return this->Internals->Client.IsConnected();
}

bool vtkModbusGantry::IsReady() const
{
  return (this->StatusWord & gantry::ReadyBit) != 0;
}

bool vtkModbusGantry::IsMoving() const
{
  return (this->StatusWord & gantry::MovingBit) != 0;
}

bool vtkModbusGantry::IsInPosition() const
{
  return (this->StatusWord & gantry::InPositionBit) != 0;
}

bool vtkModbusGantry::IsHomed() const
{
  return (this->StatusWord & gantry::HomedBit) != 0;
}

bool vtkModbusGantry::UpdateState()
{
  vtkInternals& internals = *this->Internals;
  // One request refreshes the watchdog and reads the state (function 23).
  uint16_t registers[4];
  const int error = internals.Client.Transact(
    [&](modbus_t* context)
    {
      const uint16_t count = ++internals.WatchdogCount;
      return modbus_write_and_read_registers(
        context, gantry::Watchdog, 1, &count, gantry::StatusWord, 4, registers);
    },
    this->Retries);
  if (error)
  {
    this->RefuseRequest(error, this->Internals->Motion);
    return false;
  }
  this->StatusWord = registers[0];
  this->FaultCode = registers[1];
  this->ActualAngle = gantry::GetInt32(registers + 2) * gantry::PositionUnit;
  return true;
}

bool vtkModbusGantry::Command(int control, const std::string& during)
{
  const int error = this->Internals->Client.Transact([&](modbus_t* context)
    { return modbus_write_register(context, gantry::ControlWord, control); },
    this->Retries);
  if (error)
  {
    this->RefuseRequest(error, during);
    return false;
  }
  return true;
}

bool vtkModbusGantry::Enable()
{
  if (!this->UpdateState())
  {
    return false;
  }
  if (this->FaultCode != gantry::NoFault)
  {
    this->Refuse("drive fault " + std::to_string(this->FaultCode) + " (" +
      gantry::DescribeFault(this->FaultCode) + "): reset it first");
    return false;
  }
  uint16_t registers[gantry::Watchdog - gantry::Velocity];
  registers[0] = static_cast<uint16_t>(std::lround(this->Velocity / gantry::VelocityUnit));
  registers[1] = static_cast<uint16_t>(std::lround(this->Acceleration / gantry::AccelerationUnit));
  gantry::SetInt32(registers + (gantry::SoftLimitMinimum - gantry::Velocity),
    static_cast<int32_t>(std::lround(this->SoftLimits[0] / gantry::PositionUnit)));
  gantry::SetInt32(registers + (gantry::SoftLimitMaximum - gantry::Velocity),
    static_cast<int32_t>(std::lround(this->SoftLimits[1] / gantry::PositionUnit)));
  registers[gantry::WatchdogTimeout - gantry::Velocity] =
    static_cast<uint16_t>(std::lround(this->WatchdogTimeout * 1000.0));
  const int error = this->Internals->Client.Transact(
    [&](modbus_t* context)
    {
      return modbus_write_registers(
        context, gantry::Velocity, gantry::Watchdog - gantry::Velocity, registers);
    },
    this->Retries);
  if (error)
  {
    this->RefuseRequest(error, "");
    return false;
  }
  if (!this->Command(gantry::EnableBit, "") || !this->UpdateState())
  {
    return false;
  }
  if (!this->IsReady())
  {
    this->Refuse("not ready after enabling (status word " + std::to_string(this->StatusWord) + ")");
    return false;
  }
  return true;
}

bool vtkModbusGantry::CheckReady(bool homed, const std::string& motion)
{
  this->Internals->Motion.clear();
  if (!this->UpdateState())
  {
    return false;
  }
  if (this->FaultCode != gantry::NoFault)
  {
    this->Refuse("cannot start " + motion + ": drive fault " + std::to_string(this->FaultCode) +
      " (" + gantry::DescribeFault(this->FaultCode) + "): reset it first");
    return false;
  }
  if (!this->IsReady())
  {
    this->Refuse("cannot start " + motion + ": the axis is not enabled (call Enable() first)");
    return false;
  }
  if (this->IsMoving())
  {
    this->Refuse("cannot start " + motion + ": the axis is still moving");
    return false;
  }
  if (homed && !this->IsHomed())
  {
    this->Refuse("cannot start " + motion + ": the axis is not homed (call Home() first)");
    return false;
  }
  return true;
}

bool vtkModbusGantry::BeginMotion(double target,
  double velocity,
  int control,
  const std::string& motion)
{
  const double duration =
    lfd::MotionProfile::Trapezoid(0.0, this->ActualAngle, target, velocity, this->Acceleration)
      .GetDuration();
  this->Internals->DeadlineSeconds = this->DeadlineFactor * duration + this->DeadlineMargin;
  this->Internals->Deadline = Now() + this->Internals->DeadlineSeconds;
  if (!this->Command(gantry::EnableBit | control, motion))
  {
    return false;
  }
  this->Internals->Motion = motion;
  return true;
}

bool vtkModbusGantry::Home()
{
  return this->CheckReady(false, "homing") &&
    this->BeginMotion(0.0, 0.5 * this->Velocity, gantry::HomeBit, "homing") &&
    this->WaitInPosition();
}

bool vtkModbusGantry::MoveTo(double angle)
{
  return this->StartMove(angle) && this->WaitInPosition();
}

bool vtkModbusGantry::StartMove(double angle)
{
  const std::string motion = "the move to " + Degrees(angle);
  if (!this->CheckReady(true, motion))
  {
    return false;
  }
  // !(a <= b) also refuses NaN.
  if (!(angle >= this->SoftLimits[0] && angle <= this->SoftLimits[1]))
  {
    this->Refuse("cannot start " + motion + ": outside the soft limits [" +
      Degrees(this->SoftLimits[0]) + ", " + Degrees(this->SoftLimits[1]) + "]");
    return false;
  }
  uint16_t target[2];
  gantry::SetInt32(target, static_cast<int32_t>(std::lround(angle / gantry::PositionUnit)));
  const int error = this->Internals->Client.Transact([&](modbus_t* context)
    { return modbus_write_registers(context, gantry::TargetPosition, 2, target); },
    this->Retries);
  if (error)
  {
    this->RefuseRequest(error, motion);
    return false;
  }
  return this->BeginMotion(angle, this->Velocity, gantry::StartBit, motion);
}

bool vtkModbusGantry::WaitInPosition()
{
  const bool arrived = this->PollMotion();
  // Later failures are no longer "during" this motion.
  this->Internals->Motion.clear();
  return arrived;
}

bool vtkModbusGantry::PollMotion()
{
  vtkInternals& internals = *this->Internals;
  const std::string motion = internals.Motion.empty() ? "a motion" : internals.Motion;
  for (;;)
  {
    if (!this->UpdateState())
    {
      // Best effort, once: the controller's watchdog stops the axis when
      // this does not reach it either.
      internals.Client.Transact([](modbus_t* context)
        { return modbus_write_register(context, gantry::ControlWord, gantry::QuickStopBit); },
        0);
      return false;
    }
    if (this->FaultCode != gantry::NoFault)
    {
      // The controller quick-stopped the axis itself (its fault reaction).
      this->Refuse("drive fault " + std::to_string(this->FaultCode) + " (" +
        gantry::DescribeFault(this->FaultCode) + ") during " + motion);
      return false;
    }
    if (!this->IsMoving())
    {
      if (this->IsInPosition())
      {
        return true;
      }
      this->Refuse(
        motion + " stopped before reaching its target, at " + Degrees(this->ActualAngle));
      return false;
    }
    if (Now() > internals.Deadline)
    {
      std::ostringstream reason;
      reason << motion << " was not in position within its deadline of "
             << internals.DeadlineSeconds << " s; quick-stopped";
      if (this->Command(gantry::EnableBit | gantry::QuickStopBit, motion))
      {
        this->Refuse(reason.str());
      }
      return false;
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(this->PollInterval));
  }
}

bool vtkModbusGantry::Stop()
{
  return this->Command(gantry::EnableBit | gantry::StopBit, "");
}

bool vtkModbusGantry::QuickStop()
{
  return this->Command(gantry::EnableBit | gantry::QuickStopBit, "");
}

bool vtkModbusGantry::ResetFault()
{
  if (!this->Command(gantry::FaultResetBit, "") || !this->UpdateState())
  {
    return false;
  }
  if (this->FaultCode != gantry::NoFault)
  {
    this->Refuse("drive fault " + std::to_string(this->FaultCode) + " (" +
      gantry::DescribeFault(this->FaultCode) + ") persists after a reset");
    return false;
  }
  return true;
}

void vtkModbusGantry::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Address: " << (this->Address ? this->Address : "(none)") << "\n";
  os << indent << "Port: " << this->Port << "\n";
  os << indent << "ConnectTimeout: " << this->ConnectTimeout << " s\n";
  os << indent << "ResponseTimeout: " << this->ResponseTimeout << " s\n";
  os << indent << "Retries: " << this->Retries << "\n";
  os << indent << "Velocity: " << this->Velocity << " degree/s\n";
  os << indent << "Acceleration: " << this->Acceleration << " degree/s^2\n";
  os << indent << "SoftLimits: " << this->SoftLimits[0] << ", " << this->SoftLimits[1] << "\n";
  os << indent << "WatchdogTimeout: " << this->WatchdogTimeout << " s\n";
  os << indent << "DeadlineFactor: " << this->DeadlineFactor << "\n";
  os << indent << "DeadlineMargin: " << this->DeadlineMargin << " s\n";
  os << indent << "PollInterval: " << this->PollInterval << " s\n";
  os << indent << "Connected: " << (this->IsConnected() ? "yes" : "no") << "\n";
  os << indent << "ActualAngle: " << this->ActualAngle << "\n";
  os << indent << "StatusWord: " << this->StatusWord << "\n";
  os << indent << "FaultCode: " << this->FaultCode << "\n";
}
