// vtkModbusLight against the gantry simulator's coils (a real Modbus TCP
// server on a free port of 127.0.0.1): the lamp on coil 3 (unit id 1)
// follows the passes (on for Coaxial only, then for Flood too), waits its
// settle time when it switches, leaves the other coils alone and goes off
// with Off(); a stuck relay (read-back mismatch), a coil the device does not
// have, an unreachable device and bad settings are one exact error each;
// Off() of a lamp not switched sends nothing.
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"
#include "vtkLightField.h"
#include "vtkModbusLight.h"

using namespace lfd::test;

namespace
{
/// The simulator's coils as a string of 0 and 1, coil 0 first.
std::string Coils(vtkGantrySimulator* simulator)
{
  std::string coils;
  for (int coil = 0; coil < lfd::gantry::CoilCount; ++coil)
  {
    coils += simulator->GetCoil(coil) ? '1' : '0';
  }
  return coils;
}
}

int TestModbusLight(int, char*[])
{
  vtkNew<vtkGantrySimulator> simulator;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(simulator);
  if (!simulator->Start())
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  const std::string port = std::to_string(simulator->GetBoundPort());
  vtkNew<vtkModbusLight> lamp;
  errors->Observe(lamp);
  lamp->SetAddress("127.0.0.1");
  lamp->SetPort(simulator->GetBoundPort());
  lamp->SetUnitId(1);
  lamp->SetCoil(3);
  lamp->SetResponseTimeout(0.2);
  lamp->SetSettleTime(0.1);
  bool ok = Check(lamp->GetDeviceName() == "lamp 127.0.0.1:" + port + " coil 3",
    "the device's name",
    lamp->GetDeviceName());

  // The passes: on for Coaxial only (the default), settling when it switches.
  std::string seen;
  double switching = 0.0;
  for (int pass : { vtkLightField::COAXIAL, vtkLightField::CODED, vtkLightField::FLOOD })
  {
    const double start = Now();
    ok &=
      Check(lamp->Apply(pass), std::string("Apply(") + vtkLightField::GetPassName(pass) + ")", "");
    switching += pass != vtkLightField::FLOOD ? Now() - start : 0.0;
    seen += Coils(simulator) + " ";
  }
  ok &= Check(seen == "00010000 00000000 00000000 ", "coils after Coaxial, Coded, Flood", seen);
  ok &= Check(switching >= 0.2, "two switches waited the settle time each (s)", switching);
  lamp->SetPassOn(vtkLightField::FLOOD, true);
  const bool flood = lamp->Apply(vtkLightField::FLOOD);
  ok &= Check(flood && Coils(simulator) == "00010000", "on for Flood once asked", Coils(simulator));
  lamp->Off();
  ok &= Check(Coils(simulator) == "00000000" && !errors->HasError(),
    "Off() switches it off, no error",
    Coils(simulator) + " " + (errors->HasError() ? errors->GetErrorMessage() : ""));

  // A relay that does not switch: the coil reads back as it was.
  simulator->ArmFault(lfd::gantry::StuckCoilsMode);
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "a stuck relay fails", Coils(simulator));
  ok &= CheckError(errors,
    "lamp 127.0.0.1:" + port +
      " coil 3: switched on, but the coil reads back off (a relay or output that does not "
      "switch, or the wrong coil)");
  simulator->ArmFault(lfd::gantry::NoFaultMode);

  // A coil the device does not have: the device refuses.
  lamp->SetCoil(lfd::gantry::CoilCount);
  lamp->Off();
  errors->Clear();
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "a coil the device lacks fails", "");
  ok &= CheckError(errors,
    "lamp 127.0.0.1:" + port +
      " coil 8: the controller refused the request: Illegal data address while switching it on");

  // Nobody at the address.
  lamp->SetName("coaxial lamp");
  lamp->SetCoil(0);
  lamp->SetPort(1);
  lamp->SetRetries(0);
  lamp->Off();
  errors->Clear();
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "an unreachable lamp fails", "");
  ok &= CheckError(errors,
    "coaxial lamp 127.0.0.1:1 coil 0: cannot connect: Connection refused (1 attempt) while "
    "switching it on");

  // Settings refused before any connection.
  lamp->SetAddress("lamp.local");
  lamp->Off();
  errors->Clear();
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "a host name is refused", "");
  ok &= CheckError(errors,
    "coaxial lamp lamp.local:1 coil 0: Address 'lamp.local' is not an IPv4 address (e.g. "
    "192.168.1.20)");
  lamp->SetAddress("127.0.0.1");
  lamp->SetCoil(-1);
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "a negative coil is refused", "");
  ok &= CheckError(errors, "coaxial lamp 127.0.0.1:1 coil -1: Coil -1 is out of range [0, 65535]");
  lamp->SetCoil(0);
  lamp->SetUnitId(250);
  ok &= Check(!lamp->Apply(vtkLightField::COAXIAL), "unit id 250 is refused", "");
  ok &= CheckError(errors,
    "coaxial lamp 127.0.0.1:1 coil 0: UnitId 250 is not a Modbus unit id (0 to 247, or 255 for "
    "the device itself)");

  // Off() without a switch since the last one: no request, no error (a
  // capture failing before its first photograph does not wait for the lamp).
  vtkNew<vtkModbusLight> unused;
  errors->Observe(unused);
  unused->SetAddress("127.0.0.1");
  unused->SetPort(1);
  unused->Off();
  ok &= Check(!errors->HasError(),
    "Off() of a lamp never switched: no error",
    errors->HasError() ? errors->GetErrorMessage() : "none");
  simulator->Stop();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
