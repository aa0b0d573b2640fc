#include "vtkGantrySimulator.h"

#include "lfdGantryRegisters.h"
#include "lfdMotionProfile.h"

#include "vtkObjectFactory.h"

#include <modbus/modbus.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace gantry = lfd::gantry;

namespace
{
constexpr double Never = std::numeric_limits<double>::infinity();
/// How often the axis is updated between requests (faults, watchdog, arrival).
constexpr int TickMicroseconds = 5000;

/// Whether a client may write the register (the others are read-only).
bool IsWritable(int address)
{
  switch (address)
  {
    case gantry::StatusWord:
    case gantry::FaultCodeRegister:
    case gantry::ActualPosition:
    case gantry::ActualPosition + 1:
    case gantry::Identity:
    case gantry::MapVersion:
      return false;
    default:
      return address >= 0 && address < gantry::RegisterCount;
  }
}
}

/// The controller: its registers, its axis and its connections. Every
/// member is used under Mutex by the serving thread and the accessors.
class vtkGantrySimulator::vtkInternals
{
public:
  modbus_t* Context = nullptr;
  modbus_mapping_t* Mapping = nullptr;
  int ListenSocket = -1;
  int BoundPort = 0;
  std::vector<int> Clients;
  int Connections = 0;
  std::thread Thread;
  std::atomic<bool> StopRequested{ false };
  std::mutex Mutex;
  std::chrono::steady_clock::time_point Epoch = std::chrono::steady_clock::now();

  lfd::MotionProfile Profile = lfd::MotionProfile::Rest(0.0);
  bool MoveActive = false;
  bool Homing = false;
  bool InPosition = false;
  bool Homed = false;
  bool Enabled = false;
  bool EmergencyStopActive = false;
  bool LimitSwitchActive = false;
  int FaultCode = gantry::NoFault;
  int ArmedFault = gantry::NoFaultMode;
  int QuickStops = 0;
  double TriggerTime = Never;
  double SilentUntil = -Never;
  double LastWatchdog = 0.0;
  double SilentTime = 2.0;
  double SlowFactor = 0.1;

  ~vtkInternals() { this->Close(); }

  double Now() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Epoch).count();
  }

  uint16_t* Registers() { return this->Mapping->tab_registers; }
  double Velocity() { return this->Registers()[gantry::Velocity] * gantry::VelocityUnit; }
  double Acceleration()
  {
    return this->Registers()[gantry::Acceleration] * gantry::AccelerationUnit;
  }
  double Angle(int address)
  {
    return gantry::GetInt32(this->Registers() + address) * gantry::PositionUnit;
  }

  double Position(double now)
  {
    double position, velocity;
    this->Profile.Evaluate(now, position, velocity);
    return position;
  }

  bool Moving(double now) const { return now < this->Profile.GetEnd(); }

  /// Decelerates from the current motion to rest (at rest: nothing changes).
  void Halt(double now, double deceleration)
  {
    if (!this->Moving(now))
    {
      return;
    }
    double position, velocity;
    this->Profile.Evaluate(now, position, velocity);
    this->Profile = lfd::MotionProfile::Stop(now, position, velocity, deceleration);
    this->MoveActive = false;
    this->Homing = false;
    this->InPosition = false;
    this->TriggerTime = Never;
  }

  /// A fault quick-stops and disables the axis (CiA-402's fault reaction).
  void RaiseFault(int code, double now)
  {
    this->FaultCode = code;
    this->Enabled = false;
    this->Halt(now, gantry::QuickStopFactor * this->Acceleration());
  }

  void CloseClients()
  {
    for (int client : this->Clients)
    {
      ::close(client);
    }
    this->Clients.clear();
  }

  /// The armed fault, half-way through a move.
  void Fire(double now)
  {
    const int mode = this->ArmedFault;
    this->ArmedFault = gantry::NoFaultMode;
    this->TriggerTime = Never;
    switch (mode)
    {
      case gantry::SilentMode:
        this->SilentUntil = now + this->SilentTime;
        break;
      case gantry::DriveFaultMode:
        this->RaiseFault(gantry::DriveFault, now);
        break;
      case gantry::EmergencyStopMode:
        this->EmergencyStopActive = true;
        this->RaiseFault(gantry::EmergencyStop, now);
        break;
      case gantry::LimitSwitchMode:
        this->LimitSwitchActive = true;
        this->RaiseFault(gantry::LimitSwitch, now);
        break;
      case gantry::DropConnectionMode:
        this->CloseClients();
        this->RaiseFault(gantry::ConnectionLost, now);
        break;
      default:
        break;
    }
  }

  /// Advances the controller to `now`: armed faults, the watchdog, arrival.
  void Update(double now)
  {
    if (this->Moving(now) && now >= this->TriggerTime)
    {
      this->Fire(now);
    }
    const double watchdog = this->Registers()[gantry::WatchdogTimeout] * 0.001;
    if (this->MoveActive && watchdog > 0.0 && now - this->LastWatchdog > watchdog)
    {
      this->RaiseFault(gantry::WatchdogExpired, now);
    }
    if (this->MoveActive && !this->Moving(now))
    {
      this->MoveActive = false;
      this->InPosition = true;
      this->Homed = this->Homed || this->Homing;
      this->Homing = false;
    }
  }

  /// Starts a move (or homing) from rest to `target`.
  void StartMotion(double now, double target, double velocity, bool homing)
  {
    this->Profile = lfd::MotionProfile::Trapezoid(
      now, this->Position(now), target, velocity, this->Acceleration());
    this->MoveActive = true;
    this->Homing = homing;
    this->InPosition = false;
    this->LastWatchdog = now;
    const bool fires = !homing && this->ArmedFault != gantry::NoFaultMode &&
      this->ArmedFault != gantry::SlowMode && this->ArmedFault != gantry::StuckCoilsMode;
    this->TriggerTime = fires ? now + 0.5 * this->Profile.GetDuration() : Never;
  }

  /// Carries out a control word written by a client.
  void Command(uint16_t control, double now)
  {
    const double acceleration = this->Acceleration();
    if ((control & gantry::FaultResetBit) && this->FaultCode != gantry::NoFault &&
      !this->Moving(now))
    {
      this->FaultCode = gantry::NoFault;
      this->EmergencyStopActive = false;
      this->LimitSwitchActive = false;
    }
    const bool enable = (control & gantry::EnableBit) != 0;
    if (control & gantry::QuickStopBit || (!enable && this->Moving(now)))
    {
      ++this->QuickStops;
      this->Halt(now, gantry::QuickStopFactor * acceleration);
    }
    else if (control & gantry::StopBit)
    {
      this->Halt(now, acceleration);
    }
    this->Enabled = enable && this->FaultCode == gantry::NoFault;
    if (this->Enabled && !this->Moving(now))
    {
      if (control & gantry::HomeBit)
      {
        this->StartMotion(now, 0.0, 0.5 * this->Velocity(), true);
      }
      else if (control & gantry::StartBit)
      {
        const double target = this->Angle(gantry::TargetPosition);
        if (target < this->Angle(gantry::SoftLimitMinimum) ||
          target > this->Angle(gantry::SoftLimitMaximum))
        {
          this->RaiseFault(gantry::SoftLimit, now);
        }
        else
        {
          const bool slow = this->ArmedFault == gantry::SlowMode;
          this->StartMotion(now, target, this->Velocity() * (slow ? this->SlowFactor : 1.0), false);
        }
      }
    }
  }

  uint16_t Status(double now)
  {
    uint16_t status = 0;
    status |= this->Enabled && this->FaultCode == gantry::NoFault ? gantry::ReadyBit : 0;
    status |= this->Moving(now) ? gantry::MovingBit : 0;
    status |= this->InPosition ? gantry::InPositionBit : 0;
    status |= this->Homed ? gantry::HomedBit : 0;
    status |= this->FaultCode != gantry::NoFault ? gantry::FaultBit : 0;
    status |= this->EmergencyStopActive ? gantry::EmergencyStopBit : 0;
    status |= this->LimitSwitchActive ? gantry::LimitSwitchBit : 0;
    return status;
  }

  /// The read-only registers, as they are at `now`.
  void Refresh(double now)
  {
    uint16_t* registers = this->Registers();
    registers[gantry::ControlWord] = this->Enabled ? gantry::EnableBit : 0;
    registers[gantry::StatusWord] = this->Status(now);
    registers[gantry::FaultCodeRegister] = static_cast<uint16_t>(this->FaultCode);
    gantry::SetInt32(registers + gantry::ActualPosition,
      static_cast<int32_t>(std::lround(this->Position(now) / gantry::PositionUnit)));
  }

  /// Refuses a write to a read-only register, out of the map, or of a value
  /// the register cannot take (a zero velocity or acceleration, an unknown
  /// fault mode); returns the Modbus exception, or 0 to accept it.
  int CheckWrite(const uint8_t* values, int address, int count)
  {
    for (int i = 0; i < count; ++i)
    {
      const int target = address + i;
      const int value = (values[2 * i] << 8) | values[2 * i + 1];
      if (!IsWritable(target))
      {
        return MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
      }
      if (((target == gantry::Velocity || target == gantry::Acceleration) && value == 0) ||
        (target == gantry::SimulatorFault && value >= gantry::FaultModeCount))
      {
        return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
      }
    }
    return 0;
  }

  /// Answers one request (function codes 1, 3, 5, 6, 15, 16 and 23) and
  /// carries out what it wrote.
  void Answer(const uint8_t* query, int length, double now)
  {
    const int header = modbus_get_header_length(this->Context);
    const int function = query[header];
    const auto word = [&](int offset)
    { return (query[header + offset] << 8) | query[header + offset + 1]; };
    int address = word(1);
    int count = 0;
    const uint8_t* values = nullptr;
    if (function == 0x06)
    {
      count = 1;
      values = query + header + 3;
    }
    else if (function == 0x10)
    {
      count = word(3);
      values = query + header + 6;
    }
    else if (function == 0x17)
    {
      // Write then read: the client's state poll refreshes the watchdog.
      address = word(5);
      count = word(7);
      values = query + header + 10;
    }
    else if (function != 0x03 && function != 0x01 && function != 0x05 && function != 0x0F)
    {
      modbus_reply_exception(this->Context, query, MODBUS_EXCEPTION_ILLEGAL_FUNCTION);
      return;
    }
    const int refused = values ? this->CheckWrite(values, address, count) : 0;
    if (refused)
    {
      modbus_reply_exception(this->Context, query, refused);
      return;
    }
    this->Refresh(now);
    // Stuck coils: the write is acknowledged, the outputs do not change
    // (libmodbus checks the coils' addresses and answers).
    const std::vector<uint8_t> coils(
      this->Mapping->tab_bits, this->Mapping->tab_bits + this->Mapping->nb_bits);
    modbus_reply(this->Context, query, length, this->Mapping);
    if (this->ArmedFault == gantry::StuckCoilsMode)
    {
      std::copy(coils.begin(), coils.end(), this->Mapping->tab_bits);
    }
    for (int i = 0; i < count; ++i)
    {
      if (address + i == gantry::Watchdog)
      {
        this->LastWatchdog = now;
      }
      else if (address + i == gantry::SimulatorFault)
      {
        this->ArmedFault = this->Registers()[gantry::SimulatorFault];
      }
    }
    if (values && address <= gantry::ControlWord && address + count > gantry::ControlWord)
    {
      this->Command(this->Registers()[gantry::ControlWord], now);
    }
    this->Refresh(now);
  }

  /// Waits up to one tick for connections and requests and answers them.
  void ServeOnce()
  {
    fd_set readable;
    FD_ZERO(&readable);
    FD_SET(this->ListenSocket, &readable);
    int highest = this->ListenSocket;
    std::vector<int> clients;
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      clients = this->Clients;
    }
    for (int client : clients)
    {
      FD_SET(client, &readable);
      highest = std::max(highest, client);
    }
    timeval timeout{ 0, TickMicroseconds };
    const int ready = ::select(highest + 1, &readable, nullptr, nullptr, &timeout);
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (ready > 0 && FD_ISSET(this->ListenSocket, &readable))
    {
      const int client = ::accept(this->ListenSocket, nullptr, nullptr);
      if (client >= 0)
      {
        this->Clients.push_back(client);
        ++this->Connections;
      }
    }
    for (int client : clients)
    {
      // A dropped-connection fault may have closed it meanwhile.
      if (ready <= 0 || !FD_ISSET(client, &readable) ||
        std::find(this->Clients.begin(), this->Clients.end(), client) == this->Clients.end())
      {
        continue;
      }
      uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
      modbus_set_socket(this->Context, client);
      const int length = modbus_receive(this->Context, query);
      const double now = this->Now();
      this->Update(now);
      const auto found = std::find(this->Clients.begin(), this->Clients.end(), client);
      if (found == this->Clients.end())
      {
        continue; // dropped by the fault that Update() fired
      }
      if (length < 0)
      {
        ::close(client);
        this->Clients.erase(found);
      }
      else if (length > 0 && now >= this->SilentUntil)
      {
        this->Answer(query, length, now);
      }
    }
    this->Update(this->Now());
  }

  void Close()
  {
    this->CloseClients();
    if (this->ListenSocket >= 0)
    {
      ::close(this->ListenSocket);
      this->ListenSocket = -1;
    }
    if (this->Context)
    {
      // The context's socket is a client's, already closed.
      modbus_set_socket(this->Context, -1);
      modbus_free(this->Context);
      this->Context = nullptr;
    }
    if (this->Mapping)
    {
      modbus_mapping_free(this->Mapping);
      this->Mapping = nullptr;
    }
    this->BoundPort = 0;
  }
};

vtkStandardNewMacro(vtkGantrySimulator);

vtkGantrySimulator::vtkGantrySimulator()
  : Internals(new vtkInternals)
{
  this->SetAddress("127.0.0.1");
}

vtkGantrySimulator::~vtkGantrySimulator()
{
  this->Stop();
  this->SetAddress(nullptr);
}

bool vtkGantrySimulator::Listen()
{
  vtkInternals& internals = *this->Internals;
  if (internals.ListenSocket >= 0)
  {
    return true;
  }
  const std::string device = "gantry simulator " +
    std::string(this->Address ? this->Address : "(no address)") + ":" + std::to_string(this->Port);
  if (!this->Address || !*this->Address)
  {
    vtkErrorMacro(<< device << ": no address to listen on");
    return false;
  }
  internals.Context = modbus_new_tcp(this->Address, this->Port);
  if (internals.Context)
  {
    internals.ListenSocket = modbus_tcp_listen(internals.Context, 8);
  }
  if (internals.ListenSocket < 0)
  {
    const int error = errno;
    internals.Close();
    vtkErrorMacro(<< device << ": cannot listen: " << modbus_strerror(error));
    return false;
  }
  sockaddr_in bound{};
  socklen_t size = sizeof(bound);
  ::getsockname(internals.ListenSocket, reinterpret_cast<sockaddr*>(&bound), &size);
  internals.BoundPort = ntohs(bound.sin_port);
  // A client that sends half a request must not stall the controller.
  modbus_set_indication_timeout(internals.Context, 1, 0);

  internals.Mapping = modbus_mapping_new(gantry::CoilCount, 0, gantry::RegisterCount, 0);
  uint16_t* registers = internals.Registers();
  registers[gantry::Velocity] = 3000;    // 30 degree/s
  registers[gantry::Acceleration] = 600; // 60 degree/s^2
  gantry::SetInt32(registers + gantry::SoftLimitMinimum, -360000);
  gantry::SetInt32(registers + gantry::SoftLimitMaximum, 360000);
  registers[gantry::Identity] = gantry::IdentityValue;
  registers[gantry::MapVersion] = gantry::MapVersionValue;
  registers[gantry::SimulatorFault] = static_cast<uint16_t>(this->Fault);
  internals.Profile = lfd::MotionProfile::Rest(this->StartAngle);
  internals.ArmedFault = this->Fault;
  internals.SilentTime = this->SilentTime;
  internals.SlowFactor = this->SlowFactor;
  internals.Refresh(internals.Now());
  return true;
}

int vtkGantrySimulator::GetBoundPort()
{
  return this->Internals->BoundPort;
}

bool vtkGantrySimulator::Start()
{
  if (this->Internals->Thread.joinable())
  {
    return true;
  }
  if (!this->Listen())
  {
    return false;
  }
  this->Internals->StopRequested = false;
  this->Internals->Thread = std::thread(
    [this]
    {
      while (!this->Internals->StopRequested)
      {
        this->Internals->ServeOnce();
      }
    });
  return true;
}

void vtkGantrySimulator::Stop()
{
  this->Internals->StopRequested = true;
  if (this->Internals->Thread.joinable())
  {
    this->Internals->Thread.join();
  }
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  this->Internals->Close();
}

bool vtkGantrySimulator::Serve()
{
  if (!this->Listen())
  {
    return false;
  }
  while (!this->Internals->StopRequested)
  {
    this->Internals->ServeOnce();
  }
  this->Stop();
  return true;
}

void vtkGantrySimulator::RequestStop()
{
  this->Internals->StopRequested = true;
}

void vtkGantrySimulator::ArmFault(int mode)
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  if (this->Internals->Mapping && mode >= 0 && mode < gantry::FaultModeCount)
  {
    this->Internals->ArmedFault = mode;
    this->Internals->Registers()[gantry::SimulatorFault] = static_cast<uint16_t>(mode);
  }
}

double vtkGantrySimulator::GetActualAngle()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  return this->Internals->Position(this->Internals->Now());
}

int vtkGantrySimulator::GetStatusWord()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  if (!this->Internals->Mapping)
  {
    return 0;
  }
  const double now = this->Internals->Now();
  this->Internals->Update(now);
  return this->Internals->Status(now);
}

int vtkGantrySimulator::GetFaultCode()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  return this->Internals->FaultCode;
}

double vtkGantrySimulator::GetActualVelocity()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  double position, velocity;
  this->Internals->Profile.Evaluate(this->Internals->Now(), position, velocity);
  return velocity;
}

int vtkGantrySimulator::GetNumberOfQuickStops()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  return this->Internals->QuickStops;
}

bool vtkGantrySimulator::GetCoil(int coil)
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  return this->Internals->Mapping && coil >= 0 && coil < this->Internals->Mapping->nb_bits &&
    this->Internals->Mapping->tab_bits[coil] != 0;
}

int vtkGantrySimulator::GetNumberOfConnections()
{
  std::lock_guard<std::mutex> lock(this->Internals->Mutex);
  return this->Internals->Connections;
}

void vtkGantrySimulator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Address: " << (this->Address ? this->Address : "(none)") << "\n";
  os << indent << "Port: " << this->Port << "\n";
  os << indent << "StartAngle: " << this->StartAngle << "\n";
  os << indent << "Fault: " << gantry::FaultModeName(this->Fault) << "\n";
  os << indent << "SilentTime: " << this->SilentTime << "\n";
  os << indent << "SlowFactor: " << this->SlowFactor << "\n";
  os << indent << "BoundPort: " << this->Internals->BoundPort << "\n";
}
