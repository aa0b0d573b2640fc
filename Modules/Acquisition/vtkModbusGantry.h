/**
 * @class   vtkModbusGantry
 * @brief   the capture rig's gantry: a motion controller driven over Modbus TCP
 *
 * The paper's light fields are photographed from a motorised ring gantry
 * (Sec. 4.1, Fig. 8). This client drives its motion controller through the
 * register map of lfdGantryRegisters.h (Data/README.md), modelled on
 * CiA-402 drives and the direct-data modes of turntable controllers, with
 * libmodbus: the same class talks to vtkGantrySimulator (`lfd gantry-sim`)
 * and to a real controller.
 *
 * Connect() connects within ConnectTimeout and checks the controller's
 * identity; Enable() writes the motion parameters and enables the axis;
 * Home() and MoveTo() start a motion and wait until the controller reports
 * it in position, refreshing the watchdog while waiting and giving up at a
 * move deadline (DeadlineFactor times the trapezoidal profile's duration
 * plus DeadlineMargin). Every request waits ResponseTimeout for its answer
 * and is retried (after reconnecting) up to Retries times.
 *
 * Every failure is one VTK error that names the device ("gantry
 * 127.0.0.1:1502: ") and the reason: connection refused, no answer
 * (timeout), a drive fault with its code, an emergency stop, a limit, the
 * move deadline; the call returns false. When a move fails the axis is
 * quick-stopped first (the controller does so itself on a fault).
 *
 * @sa vtkGantrySimulator vtkCaptureCamera
 */
#ifndef vtkModbusGantry_h
#define vtkModbusGantry_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class LFDACQUISITION_EXPORT vtkModbusGantry : public vtkObject
{
public:
  static vtkModbusGantry* New();
  vtkTypeMacro(vtkModbusGantry, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The controller's IP address and Modbus TCP port. Defaults nullptr and
   * 502 (the Modbus port).
   */
  vtkSetStringMacro(Address);
  vtkGetStringMacro(Address);
  vtkSetMacro(Port, int);
  vtkGetMacro(Port, int);
  ///@}

  ///@{
  /**
   * How long to wait for a connection and for each answer (seconds), and how
   * many times a request that got no answer is retried after reconnecting.
   * Defaults 1 s, 0.5 s and 2.
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
   * The motion written by Enable(): velocity limit (degree/s), acceleration
   * and deceleration (degree/s^2), soft limits (degrees; targets outside are
   * refused) and the controller's watchdog timeout (seconds, 0 = off).
   * Defaults 30 degree/s, 60 degree/s^2, [-360, 360] and 1 s.
   */
  vtkSetMacro(Velocity, double);
  vtkGetMacro(Velocity, double);
  vtkSetMacro(Acceleration, double);
  vtkGetMacro(Acceleration, double);
  vtkSetVector2Macro(SoftLimits, double);
  vtkGetVector2Macro(SoftLimits, double);
  vtkSetMacro(WatchdogTimeout, double);
  vtkGetMacro(WatchdogTimeout, double);
  ///@}

  ///@{
  /**
   * The move deadline: a move that is not in position DeadlineFactor times
   * its profile's duration plus DeadlineMargin seconds after it started is
   * quick-stopped and fails. Defaults 1.5 and 0.5 s. PollInterval: how often
   * the state is read while waiting (seconds, default 0.02).
   */
  vtkSetMacro(DeadlineFactor, double);
  vtkGetMacro(DeadlineFactor, double);
  vtkSetMacro(DeadlineMargin, double);
  vtkGetMacro(DeadlineMargin, double);
  vtkSetMacro(PollInterval, double);
  vtkGetMacro(PollInterval, double);
  ///@}

  /**
   * Reads the settings from a gantry description (gantry.json, format
   * "lfd-gantry", version 1, Data/README.md): "address" and "port" are
   * required, the motion and timeout fields optional (absent: the current
   * values stay). False, with one error naming the file and the field, when
   * the file is not a valid description; then no setting changes.
   */
  bool ReadConfiguration(const char* fileName);

  /**
   * Checks the settings, connects and checks the controller's identity and
   * register map version. Reconnects when already connected.
   */
  bool Connect();

  /**
   * Closes the connection (safe when not connected).
   */
  void Disconnect();

  /**
   * Whether the connection is open now (a failed request closes it; the
   * next one reconnects).
   */
  bool IsConnected() const;

  /**
   * Writes velocity, acceleration, soft limits and watchdog timeout, and
   * enables the axis. Fails when the controller reports a fault (reset it
   * with ResetFault()).
   */
  bool Enable();

  /**
   * Drives to the home sensor (position 0) and waits until homed.
   */
  bool Home();

  /**
   * Moves to `angle` (degrees) and waits until in position: StartMove() then
   * WaitInPosition().
   */
  bool MoveTo(double angle);

  /**
   * Starts a move to `angle` (degrees) without waiting. Needs the axis
   * enabled and homed, and `angle` within the soft limits.
   */
  bool StartMove(double angle);

  /**
   * Waits until the motion started last is in position, refreshing the
   * watchdog; quick-stops and fails at the move deadline or on a fault.
   */
  bool WaitInPosition();

  ///@{
  /**
   * Stop decelerates at Acceleration; QuickStop at 4 times it (the
   * controller's quick-stop deceleration). Both return at once.
   */
  bool Stop();
  bool QuickStop();
  ///@}

  /**
   * Clears a fault (the axis is then disabled: Enable() again).
   */
  bool ResetFault();

  /**
   * Reads status word, fault code and actual position into the values below.
   */
  bool UpdateState();

  ///@{
  /**
   * The state read last (UpdateState(), and every wait): actual position in
   * degrees, status word and fault code (lfdGantryRegisters.h), and its bits.
   */
  vtkGetMacro(ActualAngle, double);
  vtkGetMacro(StatusWord, int);
  vtkGetMacro(FaultCode, int);
  bool IsReady() const;
  bool IsMoving() const;
  bool IsInPosition() const;
  bool IsHomed() const;
  ///@}

  /**
   * "gantry <address>:<port>", as every message names the device.
   */
  std::string GetDeviceName() const;

protected:
  vtkModbusGantry();
  ~vtkModbusGantry() override;

  char* Address = nullptr;
  int Port = 502;
  double ConnectTimeout = 1.0;
  double ResponseTimeout = 0.5;
  int Retries = 2;
  double Velocity = 30.0;
  double Acceleration = 60.0;
  double SoftLimits[2] = { -360.0, 360.0 };
  double WatchdogTimeout = 1.0;
  double DeadlineFactor = 1.5;
  double DeadlineMargin = 0.5;
  double PollInterval = 0.02;

  double ActualAngle = 0.0;
  int StatusWord = 0;
  int FaultCode = 0;

private:
  vtkModbusGantry(const vtkModbusGantry&) = delete;
  void operator=(const vtkModbusGantry&) = delete;

  /// "" or why a setting is refused, naming the property or (`fileFields`)
  /// the gantry description's field.
  std::string CheckSettings(bool fileFields);
  /// The one error of a failed call: the device, then `reason`.
  void Refuse(const std::string& reason);
  /// Refuses with what a failed request's errno means.
  void RefuseRequest(int error, const std::string& during);
  /// Writes the control word.
  bool Command(int control, const std::string& during);
  /// Connected, state read, no fault, enabled (and homed when asked).
  bool CheckReady(bool homed, const std::string& motion);
  /// Writes `control` to start a motion to `target` at `velocity` and sets
  /// its deadline.
  bool BeginMotion(double target, double velocity, int control, const std::string& motion);

  /// WaitInPosition()'s polling loop.
  bool PollMotion();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
