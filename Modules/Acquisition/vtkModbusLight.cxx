#include "vtkModbusLight.h"

#include "lfdModbusClient.h"

#include "vtkLightField.h"
#include "vtkObjectFactory.h"

#include <chrono>
#include <thread>

/// The connection and what the lamp was switched to last.
class vtkModbusLight::vtkInternals
{
public:
  lfd::ModbusClient Client;
  /// Whether Client has the current settings (Off() drops them).
  bool Ready = false;
  /// The coil as read back last: 0, 1, or -1 when unknown.
  int State = -1;
  bool PassOn[vtkLightField::NUMBER_OF_PASSES] = {};
};

vtkStandardNewMacro(vtkModbusLight);

//------------------------------------------------------------------------------
vtkModbusLight::vtkModbusLight()
  : Internals(new vtkInternals)
{
  this->Internals->PassOn[vtkLightField::COAXIAL] = true;
}

//------------------------------------------------------------------------------
vtkModbusLight::~vtkModbusLight()
{
  this->SetAddress(nullptr);
}

//------------------------------------------------------------------------------
void vtkModbusLight::SetPassOn(int pass, bool on)
{
  if (pass >= 0 && pass < vtkLightField::NUMBER_OF_PASSES && this->Internals->PassOn[pass] != on)
  {
    this->Internals->PassOn[pass] = on;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkModbusLight::GetPassOn(int pass) const
{
  return pass >= 0 && pass < vtkLightField::NUMBER_OF_PASSES && this->Internals->PassOn[pass];
}

//------------------------------------------------------------------------------
std::string vtkModbusLight::GetDeviceName() const
{
  return std::string(this->Name ? this->Name : "lamp") + " " +
    (this->Address ? this->Address : "(no address)") + ":" + std::to_string(this->Port) + " coil " +
    std::to_string(this->Coil);
}

//------------------------------------------------------------------------------
bool vtkModbusLight::Apply(int pass)
{
  return this->Switch(this->GetPassOn(pass));
}

//------------------------------------------------------------------------------
bool vtkModbusLight::Switch(bool on)
{
  vtkInternals& internals = *this->Internals;
  const std::string device = this->GetDeviceName() + ": ";
  if (!internals.Ready)
  {
    lfd::ModbusSettings settings;
    settings.Address = this->Address ? this->Address : "";
    settings.Port = this->Port;
    settings.UnitId = this->UnitId;
    settings.ConnectTimeout = this->ConnectTimeout;
    settings.ResponseTimeout = this->ResponseTimeout;
    settings.Retries = this->Retries;
    const lfd::SettingCheck checks[] = {
      { "Coil", "coil", static_cast<double>(this->Coil), 0.0, 65535.0, true, "" },
      { "SettleTime", "settle_time", this->SettleTime, 0.0, 60.0, true, " s" },
    };
    std::string refused = lfd::CheckModbusSettings(settings, false);
    refused = refused.empty() ? lfd::CheckSettings(checks, 2, false) : refused;
    if (!refused.empty())
    {
      vtkErrorMacro(<< device << refused);
      return false;
    }
    internals.Client.Reset(settings);
    internals.Ready = true;
  }
  const char* state = on ? "on" : "off";
  int error = internals.Client.Transact([&](modbus_t* context)
    { return modbus_write_bit(context, this->Coil, on ? 1 : 0); },
    this->Retries);
  uint8_t readBack = 0;
  if (!error)
  {
    error = internals.Client.Transact([&](modbus_t* context)
      { return modbus_read_bits(context, this->Coil, 1, &readBack); },
      this->Retries);
  }
  if (error)
  {
    internals.State = -1;
    // A device that does not answer is not asked again by Off(): the next
    // Apply() connects anew.
    if (!lfd::ModbusClient::IsException(error))
    {
      internals.Client.Close();
      internals.Ready = false;
    }
    vtkErrorMacro(<< device << internals.Client.DescribeFailure(error) << " while switching it "
                  << state);
    return false;
  }
  if ((readBack != 0) != on)
  {
    internals.State = -1;
    vtkErrorMacro(<< device << "switched " << state << ", but the coil reads back "
                  << (readBack ? "on" : "off")
                  << " (a relay or output that does not switch, or the wrong coil)");
    return false;
  }
  // The lamp needs time to reach its brightness (or to go dark) only when
  // it changed; an unknown state may have changed.
  if (internals.State != (on ? 1 : 0))
  {
    std::this_thread::sleep_for(std::chrono::duration<double>(this->SettleTime));
  }
  internals.State = on ? 1 : 0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkModbusLight::Prepare()
{
  return this->Switch(false);
}

//------------------------------------------------------------------------------
void vtkModbusLight::Off()
{
  // Not switched since the last Off(): nothing to undo, and no reason to
  // wait for a device that may not answer (a capture failing before its
  // first photograph).
  if (!this->Internals->Ready)
  {
    return;
  }
  this->Switch(false);
  // The next Apply() connects again, with the settings then.
  this->Internals->Client.Close();
  this->Internals->Ready = false;
  this->Internals->State = -1;
}

//------------------------------------------------------------------------------
void vtkModbusLight::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Address: " << (this->Address ? this->Address : "(none)") << "\n";
  os << indent << "Port: " << this->Port << "\n";
  os << indent << "UnitId: " << this->UnitId << "\n";
  os << indent << "Coil: " << this->Coil << "\n";
  os << indent << "ConnectTimeout: " << this->ConnectTimeout << " s\n";
  os << indent << "ResponseTimeout: " << this->ResponseTimeout << " s\n";
  os << indent << "Retries: " << this->Retries << "\n";
  os << indent << "SettleTime: " << this->SettleTime << " s\n";
  os << indent << "PassOn:";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    os << " " << vtkLightField::GetPassName(pass) << "=" << (this->GetPassOn(pass) ? "on" : "off");
  }
  os << "\n";
}
