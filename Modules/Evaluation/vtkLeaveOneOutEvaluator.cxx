#include "vtkLeaveOneOutEvaluator.h"

#include "lfdRequestGuard.h"

#include "vtkCameraRig.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkLeaveOneOutEvaluator);

//------------------------------------------------------------------------------
vtkLeaveOneOutEvaluator::vtkLeaveOneOutEvaluator() = default;

//------------------------------------------------------------------------------
vtkLeaveOneOutEvaluator::~vtkLeaveOneOutEvaluator() = default;

//------------------------------------------------------------------------------
void vtkLeaveOneOutEvaluator::AddView(int view)
{
  this->Views.push_back(view);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLeaveOneOutEvaluator::RemoveAllViews()
{
  this->Views.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkLeaveOneOutEvaluator::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
double vtkLeaveOneOutEvaluator::ComputePSNR(const unsigned char* a,
  const unsigned char* b,
  const unsigned char* mask,
  vtkIdType pixels)
{
  double sum = 0.0;
  vtkIdType count = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    if (mask && !mask[p])
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double diff = static_cast<double>(a[3 * p + c]) - b[3 * p + c];
      sum += diff * diff;
    }
    ++count;
  }
  if (count == 0)
  {
    return 0.0;
  }
  const double mse = sum / (3.0 * count);
  return mse > 0.0 ? std::min(100.0, 10.0 * std::log10(255.0 * 255.0 / mse)) : 100.0;
}

//------------------------------------------------------------------------------
int vtkLeaveOneOutEvaluator::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  vtkTable* output = vtkTable::GetData(outputVector);
  auto* photos = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::COAXIAL));
  if (!photos)
  {
    vtkErrorMacro("The light field has no RGB uint8 'Coaxial' pass to evaluate.");
    return 0;
  }
  auto* photoLabels = vtkUnsignedCharArray::SafeDownCast(input->GetPass(vtkLightField::LABEL));
  vtkCameraRig* rig = input->GetRig();
  const int views = input->GetNumberOfViews();
  std::vector<int> chosen = this->Views;
  if (chosen.empty())
  {
    for (int v = 0; v < views; v += this->Stride)
    {
      chosen.push_back(v);
    }
  }
  for (int v : chosen)
  {
    if (v < 0 || v >= views)
    {
      vtkErrorMacro("View " << v << " does not exist: the light field has " << views << " views.");
      return 0;
    }
  }

  vtkNew<vtkIntArray> viewColumn;
  viewColumn->SetName("View");
  vtkNew<vtkDoubleArray> psnrColumn;
  psnrColumn->SetName("PSNR");
  vtkNew<vtkDoubleArray> objectColumn;
  objectColumn->SetName("ObjectPSNR");
  vtkNew<vtkIntArray> pixelsColumn;
  pixelsColumn->SetName("ObjectPixels");

  // The renderer sees a shallow copy so the pipeline upstream is untouched.
  vtkNew<vtkLightField> source;
  source->ShallowCopy(input);
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(source);
  renderer->SetWidth(input->GetWidth());
  renderer->SetHeight(input->GetHeight());
  renderer->SetFocalDistance(this->FocalDistance);
  renderer->SetFocalSurface(this->FocalSurface);
  // The renderer's error is said once, as this evaluator's.
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(renderer);

  const vtkIdType pixels = static_cast<vtkIdType>(input->GetWidth()) * input->GetHeight();
  std::vector<unsigned char> mask(pixels);
  this->MeanPSNR = 0.0;
  this->MeanObjectPSNR = 0.0;
  for (std::size_t i = 0; i < chosen.size(); ++i)
  {
    const int v = chosen[i];
    double K[9], R[9], t[3];
    rig->GetIntrinsics(v, K);
    rig->GetRotation(v, R);
    rig->GetTranslation(v, t);
    renderer->SetPinhole(K, R, t);
    renderer->RemoveAllExcludedViews();
    renderer->AddExcludedView(v);
    errors->Clear();
    renderer->Update();
    vtkImageData* rendered = renderer->GetOutput();
    if (rendered->GetNumberOfPoints() != pixels)
    {
      vtkErrorMacro("Rendering view "
        << v << " failed"
        << (errors->HasError() ? std::string(": ") + errors->GetErrorMessage() : std::string(".")));
      return 0;
    }
    const unsigned char* photo = photos->GetPointer(3 * pixels * v);
    const auto* image =
      vtkUnsignedCharArray::SafeDownCast(rendered->GetPointData()->GetScalars())->GetPointer(0);
    const auto* imageLabels =
      vtkUnsignedCharArray::SafeDownCast(rendered->GetPointData()->GetArray("Label"))
        ->GetPointer(0);
    vtkIdType objectPixels = 0;
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      bool object;
      if (photoLabels)
      {
        object = photoLabels->GetValue(pixels * v + p) > 0 || imageLabels[p] > 0;
      }
      else
      {
        const unsigned char* a = photo + 3 * p;
        const unsigned char* b = image + 3 * p;
        object = std::max({ a[0], a[1], a[2], b[0], b[1], b[2] }) > this->ObjectThreshold;
      }
      mask[p] = object ? 1 : 0;
      objectPixels += object ? 1 : 0;
    }
    const double psnr = ComputePSNR(photo, image, nullptr, pixels);
    const double objectPsnr = ComputePSNR(photo, image, mask.data(), pixels);
    viewColumn->InsertNextValue(v);
    psnrColumn->InsertNextValue(psnr);
    objectColumn->InsertNextValue(objectPsnr);
    pixelsColumn->InsertNextValue(static_cast<int>(objectPixels));
    this->MeanPSNR += psnr / chosen.size();
    this->MeanObjectPSNR += objectPsnr / chosen.size();
    this->UpdateProgress(static_cast<double>(i + 1) / chosen.size());
  }
  output->AddColumn(viewColumn);
  output->AddColumn(psnrColumn);
  output->AddColumn(objectColumn);
  output->AddColumn(pixelsColumn);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLeaveOneOutEvaluator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Views:";
  for (int v : this->Views)
  {
    os << " " << v;
  }
  os << "\n";
  os << indent << "Stride: " << this->Stride << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "FocalSurface: " << this->FocalSurface << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "MeanPSNR: " << this->MeanPSNR << "\n";
  os << indent << "MeanObjectPSNR: " << this->MeanObjectPSNR << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkLeaveOneOutEvaluator);
