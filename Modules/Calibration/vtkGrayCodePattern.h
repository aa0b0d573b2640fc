/**
 * @class   vtkGrayCodePattern
 * @brief   the Gray-code images a projector shows for its calibration
 *
 * vtkGrayCodePattern gives the structured-light sequence that
 * vtkProjectorCalibration decodes (OpenCV's structured_light
 * GrayCodePattern): for a projector of W x H pixels, ceil(log2 W) column
 * bits and ceil(log2 H) row bits, each shown as a pattern and its inverse
 * (so a camera pixel is decoded by comparing the two, whatever the
 * surface's reflectance), then a white and a black image (which pixels the
 * projector lights at all). Pattern i is one channel of 8-bit grey of the
 * projector's size, rows stored the VTK way; projector devices show the
 * patterns in index order and the camera captures one image per pattern.
 *
 * @sa vtkProjectorCalibration vtkCalibrationImageSource
 */
#ifndef vtkGrayCodePattern_h
#define vtkGrayCodePattern_h

#include "lfdCalibrationModule.h" // For export macro
#include "vtkObject.h"

class vtkImageData;

class LFDCALIBRATION_EXPORT vtkGrayCodePattern : public vtkObject
{
public:
  static vtkGrayCodePattern* New();
  vtkTypeMacro(vtkGrayCodePattern, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The projector's image size in pixels; default 1024 x 768.
   */
  vtkSetVector2Macro(ProjectorSize, int);
  vtkGetVector2Macro(ProjectorSize, int);
  ///@}

  /**
   * Number of images of the sequence: GetNumberOfCodeImages() + 2.
   */
  int GetNumberOfPatterns() const;

  /**
   * Number of Gray-code images: 2 (ceil(log2 W) + ceil(log2 H)).
   */
  int GetNumberOfCodeImages() const;

  ///@{
  /**
   * Indices of the white and the black image (after the codes).
   */
  int GetWhiteIndex() const { return this->GetNumberOfCodeImages(); }
  int GetBlackIndex() const { return this->GetNumberOfCodeImages() + 1; }
  ///@}

  /**
   * Pattern `i` (0 .. GetNumberOfPatterns() - 1) into `image`. Returns
   * false (with an error) for an index out of range or a projector size
   * below 2 x 2.
   */
  bool GetPattern(int i, vtkImageData* image);

protected:
  vtkGrayCodePattern() = default;
  ~vtkGrayCodePattern() override = default;

  int ProjectorSize[2] = { 1024, 768 };

private:
  vtkGrayCodePattern(const vtkGrayCodePattern&) = delete;
  void operator=(const vtkGrayCodePattern&) = delete;
};

#endif
