/**
 * @class   vtkProjectorView
 * @brief   2D view of a projector's colour mask, with a brush that paints it
 *
 * Chen et al. 2005 (section 4.1) split a real object by painting, by hand,
 * one colour mask per video projector while the projector shows the mask
 * live on the object. vtkProjectorView sets up a given vtkRenderer, as
 * vtkImageViewer2 does, to show projector `Projector`'s mask (the light
 * field's GetProjectorMasks() slice, as the projector shows it: top row at
 * the top), and, once an interactor is set and the view enabled (On()),
 * paints it: a left-button drag in this view's renderer paints every mask
 * pixel within BrushRadius pixels of the mouse path in the palette colour of
 * BrushLabel (0 paints black, no part).
 *
 * The view never edits the light field itself. A stroke paints a working
 * copy (shown while painting); on release the view invokes MaskStrokeEvent
 * (call data: the projector index, int*) and GetStrokeMask() holds the
 * painted mask. Apply it as one undoable command of the scene logic:
 *
 *     view.AddObserver(lfd.vtkProjectorView.MaskStrokeEvent,
 *         lambda v, e: logic.SetProjectorMask(v.GetProjector(), v.GetStrokeMask()))
 *
 * The view shows the light field's mask again before its next render, so a
 * stroke nobody applies is dropped, and an undo shows at once.
 *
 * **Simulation.** With a mesh (SetSimulationMesh(): the object the light
 * field was synthesised from, e.g. vtkProceduralObjectSource's fish) the
 * view also shows, right of the mask, the Coded pass of camera view
 * SimulationView re-rendered by vtkLightFieldCapture from that mesh with the
 * current masks (the working copy while painting), so the painter sees the
 * colours land on the object. It is re-rendered at each paint step and when
 * the masks change; GetLastSimulationTime() gives the last re-render's
 * wall-clock time in milliseconds.
 *
 * WriteMask() saves a projector's mask as an RGB image (PNG by extension)
 * that `lfd synth --projector-mask` accepts.
 *
 * @sa vtkLightFieldCapture vtkGantryCameraView vtkRigView
 */
#ifndef vtkProjectorView_h
#define vtkProjectorView_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkCalibrationView.h"
#include "vtkCommand.h" // For vtkCommand::UserEvent

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkPolyData;

class LFDWIDGETS_EXPORT vtkProjectorView : public vtkCalibrationView
{
public:
  static vtkProjectorView* New();
  vtkTypeMacro(vtkProjectorView, vtkCalibrationView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Invoked when a stroke ends; call data: the projector index (int*).
   */
  enum Events
  {
    MaskStrokeEvent = vtkCommand::UserEvent + 1010
  };

  ///@{
  /**
   * The projector shown (default 0).
   */
  void SetProjector(int projector);
  vtkGetMacro(Projector, int);
  ///@}

  ///@{
  /**
   * Brush radius in projector pixels (default 4) and the label whose palette
   * colour it paints (default 1; 0 paints black).
   */
  vtkSetClampMacro(BrushRadius, double, 0.5, 4096.0);
  vtkGetMacro(BrushRadius, double);
  vtkSetClampMacro(BrushLabel, int, 0, 255);
  vtkGetMacro(BrushLabel, int);
  ///@}

  /**
   * The mask painted by the last stroke (Wp x Hp x 1, RGB uint8 scalars
   * "Mask", bottom row first), empty before the first stroke.
   */
  vtkImageData* GetStrokeMask();

  ///@{
  /**
   * The mesh (and its optional texture) to re-render the coded pass from;
   * nullptr (default) shows the mask alone.
   */
  void SetSimulationMesh(vtkPolyData* mesh);
  vtkPolyData* GetSimulationMesh();
  void SetSimulationTexture(vtkImageData* texture);
  ///@}

  /**
   * Simulates the object the light field records in its provenance: a
   * capture of a built-in object (`lfd synth --object NAME`, `lfd demo`)
   * records "object": NAME, and this rebuilds it with
   * vtkProceduralObjectSource as the simulation mesh and texture. Returns
   * false, and clears them, when the light field records none (a mesh of
   * the user's, a real capture).
   */
  bool SimulateRecordedObject();

  ///@{
  /**
   * The camera view whose coded pass is re-rendered (default 0).
   */
  void SetSimulationView(int view);
  vtkGetMacro(SimulationView, int);
  ///@}

  /**
   * The last re-rendered coded view (RGB uint8 image, bottom row first;
   * empty without a simulation).
   */
  vtkImageData* GetSimulatedImage();

  /**
   * Milliseconds the last coded re-render took (0 before the first).
   */
  vtkGetMacro(LastSimulationTime, double);

  /**
   * Writes projector `projector`'s mask to `fileName` (an RGB image, the
   * format by extension). False with an error naming the file when it
   * cannot be written or there is no such mask.
   */
  bool WriteMask(int projector, const char* fileName);

  /**
   * Shows the light field's current mask (and re-renders the simulation)
   * when it changed; called before each render of the renderer.
   */
  void Refresh() override;

  /**
   * Fits the mask (and the simulated view) into the renderer's viewport.
   */
  void ResetCamera() override;

protected:
  vtkProjectorView();
  ~vtkProjectorView() override;

  void LightFieldChanged() override;
  bool HandleEvent(unsigned long event, int x, int y) override;
  bool BeginStroke(int x, int y);
  void ContinueStroke(int x, int y);
  void EndStroke();
  void ShowMask();
  void Simulate();

  int Projector = 0;
  double BrushRadius = 4.0;
  int BrushLabel = 1;
  int SimulationView = 0;
  double LastSimulationTime = 0.0;

private:
  vtkProjectorView(const vtkProjectorView&) = delete;
  void operator=(const vtkProjectorView&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
