/**
 * @class   vtkLightFieldMapper
 * @brief   draws a (deformed) light field inside a vtkRenderer
 *
 * vtkLightFieldMapper is the image-based mapper of a vtkLightFieldActor: at
 * each render it asks vtkLightFieldRenderer for the view of the renderer's
 * active camera at the viewport's size (input port 0: the vtkLightField;
 * port 1, optional: the deformation cage) and draws it as a full-viewport
 * quad that also writes depth, so ordinary VTK actors (the cage outline,
 * widgets) composite with it. With a proxy (a light field with a Depth
 * pass: vtkLightFieldRenderer's focal surface, automatic by default) the
 * depth is the object's surface, through the warp when deformed, so an actor
 * inside the object is hidden; through the focal plane it is approximate:
 * the middle of the part's box along the ray (see vtkLightFieldRenderer's
 * `Depth` array). Background pixels are not drawn.
 *
 * The image is recomputed only when the camera, the cage, the light field or
 * the viewport size change (pipeline modification times). While the render
 * window renders at an interactive rate (DesiredUpdateRate at least
 * InteractiveUpdateRate, which vtkRenderWindowInteractor sets during
 * interaction) the image is computed at 1 / InteractiveSubsampling of the
 * resolution and magnified; the next still render is full resolution
 * (progressive refinement). With AdaptiveSubsampling on, an interactive
 * render computes fewer pixels still when the last computation says that
 * 1 / InteractiveSubsampling would not fit in the frame time the window
 * asks for (1 / DesiredUpdateRate), as VTK's level-of-detail actors do: a
 * cage of many boxes stays interactive. An error of the view's computation is reported
 * as the mapper's own (see vtkLightFieldErrorObserver).
 *
 * GetDepthImage() gives the depth the last render wrote, so that a widget
 * drawn over the light field can tell which of its handles the object hides
 * (vtkCageRepresentation::SetOccluderDepth()).
 *
 * @sa vtkLightFieldActor vtkLightFieldRenderer
 */
#ifndef vtkLightFieldMapper_h
#define vtkLightFieldMapper_h

#include "lfdRenderingModule.h" // For export macro
#include "vtkAbstractMapper3D.h"

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkLightFieldRenderer;
class vtkRenderer;
class vtkWindow;

class LFDRENDERING_EXPORT vtkLightFieldMapper : public vtkAbstractMapper3D
{
public:
  static vtkLightFieldMapper* New();
  vtkTypeMacro(vtkLightFieldMapper, vtkAbstractMapper3D);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The light field (port 0) and the optional cage (port 1).
   */
  void SetInputConnection(vtkAlgorithmOutput* output)
  {
    this->Superclass::SetInputConnection(output);
  }
  void SetInputData(vtkDataObject* lightField);
  void SetCageConnection(vtkAlgorithmOutput* output);
  void SetCageData(vtkDataObject* cage);
  ///@}

  ///@{
  /**
   * Interactive renders: at or above this desired update rate (frames per
   * second) the image is computed at 1 / InteractiveSubsampling of the
   * viewport's resolution. Defaults 1.0 and 4.
   */
  vtkSetMacro(InteractiveUpdateRate, double);
  vtkGetMacro(InteractiveUpdateRate, double);
  vtkSetClampMacro(InteractiveSubsampling, int, 1, 64);
  vtkGetMacro(InteractiveSubsampling, int);
  ///@}

  ///@{
  /**
   * Interactive renders subsample more than InteractiveSubsampling (up to
   * 64) when the time per pixel of the last computation times the pixels
   * at InteractiveSubsampling exceeds 1 / DesiredUpdateRate of the window.
   * Default off.
   */
  vtkSetMacro(AdaptiveSubsampling, bool);
  vtkGetMacro(AdaptiveSubsampling, bool);
  vtkBooleanMacro(AdaptiveSubsampling, bool);
  ///@}

  /**
   * The light-field renderer the mapper drives (for focal distance,
   * subdivision, background...).
   */
  vtkLightFieldRenderer* GetLightFieldRenderer();

  /**
   * Size of the image computed by the last render (smaller than the viewport
   * while interacting).
   */
  vtkGetVector2Macro(LastImageSize, int);

  /**
   * The depth the last render wrote, one float per pixel of the computed
   * image (LastImageSize: coarser than the viewport while interacting), in
   * the renderer's z-buffer convention: 0 at the near clipping plane, 1 at
   * the far one and where no ray hits the object. Pixel (i, j) counts from
   * the viewport's lower left corner. Empty before the first render; the
   * same object is refilled by each render.
   */
  vtkImageData* GetDepthImage();

  /**
   * Computes the view of `renderer`'s active camera and draws it.
   */
  void Render(vtkRenderer* renderer);

  ///@{
  /**
   * Bounds of what the light field can show: the deformed cage's bounds
   * joined with a box of half the rig radius around the rig centre (of its
   * cylinder fit, vtkCameraRig::FitCylinder()). Computed from the inputs as
   * they are, without updating the pipeline: update the inputs (or render
   * once) before ResetCamera() if it must see them.
   */
  double* GetBounds() override;
  using vtkAbstractMapper3D::GetBounds;
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkLightFieldMapper();
  ~vtkLightFieldMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  double InteractiveUpdateRate = 1.0;
  int InteractiveSubsampling = 4;
  bool AdaptiveSubsampling = false;
  int LastImageSize[2] = { 0, 0 };

private:
  vtkLightFieldMapper(const vtkLightFieldMapper&) = delete;
  void operator=(const vtkLightFieldMapper&) = delete;

  // Converts the view's image (colour, camera depth) into the textures
  // (RGBA, window depth for the clipping range `range`).
  void Upload(vtkOpenGLRenderWindow* window, vtkImageData* image, const double range[2]);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
