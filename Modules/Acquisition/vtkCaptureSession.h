/**
 * @class   vtkCaptureSession
 * @brief   captures a light field: gantry, lights and camera driven through a plan
 *
 * The paper's capture (Chen, Ofek, Shum, Levoy, I3D 2005, Sec. 4.1, Fig. 8)
 * photographs an object from every position of a ring gantry under a
 * coaxial, a colour-coded and a floodlit lighting. A session executes such
 * a plan: for each planned view k (the views of the writer's plan, in
 * order) it moves the gantry to FirstAngle + k AngleStep and waits in
 * position, then for each pass of the writer asks every light to Apply()
 * it and the camera to Acquire() a frame, and commits the view to the
 * dataset (vtkIncrementalLightFieldWriter) before the next move. The same
 * code drives the real devices and the simulated ones (vtkGantrySimulator,
 * vtkSimulatedRigCamera).
 *
 * Capture() starts a new dataset, Resume() continues one after its complete
 * views (after a fault, Abort(), a crash or kill -9: a view is either listed
 * complete with all its images or taken again). Before the first move the
 * gantry is connected, a fault it reports is reset, it is enabled, and
 * homed when it is not; the camera is opened and the lights prepared
 * (vtkCaptureLight::Prepare()); a new dataset is created only then.
 *
 * A failure of any device stops the gantry first (QuickStop()), switches
 * the lights off, closes the camera and is reported as ONE error: the view,
 * then the device's own message naming it ("gantry 127.0.0.1:1502: ...",
 * "Camera 127.0.0.1: ..."); further messages of the devices while stopping
 * are not reported. Abort() (safe from a signal handler) stops after the
 * view being taken, without an error.
 *
 * ProgressEvent is invoked after every committed view with the fraction of
 * planned views complete (double*); GetSecondsRemaining() is the estimate
 * at that moment. The timings separate the devices' time (moves and
 * acquisitions) from the session's own (lights, writing, bookkeeping).
 *
 * @sa vtkModbusGantry vtkCaptureCamera vtkCaptureLight vtkIncrementalLightFieldWriter
 */
#ifndef vtkCaptureSession_h
#define vtkCaptureSession_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <csignal> // For std::sig_atomic_t
#include <string>  // For std::string
#include <vector>  // For std::vector

class vtkCaptureCamera;
class vtkCaptureLight;
class vtkIncrementalLightFieldWriter;
class vtkLightFieldErrorObserver;
class vtkModbusGantry;

class LFDACQUISITION_EXPORT vtkCaptureSession : public vtkObject
{
public:
  static vtkCaptureSession* New();
  vtkTypeMacro(vtkCaptureSession, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The devices: the gantry, the camera and the lights (coaxial lamp,
   * projectors), which are applied in the order they were added.
   */
  virtual void SetGantry(vtkModbusGantry* gantry);
  vtkGetObjectMacro(Gantry, vtkModbusGantry);
  virtual void SetCamera(vtkCaptureCamera* camera);
  vtkGetObjectMacro(Camera, vtkCaptureCamera);
  void AddLight(vtkCaptureLight* light);
  void RemoveAllLights();
  int GetNumberOfLights() const;
  ///@}

  /**
   * The dataset writer: set its Directory, Plan and passes before
   * Capture(). Never nullptr.
   */
  vtkIncrementalLightFieldWriter* GetWriter();

  ///@{
  /**
   * The gantry angle of planned view k is FirstAngle + k AngleStep
   * (degrees). Defaults 0 and 10.
   */
  vtkSetMacro(FirstAngle, double);
  vtkGetMacro(FirstAngle, double);
  vtkSetMacro(AngleStep, double);
  vtkGetMacro(AngleStep, double);
  ///@}

  ///@{
  /**
   * Captures the plan into a new dataset, or continues the dataset's
   * capture. True when every planned view is complete or the session was
   * aborted (GetAborted()); false after one error.
   */
  bool Capture();
  bool Resume();
  ///@}

  ///@{
  /**
   * Asks the running capture to stop after the view it is taking;
   * async-signal-safe. Capture() and Resume() clear the request when they
   * start. GetAborted(): the last run stopped because of it.
   */
  void Abort();
  vtkGetMacro(Aborted, bool);
  ///@}

  ///@{
  /**
   * The last run: views taken by it; from the first move to the last
   * commit, the seconds the gantry spent moving and the camera acquiring,
   * and the seconds of everything else (lights, writing, the session's own
   * work; connecting and homing before are in neither); the estimate of the
   * seconds still needed (after each view).
   */
  vtkGetMacro(NumberOfViewsTaken, int);
  vtkGetMacro(DeviceSeconds, double);
  vtkGetMacro(OverheadSeconds, double);
  vtkGetMacro(SecondsRemaining, double);
  ///@}

protected:
  vtkCaptureSession();
  ~vtkCaptureSession() override;

  vtkModbusGantry* Gantry = nullptr;
  vtkCaptureCamera* Camera = nullptr;
  double FirstAngle = 0.0;
  double AngleStep = 10.0;
  bool Aborted = false;
  int NumberOfViewsTaken = 0;
  double DeviceSeconds = 0.0;
  double OverheadSeconds = 0.0;
  double SecondsRemaining = 0.0;

private:
  vtkCaptureSession(const vtkCaptureSession&) = delete;
  void operator=(const vtkCaptureSession&) = delete;

  bool Run(bool resume);
  /// Connects, resets a fault, enables and homes the gantry; opens the
  /// camera; prepares the lights.
  bool PrepareDevices();
  /// Moves to view `view`'s angle, photographs every pass, commits the view.
  bool TakeView(int view);
  /// Stops the gantry, lights off, camera closed; reports `context` and the
  /// first device error (or `context` alone) as the session's one error.
  bool Fail(const std::string& context);

  std::vector<vtkSmartPointer<vtkCaptureLight>> Lights;
  vtkSmartPointer<vtkIncrementalLightFieldWriter> Writer;
  vtkSmartPointer<vtkLightFieldErrorObserver> DeviceErrors;
  volatile std::sig_atomic_t AbortRequested = 0;
};

#endif
