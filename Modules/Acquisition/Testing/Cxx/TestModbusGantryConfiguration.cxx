// vtkModbusGantry::ReadConfiguration: a gantry description (gantry.json)
// sets the client; a malformed one gives one error naming the file and the
// field, and changes no setting.
#include "lfdGantryTestUtilities.h"

#include <fstream>

namespace
{
std::string WriteDescription(const std::string& name, const std::string& text)
{
  const std::string path = std::string(LFD_TEST_TEMP_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}
}

int TestModbusGantryConfiguration(int, char*[])
{
  using lfd::test::Check;
  using lfd::test::CheckError;
  bool ok = true;
  vtkNew<vtkLightFieldErrorObserver> errors;
  vtkNew<vtkModbusGantry> device;
  errors->Observe(device);

  const std::string good = WriteDescription("gantry_good.json",
    R"({ "format": "lfd-gantry", "version": 1, "address": "192.168.1.20", "port": 1502,
         "velocity": 45, "soft_limits": [-10, 370], "retries": 1 })");
  ok &= Check(device->ReadConfiguration(good.c_str()), "a description is read", good);
  ok &= Check(std::string(device->GetAddress()) == "192.168.1.20" && device->GetPort() == 1502 &&
      device->GetVelocity() == 45.0 && device->GetSoftLimits()[0] == -10.0 &&
      device->GetSoftLimits()[1] == 370.0 && device->GetRetries() == 1,
    "address, port, velocity, soft limits, retries set",
    device->GetDeviceName());
  ok &= Check(device->GetAcceleration() == 60.0 && device->GetResponseTimeout() == 0.5,
    "absent fields keep their values",
    device->GetAcceleration());

  const struct
  {
    const char* Name;
    const char* Text;
    const char* Problem;
  } refused[] = {
    { "gantry_no_port.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "10.0.0.2" })",
      R"(field "port": missing)" },
    { "gantry_scene.json",
      R"({ "format": "lfd-scene", "version": 1 })",
      R"(field "format": expected "lfd-gantry", found "lfd-scene")" },
    { "gantry_version.json",
      R"({ "format": "lfd-gantry", "version": 2 })",
      R"(field "version": unsupported version (this reader reads version 1))" },
    { "gantry_port.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "10.0.0.2", "port": 0 })",
      R"(field "port": expected an integer in [1, 65535], found the number 0)" },
    { "gantry_host.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "gantry.local", "port": 502 })",
      R"(field "address": 'gantry.local' is not an IPv4 address (e.g. 192.168.1.20))" },
    { "gantry_velocity.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "10.0.0.2", "port": 502,
           "velocity": 700 })",
      R"(field "velocity": 700 degree/s is out of range (0, 655.35])" },
    { "gantry_limits.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "10.0.0.2", "port": 502,
           "soft_limits": [90] })",
      R"(field "soft_limits": expected an array of 2 numbers, found an array of 1 elements)" },
    { "gantry_order.json",
      R"({ "format": "lfd-gantry", "version": 1, "address": "10.0.0.2", "port": 502,
           "soft_limits": [90, -90] })",
      R"(field "soft_limits": [90, -90] deg: the minimum is not below the maximum)" },
  };
  for (const auto& description : refused)
  {
    const std::string path = WriteDescription(description.Name, description.Text);
    ok &= Check(!device->ReadConfiguration(path.c_str()),
      std::string(description.Name) + " refused",
      "refused");
    ok &= CheckError(errors, path + ": " + description.Problem);
  }
  ok &= Check(std::string(device->GetAddress()) == "192.168.1.20" && device->GetPort() == 1502 &&
      device->GetVelocity() == 45.0,
    "the refused descriptions changed nothing",
    device->GetDeviceName());
  const std::string missing = std::string(LFD_TEST_TEMP_DIR) + "/gantry_missing.json";
  ok &= Check(!device->ReadConfiguration(missing.c_str()), "a missing file refused", "refused");
  ok &= CheckError(errors, missing + ": file not found");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
