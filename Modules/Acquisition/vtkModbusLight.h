/**
 * @class   vtkModbusLight
 * @brief   a lamp switched by a Modbus coil: the coaxial light of a real rig
 *
 * The paper's coaxial light (Sec. 4.1, Fig. 8) travels with the camera and
 * is on for the Coaxial pass only. On a real rig such a lamp is switched by
 * a digital output of the motion controller or by a Modbus TCP relay
 * module: a coil. This light writes coil Coil of the device at
 * Address:Port (unit UnitId) for each pass (on in the passes of SetPassOn(),
 * by default the Coaxial pass only), reads it back, which must give what was
 * written (a relay that does not switch, an output without supply, a wrong
 * coil number on a device that keeps coils it does not drive: the capture
 * stops instead of photographing in the dark), and when the lamp changed,
 * waits SettleTime for it to reach full brightness.
 *
 * The connection (connect and response timeouts, bounded retries after
 * reconnecting) is the gantry client's (lfdModbusClient.h): the lamp opens
 * its own connection at the first Apply() and closes it in Off(). The
 * gantry simulator (vtkGantrySimulator, `lfd gantry-sim`) serves coils, so
 * the lamp runs against it as against real hardware.
 *
 * Every failure is one VTK error naming the device ("coaxial lamp
 * 127.0.0.1:1502 coil 0: ..." with Name "coaxial lamp"; "lamp ..." without
 * a Name) and the reason, and Apply() returns false.
 *
 * @sa vtkCaptureLight vtkModbusGantry vtkGantrySimulator
 */
#ifndef vtkModbusLight_h
#define vtkModbusLight_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureLight.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class LFDACQUISITION_EXPORT vtkModbusLight : public vtkCaptureLight
{
public:
  static vtkModbusLight* New();
  vtkTypeMacro(vtkModbusLight, vtkCaptureLight);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The device's IPv4 address, Modbus TCP port and unit id (a relay module
   * behind a gateway may need its own, 0 to 247; 255 addresses the device
   * itself).
   * Defaults nullptr, 502 and 255.
   */
  vtkSetStringMacro(Address);
  vtkGetStringMacro(Address);
  vtkSetMacro(Port, int);
  vtkGetMacro(Port, int);
  vtkSetMacro(UnitId, int);
  vtkGetMacro(UnitId, int);
  ///@}

  ///@{
  /**
   * The coil (0-based address) the lamp is wired to. Default 0.
   */
  vtkSetMacro(Coil, int);
  vtkGetMacro(Coil, int);
  ///@}

  ///@{
  /**
   * How long to wait for a connection and for each answer (seconds), and
   * how many times a request that got no answer is retried after
   * reconnecting. Defaults 1 s, 0.5 s and 2, as the gantry's.
   */
  vtkSetMacro(ConnectTimeout, double);
  vtkGetMacro(ConnectTimeout, double);
  vtkSetMacro(ResponseTimeout, double);
  vtkGetMacro(ResponseTimeout, double);
  vtkSetMacro(Retries, int);
  vtkGetMacro(Retries, int);
  ///@}

  ///@{
  /**
   * Seconds waited after the lamp switched, before the photograph (a lamp
   * takes time to reach full brightness, and to go dark). Default 0.05.
   */
  vtkSetMacro(SettleTime, double);
  vtkGetMacro(SettleTime, double);
  ///@}

  ///@{
  /**
   * Whether the lamp is on in pass `pass` (vtkLightField::COAXIAL, CODED,
   * FLOOD). Default: on in COAXIAL only. Passes out of range are ignored
   * (off).
   */
  void SetPassOn(int pass, bool on);
  bool GetPassOn(int pass) const;
  ///@}

  /**
   * Switches the coil as pass `pass` needs, checks it reads back so and
   * waits SettleTime when it changed. False, with an error naming the
   * device, when the settings are invalid, the device does not answer or
   * refuses, or the coil reads back otherwise.
   */
  bool Apply(int pass) override;

  /**
   * Switches the coil off (best effort: a failure is reported, the
   * connection closed anyway) and closes the connection; does nothing when
   * the lamp was not switched since the last Off(), or stopped answering.
   */
  void Off() override;

  /**
   * Switches the coil off, with Apply()'s checks: the lamp is there, its
   * coil switches, and it is dark before the capture.
   */
  bool Prepare() override;

  /**
   * Switches the coil on or off, with Apply()'s checks.
   */
  bool Switch(bool on);

  /**
   * "<Name or lamp> <address>:<port> coil <coil>", as every message names
   * the device.
   */
  std::string GetDeviceName() const;

protected:
  vtkModbusLight();
  ~vtkModbusLight() override;

  char* Address = nullptr;
  int Port = 502;
  int UnitId = 255;
  int Coil = 0;
  double ConnectTimeout = 1.0;
  double ResponseTimeout = 0.5;
  int Retries = 2;
  double SettleTime = 0.05;

private:
  vtkModbusLight(const vtkModbusLight&) = delete;
  void operator=(const vtkModbusLight&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
