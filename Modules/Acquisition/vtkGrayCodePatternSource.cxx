#include "vtkGrayCodePatternSource.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkGrayCodePatternSource);

namespace
{
// Bits needed to number `count` stripes: ceil(log2(count)).
int BitsFor(int count)
{
  int bits = 0;
  while ((1LL << bits) < count)
  {
    ++bits;
  }
  return bits;
}
}

//------------------------------------------------------------------------------
vtkGrayCodePatternSource::vtkGrayCodePatternSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkGrayCodePatternSource::GetNumberOfColumnBits()
{
  return BitsFor(this->Width);
}

//------------------------------------------------------------------------------
int vtkGrayCodePatternSource::GetNumberOfRowBits()
{
  return BitsFor(this->Height);
}

//------------------------------------------------------------------------------
int vtkGrayCodePatternSource::GetNumberOfPatterns()
{
  return 2 * (this->GetNumberOfColumnBits() + this->GetNumberOfRowBits());
}

//------------------------------------------------------------------------------
int vtkGrayCodePatternSource::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGrayCodePatternSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  const int patterns = this->GetNumberOfPatterns();
  if (this->PatternIndex >= patterns)
  {
    vtkErrorMacro("PatternIndex " << this->PatternIndex << " is out of range: a " << this->Width
                                  << " x " << this->Height << " projector has " << patterns
                                  << " Gray-code patterns.");
    return 0;
  }
  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const int columnBits = this->GetNumberOfColumnBits();
  const bool columns = this->PatternIndex < 2 * columnBits;
  const int m = (columns ? this->PatternIndex : this->PatternIndex - 2 * columnBits) / 2;
  const int bit = (columns ? columnBits : this->GetNumberOfRowBits()) - 1 - m;
  const bool inverse = this->PatternIndex % 2 == 1;
  auto* pixels = static_cast<unsigned char*>(output->GetScalarPointer());
  for (int j = 0; j < this->Height; ++j)
  {
    // VTK row j is projector row y = Height - 1 - j, counted from the top.
    const int y = this->Height - 1 - j;
    for (int x = 0; x < this->Width; ++x)
    {
      const int index = columns ? x : y;
      const bool on = (((index ^ (index >> 1)) >> bit) & 1) != inverse;
      unsigned char* pixel = pixels + 3 * (static_cast<size_t>(j) * this->Width + x);
      pixel[0] = pixel[1] = pixel[2] = on ? 255 : 0;
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkGrayCodePatternSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "PatternIndex: " << this->PatternIndex << "\n";
}
