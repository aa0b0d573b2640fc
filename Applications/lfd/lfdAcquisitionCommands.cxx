// `lfd gantry-sim` (the simulated gantry controller) and `lfd gantry
// status|home|move|stop|reset` (the gantry client): vtkGantrySimulator and
// vtkModbusGantry on the command line.
#include "lfdCommands.h"

#include "lfdGantryRegisters.h"
#include "vtkGantrySimulator.h"
#include "vtkLightField.h"
#include "vtkModbusGantry.h"
#include "vtkModbusLight.h"
#include "vtkNew.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace lfd::cli
{
namespace
{
namespace gantry = lfd::gantry;

/// The simulator a signal stops (RequestStop() is async-signal-safe).
vtkGantrySimulator* ServingSimulator = nullptr;

extern "C" void StopServing(int)
{
  if (ServingSimulator)
  {
    ServingSimulator->RequestStop();
  }
}

struct SimulatorOptions
{
  std::string Address = "127.0.0.1";
  int Port = 1502;
  std::string Fault = "none";
  double StartAngle = 37.5;
  double SilentTime = 2.0;
  double SlowFactor = 0.1;
  std::string PidFile;
  bool Detach = false;
};

void WritePidFile(const std::string& path, pid_t pid)
{
  std::string error;
  if (!path.empty() && !lfd::io::WriteFileAtomically(path, std::to_string(pid) + "\n", error))
  {
    Fail("--pid-file " + path + ": " + error);
  }
}

/// Serves until SIGTERM or SIGINT; with `detach`, in a child process that
/// is listening when this one returns (so a test fixture may connect at once).
void RunSimulator(const SimulatorOptions& options)
{
  int mode = 0;
  while (mode < gantry::FaultModeCount && options.Fault != gantry::FaultModeName(mode))
  {
    ++mode;
  }
  vtkNew<vtkGantrySimulator> simulator;
  simulator->SetAddress(options.Address.c_str());
  simulator->SetPort(options.Port);
  simulator->SetFault(mode);
  simulator->SetStartAngle(options.StartAngle);
  simulator->SetSilentTime(options.SilentTime);
  simulator->SetSlowFactor(options.SlowFactor);
  {
    StepErrors errors;
    errors->Observe(simulator);
    if (!simulator->Listen())
    {
      errors.FailOnError();
    }
  }
  const std::string where = options.Address + ":" + std::to_string(simulator->GetBoundPort());
  if (options.Detach)
  {
    std::fflush(stdout);
    const pid_t child = ::fork();
    if (child < 0)
    {
      Fail("cannot start the simulator process");
    }
    if (child > 0)
    {
      WritePidFile(options.PidFile, child);
      std::printf("gantry simulator %s (fault: %s) serving in process %d; stop it with kill %d\n",
        where.c_str(),
        options.Fault.c_str(),
        static_cast<int>(child),
        static_cast<int>(child));
      return;
    }
    // The child: no terminal, no inherited output pipes (CTest waits for them).
    ::setsid();
    const int null = ::open("/dev/null", O_RDWR);
    for (int fd = 0; fd < 3; ++fd)
    {
      ::dup2(null, fd);
    }
  }
  else
  {
    WritePidFile(options.PidFile, ::getpid());
    std::printf("gantry simulator %s (fault: %s) serving in process %d; stop it with Ctrl-C\n",
      where.c_str(),
      options.Fault.c_str(),
      static_cast<int>(::getpid()));
    std::fflush(stdout);
  }
  ServingSimulator = simulator;
  std::signal(SIGTERM, StopServing);
  std::signal(SIGINT, StopServing);
  simulator->Serve();
  ServingSimulator = nullptr;
  if (!options.PidFile.empty())
  {
    lfd::io::RemoveQuietly(options.PidFile);
  }
  if (options.Detach)
  {
    // A forked child has none of the parent's library threads (log4cplus
    // starts one), whose exit handlers would wait for them forever; the
    // sockets are closed and the pid file removed: nothing is left to do.
    std::_Exit(0);
  }
}

void AddSimulatorCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto options = std::make_shared<SimulatorOptions>();
  auto* command = app.add_subcommand("gantry-sim",
    "serve a simulated gantry controller over Modbus TCP (the register map of Data/README.md): "
    "trapezoidal moves, homing, a watchdog, 8 coils (digital outputs, e.g. a lamp's) and faults "
    "on demand; serves until SIGTERM/SIGINT");
  command->add_option("--address", options->Address, "IPv4 address to listen on")
    ->capture_default_str();
  numbers.Add(command, "--port", options->Port, 0, 65535, "TCP port to listen on (0: any free)");
  std::vector<std::string> modes;
  for (int mode = 0; mode < gantry::FaultModeCount; ++mode)
  {
    modes.emplace_back(gantry::FaultModeName(mode));
  }
  command
    ->add_option("--fault",
      options->Fault,
      "fault armed for the first move, fired half-way through it: silent (no answers for "
      "--silent-seconds), drive, estop, limit, drop (closes every connection); slow runs every "
      "move at --slow-factor of its velocity; stuck makes the coils (digital outputs 0-7, e.g. "
      "the coaxial lamp's) ignore writes")
    ->check(CLI::IsMember(modes))
    ->capture_default_str();
  numbers.AddReal(
    command, "--start-angle", options->StartAngle, "axis position before homing, in degrees");
  numbers.Add(command,
    "--silent-seconds",
    options->SilentTime,
    0.0,
    3600.0,
    "how long the silent fault stops answering");
  numbers.Add(command,
    "--slow-factor",
    options->SlowFactor,
    0.001,
    1.0,
    "fraction of the velocity a slow move runs at");
  command->add_option("--pid-file",
    options->PidFile,
    "write the serving process's id into this file (removed when it stops)");
  command->add_flag(
    "--detach", options->Detach, "serve in a background process and return once it listens");
  commands.push_back({ command, [options] { RunSimulator(*options); }, false });
}

/// The connection options every `lfd gantry` command takes.
struct ClientOptions
{
  std::string Config;
  std::string Address = "127.0.0.1";
  int Port = 502;
  double Timeout = 0.5;
  int Retries = 2;
  double Velocity = 30.0;
  double Acceleration = 60.0;
  double Angle = 0.0;
  int Coil = 0;
  int UnitId = 255;
  std::string LampState;
  /// The options above as given on the command line (with --config, only
  /// those given override the description).
  std::vector<CLI::Option*> Given;
};

/// "gantry 127.0.0.1:1502: at 30 deg, ready, homed, in position".
void PrintState(vtkModbusGantry* device)
{
  std::string state = device->IsReady() ? "ready" : "disabled";
  state += device->IsHomed() ? ", homed" : ", not homed";
  state +=
    device->IsMoving() ? ", moving" : (device->IsInPosition() ? ", in position" : ", stopped");
  if (device->GetFaultCode() != gantry::NoFault)
  {
    state += ", drive fault " + std::to_string(device->GetFaultCode()) + " (" +
      gantry::DescribeFault(device->GetFaultCode()) + ")";
  }
  std::printf("%s: at %.3f deg, %s\n",
    device->GetDeviceName().c_str(),
    device->GetActualAngle(),
    state.c_str());
}

enum class GantryAction
{
  Status,
  Home,
  Move,
  Stop,
  Reset,
  Lamp
};

/// Switches the lamp on coil --coil of the device the gantry's settings
/// address (the controller, or a relay module at --address), as `lfd
/// capture --coaxial-coil` does, and prints it read back.
void SwitchLamp(vtkModbusGantry* device, const ClientOptions& options, StepErrors& errors)
{
  vtkNew<vtkModbusLight> lamp;
  errors->Observe(lamp);
  lamp->SetName("coaxial lamp");
  lamp->SetAddress(device->GetAddress());
  lamp->SetPort(device->GetPort());
  lamp->SetUnitId(options.UnitId);
  lamp->SetCoil(options.Coil);
  lamp->SetConnectTimeout(device->GetConnectTimeout());
  lamp->SetResponseTimeout(device->GetResponseTimeout());
  lamp->SetRetries(device->GetRetries());
  lamp->SetSettleTime(0.0);
  if (!lamp->Switch(options.LampState == "on"))
  {
    errors.FailOnError();
  }
  std::printf("%s: %s (read back)\n", lamp->GetDeviceName().c_str(), options.LampState.c_str());
}

void RunGantry(const ClientOptions& options, GantryAction action)
{
  vtkNew<vtkModbusGantry> device;
  StepErrors errors;
  errors->Observe(device);
  const auto check = [&](bool done)
  {
    if (!done)
    {
      errors.FailOnError();
      Fail(device->GetDeviceName() + ": failed");
    }
  };
  const bool described = !options.Config.empty();
  if (described)
  {
    check(device->ReadConfiguration(options.Config.c_str()));
  }
  const auto given = [&](size_t i) { return !described || options.Given[i]->count() > 0; };
  if (given(0))
  {
    device->SetAddress(options.Address.c_str());
  }
  if (given(1))
  {
    device->SetPort(options.Port);
  }
  if (given(2))
  {
    device->SetResponseTimeout(options.Timeout);
  }
  if (given(3))
  {
    device->SetRetries(options.Retries);
  }
  if (given(4))
  {
    device->SetVelocity(options.Velocity);
  }
  if (given(5))
  {
    device->SetAcceleration(options.Acceleration);
  }
  if (action == GantryAction::Lamp)
  {
    // A relay module is no gantry controller: no identity to check.
    SwitchLamp(device, options, errors);
    return;
  }
  check(device->Connect());
  switch (action)
  {
    case GantryAction::Home:
      check(device->Enable() && device->Home());
      break;
    case GantryAction::Move:
      check(device->Enable() && device->MoveTo(options.Angle));
      break;
    case GantryAction::Stop:
      check(device->QuickStop());
      break;
    case GantryAction::Reset:
      check(device->ResetFault());
      break;
    case GantryAction::Status:
    case GantryAction::Lamp:
      break;
  }
  check(device->UpdateState());
  PrintState(device);
}

void AddGantryCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto* group = app.add_subcommand(
    "gantry", "drive a gantry controller over Modbus TCP (a real one or 'lfd gantry-sim')");
  group->require_subcommand(1);
  const struct
  {
    const char* Name;
    GantryAction Action;
    const char* Help;
  } leaves[] = {
    { "status", GantryAction::Status, "print the axis position and state" },
    { "home", GantryAction::Home, "enable the axis and drive it to the home sensor (0 deg)" },
    { "move", GantryAction::Move, "enable the axis and move it to ANGLE degrees (homed first)" },
    { "stop", GantryAction::Stop, "quick-stop the axis" },
    { "reset", GantryAction::Reset, "clear a drive fault (then home or move enables again)" },
    { "lamp",
      GantryAction::Lamp,
      "switch the coaxial lamp on coil --coil of the controller (or of the relay module at "
      "--address) on or off and check it reads back so, as lfd capture --coaxial-coil does" },
  };
  for (const auto& leaf : leaves)
  {
    auto options = std::make_shared<ClientOptions>();
    auto* command = group->add_subcommand(leaf.Name, leaf.Help);
    command->add_option("--config",
      options->Config,
      "the gantry description (gantry.json, Data/README.md); the options below given as well "
      "override it");
    options->Given = {
      command->add_option("--address", options->Address, "the controller's IPv4 address")
        ->capture_default_str(),
      numbers.Add(command, "--port", options->Port, 1, 65535, "the controller's Modbus TCP port"),
      numbers.Add(
        command, "--timeout", options->Timeout, 0.001, 3600.0, "seconds to wait for each answer"),
      numbers.Add(
        command, "--retries", options->Retries, 0, 100, "retries of a request that got no answer"),
      numbers.Add(command, "--velocity", options->Velocity, 0.01, 655.35, "degree/s"),
      numbers.Add(command, "--acceleration", options->Acceleration, 0.1, 6553.5, "degree/s^2"),
    };
    if (leaf.Action == GantryAction::Move)
    {
      numbers.AddReal(command, "angle", options->Angle, "target angle in degrees")->required();
    }
    if (leaf.Action == GantryAction::Lamp)
    {
      command->add_option("state", options->LampState, "on or off")
        ->check(CLI::IsMember({ "on", "off" }))
        ->required();
      numbers.Add(command, "--coil", options->Coil, 0, 65535, "the lamp's coil (0-based)");
      numbers.Add(command,
        "--unit",
        options->UnitId,
        0,
        255,
        "Modbus unit id: 0 to 247 (a relay module behind a gateway), or 255 for the device itself");
    }
    const GantryAction action = leaf.Action;
    commands.push_back({ command, [options, action] { RunGantry(*options, action); }, false });
  }
}
}

void AddAcquisitionCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  AddSimulatorCommand(app, numbers, commands);
  AddGantryCommands(app, numbers, commands);
}
}
