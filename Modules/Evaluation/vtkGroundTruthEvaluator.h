/**
 * @class   vtkGroundTruthEvaluator
 * @brief   measures a deformed light-field render against the deformed source mesh
 *
 * For a synthetic light field the source mesh is known (DESIGN.md section
 * 4.5): the evaluator deforms the mesh with the same cage map
 * (vtkCageTransform), renders it with the same coaxial light from the same
 * camera (vtkLightFieldCapture from a one-view rig), renders the light field
 * through the cage (vtkLightFieldRenderer) and compares the two images:
 * The truth is prefiltered at least as densely as the light field was
 * captured: Supersample 0 (default) reads the capture's "supersample" from
 * the light field's provenance (vtkLightFieldCapture::SetSupersample; 1
 * when absent) and scales it by the capture's pixel density over the
 * evaluated camera's (focal lengths in pixels; rounded up), so a prefiltered
 * capture is compared with a prefiltered truth, a point-sampled one with a
 * point-sampled truth, and a capture at twice the evaluated resolution (2 x
 * 2 samples per pixel: 4 x 4 per evaluated pixel) with a truth of 4 x 4.
 * PSNR and SSIM over the object pixels (where either image shows a part),
 * the IoU of the two silhouettes and the fraction of object pixels whose
 * part label agrees.
 *
 * Inputs: port 0 the vtkLightField, port 1 the source vtkPolyData (with its
 * "Label" cell array and colours or texture coordinates), port 2 the cage
 * (vtkUnstructuredGrid as vtkLightFieldRenderer takes it; optional: without
 * it both images are undeformed), port 3 the texture image (optional).
 * Outputs: port 0 the light-field render, port 1 the ground truth, each an
 * RGB image with a "Label" array.
 *
 * @sa vtkLightFieldRenderer vtkCageTransform vtkLightFieldCapture
 */
#ifndef vtkGroundTruthEvaluator_h
#define vtkGroundTruthEvaluator_h

#include "lfdEvaluationModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class vtkCamera;
class vtkLightField;

class LFDEVALUATION_EXPORT vtkGroundTruthEvaluator : public vtkImageAlgorithm
{
public:
  static vtkGroundTruthEvaluator* New();
  vtkTypeMacro(vtkGroundTruthEvaluator, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's request; a C++ exception thrown by it becomes this
   * algorithm's error (error code UnknownError), see lfdRequestGuard.h.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * The inputs (see above).
   */
  void SetMeshConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetMeshData(vtkDataObject* mesh) { this->SetInputData(1, mesh); }
  void SetCageConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  void SetCageData(vtkDataObject* cage) { this->SetInputData(2, cage); }
  void SetTextureConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(3, output); }
  void SetTextureData(vtkDataObject* texture) { this->SetInputData(3, texture); }
  ///@}

  ///@{
  /**
   * The camera both images are rendered from, and their size (default
   * 256 x 256).
   */
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  vtkSetClampMacro(Width, int, 1, VTK_INT_MAX);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 1, VTK_INT_MAX);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * Focal distance, box subdivision, widened camera search, object
   * threshold and anti-aliasing of the light-field render (see vtkLightFieldRenderer, which
   * refuses a subdivision over its budget; subdivision 0 = automatic,
   * widened search 0 = off).
   */
  vtkSetMacro(FocalDistance, double);
  vtkGetMacro(FocalDistance, double);
  ///@}

  ///@{
  /**
   * Focal surface passed to the renderer (vtkLightFieldRenderer::FocalSurfaceType;
   * default automatic: the proxy when the light field has a Depth pass).
   */
  vtkSetClampMacro(FocalSurface, int, 0, 2);
  vtkGetMacro(FocalSurface, int);
  vtkSetMacro(Subdivision, int);
  vtkGetMacro(Subdivision, int);
  vtkSetClampMacro(WidenedSearch, int, 0, 64);
  vtkGetMacro(WidenedSearch, int);
  vtkSetClampMacro(ObjectThreshold, double, 0.0, 255.0);
  vtkGetMacro(ObjectThreshold, double);
  vtkSetMacro(AntiAliasing, bool);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Ambient coefficient of the ground truth's coaxial light
   * (vtkLightFieldCapture::SetAmbient): set it to the light field's own
   * (default 0.1, the capture's default). 1 renders the mesh unlit, which
   * with a light field captured unlit takes lighting out of the comparison.
   */
  vtkSetClampMacro(Ambient, double, 0.0, 1.0);
  vtkGetMacro(Ambient, double);
  ///@}

  ///@{
  /**
   * Samples per pixel along each axis of the ground truth's colour
   * (vtkLightFieldCapture::SetSupersample); 0 (default): the light field's
   * own, from its provenance (1 when it records none), times the capture's
   * pixel density over the camera's (GetTruthSupersample()).
   */
  vtkSetClampMacro(Supersample, int, 0, 8);
  vtkGetMacro(Supersample, int);
  ///@}

  ///@{
  /**
   * The supersampling a light field was captured with: the "supersample"
   * of its provenance (vtkLightFieldCapture), 1 when it records none.
   */
  static int GetCaptureSupersample(vtkLightField* lightField);
  ///@}

  ///@{
  /**
   * The truth's samples per pixel along each axis when Supersample is 0:
   * GetCaptureSupersample() times the focal length in pixels of the light
   * field's view 0 over `focalPixels` (the evaluated camera's), rounded up,
   * at least 1: the truth is never sampled more coarsely than the capture.
   */
  static int GetTruthSupersample(vtkLightField* lightField, double focalPixels);
  ///@}

  ///@{
  /**
   * Before the cage map deforms it, the mesh is refined
   * (vtkAdaptiveSubdivisionFilter) until no edge is longer than this, so
   * the deformed mesh follows the map inside its triangles too (a map bends
   * straight edges). 0 (default): 1 % of the mesh's bounding-box diagonal.
   */
  vtkSetClampMacro(MaximumEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /**
   * The figures, after Update(): PSNR (dB, 100 when equal) and SSIM (mean
   * over 7x7 windows centred on object pixels, luminance) over the object
   * pixels, silhouette IoU, label agreement over the object pixels, and the
   * number of object pixels. SSIM is measured on the object region only,
   * never the whole image (the background would inflate it): `lfd eval
   * groundtruth` prints it as "SSIM (object)", next to "PSNR (object)".
   */
  vtkGetMacro(PSNR, double);
  vtkGetMacro(SSIM, double);
  vtkGetMacro(IoU, double);
  vtkGetMacro(LabelAgreement, double);
  vtkGetMacro(ObjectPixels, vtkIdType);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkGroundTruthEvaluator();
  ~vtkGroundTruthEvaluator() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkCamera* Camera = nullptr;
  int Width = 256;
  int Height = 256;
  double FocalDistance = 0.0;
  int FocalSurface = 0;
  int Subdivision = 1;
  int WidenedSearch = 2;
  double ObjectThreshold = 10.0;
  bool AntiAliasing = true;
  double Ambient = 0.1;
  int Supersample = 0;
  double MaximumEdgeLength = 0.0;
  double PSNR = 0.0;
  double SSIM = 0.0;
  double IoU = 0.0;
  double LabelAgreement = 0.0;
  vtkIdType ObjectPixels = 0;

private:
  vtkGroundTruthEvaluator(const vtkGroundTruthEvaluator&) = delete;
  void operator=(const vtkGroundTruthEvaluator&) = delete;
};

#endif
