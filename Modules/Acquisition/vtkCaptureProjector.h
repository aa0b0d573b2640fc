/**
 * @class   vtkCaptureProjector
 * @brief   a projector of the capture rig: shows its colour mask, white or
 *          black according to the pass, or any pattern
 *
 * The projectors of the paper's Sec. 4.1 paint the object with colour masks
 * (the Coded pass: one colour per part, painted in the Studio) and light it
 * white (the Flood pass); in the Coaxial pass they are dark. Apply(pass)
 * shows the pattern of the pass: the slice ProjectorIndex of Masks
 * (Wp x Hp x P, RGB uint8, rows bottom first: a light field's
 * GetProjectorMasks()) for CODED, white for FLOOD, black for COAXIAL.
 * ShowPattern() shows any RGB uint8 image of the projector's Resolution,
 * e.g. the Gray codes of vtkGrayCodePatternSource for calibration.
 *
 * Subclasses put the pattern where it goes: vtkProjectorWindow on a screen
 * of an X display (a real projector), vtkSimulatedProjector into the
 * simulated rig camera's renders.
 *
 * @sa vtkCaptureLight vtkProjectorWindow vtkSimulatedProjector
 * vtkGrayCodePatternSource
 */
#ifndef vtkCaptureProjector_h
#define vtkCaptureProjector_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureLight.h"

class vtkImageData;

class LFDACQUISITION_EXPORT vtkCaptureProjector : public vtkCaptureLight
{
public:
  vtkTypeMacro(vtkCaptureProjector, vtkCaptureLight);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The projectors' colour masks (Wp x Hp x P, RGB uint8 "Mask" array or
   * scalars, rows bottom first) and which slice is this projector's.
   * Defaults nullptr and 0.
   */
  virtual void SetMasks(vtkImageData* masks);
  vtkGetObjectMacro(Masks, vtkImageData);
  vtkSetClampMacro(ProjectorIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(ProjectorIndex, int);
  ///@}

  ///@{
  /**
   * The projector's image size in pixels. (0, 0), the default, takes the
   * size of Masks.
   */
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  ///@}

  /**
   * The resolution in use: Resolution, or the size of Masks; false when
   * neither is set.
   */
  bool GetPatternSize(int size[2]);

  /**
   * Black for COAXIAL, this projector's mask for CODED, white for FLOOD.
   */
  bool Apply(int pass) override;

  /**
   * Shows black.
   */
  void Off() override;

  /**
   * Opens the device (PrepareDevice()).
   */
  bool Prepare() override { return this->PrepareDevice(); }

  /**
   * Shows `pattern`: RGB uint8 scalars of the projector's size, one slice,
   * rows bottom first. False, with an error naming the projector, when the
   * pattern does not fit or the device fails.
   */
  virtual bool ShowPattern(vtkImageData* pattern) = 0;

protected:
  vtkCaptureProjector();
  ~vtkCaptureProjector() override;

  /**
   * Gets the device ready to show patterns (opens it, learns its
   * Resolution); false with an error naming the projector. Apply(), Off()
   * and ShowPattern() call it first. The default has nothing to do.
   */
  virtual bool PrepareDevice() { return true; }

  /**
   * A plain RGB image of the projector's size, or nullptr (with an error)
   * when it has none.
   */
  vtkImageData* MakeSolidPattern(unsigned char value);

  /**
   * Whether `pattern` is RGB uint8 of the pattern size; reports the
   * mismatch as an error naming the projector.
   */
  bool CheckPattern(vtkImageData* pattern);

  vtkImageData* Masks = nullptr;
  int ProjectorIndex = 0;
  int Resolution[2] = { 0, 0 };

private:
  vtkCaptureProjector(const vtkCaptureProjector&) = delete;
  void operator=(const vtkCaptureProjector&) = delete;
};

#endif
