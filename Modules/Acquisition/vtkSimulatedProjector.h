/**
 * @class   vtkSimulatedProjector
 * @brief   a projector of the simulated rig: what it shows lights the
 *          simulated camera's renders
 *
 * The simulated counterpart of vtkProjectorWindow: ShowPattern() hands the
 * pattern to Camera (vtkSimulatedRigCamera::SetProjectorPattern) as
 * projector ProjectorIndex of the camera's Projectors, so the next frames
 * show the object lit by it (vtkLightFieldCapture's synthetic projectors).
 * Off() darkens it. The Resolution defaults to the simulated projector's
 * image size.
 *
 * @sa vtkCaptureProjector vtkSimulatedRigCamera
 */
#ifndef vtkSimulatedProjector_h
#define vtkSimulatedProjector_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureProjector.h"

class vtkSimulatedRigCamera;

class LFDACQUISITION_EXPORT vtkSimulatedProjector : public vtkCaptureProjector
{
public:
  static vtkSimulatedProjector* New();
  vtkTypeMacro(vtkSimulatedProjector, vtkCaptureProjector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The simulated camera whose renders this projector lights. Default
   * nullptr.
   */
  virtual void SetCamera(vtkSimulatedRigCamera* camera);
  vtkGetObjectMacro(Camera, vtkSimulatedRigCamera);
  ///@}

  bool ShowPattern(vtkImageData* pattern) override;
  void Off() override;

protected:
  vtkSimulatedProjector();
  ~vtkSimulatedProjector() override;

  /**
   * Needs the Camera; takes the Resolution from its projectors when unset.
   */
  bool PrepareDevice() override;

  vtkSimulatedRigCamera* Camera = nullptr;

private:
  vtkSimulatedProjector(const vtkSimulatedProjector&) = delete;
  void operator=(const vtkSimulatedProjector&) = delete;
};

#endif
