#include "vtkProjectorSegmentation.h"

#include "lfdColour.h"
#include "lfdLabelMorphology.h"
#include "vtkLabelPalette.h"
#include "vtkLabelPropagation.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkProjectorSegmentation);
vtkCxxSetObjectMacro(vtkProjectorSegmentation, Palette, vtkUnsignedCharArray);

namespace
{
// Sensor noise: the median of Immerkaer's estimate over the channels of up
// to 8 views of the Flood pass.
double EstimateFloodNoise(const unsigned char* flood, int width, int height, int views)
{
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  std::vector<double> estimates;
  const int step = std::max(1, views / 8);
  std::vector<unsigned char> grey(pixels);
  for (int view = 0; view < views; view += step)
  {
    const unsigned char* rgb = flood + 3 * view * pixels;
    for (int c = 0; c < 3; ++c)
    {
      for (vtkIdType p = 0; p < pixels; ++p)
      {
        grey[p] = rgb[3 * p + c];
      }
      const double estimate = lfd::segmentation::EstimateNoise(grey, width, height);
      if (estimate >= 0.0)
      {
        estimates.push_back(estimate);
      }
    }
  }
  std::sort(estimates.begin(), estimates.end());
  return estimates.empty() ? 0.0 : estimates[estimates.size() / 2];
}

// Classifies one pixel from its Coded (B) and Flood (W) colours: Eq. 1
// normalises B by W on the bright channels, then the nearest palette colour
// in CIELAB wins when it is close and clearly nearer than the second.
struct PixelClassifier
{
  int Labels = 0;
  std::vector<glm::dvec3> Colours;    // palette, sRGB, by label
  std::vector<glm::dvec3> ColoursLab; // palette, CIELAB, by label
  double Sigma = 0.0;                 // sensor noise
  double Dark = 0.0;                  // Flood channels below it are dark
  double Accepted = 0.0;              // largest CIELAB distance to a colour
  double MinimumConfidence = 0.0;

  // False when every channel is dark (the pixel is not lit); otherwise the
  // label (0 = undecided) and its confidence.
  bool Classify(const unsigned char* b,
    const unsigned char* w,
    unsigned char& label,
    unsigned char& confidence) const
  {
    // Eq. 1 on the bright channels; the noise of B' on the worst one.
    bool bright[3];
    glm::dvec3 normalised(0.0);
    double noise = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      bright[c] = w[c] >= this->Dark;
      if (bright[c])
      {
        normalised[c] = lfd::NormaliseByFlood(b[c], w[c]);
        noise = std::max(noise, 256.0 * this->Sigma / w[c]);
      }
    }
    if (!bright[0] && !bright[1] && !bright[2])
    {
      return false;
    }
    double d1 = std::numeric_limits<double>::infinity();
    double d2 = d1;
    int nearest = 0;
    // With every channel bright, the pixel's CIELAB is the same for every
    // candidate; otherwise its dark channels take each candidate's own
    // value, so they do not vote.
    const bool allBright = bright[0] && bright[1] && bright[2];
    const glm::dvec3 seenLab = allBright ? lfd::SrgbToLab(normalised) : glm::dvec3(0.0);
    for (int candidate = 1; candidate <= this->Labels; ++candidate)
    {
      glm::dvec3 lab = seenLab;
      if (!allBright)
      {
        glm::dvec3 seen = normalised;
        for (int c = 0; c < 3; ++c)
        {
          seen[c] = bright[c] ? seen[c] : this->Colours[candidate][c];
        }
        lab = lfd::SrgbToLab(seen);
      }
      const double d = glm::length(lab - this->ColoursLab[candidate]);
      if (d < d1)
      {
        d2 = d1;
        d1 = d;
        nearest = candidate;
      }
      else if (d < d2)
      {
        d2 = d;
      }
    }
    const bool close = d1 <= std::max(this->Accepted, 3.0 * noise);
    const bool clear = this->Labels == 1 ||
      (d2 - d1 > 2.0 * noise && d2 - d1 >= this->MinimumConfidence * (d2 + d1));
    if (close && clear)
    {
      label = static_cast<unsigned char>(nearest);
      confidence = this->Labels == 1
        ? 255
        : static_cast<unsigned char>(std::lround(255.0 * (d2 - d1) / (d2 + d1)));
    }
    return true;
  }
};
}

//------------------------------------------------------------------------------
vtkProjectorSegmentation::vtkProjectorSegmentation() = default;

//------------------------------------------------------------------------------
vtkProjectorSegmentation::~vtkProjectorSegmentation()
{
  this->SetPalette(nullptr);
}

//------------------------------------------------------------------------------
bool vtkProjectorSegmentation::Split(vtkLightField* input,
  vtkLightField* output,
  std::string& error)
{
  this->NumberOfCompletedPixels = 0;
  auto* codedArray = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::CODED));
  auto* floodArray = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::FLOOD));
  if (!codedArray || !floodArray)
  {
    error = std::string("vtkProjectorSegmentation: the light field has no ") +
      (codedArray ? "Flood" : "Coded") +
      " pass (projector segmentation needs the Coded and Flood passes)";
    return false;
  }
  vtkUnsignedCharArray* palette = this->Palette ? this->Palette : input->GetPalette();
  if (!palette || palette->GetNumberOfComponents() != 3 || palette->GetNumberOfTuples() < 2)
  {
    error = "vtkProjectorSegmentation: no label palette with at least one label colour (give the "
            "light field a palette, or SetPalette())";
    return false;
  }
  const int labels = static_cast<int>(palette->GetNumberOfTuples()) - 1;
  if (labels > 255)
  {
    error = "vtkProjectorSegmentation: the palette has " + std::to_string(labels) +
      " labels; at most 255 fit the Label pass";
    return false;
  }
  const int width = input->GetWidth();
  const int height = input->GetHeight();
  const int views = input->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  const unsigned char* coded = codedArray->GetPointer(0);
  const unsigned char* flood = floodArray->GetPointer(0);

  // Sensor noise: given, or estimated from the Flood pass.
  const double sigma =
    this->NoiseSigma < 0.0 ? EstimateFloodNoise(flood, width, height, views) : this->NoiseSigma;
  this->EstimatedNoise = sigma;
  PixelClassifier classifier;
  classifier.Labels = labels;
  classifier.Sigma = sigma;
  classifier.Dark = this->DarkThreshold >= 0.0 ? this->DarkThreshold : std::max(8.0, 5.0 * sigma);
  const double separation = vtkLabelPalette::GetSeparation(palette);
  classifier.Accepted =
    labels > 1 ? this->RejectionFactor * 0.5 * separation : std::numeric_limits<double>::infinity();
  classifier.MinimumConfidence = this->MinimumConfidence;
  classifier.Colours.resize(labels + 1);
  classifier.ColoursLab.resize(labels + 1);
  for (int label = 1; label <= labels; ++label)
  {
    classifier.Colours[label] = glm::dvec3(palette->GetTypedComponent(label, 0),
      palette->GetTypedComponent(label, 1),
      palette->GetTypedComponent(label, 2));
    classifier.ColoursLab[label] = lfd::SrgbToLab(classifier.Colours[label]);
  }

  unsigned char* label =
    static_cast<unsigned char*>(output->AllocatePass(vtkLightField::LABEL)->GetVoidPointer(0));
  unsigned char* confidence =
    static_cast<unsigned char*>(output->AllocatePass(vtkLightField::CONFIDENCE)->GetVoidPointer(0));
  const int radius = this->MorphologyRadius;
  vtkSMPTools::For(0,
    views,
    [&](int first, int last)
    {
      std::vector<unsigned char> lit(pixels);
      for (int view = first; view < last; ++view)
      {
        const vtkIdType offset = view * pixels;
        for (vtkIdType p = 0; p < pixels; ++p)
        {
          label[offset + p] = 0;
          confidence[offset + p] = 0;
          lit[p] = classifier.Classify(coded + 3 * (offset + p),
                     flood + 3 * (offset + p),
                     label[offset + p],
                     confidence[offset + p])
            ? 255
            : 0;
        }
        lfd::segmentation::CleanLabels(label + offset, lit.data(), width, height, labels, radius);
        for (vtkIdType p = 0; p < pixels; ++p)
        {
          confidence[offset + p] = label[offset + p] ? confidence[offset + p] : 0;
        }
      }
    });
  return !this->CompleteLabels || !input->GetPass(vtkLightField::COAXIAL) ||
    this->Complete(input, output, error);
}

//------------------------------------------------------------------------------
bool vtkProjectorSegmentation::Complete(vtkLightField* input,
  vtkLightField* output,
  std::string& error)
{
  auto* labels = vtkUnsignedCharArray::SafeDownCast(output->GetPass(vtkLightField::LABEL));
  unsigned char* label = labels->GetPointer(0);
  const vtkIdType values = labels->GetNumberOfTuples();
  if (std::none_of(label, label + values, [](unsigned char l) { return l != 0; }))
  {
    return true; // nothing decided to complete from
  }
  vtkNew<vtkLabelPropagation> propagation;
  propagation->SetInputData(input);
  propagation->SetThreshold(this->ObjectThreshold);
  propagation->SetPaintedViews(labels, input->GetWidth(), input->GetHeight());
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(propagation);
  propagation->Update();
  if (errors->HasError() || propagation->GetErrorCode() != 0)
  {
    std::ostringstream proxy;
    if (input->GetPass(vtkLightField::DEPTH))
    {
      proxy << "Depth pass";
    }
    else
    {
      proxy << "visual hull (Coaxial brighter than ObjectThreshold " << this->ObjectThreshold
            << ")";
    }
    error = "vtkProjectorSegmentation: completing the pixels no projector decided through the " +
      proxy.str() + ": " +
      (errors->HasError() ? errors->GetErrorMessage() : "the propagation failed");
    return false;
  }
  const unsigned char* completed = static_cast<const unsigned char*>(
    propagation->GetOutput()->GetPass(vtkLightField::LABEL)->GetVoidPointer(0));
  for (vtkIdType i = 0; i < values; ++i)
  {
    if (label[i] == 0 && completed[i] != 0)
    {
      label[i] = completed[i];
      ++this->NumberOfCompletedPixels;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Palette: " << (this->Palette ? "set" : "(the input's)") << "\n";
  os << indent << "NoiseSigma: " << this->NoiseSigma << "\n";
  os << indent << "EstimatedNoise: " << this->EstimatedNoise << "\n";
  os << indent << "DarkThreshold: " << this->DarkThreshold << "\n";
  os << indent << "RejectionFactor: " << this->RejectionFactor << "\n";
  os << indent << "MinimumConfidence: " << this->MinimumConfidence << "\n";
  os << indent << "MorphologyRadius: " << this->MorphologyRadius << "\n";
  os << indent << "CompleteLabels: " << this->CompleteLabels << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "NumberOfCompletedPixels: " << this->NumberOfCompletedPixels << "\n";
}
