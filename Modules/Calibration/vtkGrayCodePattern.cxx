#include "vtkGrayCodePattern.h"

#include "lfdCalibrationImages.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

#include <opencv2/structured_light.hpp>

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkGrayCodePattern);

namespace
{
/// Bits that number `pixels` positions.
int Bits(int pixels)
{
  return pixels > 1 ? static_cast<int>(std::ceil(std::log2(static_cast<double>(pixels)))) : 0;
}
}

//------------------------------------------------------------------------------
int vtkGrayCodePattern::GetNumberOfCodeImages() const
{
  return 2 * (Bits(this->ProjectorSize[0]) + Bits(this->ProjectorSize[1]));
}

//------------------------------------------------------------------------------
int vtkGrayCodePattern::GetNumberOfPatterns() const
{
  return this->GetNumberOfCodeImages() + 2;
}

//------------------------------------------------------------------------------
bool vtkGrayCodePattern::GetPattern(int i, vtkImageData* image)
{
  if (this->ProjectorSize[0] < 2 || this->ProjectorSize[1] < 2)
  {
    vtkErrorMacro("Gray-code pattern: projector size "
      << this->ProjectorSize[0] << " x " << this->ProjectorSize[1] << " is below 2 x 2");
    return false;
  }
  if (i < 0 || i >= this->GetNumberOfPatterns())
  {
    vtkErrorMacro("Gray-code pattern " << i << ": expected an index from 0 to "
                                       << this->GetNumberOfPatterns() - 1);
    return false;
  }
  auto codes =
    cv::structured_light::GrayCodePattern::create(this->ProjectorSize[0], this->ProjectorSize[1]);
  cv::Mat pattern;
  if (i < this->GetNumberOfCodeImages())
  {
    std::vector<cv::Mat> patterns;
    codes->generate(patterns);
    pattern = patterns[i];
  }
  else
  {
    cv::Mat black;
    cv::Mat white;
    codes->getImagesForShadowMasks(black, white);
    pattern = i == this->GetWhiteIndex() ? white : black;
  }
  lfd::calibration::FromGrey(pattern, image);
  return true;
}

//------------------------------------------------------------------------------
void vtkGrayCodePattern::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ProjectorSize: " << this->ProjectorSize[0] << " x " << this->ProjectorSize[1]
     << "\n";
}
