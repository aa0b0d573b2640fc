#include "vtkGroundTruthEvaluator.h"

#include "lfdJsonFields.h"
#include "lfdPinholeCamera.h"
#include "lfdRequestGuard.h"

#include "vtkAdaptiveSubdivisionFilter.h"
#include "vtkCageTransform.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGroundTruthEvaluator);

namespace
{
// Longest edge of the refined ground-truth mesh, as a fraction of its
// bounding-box diagonal, when MaximumEdgeLength is 0.
constexpr double DefaultEdgeFraction = 0.01;
}
vtkCxxSetObjectMacro(vtkGroundTruthEvaluator, Camera, vtkCamera);

namespace
{
/**
 * Mean SSIM (Wang, Bovik, Sheikh and Simoncelli 2004) of the luminance of
 * two RGB images over 7x7 windows centred on the pixels where `mask` is set.
 */
double MaskedSSIM(const unsigned char* a,
  const unsigned char* b,
  const unsigned char* mask,
  int width,
  int height)
{
  auto luminance = [](const unsigned char* rgb)
  { return 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]; };
  const double c1 = std::pow(0.01 * 255.0, 2.0);
  const double c2 = std::pow(0.03 * 255.0, 2.0);
  double sum = 0.0;
  vtkIdType count = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      if (!mask[y * width + x])
      {
        continue;
      }
      double ma = 0.0, mb = 0.0, aa = 0.0, bb = 0.0, ab = 0.0;
      int n = 0;
      for (int j = std::max(0, y - 3); j <= std::min(height - 1, y + 3); ++j)
      {
        for (int i = std::max(0, x - 3); i <= std::min(width - 1, x + 3); ++i)
        {
          const double la = luminance(a + 3 * (j * width + i));
          const double lb = luminance(b + 3 * (j * width + i));
          ma += la;
          mb += lb;
          aa += la * la;
          bb += lb * lb;
          ab += la * lb;
          ++n;
        }
      }
      ma /= n;
      mb /= n;
      const double va = aa / n - ma * ma;
      const double vb = bb / n - mb * mb;
      const double cov = ab / n - ma * mb;
      sum +=
        ((2.0 * ma * mb + c1) * (2.0 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}
}

//------------------------------------------------------------------------------
vtkGroundTruthEvaluator::vtkGroundTruthEvaluator()
{
  this->SetNumberOfInputPorts(4);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkGroundTruthEvaluator::~vtkGroundTruthEvaluator()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkGroundTruthEvaluator::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  return this->Camera ? std::max(mtime, this->Camera->GetMTime()) : mtime;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::FillInputPortInformation(int port, vtkInformation* info)
{
  const char* types[4] = { "vtkLightField", "vtkPolyData", "vtkUnstructuredGrid", "vtkImageData" };
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), types[port]);
  if (port >= 2)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  for (int port : { 0, 3 })
  {
    if (vtkInformation* inInfo = inputVector[port]->GetInformationObject(0))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
        6);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkLightField* lightField = vtkLightField::GetData(inputVector[0]);
  vtkPolyData* mesh = vtkPolyData::GetData(inputVector[1]);
  vtkUnstructuredGrid* cageGrid = vtkUnstructuredGrid::GetData(inputVector[2]);
  vtkImageData* texture = vtkImageData::GetData(inputVector[3]);
  if (!this->Camera)
  {
    vtkErrorMacro("No camera: set one with SetCamera().");
    return 0;
  }

  // The light field through the cage.
  vtkNew<vtkLightField> source;
  source->ShallowCopy(lightField);
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(source);
  renderer->SetCamera(this->Camera);
  renderer->SetWidth(this->Width);
  renderer->SetHeight(this->Height);
  renderer->SetFocalDistance(this->FocalDistance);
  renderer->SetFocalSurface(this->FocalSurface);
  renderer->SetSubdivision(this->Subdivision);
  renderer->SetWidenedSearch(this->WidenedSearch);
  renderer->SetObjectThreshold(this->ObjectThreshold);
  renderer->SetAntiAliasing(this->AntiAliasing);
  // The inner algorithms' errors are said once, as this evaluator's.
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(renderer);

  // The mesh through the same map, captured with the same light from the
  // same camera.
  vtkNew<vtkPolyData> deformed;
  deformed->ShallowCopy(mesh);
  if (cageGrid)
  {
    vtkNew<vtkDeformationCage> cage;
    cage->InitializeFromGrid(cageGrid);
    renderer->SetCageData(cage);
    vtkNew<vtkCageTransform> map;
    map->SetCage(cage);
    // The map bends straight edges: refine the mesh first, or a long
    // triangle (a limb modelled by its two ends) stays straight where the
    // map curves it, and the ground truth would be wrong, not the render.
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    vtkNew<vtkAdaptiveSubdivisionFilter> refine;
    refine->SetInputConnection(triangles->GetOutputPort());
    refine->SetMaximumEdgeLength(this->MaximumEdgeLength > 0.0
        ? this->MaximumEdgeLength
        : DefaultEdgeFraction * mesh->GetLength());
    refine->SetMaximumNumberOfPasses(32);
    vtkNew<vtkTransformPolyDataFilter> warp;
    warp->SetInputConnection(refine->GetOutputPort());
    warp->SetTransform(map);
    warp->Update();
    deformed->ShallowCopy(warp->GetOutput());
  }
  renderer->Update();

  double K[9], R[9], t[3];
  vtkCameraRig::CameraToPinhole(this->Camera, this->Width, this->Height, K, R, t);
  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(1);
  rig->SetImageSize(this->Width, this->Height);
  rig->SetView(0, K, R, t);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputData(deformed);
  if (texture)
  {
    capture->SetTextureData(texture);
  }
  capture->SetRig(rig);
  capture->CaptureDepthOff();
  capture->SetAmbient(this->Ambient);
  capture->SetSupersample(
    this->Supersample > 0 ? this->Supersample : GetTruthSupersample(lightField, K[4]));
  errors->Observe(capture);
  capture->Update();
  vtkLightField* truth = capture->GetOutput();
  if (renderer->GetErrorCode() || capture->GetErrorCode() || !truth->GetPass(vtkLightField::LABEL))
  {
    vtkErrorMacro("Rendering the light field or the ground truth failed"
      << (errors->HasError() ? std::string(": ") + errors->GetErrorMessage() : std::string(".")));
    return 0;
  }

  // Both images in VTK row order: the capture's single view is its slice 0.
  vtkImageData* render = renderer->GetOutput();
  const vtkIdType pixels = static_cast<vtkIdType>(this->Width) * this->Height;
  const auto* a =
    vtkUnsignedCharArray::SafeDownCast(render->GetPointData()->GetScalars())->GetPointer(0);
  const auto* la =
    vtkUnsignedCharArray::SafeDownCast(render->GetPointData()->GetArray("Label"))->GetPointer(0);
  auto* truthColor = vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::COAXIAL));
  auto* truthLabel = vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::LABEL));
  const unsigned char* b = truthColor->GetPointer(0);
  const unsigned char* lb = truthLabel->GetPointer(0);
  std::vector<unsigned char> mask(pixels);
  vtkIdType both = 0, either = 0, agree = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    mask[p] = (la[p] > 0 || lb[p] > 0) ? 1 : 0;
    either += mask[p];
    both += (la[p] > 0 && lb[p] > 0) ? 1 : 0;
    agree += (mask[p] && la[p] == lb[p]) ? 1 : 0;
  }
  this->ObjectPixels = either;
  this->IoU = either ? static_cast<double>(both) / either : 0.0;
  this->LabelAgreement = either ? static_cast<double>(agree) / either : 0.0;
  this->PSNR = vtkLeaveOneOutEvaluator::ComputePSNR(a, b, mask.data(), pixels);
  this->SSIM = MaskedSSIM(a, b, mask.data(), this->Width, this->Height);

  vtkImageData* renderOut = vtkImageData::GetData(outputVector, 0);
  renderOut->ShallowCopy(render);
  vtkImageData* truthOut = vtkImageData::GetData(outputVector, 1);
  truthOut->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  truthOut->GetPointData()->SetScalars(truthColor);
  truthOut->GetPointData()->AddArray(truthLabel);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::GetCaptureSupersample(vtkLightField* lightField)
{
  const char* provenance = lightField ? lightField->GetProvenance() : nullptr;
  lfd::io::Json document;
  std::string error;
  if (provenance && lfd::io::ParseJsonText(provenance, document, error) && document.is_object() &&
    document.contains("supersample") && document["supersample"].is_number_integer())
  {
    return std::max(1, document["supersample"].get<int>());
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkGroundTruthEvaluator::GetTruthSupersample(vtkLightField* lightField, double focalPixels)
{
  const int captured = GetCaptureSupersample(lightField);
  vtkCameraRig* rig = lightField ? lightField->GetRig() : nullptr;
  if (!rig || rig->GetNumberOfViews() < 1 || !(focalPixels > 0.0))
  {
    return captured;
  }
  // A capture at a finer pixel pitch than the evaluated camera's holds more
  // samples per evaluated pixel than its own supersampling: a truth at only
  // that supersampling would be the coarser (more aliased) image of the two.
  const double density = rig->GetCamera(0).K[1][1] / focalPixels;
  const double samples = std::ceil(captured * density - 1e-6);
  return static_cast<int>(std::clamp(samples, 1.0, 8.0));
}

//------------------------------------------------------------------------------
void vtkGroundTruthEvaluator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "FocalSurface: " << this->FocalSurface << "\n";
  os << indent << "Subdivision: " << this->Subdivision << "\n";
  os << indent << "WidenedSearch: " << this->WidenedSearch << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "AntiAliasing: " << (this->AntiAliasing ? "On" : "Off") << "\n";
  os << indent << "Ambient: " << this->Ambient << "\n";
  os << indent << "Supersample: " << this->Supersample << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "PSNR: " << this->PSNR << "\n";
  os << indent << "SSIM: " << this->SSIM << "\n";
  os << indent << "IoU: " << this->IoU << "\n";
  os << indent << "LabelAgreement: " << this->LabelAgreement << "\n";
  os << indent << "ObjectPixels: " << this->ObjectPixels << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkGroundTruthEvaluator);
