/**
 * @class   vtkLightFieldProxy
 * @brief   a geometric proxy of the object: a Depth pass estimated from the light field itself
 *
 * The renderer's per-pixel focal surface (vtkLightFieldRenderer::SetFocalSurface,
 * beyond the paper; cf. the Lumigraph's depth correction, Gortler et al.
 * 1996, and Unstructured Lumigraph Rendering, Buehler et al. 2001) needs a
 * depth map per view. A synthetic capture records the true one
 * (vtkLightFieldCapture's Depth pass): it is passed through unchanged unless
 * ReplaceDepth is on. Otherwise the depth is estimated:
 *
 * 1. the visual hull of the object's silhouettes (the Coaxial pass brighter
 *    than Threshold, its holes filled unless they show the backdrop, as
 *    vtkLabelPropagation carves it, Resolution voxels
 *    along its longest side), and per view the depth of the first hull
 *    voxel each object pixel sees: the hull contains the object, so the
 *    surface lies at or behind that depth;
 * 2. a plane sweep refines it (photo-consistency, Collins 1996; Seitz and
 *    Dyer's consistency of a point seen by several cameras): SweepSteps
 *    depths from the hull's to SweepDepth (a fraction of the hull's
 *    diagonal) behind it are tried per pixel; each point is projected into
 *    the Neighbours nearest views (by camera centre), its cost is the mean
 *    absolute RGB difference to them, aggregated over a (2 Window + 1)^2
 *    window of object pixels; the cheapest depth wins.
 *
 * Pixels outside the silhouette get depth 0 (no surface). The output is the
 * input with the `Depth` pass (camera z, float) added; the rest is shared.
 * Progress events report the views done. Bad input is one readable error:
 * no Coaxial pass, an empty hull.
 *
 * @sa vtkLightFieldRenderer vtkLabelPropagation
 */
#ifndef vtkLightFieldProxy_h
#define vtkLightFieldProxy_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkLightFieldAlgorithm.h"

class LFDSEGMENTATION_EXPORT vtkLightFieldProxy : public vtkLightFieldAlgorithm
{
public:
  static vtkLightFieldProxy* New();
  vtkTypeMacro(vtkLightFieldProxy, vtkLightFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The light field to estimate the proxy of.
  void SetInputData(vtkLightField* input);

  ///@{
  /**
   * Estimate the depth even when the input has a Depth pass (replacing it).
   * Default off: a recorded Depth pass is the proxy.
   */
  vtkSetMacro(ReplaceDepth, bool);
  vtkGetMacro(ReplaceDepth, bool);
  vtkBooleanMacro(ReplaceDepth, bool);
  ///@}

  ///@{
  /**
   * Voxels of the visual hull along its longest side. Default 128.
   */
  vtkSetClampMacro(Resolution, int, 8, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Silhouette threshold on the Coaxial pass (mean of RGB) and the pixels of
   * silhouette or calibration error the hull tolerates (see
   * vtkLabelPropagation). Defaults 20 and 1.5.
   */
  vtkSetClampMacro(Threshold, double, 0.0, 255.0);
  vtkGetMacro(Threshold, double);
  vtkSetClampMacro(SilhouetteTolerance, double, 0.0, 100.0);
  vtkGetMacro(SilhouetteTolerance, double);
  ///@}

  ///@{
  /**
   * The plane sweep: depths tried per pixel (1 = the hull alone), how far
   * behind the hull they reach (fraction of the hull's bounding diagonal),
   * the neighbouring views compared and the radius of the cost window.
   * Defaults 24, 0.1, 2 and 2.
   */
  vtkSetClampMacro(SweepSteps, int, 1, 256);
  vtkGetMacro(SweepSteps, int);
  vtkSetClampMacro(SweepDepth, double, 0.0, 1.0);
  vtkGetMacro(SweepDepth, double);
  vtkSetClampMacro(Neighbours, int, 1, 8);
  vtkGetMacro(Neighbours, int);
  vtkSetClampMacro(Window, int, 0, 16);
  vtkGetMacro(Window, int);
  ///@}

protected:
  vtkLightFieldProxy();
  ~vtkLightFieldProxy() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  bool ReplaceDepth = false;
  int Resolution = 128;
  double Threshold = 20.0;
  double SilhouetteTolerance = 1.5;
  int SweepSteps = 24;
  double SweepDepth = 0.1;
  int Neighbours = 2;
  int Window = 2;

private:
  vtkLightFieldProxy(const vtkLightFieldProxy&) = delete;
  void operator=(const vtkLightFieldProxy&) = delete;
};

#endif
