/**
 * @class   vtkSimulatedRigCamera
 * @brief   a fake GigE Vision camera on the network whose frames are renders
 *          of a synthetic object as the capture rig would photograph it
 *
 * The simulated rig (issue 12, paper Sec. 4.1) runs a capture through real
 * protocols: this class serves an in-process Aravis fake GigE Vision camera
 * (ArvGvFakeCamera, GVCP port 3956 of Address) that any GigE Vision client,
 * vtkAravisCamera or `arv-viewer-0.8`, opens, triggers and streams from.
 * Each triggered frame is rendered at that moment by vtkLightFieldCapture
 * (GetCapture(): connect the mesh, e.g. vtkProceduralObjectSource's fish,
 * and set its Ambient and ProjectorAmbient; the rest is set per frame):
 *
 * - the camera: view HomeView of Rig at gantry angle 0, turned about the
 *   rig's fitted cylinder axis by the current gantry angle (right-handed,
 *   degrees, so angle 360 k / N is view k of a ring of N views built by
 *   vtkCameraRig::MakeCylinder); the angle comes from the AngleSource
 *   when one is set (the gantry's actual position, read at exposure
 *   time), else from Angle;
 * - the lights, as the simulated lights set them: the coaxial lamp
 *   (SetCoaxialLight, vtkSimulatedCoaxialLight; or, with a
 *   CoaxialLightSource, the lamp as the rig switched it, e.g. the gantry
 *   simulator's coil that a vtkModbusLight drives) renders the Coaxial pass;
 *   each projector of Projectors that shows a pattern
 *   (SetProjectorPattern, vtkSimulatedProjector) lights the object as
 *   vtkLightFieldCapture's Coded pass with that pattern as its mask (a
 *   white pattern is the Flood pass, Gray codes work alike); lights add up;
 * - Gaussian sensor noise of SensorNoise 8-bit levels (seeded), then the
 *   pixel format the client chose (RGB8, Mono8, Bayer, see lfdPixelFormat.h).
 *   ExposureTime and Gain are accepted but do not change the image.
 *
 * Rendering needs an OpenGL context (an X server, e.g. `xvfb-run -a`).
 * Aravis calls the frame callback in its own thread, which also answers the
 * control channel; the frame is rendered in a render thread of this class
 * that creates and owns its OpenGL windows, and handed over. The
 * AngleSource is called in that thread. Between Start() and Stop() the
 * capture, rig and projectors belong to the render thread: configure them
 * before Start().
 *
 * Faults on demand, for the client's retry logic: DropFrames(n) sends
 * nothing for the next n frames (the client times out), DamageFrames(n)
 * loses half the packets of the next n frames (the client gets a frame
 * whose status is not SUCCESS), DelayFrames(n, ms) sends the next n frames
 * ms late (a slow camera: a client that gave up on the trigger and sent
 * another gets both frames; like Aravis's fake camera, it answers no control
 * packet meanwhile, and past its 3 s heartbeat timeout it drops the client).
 * When the AngleSource fails the frame is
 * dropped too.
 *
 * @sa vtkAravisCamera vtkSimulatedProjector vtkSimulatedCoaxialLight
 * vtkLightFieldCapture
 */
#ifndef vtkSimulatedRigCamera_h
#define vtkSimulatedRigCamera_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#ifndef __VTK_WRAP__
#include <functional> // For the angle source
#endif

class vtkCameraRig;
class vtkImageData;
class vtkLightFieldCapture;

class LFDACQUISITION_EXPORT vtkSimulatedRigCamera : public vtkObject
{
public:
  static vtkSimulatedRigCamera* New();
  vtkTypeMacro(vtkSimulatedRigCamera, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The IPv4 address the camera serves on (default "127.0.0.1") and its
   * serial number (default "LFD-SIM").
   */
  vtkSetStringMacro(Address);
  vtkGetStringMacro(Address);
  vtkSetStringMacro(SerialNumber);
  vtkGetStringMacro(SerialNumber);
  ///@}

  /**
   * The renderer of the frames: connect the mesh to it and set its
   * lighting before Start().
   */
  vtkLightFieldCapture* GetCapture();

  ///@{
  /**
   * The rig whose view HomeView is the camera at gantry angle 0 (its image
   * size is the frame size); it needs a fitted cylinder, whose axis is the
   * gantry's. Defaults nullptr and 0.
   */
  virtual void SetRig(vtkCameraRig* rig);
  vtkGetObjectMacro(Rig, vtkCameraRig);
  vtkSetClampMacro(HomeView, int, 0, VTK_INT_MAX);
  vtkGetMacro(HomeView, int);
  ///@}

  ///@{
  /**
   * The projectors (K, R, t, image size) fixed in the world, e.g. a
   * synthetic light field's GetProjectors(). Default nullptr: none.
   */
  virtual void SetProjectors(vtkCameraRig* projectors);
  vtkGetObjectMacro(Projectors, vtkCameraRig);
  ///@}

  ///@{
  /**
   * The gantry angle in degrees used when no AngleSource is set. Default 0.
   */
  vtkSetMacro(Angle, double);
  vtkGetMacro(Angle, double);
  ///@}

#ifndef __VTK_WRAP__
  /**
   * Where the gantry angle comes from at each exposure: a function that
   * sets the angle in degrees and returns true, or returns false when it
   * cannot tell (the frame is then dropped). Called in the render thread.
   * An empty function (the default) uses Angle.
   */
  void SetAngleSource(std::function<bool(double& degrees)> source);

  /**
   * Where the coaxial lamp's state comes from at each exposure: a function
   * that returns whether the lamp is on now (e.g. the gantry simulator's
   * coil, vtkGantrySimulator::GetCoil()). Called in the render thread and by
   * GetCoaxialLight(). An empty function (the default) uses
   * SetCoaxialLight().
   */
  void SetCoaxialLightSource(std::function<bool()> source);
#endif

  ///@{
  /**
   * Standard deviation of the Gaussian sensor noise in 8-bit levels
   * (default 0) and its seed (default 1).
   */
  vtkSetClampMacro(SensorNoise, double, 0.0, 255.0);
  vtkGetMacro(SensorNoise, double);
  vtkSetMacro(NoiseSeed, int);
  vtkGetMacro(NoiseSeed, int);
  ///@}

  ///@{
  /**
   * The lights the next frames are rendered under: the coaxial lamp on or
   * off, and the pattern projector `projector` shows (RGB uint8 of the
   * projector's image size, rows bottom first as in a light field's
   * projector masks; copied), nullptr for dark. False, with an error, for
   * a projector that does not exist or a pattern of the wrong size. Safe
   * to call while the camera runs. GetCoaxialLight() asks the
   * CoaxialLightSource when one is set.
   */
  void SetCoaxialLight(bool on);
  bool GetCoaxialLight();
  bool SetProjectorPattern(int projector, vtkImageData* pattern);
  ///@}

  /**
   * The projectors that light the object now: those showing a pattern that
   * is not all black.
   */
  int GetNumberOfLitProjectors();

  ///@{
  /**
   * Faults: the next `count` frames are not sent at all, lose half of
   * their packets, or are sent `milliseconds` late. Safe to call while the
   * camera runs.
   */
  void DropFrames(int count);
  void DamageFrames(int count);
  void DelayFrames(int count, int milliseconds);
  ///@}

  /**
   * Starts the render thread and serves the camera. False, with an error
   * naming the address, when the rig or the capture's input is missing,
   * the address is not a local IPv4 address or another camera serves there.
   */
  bool Start();

  /**
   * Stops serving and rendering; safe to call when not running.
   */
  void Stop();

  /**
   * Whether Start() succeeded and Stop() has not been called.
   */
  bool IsRunning();

  /**
   * Frames rendered and handed to the camera since Start() (dropped ones
   * are not counted).
   */
  int GetNumberOfFramesRendered();

protected:
  vtkSimulatedRigCamera();
  ~vtkSimulatedRigCamera() override;

  char* Address = nullptr;
  char* SerialNumber = nullptr;
  vtkCameraRig* Rig = nullptr;
  int HomeView = 0;
  vtkCameraRig* Projectors = nullptr;
  double Angle = 0.0;
  double SensorNoise = 0.0;
  int NoiseSeed = 1;

private:
  vtkSimulatedRigCamera(const vtkSimulatedRigCamera&) = delete;
  void operator=(const vtkSimulatedRigCamera&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
