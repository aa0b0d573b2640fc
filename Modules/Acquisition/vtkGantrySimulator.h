/**
 * @class   vtkGantrySimulator
 * @brief   a simulated ring gantry: a real Modbus TCP server with a
 *          trapezoidal motion profile and faults on demand
 *
 * The capture rig of the paper (Sec. 4.1, Fig. 8) turns the camera around
 * the object on a motorised gantry. This class stands in for its motion
 * controller on a network address (127.0.0.1 by default), speaking Modbus
 * TCP with the register map of lfdGantryRegisters.h (Data/README.md), so
 * that vtkModbusGantry, `lfd gantry` and `lfd capture` run unchanged
 * against it and against a real controller.
 *
 * The axis follows trapezoidal profiles (lfd::MotionProfile) evaluated at
 * the instant each request is answered; homing drives to the home sensor at
 * position 0 at half the velocity. Faults on demand (lfd::gantry::FaultMode),
 * armed by SetFault() before Start()/Serve(), by ArmFault() while serving,
 * or by a client writing the SimulatorFault register, fire half-way through
 * the next move: silent (no answers for SilentTime seconds), drive fault,
 * emergency stop and limit switch (each quick-stops the axis and faults it),
 * dropped connection (every connection closed, axis quick-stopped); slow
 * runs every move at SlowFactor of its velocity; stuck coils acknowledge
 * writes to the coils without changing them. The watchdog quick-stops a
 * move that receives no watchdog write within the watchdog timeout.
 *
 * The controller's digital outputs are coils 0 .. lfd::gantry::CoilCount - 1
 * (read with function 1, written with 5 and 15), all off at power-up: a
 * vtkModbusLight switches a lamp on one, and the simulated rig camera can
 * follow it (GetCoil()).
 *
 * Start() serves in a thread of this process (tests); Serve() serves in the
 * calling thread until RequestStop() (`lfd gantry-sim`, which calls it from
 * its signal handler). Failures to listen are one error naming the address
 * and port.
 *
 * @sa vtkModbusGantry
 */
#ifndef vtkGantrySimulator_h
#define vtkGantrySimulator_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class LFDACQUISITION_EXPORT vtkGantrySimulator : public vtkObject
{
public:
  static vtkGantrySimulator* New();
  vtkTypeMacro(vtkGantrySimulator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The address and TCP port to listen on. Port 0 (the default) takes a free
   * port, which GetBoundPort() tells once listening. Default address
   * 127.0.0.1.
   */
  vtkSetStringMacro(Address);
  vtkGetStringMacro(Address);
  vtkSetClampMacro(Port, int, 0, 65535);
  vtkGetMacro(Port, int);
  ///@}

  ///@{
  /**
   * The axis position (degrees) before homing, where the simulated axis
   * happens to be when the controller powers up. Default 37.5.
   */
  vtkSetMacro(StartAngle, double);
  vtkGetMacro(StartAngle, double);
  ///@}

  ///@{
  /**
   * The fault (lfd::gantry::FaultMode) armed when serving starts. Default 0
   * (none).
   */
  vtkSetClampMacro(Fault, int, 0, 7);
  vtkGetMacro(Fault, int);
  ///@}

  ///@{
  /**
   * How long the silent fault stops answering (seconds, default 2), and the
   * fraction of the velocity a slow move runs at (default 0.1).
   */
  vtkSetClampMacro(SilentTime, double, 0.0, 3600.0);
  vtkGetMacro(SilentTime, double);
  vtkSetClampMacro(SlowFactor, double, 0.001, 1.0);
  vtkGetMacro(SlowFactor, double);
  ///@}

  /**
   * Binds and listens. False, with an error naming address and port, when
   * it cannot (port taken, bad address). Start() and Serve() call it when it
   * has not been called.
   */
  bool Listen();

  /**
   * The port listened on (the one chosen for Port 0); 0 when not listening.
   */
  int GetBoundPort();

  /**
   * Serves in a thread of this process until Stop(). False when it cannot
   * listen.
   */
  bool Start();

  /**
   * Stops serving (the thread of Start() is joined) and closes every
   * connection and the listening socket.
   */
  void Stop();

  /**
   * Serves in the calling thread until RequestStop(). False when it cannot
   * listen.
   */
  bool Serve();

  /**
   * Asks Serve() to return; safe to call from a signal handler.
   */
  void RequestStop();

  /**
   * Arms a fault (lfd::gantry::FaultMode) while serving, as a write of the
   * SimulatorFault register does.
   */
  void ArmFault(int mode);

  ///@{
  /**
   * The axis as the controller sees it now: position in degrees, velocity
   * in degree/s, status word and fault code (lfdGantryRegisters.h), the
   * number of quick stops clients commanded (a quick-stop bit, or the
   * enable bit dropped during a move) and of client connections accepted
   * so far; and whether coil `coil` (a digital output) is on (false for a
   * coil that does not exist or when not listening).
   */
  double GetActualAngle();
  double GetActualVelocity();
  int GetStatusWord();
  int GetFaultCode();
  int GetNumberOfQuickStops();
  int GetNumberOfConnections();
  bool GetCoil(int coil);
  ///@}

protected:
  vtkGantrySimulator();
  ~vtkGantrySimulator() override;

  char* Address = nullptr;
  int Port = 0;
  double StartAngle = 37.5;
  int Fault = 0;
  double SilentTime = 2.0;
  double SlowFactor = 0.1;

private:
  vtkGantrySimulator(const vtkGantrySimulator&) = delete;
  void operator=(const vtkGantrySimulator&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
