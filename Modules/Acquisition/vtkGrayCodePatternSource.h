/**
 * @class   vtkGrayCodePatternSource
 * @brief   the Gray-code stripe patterns a projector shows for calibration
 *
 * Structured light for projector calibration (Moreno and Taubin, "Simple,
 * Accurate, and Robust Projector-Camera Calibration", 3DIMPVT 2012): each
 * projector column x and row y is identified by the binary-reflected Gray
 * code g = v ^ (v >> 1) of its index, one bit per pattern, each pattern
 * followed by its inverse so that a camera pixel is decoded by comparing
 * the two. With Nc = ceil(log2 Width) column bits and Nr = ceil(log2
 * Height) row bits there are GetNumberOfPatterns() = 2 (Nc + Nr) patterns:
 * pattern 2m (m < Nc) is white where bit Nc - 1 - m (most significant
 * first) of the column's code is 1, pattern 2m + 1 its inverse; patterns
 * 2 Nc + 2m and 2 Nc + 2m + 1 do the same for the rows, y counted from the
 * top of the projector image.
 *
 * The output is one Width x Height RGB uint8 image (grey: 0 or 255 in all
 * three channels), rows bottom first like every VTK image and the
 * projectors' masks, so it goes to vtkCaptureProjector::ShowPattern() as
 * it is.
 *
 * @sa vtkCaptureProjector
 */
#ifndef vtkGrayCodePatternSource_h
#define vtkGrayCodePatternSource_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class LFDACQUISITION_EXPORT vtkGrayCodePatternSource : public vtkImageAlgorithm
{
public:
  static vtkGrayCodePatternSource* New();
  vtkTypeMacro(vtkGrayCodePatternSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The projector's image size in pixels. Default 1024 x 768.
   */
  vtkSetClampMacro(Width, int, 1, 65536);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 1, 65536);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * Which pattern to generate, in [0, GetNumberOfPatterns()). Default 0.
   */
  vtkSetClampMacro(PatternIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(PatternIndex, int);
  ///@}

  ///@{
  /**
   * Bits of the column and row codes, and the number of patterns.
   */
  int GetNumberOfColumnBits();
  int GetNumberOfRowBits();
  int GetNumberOfPatterns();
  ///@}

protected:
  vtkGrayCodePatternSource();
  ~vtkGrayCodePatternSource() override = default;

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Width = 1024;
  int Height = 768;
  int PatternIndex = 0;

private:
  vtkGrayCodePatternSource(const vtkGrayCodePatternSource&) = delete;
  void operator=(const vtkGrayCodePatternSource&) = delete;
};

#endif
