/**
 * @class   vtkGantryCameraView
 * @brief   2D view of one captured view: its photo in any pass, the rest boxes projected over it
 *
 * vtkGantryCameraView sets up a given vtkRenderer, as vtkImageViewer2 does,
 * to look through one calibrated camera of a light field: view `View`'s
 * image in pass `Pass`, as captured (top row at the top), with
 * - the cage's **rest boxes projected** over it in their labels' palette
 *   colours: each edge is sampled (EdgeSamples points) and every sample is
 *   projected through the view's K, R, t and lens distortion
 *   (lfd::PinholeCamera::Project), so distorted edges curve. This is the
 *   check of Chen et al. 2005, section 4.1: "project the boxes onto each
 *   camera's view and verify";
 * - the labelled pixels that fall **outside** every rest box of their label
 *   highlighted in magenta, and the view's coverage figure (the smallest
 *   fraction of a label's pixels inside its boxes) in the corner. Both come
 *   from vtkBoxCoverageCheck (its outside-mask output and
 *   GetViewCoverage()), the implementation `lfd split check` reports, run
 *   once per change of the light field or the rest cage (not on a drag,
 *   which moves deformed points only).
 *
 * Passes: those of vtkLightField (Coaxial, Coded, Flood as captured; Label
 * in palette colours; Depth as grey, near bright; Confidence as grey) and
 * NORMALISED, the coded pass normalised by the flood pass (Eq. 1, B' = 256
 * B / W per channel, lfd::NormaliseByFlood; 0 where W is 0). A pass the
 * light field does not hold is an error (the image is then black).
 *
 * The view refreshes itself before each render of its renderer when the
 * light field, the cage's rest boxes or the palette changed. It handles no
 * interactor events.
 *
 * @sa vtkBoxCoverageCheck vtkRigView vtkProjectorView
 */
#ifndef vtkGantryCameraView_h
#define vtkGantryCameraView_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkCalibrationView.h"
#include "vtkLightField.h" // For vtkLightField::NUMBER_OF_PASSES

#include <memory> // For std::unique_ptr

class vtkBoxCoverageCheck;
class vtkDeformationCage;
class vtkLightField;
class vtkUnsignedCharArray;
class vtkImageData;
class vtkPolyData;

class LFDWIDGETS_EXPORT vtkGantryCameraView : public vtkCalibrationView
{
public:
  static vtkGantryCameraView* New();
  vtkTypeMacro(vtkGantryCameraView, vtkCalibrationView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass shown besides those of vtkLightField::Pass.
   */
  enum
  {
    NORMALISED = vtkLightField::NUMBER_OF_PASSES
  };

  ///@{
  /**
   * The cage whose rest boxes are projected.
   */
  void SetCage(vtkDeformationCage* cage);
  vtkDeformationCage* GetCage();
  ///@}

  ///@{
  /**
   * The view shown (default 0; clamped to the light field's views when
   * shown).
   */
  void SetView(int view);
  vtkGetMacro(View, int);
  ///@}

  ///@{
  /**
   * The pass shown: a vtkLightField::Pass or NORMALISED. Default COAXIAL.
   */
  void SetPass(int pass);
  vtkGetMacro(Pass, int);
  ///@}

  ///@{
  /**
   * Whether the projected rest boxes and the outside pixels are shown.
   * Both on by default.
   */
  void SetShowBoxes(bool show);
  vtkGetMacro(ShowBoxes, bool);
  vtkBooleanMacro(ShowBoxes, bool);
  void SetShowOutside(bool show);
  vtkGetMacro(ShowOutside, bool);
  vtkBooleanMacro(ShowOutside, bool);
  ///@}

  ///@{
  /**
   * Points sampled along each box edge before projection. Default 24.
   */
  vtkSetClampMacro(EdgeSamples, int, 2, 1000);
  vtkGetMacro(EdgeSamples, int);
  ///@}

  /**
   * Rebuilds what changed (image, boxes, coverage); called before each
   * render of the renderer.
   */
  void Refresh() override;

  /**
   * Fits the image into the renderer's viewport (parallel projection).
   */
  void ResetCamera() override;

  /**
   * The coverage of the shown view (vtkBoxCoverageCheck::GetViewCoverage),
   * or -1 without a cage, a Label pass or a rig.
   */
  double GetCoverage();

  /**
   * The colours labels are shown with, into `palette`: the light field's
   * own palette, or for a light field without one the default palette for
   * the cage's labels (vtkLabelPalette::BuildDefault), which the cage widget
   * shows too. `cage` may be null.
   */
  static void GetShownPalette(vtkLightField* lightField,
    vtkDeformationCage* cage,
    vtkUnsignedCharArray* palette);

  /**
   * The coverage check behind the view, up to date (its table, summaries
   * and outside mask for every view).
   */
  vtkBoxCoverageCheck* GetCoverageCheck();

  ///@{
  /**
   * What is shown: the view's image (RGB uint8, W x H, bottom row first),
   * the projected box edges (polylines in image coordinates, cell colours
   * "Colors") and the number of outside pixels highlighted.
   */
  vtkImageData* GetImage();
  vtkPolyData* GetProjectedBoxes();
  vtkIdType GetNumberOfOutsidePixels();
  ///@}

protected:
  vtkGantryCameraView();
  ~vtkGantryCameraView() override;

  void LightFieldChanged() override;
  bool HandleEvent(unsigned long, int, int) override { return false; }
  void UpdateImage();
  void UpdateBoxes();
  void UpdateCoverage();

  int View = 0;
  int Pass = vtkLightField::COAXIAL;
  bool ShowBoxes = true;
  bool ShowOutside = true;
  int EdgeSamples = 24;

private:
  vtkGantryCameraView(const vtkGantryCameraView&) = delete;
  void operator=(const vtkGantryCameraView&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
