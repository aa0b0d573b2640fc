/**
 * @class   vtkAravisCamera
 * @brief   a GigE Vision camera driven through Aravis: one software-triggered
 *          frame per Acquire()
 *
 * Open() connects to the camera at Address (an IP address or an Aravis
 * device id; no discovery, which costs a second), clears the triggers a
 * previous client may have left (camera registers persist between
 * clients), applies ExposureTime, Gain and PixelFormat, selects a software
 * trigger on FrameStart and starts a continuous acquisition. The GigE Vision
 * stream is set up for loopback and cheap cameras alike: no packet socket
 * (it receives nothing on `lo`), a fixed 4 MiB socket buffer, 1400-byte
 * packets.
 *
 * Acquire() triggers, waits up to FrameTimeout for the frame and checks its
 * status: a frame that did not arrive or arrived incomplete (missing
 * packets, timeout...) is triggered again, up to MaximumAttempts in all.
 * A trigger given up on may still be answered later (a camera that was
 * only slow): the camera counts the triggers it has not yet received a
 * frame for, and the next Acquire() first waits (up to FrameTimeout) for
 * those frames and discards them, so that a frame exposed under the
 * previous pass's lights is never taken for the next one's. The frame is converted to RGB uint8
 * (Mono8 as grey, Bayer by bilinear demosaicing, see lfdPixelFormat.h) with
 * row 0 the top of the photograph (vtkCaptureCamera's convention).
 *
 * Every failure is one VTK error naming the camera and what failed, e.g.
 * `Camera 127.0.0.1: refuses Gain = 20 dB: ...` or
 * `Camera 10.0.0.9: cannot connect: ...`.
 *
 * @sa vtkCaptureCamera vtkSimulatedRigCamera
 */
#ifndef vtkAravisCamera_h
#define vtkAravisCamera_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureCamera.h"

#include <memory> // For std::unique_ptr

class LFDACQUISITION_EXPORT vtkAravisCamera : public vtkCaptureCamera
{
public:
  static vtkAravisCamera* New();
  vtkTypeMacro(vtkAravisCamera, vtkCaptureCamera);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Pixel formats the camera may send (GenICam names).
   */
  enum PixelFormats
  {
    RGB8 = 0,
    BAYER_RG8,
    BAYER_BG8,
    BAYER_GB8,
    BAYER_GR8,
    MONO8
  };

  ///@{
  /**
   * The pixel format asked of the camera (default RGB8). Frames are RGB
   * whatever it is.
   */
  vtkSetClampMacro(PixelFormat, int, RGB8, MONO8);
  vtkGetMacro(PixelFormat, int);
  ///@}

  /**
   * The GenICam name of a pixel format ("RGB8", "BayerRG8", ...), nullptr
   * when out of range; and the format of a name (-1 when unknown).
   */
  static const char* GetPixelFormatName(int format);
  static int GetPixelFormatFromName(const char* name);

  ///@{
  /**
   * How long Acquire() waits for one frame, in milliseconds (default 2000),
   * and how many frames it triggers before giving up (default 3).
   */
  vtkSetClampMacro(FrameTimeout, int, 1, 600000);
  vtkGetMacro(FrameTimeout, int);
  vtkSetClampMacro(MaximumAttempts, int, 1, 100);
  vtkGetMacro(MaximumAttempts, int);
  ///@}

  /**
   * Frames triggered again since Open() because the first did not arrive
   * whole (a figure for the session's report and for the tests).
   */
  vtkGetMacro(NumberOfRetries, int);

  /**
   * Late frames (answers to triggers given up on) discarded since Open().
   */
  vtkGetMacro(NumberOfLateFrames, int);

  ///@{
  /**
   * The frame size the camera reported at Open() (0 before).
   */
  vtkGetVector2Macro(FrameSize, int);
  ///@}

  bool Open() override;
  bool Acquire(vtkImageData* frame) override;
  void Close() override;

protected:
  vtkAravisCamera();
  ~vtkAravisCamera() override;

  int PixelFormat = RGB8;
  int FrameTimeout = 2000;
  int MaximumAttempts = 3;
  int NumberOfRetries = 0;
  int NumberOfLateFrames = 0;
  int FrameSize[2] = { 0, 0 };

private:
  vtkAravisCamera(const vtkAravisCamera&) = delete;
  void operator=(const vtkAravisCamera&) = delete;

  // Waits for and discards the frames still owed to triggers given up on.
  void DiscardLateFrames();

  struct Device;
  std::unique_ptr<Device> Connection;
};

#endif
