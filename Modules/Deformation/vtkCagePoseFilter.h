/**
 * @class   vtkCagePoseFilter
 * @brief   poses a slab cage: twist, swim or bend its layers of corners
 *
 * vtkCagePoseFilter produces the deformations shown in the paper (Chen,
 * Ofek, Shum, Levoy, "Interactive Deformation of Light Fields", I3D 2005)
 * on a cage such as vtkPartCageSource builds. It copies the input cage
 * (a vtkDeformationCage, or any vtkUnstructuredGrid read as one by
 * vtkDeformationCage::InitializeFromGrid), starts from its **rest**
 * positions, and moves the deformed points layer by layer. A layer is the
 * set of points sharing the same rest coordinate along Axis (within 1e-6 of
 * the cage's length); layers are numbered k = 0..L-1 in increasing
 * coordinate, and each is rotated rigidly about a line through its centre
 * (the mean of its rest points):
 *
 * - TWIST (Fig. 1, the twisted objects): about the slab axis itself, by an
 *   angle growing linearly along the axis from 0 at the first layer to
 *   Angle at the last.
 * - SWIM (Fig. 13, the swimming fish): about TurnAxis by
 *   Angle * sin(Phase - k * Wavelength), and shifted along n = TurnAxis x
 *   Axis by Amplitude * length * sin(Phase - k * Wavelength + 0.5), where
 *   length is the cage's rest extent along Axis: a wave travelling towards
 *   the last layer as Phase grows. Every box, head and tail included, turns
 *   with the layers it shares with the body.
 * - BEND: about TurnAxis by an angle growing linearly along the axis from
 *   -Angle/2 at the first layer to +Angle/2 at the last, each layer centre
 *   placed on the circular arc of the same length that turns by Angle, so
 *   the layers stay orthogonal to the arc and the cage curves smoothly
 *   (towards +n for a positive Angle).
 *
 * TurnAxis is made orthogonal to Axis (its component along Axis is
 * dropped); it must not be parallel to Axis in SWIM and BEND. Angles are in
 * degrees, Phase and Wavelength in radians. Moderate poses (twist of
 * 45 degrees, swim of 20) of a vtkPartCageSource cage pass
 * vtkDeformationCage::Validate(); large ones may fold boxes, which Validate()
 * reports.
 *
 * @sa vtkPartCageSource vtkDeformationCage vtkKeyframeInterpolator
 */
#ifndef vtkCagePoseFilter_h
#define vtkCagePoseFilter_h

#include "lfdDeformationModule.h" // For export macro
#include "vtkDeformationCageAlgorithm.h"

class vtkDeformationCage;

class LFDDEFORMATION_EXPORT vtkCagePoseFilter : public vtkDeformationCageAlgorithm
{
public:
  static vtkCagePoseFilter* New();
  vtkTypeMacro(vtkCagePoseFilter, vtkDeformationCageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum PoseMode
  {
    TWIST = 0,
    SWIM = 1,
    BEND = 2
  };

  ///@{
  /**
   * The pose. Default TWIST.
   */
  vtkSetClampMacro(Mode, int, TWIST, BEND);
  vtkGetMacro(Mode, int);
  void SetModeToTwist() { this->SetMode(TWIST); }
  void SetModeToSwim() { this->SetMode(SWIM); }
  void SetModeToBend() { this->SetMode(BEND); }
  ///@}

  ///@{
  /**
   * The angle in degrees: the twist of the last layer (TWIST), the peak turn
   * of a layer (SWIM), the total turn from first to last layer (BEND).
   * Default 45.
   */
  vtkSetMacro(Angle, double);
  vtkGetMacro(Angle, double);
  ///@}

  ///@{
  /**
   * SWIM: the phase of the wave in radians (animate it for a swim cycle).
   * Default 0.
   */
  vtkSetMacro(Phase, double);
  vtkGetMacro(Phase, double);
  ///@}

  ///@{
  /**
   * SWIM: the phase difference between consecutive layers, radians.
   * Default 1.2.
   */
  vtkSetMacro(Wavelength, double);
  vtkGetMacro(Wavelength, double);
  ///@}

  ///@{
  /**
   * SWIM: the peak sideways shift of a layer as a fraction of the cage's
   * length along Axis. Default 0.06.
   */
  vtkSetMacro(Amplitude, double);
  vtkGetMacro(Amplitude, double);
  ///@}

  ///@{
  /**
   * The slab axis: 0, 1, 2 or -1 (default) for the longest side of the rest
   * cage's bounds.
   */
  vtkSetClampMacro(Axis, int, -1, 2);
  vtkGetMacro(Axis, int);
  ///@}

  ///@{
  /**
   * SWIM and BEND: the direction the layers turn about. Default (0, 1, 0),
   * the vertical.
   */
  vtkSetVector3Macro(TurnAxis, double);
  vtkGetVector3Macro(TurnAxis, double);
  ///@}

  /**
   * The number of layers found by the last update (0 before).
   */
  vtkGetMacro(NumberOfLayers, int);

protected:
  vtkCagePoseFilter();
  ~vtkCagePoseFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = TWIST;
  double Angle = 45.0;
  double Phase = 0.0;
  double Wavelength = 1.2;
  double Amplitude = 0.06;
  int Axis = -1;
  double TurnAxis[3] = { 0.0, 1.0, 0.0 };
  int NumberOfLayers = 0;

private:
  vtkCagePoseFilter(const vtkCagePoseFilter&) = delete;
  void operator=(const vtkCagePoseFilter&) = delete;
};

#endif
