// One error naming the device for each refused setting, for a controller
// that is not there (ECONNREFUSED), for a simulator on a taken port, and
// for a call before Connect().
#include "lfdGantryTestUtilities.h"

int TestModbusGantryErrors(int, char*[])
{
  using lfd::test::Check;
  using lfd::test::CheckError;
  bool ok = true;
  vtkNew<vtkLightFieldErrorObserver> errors;

  // A free port: served once, then closed.
  vtkNew<vtkGantrySimulator> simulator;
  errors->Observe(simulator);
  ok &= Check(simulator->Start(), "simulator serving", simulator->GetBoundPort());
  const int port = simulator->GetBoundPort();
  vtkNew<vtkGantrySimulator> second;
  errors->Observe(second);
  second->SetPort(port);
  ok &= Check(!second->Start(), "a second simulator on the same port fails", "failed");
  ok &= CheckError(errors,
    "gantry simulator 127.0.0.1:" + std::to_string(port) +
      ": cannot listen: Address already in use");
  simulator->Stop();

  vtkNew<vtkModbusGantry> device;
  errors->Observe(device);
  device->SetAddress("127.0.0.1");
  device->SetPort(port);
  const std::string name = "gantry 127.0.0.1:" + std::to_string(port) + ": ";
  ok &=
    Check(!device->Connect() && !device->IsConnected(), "nothing listens: Connect fails", "failed");
  ok &= CheckError(errors, name + "cannot connect: Connection refused (3 attempts)");
  ok &= Check(!device->UpdateState(), "UpdateState before connecting fails", "failed");
  ok &= CheckError(errors, name + "not connected (call Connect() first)");

  // Each bad setting: one error naming it, nothing sent.
  const struct
  {
    void (*Spoil)(vtkModbusGantry*);
    const char* Message;
  } settings[] = {
    { [](vtkModbusGantry* g) { g->SetAddress("gantry.local"); },
      "gantry gantry.local:PORT: Address 'gantry.local' is not an IPv4 address (e.g. "
      "192.168.1.20)" },
    { [](vtkModbusGantry* g) { g->SetAddress(nullptr); },
      "gantry (no address):PORT: Address '' is not an IPv4 address (e.g. 192.168.1.20)" },
    { [](vtkModbusGantry* g) { g->SetPort(70000); },
      "gantry 127.0.0.1:70000: Port 70000 is out of range [1, 65535]" },
    { [](vtkModbusGantry* g) { g->SetResponseTimeout(0.0); },
      "NAME: ResponseTimeout 0 s is out of range (0, 3600]" },
    { [](vtkModbusGantry* g) { g->SetVelocity(700.0); },
      "NAME: Velocity 700 degree/s is out of range (0, 655.35]" },
    { [](vtkModbusGantry* g) { g->SetAcceleration(-1.0); },
      "NAME: Acceleration -1 degree/s^2 is out of range (0, 6553.5]" },
    { [](vtkModbusGantry* g) { g->SetSoftLimits(10.0, -10.0); },
      "NAME: SoftLimits [10, -10] deg: the minimum is not below the maximum" },
    { [](vtkModbusGantry* g) { g->SetWatchdogTimeout(100.0); },
      "NAME: WatchdogTimeout 100 s is out of range [0, 65.535]" },
  };
  for (const auto& setting : settings)
  {
    vtkNew<vtkModbusGantry> spoiled;
    errors->Observe(spoiled);
    spoiled->SetAddress("127.0.0.1");
    spoiled->SetPort(port);
    setting.Spoil(spoiled);
    std::string expected = setting.Message;
    const size_t at = expected.find("PORT");
    if (at != std::string::npos)
    {
      expected.replace(at, 4, std::to_string(port));
    }
    if (expected.compare(0, 4, "NAME") == 0)
    {
      expected = name.substr(0, name.size() - 2) + expected.substr(4);
    }
    ok &= Check(!spoiled->Connect(), "refused setting: Connect fails", "failed");
    ok &= CheckError(errors, expected);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
