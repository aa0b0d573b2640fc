/**
 * @class   vtkCaptureCamera
 * @brief   a camera that a capture session triggers: one frame per call
 *
 * The capture session (paper Sec. 4.1: a camera on a ring gantry takes a
 * coaxial, a colour-coded and a floodlit photograph at every position)
 * sees every camera through this interface, so a real GigE Vision camera
 * and the simulated rig camera run the same plan and code. Open() connects
 * to the device at Address, Acquire() triggers one frame and waits for it,
 * Close() releases the device. Failures are reported as one VTK error that
 * names the device (Address) and the reason, and the call returns false.
 *
 * @sa vtkCaptureLight
 */
#ifndef vtkCaptureCamera_h
#define vtkCaptureCamera_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"

class vtkImageData;

class LFDACQUISITION_EXPORT vtkCaptureCamera : public vtkObject
{
public:
  vtkTypeMacro(vtkCaptureCamera, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Where the device is (an IP address, a serial number...), used in every
   * error message. Default nullptr.
   */
  vtkSetStringMacro(Address);
  vtkGetStringMacro(Address);
  ///@}

  ///@{
  /**
   * Exposure time in microseconds and analogue gain in dB, applied by
   * Open(). Defaults 10000 us and 0 dB.
   */
  vtkSetClampMacro(ExposureTime, double, 1.0, 1.0e7);
  vtkGetMacro(ExposureTime, double);
  vtkSetClampMacro(Gain, double, 0.0, 48.0);
  vtkGetMacro(Gain, double);
  ///@}

  /**
   * Connects to the device and applies the settings. False, with an error
   * naming the device, when it cannot.
   */
  virtual bool Open() = 0;

  /**
   * Triggers one frame and stores it in `frame` as an RGB uint8 image
   * (OpenCV row order: row 0 is the top of the photograph). False, with an
   * error naming the device, when no good frame came.
   */
  virtual bool Acquire(vtkImageData* frame) = 0;

  /**
   * Releases the device; safe to call when it is not open.
   */
  virtual void Close() = 0;

protected:
  vtkCaptureCamera();
  ~vtkCaptureCamera() override;

  char* Address = nullptr;
  double ExposureTime = 10000.0;
  double Gain = 0.0;

private:
  vtkCaptureCamera(const vtkCaptureCamera&) = delete;
  void operator=(const vtkCaptureCamera&) = delete;
};

#endif
