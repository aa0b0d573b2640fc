/**
 * @class   vtkCaptureLight
 * @brief   a light of the capture rig: the coaxial light or a projector
 *
 * Each view of a capture is photographed under several lightings, the
 * passes of the paper's Sec. 4.1 (vtkLightField::COAXIAL, CODED, FLOOD):
 * before each photograph the session asks every light to Apply() the pass,
 * and each light turns itself on or off or shows the pattern that the pass
 * needs (a projector shows its colour mask for CODED and white for FLOOD;
 * the coaxial light is on for COAXIAL only). Failures are reported as one
 * VTK error naming the device, and the call returns false.
 *
 * @sa vtkCaptureCamera vtkLightField
 */
#ifndef vtkCaptureLight_h
#define vtkCaptureLight_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkObject.h"

class LFDACQUISITION_EXPORT vtkCaptureLight : public vtkObject
{
public:
  vtkTypeMacro(vtkCaptureLight, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * A name for the device in messages (e.g. "projector 1", ":0.1").
   * Default nullptr.
   */
  vtkSetStringMacro(Name);
  vtkGetStringMacro(Name);
  ///@}

  /**
   * Sets the light for a pass, a vtkLightField pass index (COAXIAL, CODED,
   * FLOOD). False, with an error naming the device, when it cannot.
   */
  virtual bool Apply(int pass) = 0;

  /**
   * Switches the light off (a projector shows black).
   */
  virtual void Off() = 0;

  /**
   * Gets the light ready before a capture's first move, so that a device
   * that is not there stops the capture before anything is written: opens
   * or connects to it (a lamp is switched off, which checks its coil). False,
   * with an error naming the device, when it cannot. The default has nothing
   * to do.
   */
  virtual bool Prepare() { return true; }

protected:
  vtkCaptureLight();
  ~vtkCaptureLight() override;

  char* Name = nullptr;

private:
  vtkCaptureLight(const vtkCaptureLight&) = delete;
  void operator=(const vtkCaptureLight&) = delete;
};

#endif
