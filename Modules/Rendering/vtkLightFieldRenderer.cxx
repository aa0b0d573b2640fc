#include "vtkLightFieldRenderer.h"

#include "lfdCylinderSampling.h"
#include "lfdPinholeCamera.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkLightFieldRenderer);
vtkCxxSetObjectMacro(vtkLightFieldRenderer, Camera, vtkCamera);

namespace
{
/// One ray per pixel through the cylindrical sampler, rows in parallel.
struct RenderRows
{
  const lfd::LightFieldSampler& Sampler;
  glm::dvec3 Origin;
  glm::dmat3 PixelToDirection;
  int Width;
  int Height;
  bool UseLabels;
  std::uint8_t Background[3];
  std::uint8_t* Radiance; // output, VTK row order
  std::uint8_t* Labels;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    lfd::RaySamples samples;
    for (vtkIdType j = begin; j < end; ++j)
    {
      const double y = static_cast<double>(this->Height - 1 - j); // OpenCV row
      for (int x = 0; x < this->Width; ++x)
      {
        const vtkIdType id = j * this->Width + x;
        std::uint8_t* rgb = this->Radiance + 3 * id;
        const glm::dvec3 d = this->PixelToDirection * glm::dvec3(x, y, 1.0);
        int label = 0;
        glm::dvec3 color;
        if (this->Sampler.Gather(this->Origin, d, samples))
        {
          label = this->UseLabels ? lfd::VoteLabel(samples) : 0;
          lfd::BlendLabel(samples, label, color);
        }
        this->Labels[id] = static_cast<std::uint8_t>(label);
        if (samples.Count == 0 || (this->UseLabels && label == 0))
        {
          std::copy(this->Background, this->Background + 3, rgb);
          continue;
        }
        for (int c = 0; c < 3; ++c)
        {
          rgb[c] = static_cast<std::uint8_t>(std::clamp(std::lround(color[c]), 0L, 255L));
        }
      }
    }
  }
};
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer::vtkLightFieldRenderer()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer::~vtkLightFieldRenderer()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetPinhole(const double K[9], const double R[9], const double t[3])
{
  std::copy(K, K + 9, this->PinholeK);
  std::copy(R, R + 9, this->PinholeR);
  std::copy(t, t + 3, this->PinholeT);
  this->SetCamera(nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::AddExcludedView(int view)
{
  this->ExcludedViews.push_back(view);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::RemoveAllExcludedViews()
{
  if (!this->ExcludedViews.empty())
  {
    this->ExcludedViews.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::GetNumberOfExcludedViews() const
{
  return static_cast<int>(this->ExcludedViews.size());
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldRenderer::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Camera)
  {
    mtime = std::max(mtime, this->Camera->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Any view may be sampled: ask for the whole light field.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
    6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!input)
  {
    vtkErrorMacro("The input is not a vtkLightField.");
    return 0;
  }
  auto* radiance = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL));
  if (!radiance || radiance->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The light field has no RGB uint8 'Coaxial' pass to render from.");
    return 0;
  }
  vtkCameraRig* rig = input->GetRig();
  const int views = input->GetNumberOfViews();
  if (!rig || rig->GetNumberOfViews() != views)
  {
    vtkErrorMacro("The light field has " << views << " views but its rig has "
                                         << (rig ? rig->GetNumberOfViews() : 0) << " cameras.");
    return 0;
  }
  const lfd::RingLayout layout = rig->GetRingLayout(this->ExcludedViews);
  if (layout.Rows.empty())
  {
    vtkErrorMacro("No cylinder could be fitted to the rig, or every view is excluded.");
    return 0;
  }
  std::vector<lfd::PinholeCamera> cameras(views);
  for (int v = 0; v < views; ++v)
  {
    cameras[v] = rig->GetCamera(v);
  }

  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = { radiance->GetPointer(0), input->GetWidth(), input->GetHeight(), 3 };
  auto* labels = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::LABEL));
  const bool useLabels = this->UseLabels && labels;
  if (useLabels)
  {
    sampler.Labels = { labels->GetPointer(0), input->GetWidth(), input->GetHeight(), 1 };
  }
  sampler.FocalDistance = this->FocalDistance;

  double K[9], R[9], t[3];
  if (this->Camera)
  {
    vtkCameraRig::CameraToPinhole(this->Camera, this->Width, this->Height, K, R, t);
  }
  else
  {
    std::copy(this->PinholeK, this->PinholeK + 9, K);
    std::copy(this->PinholeR, this->PinholeR + 9, R);
    std::copy(this->PinholeT, this->PinholeT + 3, t);
  }
  const lfd::PinholeCamera eye = lfd::PinholeCamera::FromRowMajor(K, R, t);

  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkUnsignedCharArray> image;
  image->SetName("Radiance");
  image->SetNumberOfComponents(3);
  image->SetNumberOfTuples(static_cast<vtkIdType>(this->Width) * this->Height);
  vtkNew<vtkUnsignedCharArray> imageLabels;
  imageLabels->SetName("Label");
  imageLabels->SetNumberOfTuples(image->GetNumberOfTuples());

  RenderRows functor{ sampler,
    eye.Center(),
    eye.PixelToDirection(),
    this->Width,
    this->Height,
    useLabels,
    {},
    image->GetPointer(0),
    imageLabels->GetPointer(0) };
  for (int c = 0; c < 3; ++c)
  {
    functor.Background[c] =
      static_cast<std::uint8_t>(std::clamp(std::lround(255.0 * this->Background[c]), 0L, 255L));
  }
  vtkSMPTools::For(0, this->Height, functor);

  output->GetPointData()->SetScalars(image);
  output->GetPointData()->AddArray(imageLabels);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  if (!this->Camera)
  {
    os << indent << "Pinhole K:";
    for (double k : this->PinholeK)
    {
      os << " " << k;
    }
    os << "\n" << indent << "Pinhole R:";
    for (double r : this->PinholeR)
    {
      os << " " << r;
    }
    os << "\n"
       << indent << "Pinhole t: " << this->PinholeT[0] << " " << this->PinholeT[1] << " "
       << this->PinholeT[2] << "\n";
  }
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "Background: " << this->Background[0] << " " << this->Background[1] << " "
     << this->Background[2] << "\n";
  os << indent << "UseLabels: " << this->UseLabels << "\n";
  os << indent << "ExcludedViews:";
  for (int v : this->ExcludedViews)
  {
    os << " " << v;
  }
  os << "\n";
}
