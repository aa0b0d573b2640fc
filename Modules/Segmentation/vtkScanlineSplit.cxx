#include "vtkScanlineSplit.h"

#include "lfdLabelMorphology.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkScanlineSplit);

//------------------------------------------------------------------------------
vtkScanlineSplit::vtkScanlineSplit() = default;

//------------------------------------------------------------------------------
vtkScanlineSplit::~vtkScanlineSplit() = default;

//------------------------------------------------------------------------------
void vtkScanlineSplit::AddBoundary(int row)
{
  if (std::find(this->Boundaries.begin(), this->Boundaries.end(), row) == this->Boundaries.end())
  {
    this->Boundaries.push_back(row);
    std::sort(this->Boundaries.begin(), this->Boundaries.end());
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkScanlineSplit::RemoveAllBoundaries()
{
  this->Boundaries.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkScanlineSplit::SetBandLabel(int band, int label)
{
  if (band < 0 || label < 0 || label > 255)
  {
    vtkErrorMacro("SetBandLabel: band " << band << " and label " << label
                                        << " must be >= 0, and the label <= 255.");
    return;
  }
  if (static_cast<int>(this->BandLabels.size()) <= band)
  {
    const int old = static_cast<int>(this->BandLabels.size());
    this->BandLabels.resize(band + 1);
    for (int b = old; b <= band; ++b)
    {
      this->BandLabels[b] = b + 1;
    }
  }
  this->BandLabels[band] = label;
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkScanlineSplit::GetBandLabel(int band) const
{
  return band >= 0 && band < static_cast<int>(this->BandLabels.size()) ? this->BandLabels[band]
                                                                       : band + 1;
}

//------------------------------------------------------------------------------
bool vtkScanlineSplit::Split(vtkLightField* input, vtkLightField* output, std::string& error)
{
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  auto* silhouette = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::LABEL));
  auto* coaxial = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL));
  if (!silhouette && !coaxial)
  {
    error = "vtkScanlineSplit: the light field has neither a Label nor a Coaxial pass to find the "
            "object in";
    return false;
  }
  const int bands = static_cast<int>(this->Boundaries.size()) + 1;
  if (static_cast<int>(this->BandLabels.size()) > bands)
  {
    error = "vtkScanlineSplit: labels are given for " + std::to_string(this->BandLabels.size()) +
      " bands but " + std::to_string(this->Boundaries.size()) + " boundaries make " +
      std::to_string(bands);
    return false;
  }
  for (int row : this->Boundaries)
  {
    if (row < 0 || row > height)
    {
      error = "vtkScanlineSplit: boundary row " + std::to_string(row) +
        " is outside the images (0.." + std::to_string(height) + ")";
      return false;
    }
  }
  // Label of every image row (from the top).
  std::vector<unsigned char> rowLabel(height);
  for (int y = 0; y < height; ++y)
  {
    const int band =
      static_cast<int>(std::upper_bound(this->Boundaries.begin(), this->Boundaries.end(), y) -
        this->Boundaries.begin());
    rowLabel[y] = static_cast<unsigned char>(this->GetBandLabel(band));
  }
  // The input's Label is read before the output's replaces it.
  std::vector<unsigned char> mask(pixels);
  unsigned char* label =
    static_cast<unsigned char*>(output->AllocatePass(vtkLightField::LABEL)->GetVoidPointer(0));
  for (int view = 0; view < views; ++view)
  {
    const vtkIdType offset = view * pixels;
    if (silhouette)
    {
      for (vtkIdType p = 0; p < pixels; ++p)
      {
        mask[p] = silhouette->GetValue(offset + p) > 0 ? 1 : 0;
      }
    }
    else
    {
      lfd::segmentation::ObjectMask(coaxial->GetPointer(3 * offset),
        width,
        height,
        this->Threshold,
        this->MorphologyRadius,
        mask.data());
    }
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      // Rows are stored bottom first: point row j is image row H - 1 - j.
      const int y = height - 1 - static_cast<int>(p / width);
      label[offset + p] = mask[p] ? rowLabel[y] : 0;
    }
    this->UpdateProgress(static_cast<double>(view + 1) / views);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkScanlineSplit::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Boundaries:";
  for (int row : this->Boundaries)
  {
    os << " " << row;
  }
  os << "\n";
  os << indent << "BandLabels:";
  for (size_t band = 0; band <= this->Boundaries.size(); ++band)
  {
    os << " " << this->GetBandLabel(static_cast<int>(band));
  }
  os << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "MorphologyRadius: " << this->MorphologyRadius << "\n";
}
