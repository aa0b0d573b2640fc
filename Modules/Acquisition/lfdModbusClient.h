/**
 * @file   lfdModbusClient.h
 * @brief  The Modbus TCP connection of the rig's Modbus devices (the gantry's
 *         motion controller, vtkModbusGantry; a lamp on a coil,
 *         vtkModbusLight): connect and response timeouts, bounded retries
 *         after reconnecting, what a failure means in one phrase, and the
 *         checks of the connection settings. Private to the module (it
 *         includes libmodbus); not wrapped.
 */
#ifndef lfdModbusClient_h
#define lfdModbusClient_h

#include <modbus/modbus.h>

#include <cerrno>
#include <string>

namespace lfd
{
/// Where a Modbus TCP device is and how long to wait for it.
struct ModbusSettings
{
  std::string Address;
  int Port = 502;
  int UnitId = MODBUS_TCP_SLAVE;
  double ConnectTimeout = 1.0;
  double ResponseTimeout = 0.5;
  int Retries = 2;
};

/// A setting and its range, for one message when it is out of it: the
/// property's name (or, from a description file, the field's), its value,
/// the bounds (the lowest included or not, the highest included) and unit.
struct SettingCheck
{
  const char* Name;
  const char* Field;
  double Value;
  double Lowest;
  double Highest;
  bool LowestIncluded;
  const char* Unit;
};

/**
 * "" or why a setting of `checks` is out of range, naming the property or
 * (`fileFields`) the description's field, e.g. `field "port": 0 is out of
 * range [1, 65535]`. NaN is out of every range.
 */
std::string CheckSettings(const SettingCheck* checks, int count, bool fileFields);

/**
 * "" or why the connection settings are refused: the address is not IPv4,
 * or the port, unit id (0-247 or 255), timeouts or retries are out of range (named as the
 * properties Address, Port, UnitId, ConnectTimeout, ResponseTimeout,
 * Retries or the fields address, port, unit_id, connect_timeout,
 * response_timeout, retries).
 */
std::string CheckModbusSettings(const ModbusSettings& settings, bool fileFields);

/**
 * One connection to a Modbus TCP device, reconnected on demand.
 */
class ModbusClient
{
public:
  ModbusClient() = default;
  ModbusClient(const ModbusClient&) = delete;
  ModbusClient& operator=(const ModbusClient&) = delete;
  ~ModbusClient() { this->Close(); }

  /// Closes any connection and prepares one to `settings` (connected by the
  /// first Transact()).
  void Reset(const ModbusSettings& settings);

  /// Closes the connection (safe when there is none).
  void Close();

  bool IsConnected() const { return this->Connected; }

  /**
   * Sends a request (`request(context)` returns -1 on failure, as libmodbus
   * calls do) with up to `retries` retries, reconnecting first when not
   * connected and after a failure that is not the device's refusal (a
   * Modbus exception). Returns 0 or the last errno.
   */
  template<typename Request>
  int Transact(Request request, int retries)
  {
    if (!this->Context)
    {
      return ENOTCONN; // Reset() makes the context
    }
    int error = 0;
    for (int attempt = 0; attempt <= retries; ++attempt)
    {
      this->FailedToConnect = false;
      if (!this->Connected)
      {
        error = this->Open();
        this->FailedToConnect = error != 0;
        if (error)
        {
          continue;
        }
      }
      if (request(this->Context) != -1)
      {
        return 0;
      }
      error = errno;
      if (IsException(error))
      {
        return error;
      }
      modbus_close(this->Context);
      this->Connected = false;
    }
    return error;
  }

  /**
   * What the failure `error` of the last Transact() (with the settings'
   * Retries) means, for one message: "cannot connect: Connection refused (3
   * attempts)", "no answer within 0.5 s (Connection timed out; 3
   * attempts)", "the controller refused the request: Illegal data address"...
   */
  std::string DescribeFailure(int error) const;

  /// A Modbus exception: the device answered and refused the request.
  static bool IsException(int error)
  {
    return error > MODBUS_ENOBASE && error < MODBUS_ENOBASE + MODBUS_EXCEPTION_MAX;
  }

private:
  /// Connects within the connect timeout; 0 or the errno.
  int Open();

  ModbusSettings Settings;
  modbus_t* Context = nullptr;
  bool Connected = false;
  /// Whether the last failure happened while connecting.
  bool FailedToConnect = false;
};
}

#endif
