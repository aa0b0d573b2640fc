/**
 * @class   vtkSimulatedCoaxialLight
 * @brief   the coaxial lamp of the simulated rig: on for the Coaxial pass only
 *
 * The lamp that travels with the camera (paper Sec. 4.1, DESIGN.md
 * section 5): Apply(COAXIAL) switches the simulated camera's coaxial light
 * on (its frames then show vtkLightFieldCapture's Coaxial pass), any other
 * pass and Off() switch it off.
 *
 * @sa vtkCaptureLight vtkSimulatedRigCamera vtkSimulatedProjector
 */
#ifndef vtkSimulatedCoaxialLight_h
#define vtkSimulatedCoaxialLight_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureLight.h"

class vtkSimulatedRigCamera;

class LFDACQUISITION_EXPORT vtkSimulatedCoaxialLight : public vtkCaptureLight
{
public:
  static vtkSimulatedCoaxialLight* New();
  vtkTypeMacro(vtkSimulatedCoaxialLight, vtkCaptureLight);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The simulated camera the lamp is mounted on. Default nullptr.
   */
  virtual void SetCamera(vtkSimulatedRigCamera* camera);
  vtkGetObjectMacro(Camera, vtkSimulatedRigCamera);
  ///@}

  bool Apply(int pass) override;
  void Off() override;

protected:
  vtkSimulatedCoaxialLight();
  ~vtkSimulatedCoaxialLight() override;

  vtkSimulatedRigCamera* Camera = nullptr;

private:
  vtkSimulatedCoaxialLight(const vtkSimulatedCoaxialLight&) = delete;
  void operator=(const vtkSimulatedCoaxialLight&) = delete;
};

#endif
