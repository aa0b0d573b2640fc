#include "lfdModbusClient.h"

#include <arpa/inet.h>

#include <cmath>
#include <sstream>

namespace lfd
{
namespace
{
void SetModbusTimeout(modbus_t* context, double seconds)
{
  const double whole = std::floor(seconds);
  modbus_set_response_timeout(context,
    static_cast<uint32_t>(whole),
    static_cast<uint32_t>(std::lround((seconds - whole) * 1e6)));
}
}

std::string CheckSettings(const SettingCheck* checks, int count, bool fileFields)
{
  for (int i = 0; i < count; ++i)
  {
    const SettingCheck& check = checks[i];
    // !(a <= b) also refuses NaN.
    const bool low =
      check.LowestIncluded ? !(check.Value >= check.Lowest) : !(check.Value > check.Lowest);
    if (low || !(check.Value <= check.Highest))
    {
      std::ostringstream reason;
      reason << (fileFields ? "field \"" + std::string(check.Field) + "\": "
                            : std::string(check.Name) + " ")
             << check.Value << check.Unit << " is out of range "
             << (check.LowestIncluded ? "[" : "(") << check.Lowest << ", " << check.Highest << "]";
      return reason.str();
    }
  }
  return std::string();
}

std::string CheckModbusSettings(const ModbusSettings& settings, bool fileFields)
{
  in_addr parsed{};
  if (inet_pton(AF_INET, settings.Address.c_str(), &parsed) != 1)
  {
    return (fileFields ? "field \"address\": " : "Address ") + std::string("'") + settings.Address +
      "' is not an IPv4 address (e.g. 192.168.1.20)";
  }
  const SettingCheck checks[] = {
    { "Port", "port", static_cast<double>(settings.Port), 1.0, 65535.0, true, "" },
    { "UnitId", "unit_id", static_cast<double>(settings.UnitId), 0.0, 255.0, true, "" },
    { "ConnectTimeout", "connect_timeout", settings.ConnectTimeout, 0.0, 3600.0, false, " s" },
    { "ResponseTimeout", "response_timeout", settings.ResponseTimeout, 0.0, 3600.0, false, " s" },
    { "Retries", "retries", static_cast<double>(settings.Retries), 0.0, 100.0, true, "" },
  };
  const std::string refused =
    CheckSettings(checks, static_cast<int>(sizeof(checks) / sizeof(checks[0])), fileFields);
  // Modbus TCP takes the serial line's unit ids, or 255 for the device
  // itself (libmodbus refuses the others).
  if (refused.empty() && settings.UnitId > 247 && settings.UnitId != MODBUS_TCP_SLAVE)
  {
    return (fileFields ? "field \"unit_id\": " : "UnitId ") + std::to_string(settings.UnitId) +
      " is not a Modbus unit id (0 to 247, or 255 for the device itself)";
  }
  return refused;
}

void ModbusClient::Reset(const ModbusSettings& settings)
{
  this->Close();
  this->Settings = settings;
  this->Context = modbus_new_tcp(settings.Address.c_str(), settings.Port);
  if (this->Context)
  {
    modbus_set_slave(this->Context, settings.UnitId);
  }
}

void ModbusClient::Close()
{
  if (this->Context)
  {
    modbus_close(this->Context);
    modbus_free(this->Context);
    this->Context = nullptr;
  }
  this->Connected = false;
}

int ModbusClient::Open()
{
  // libmodbus waits for a TCP connection as long as for an answer.
  SetModbusTimeout(this->Context, this->Settings.ConnectTimeout);
  if (modbus_connect(this->Context) == -1)
  {
    const int error = errno;
    modbus_close(this->Context);
    return error;
  }
  SetModbusTimeout(this->Context, this->Settings.ResponseTimeout);
  this->Connected = true;
  return 0;
}

std::string ModbusClient::DescribeFailure(int error) const
{
  std::ostringstream text;
  const int attempts = this->Settings.Retries + 1;
  const std::string tries = attempts == 1 ? "1 attempt" : std::to_string(attempts) + " attempts";
  if (error == ENOTCONN)
  {
    text << "not connected (call Connect() first)";
  }
  else if (IsException(error))
  {
    text << "the controller refused the request: " << modbus_strerror(error);
  }
  else if (this->FailedToConnect)
  {
    text << "cannot connect";
    if (error == ETIMEDOUT || error == EINPROGRESS)
    {
      text << " within " << this->Settings.ConnectTimeout << " s";
    }
    text << ": " << modbus_strerror(error) << " (" << tries << ")";
  }
  else if (error == ETIMEDOUT)
  {
    text << "no answer within " << this->Settings.ResponseTimeout << " s ("
         << modbus_strerror(error) << "; " << tries << ")";
  }
  else
  {
    text << "communication failed: " << modbus_strerror(error) << " (" << tries << ")";
  }
  return text.str();
}
}
