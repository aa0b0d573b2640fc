/**
 * @class   vtkLeaveOneOutEvaluator
 * @brief   measures light-field sampling by re-rendering captured views from the others
 *
 * For each chosen view, vtkLeaveOneOutEvaluator renders that view's exact
 * camera (its K, R, t) with vtkLightFieldRenderer from all the *other* views
 * (the view and its near-duplicates are excluded, see vtkCameraRig) and
 * compares the result with the captured image: PSNR over the whole image and
 * over the object's pixels. Object pixels are the pixels where the captured
 * image or the render shows the object: label > 0 when the light field has a
 * Label pass, otherwise a colour channel above ObjectThreshold (the dark
 * backgrounds of turntable captures such as the Middlebury rings).
 *
 * The output is a vtkTable, one row per evaluated view, with the columns
 * `View`, `PSNR`, `ObjectPSNR` (dB; 100 for a perfect match) and
 * `ObjectPixels`. GetMeanPSNR() and GetMeanObjectPSNR() give the means.
 *
 * @sa vtkLightFieldRenderer
 */
#ifndef vtkLeaveOneOutEvaluator_h
#define vtkLeaveOneOutEvaluator_h

#include "lfdEvaluationModule.h" // For export macro
#include "vtkTableAlgorithm.h"

#include <vector> // For std::vector

class LFDEVALUATION_EXPORT vtkLeaveOneOutEvaluator : public vtkTableAlgorithm
{
public:
  static vtkLeaveOneOutEvaluator* New();
  vtkTypeMacro(vtkLeaveOneOutEvaluator, vtkTableAlgorithm);
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
   * Views to evaluate. When none is added, every Stride-th view is
   * evaluated (Stride defaults to 1: all views).
   */
  void AddView(int view);
  void RemoveAllViews();
  vtkSetClampMacro(Stride, int, 1, VTK_INT_MAX);
  vtkGetMacro(Stride, int);
  ///@}

  ///@{
  /**
   * Focal distance passed to the renderer (see vtkLightFieldRenderer).
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
  ///@}

  ///@{
  /**
   * Brightest-channel value (0-255) above which a pixel counts as object
   * when the light field has no Label pass. Default 20.
   */
  vtkSetClampMacro(ObjectThreshold, int, 0, 255);
  vtkGetMacro(ObjectThreshold, int);
  ///@}

  ///@{
  /**
   * Means over the evaluated views, after Update().
   */
  vtkGetMacro(MeanPSNR, double);
  vtkGetMacro(MeanObjectPSNR, double);
  ///@}

  /**
   * PSNR in dB of two RGB uint8 arrays over the pixels where `mask` is
   * non-zero (all pixels when `mask` is null); 100 when they are equal,
   * 0 when the mask is empty.
   */
  static double ComputePSNR(const unsigned char* a,
    const unsigned char* b,
    const unsigned char* mask,
    vtkIdType pixels);

protected:
  vtkLeaveOneOutEvaluator();
  ~vtkLeaveOneOutEvaluator() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::vector<int> Views;
  int Stride = 1;
  double FocalDistance = 0.0;
  int FocalSurface = 0;
  int ObjectThreshold = 20;
  double MeanPSNR = 0.0;
  double MeanObjectPSNR = 0.0;

private:
  vtkLeaveOneOutEvaluator(const vtkLeaveOneOutEvaluator&) = delete;
  void operator=(const vtkLeaveOneOutEvaluator&) = delete;
};

#endif
