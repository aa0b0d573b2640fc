#include "vtkProjectorView.h"

#include "lfdJsonFields.h"
#include "lfdPinholeCamera.h"
#include "lfdProjectorMasks.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageFileWriter.h"
#include "vtkImageMapper3D.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>

vtkStandardNewMacro(vtkProjectorView);

namespace
{
// Slice `slice` of an RGB image stack into `image` (W x H x 1, "Mask").
void CopySlice(vtkImageData* stack, int slice, vtkImageData* image)
{
  const int* dims = stack->GetDimensions();
  const vtkIdType pixels = static_cast<vtkIdType>(dims[0]) * dims[1];
  image->SetDimensions(dims[0], dims[1], 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("Mask");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(pixels);
  const unsigned char* from = lfd::GetMaskColours(stack)->GetPointer(3 * slice * pixels);
  std::copy_n(from, 3 * pixels, rgb->GetPointer(0));
  image->GetPointData()->SetScalars(rgb);
}
}

struct vtkProjectorView::Internals
{
  vtkLightField* LightField = nullptr; // the view's, for the helpers below
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkImageData> Texture;
  vtkNew<vtkImageData> Shown;
  vtkNew<vtkImageData> Simulated;
  vtkNew<vtkImageData> StrokeMask;
  vtkNew<vtkImageData> Working; // the whole mask stack while painting
  vtkNew<vtkImageActor> MaskActor;
  vtkNew<vtkImageActor> SimulatedActor;
  vtkNew<vtkLightFieldCapture> Capture;
  bool Painting = false;
  double Last[2] = { 0.0, 0.0 }; // last brush position, image pixels
  vtkMTimeType ShownTime = 0;    // the masks' time when shown; 0 = stale

  Internals()
  {
    this->MaskActor->GetMapper()->SetInputData(this->Shown);
    this->MaskActor->InterpolateOff();
    this->SimulatedActor->GetMapper()->SetInputData(this->Simulated);
    this->SimulatedActor->InterpolateOff();
    this->SimulatedActor->VisibilityOff();
    this->Capture->CaptureCoaxialOff();
    this->Capture->CaptureLabelOff();
    this->Capture->CaptureDepthOff();
  }

  vtkImageData* Masks() const
  {
    return this->LightField ? this->LightField->GetProjectorMasks() : nullptr;
  }

  vtkMTimeType MasksTime() const
  {
    vtkImageData* masks = this->Masks();
    vtkUnsignedCharArray* rgb = lfd::GetMaskColours(masks);
    return masks && rgb ? std::max(masks->GetMTime(), rgb->GetMTime()) : 1;
  }

  bool HasMask(int projector) const
  {
    vtkImageData* masks = this->Masks();
    return lfd::GetMaskColours(masks) && projector >= 0 && projector < masks->GetDimensions()[2];
  }
};

//------------------------------------------------------------------------------
vtkProjectorView::vtkProjectorView()
  : Internal(new Internals)
{
  this->AddViewProp(this->Internal->MaskActor);
  this->AddViewProp(this->Internal->SimulatedActor);
  this->SetHandledEvents({ vtkCommand::LeftButtonPressEvent,
    vtkCommand::MouseMoveEvent,
    vtkCommand::LeftButtonReleaseEvent });
}

//------------------------------------------------------------------------------
vtkProjectorView::~vtkProjectorView() = default;

//------------------------------------------------------------------------------
void vtkProjectorView::LightFieldChanged()
{
  this->Internal->LightField = this->GetLightField();
  this->Internal->ShownTime = 0;
}

//------------------------------------------------------------------------------
void vtkProjectorView::SetProjector(int projector)
{
  if (projector != this->Projector)
  {
    this->Projector = projector;
    this->Internal->ShownTime = 0;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkProjectorView::GetStrokeMask()
{
  return this->Internal->StrokeMask;
}

//------------------------------------------------------------------------------
void vtkProjectorView::SetSimulationMesh(vtkPolyData* mesh)
{
  this->Internal->Mesh = mesh;
  this->Internal->ShownTime = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkProjectorView::SimulateRecordedObject()
{
  vtkLightField* lightField = this->GetLightField();
  const char* provenance = lightField ? lightField->GetProvenance() : nullptr;
  lfd::io::Json document;
  std::string error;
  int object = -1;
  if (provenance && lfd::io::ParseJsonText(provenance, document, error) && document.is_object() &&
    document.contains("object") && document["object"].is_string())
  {
    object =
      vtkProceduralObjectSource::GetObjectFromString(document["object"].get<std::string>().c_str());
  }
  if (object < 0)
  {
    this->SetSimulationMesh(nullptr);
    this->SetSimulationTexture(nullptr);
    return false;
  }
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObject(object);
  source->Update();
  this->SetSimulationMesh(source->GetOutput());
  this->SetSimulationTexture(source->GetTextureOutput());
  return true;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkProjectorView::GetSimulationMesh()
{
  return this->Internal->Mesh;
}

//------------------------------------------------------------------------------
void vtkProjectorView::SetSimulationTexture(vtkImageData* texture)
{
  this->Internal->Texture = texture;
  this->Internal->ShownTime = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkProjectorView::SetSimulationView(int view)
{
  if (view != this->SimulationView)
  {
    this->SimulationView = view;
    this->Internal->ShownTime = 0;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkProjectorView::GetSimulatedImage()
{
  return this->Internal->Simulated;
}

//------------------------------------------------------------------------------
void vtkProjectorView::Refresh()
{
  Internals& internal = *this->Internal;
  if (internal.Painting || internal.ShownTime == internal.MasksTime())
  {
    return;
  }
  this->ShowMask();
  this->Simulate();
  internal.ShownTime = internal.MasksTime();
}

//------------------------------------------------------------------------------
void vtkProjectorView::ShowMask()
{
  Internals& internal = *this->Internal;
  vtkImageData* source = internal.Painting ? internal.Working.Get() : internal.Masks();
  if (internal.HasMask(this->Projector))
  {
    CopySlice(source, this->Projector, internal.Shown);
  }
  else
  {
    internal.Shown->Initialize();
  }
  internal.MaskActor->SetVisibility(internal.Shown->GetNumberOfPoints() > 0);
}

//------------------------------------------------------------------------------
void vtkProjectorView::Simulate()
{
  Internals& internal = *this->Internal;
  vtkLightField* lightField = internal.LightField;
  const bool possible = internal.Mesh && lightField && internal.Masks() &&
    lightField->GetProjectors()->GetNumberOfViews() > 0 && this->SimulationView >= 0 &&
    this->SimulationView < lightField->GetRig()->GetNumberOfViews();
  internal.SimulatedActor->SetVisibility(possible);
  if (!possible)
  {
    internal.Simulated->Initialize();
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  vtkCameraRig* rig = lightField->GetRig();
  vtkNew<vtkCameraRig> view;
  view->SetNumberOfViews(1);
  view->SetImageSize(rig->GetImageSize());
  view->SetView(0, rig->GetCamera(this->SimulationView));
  vtkLightFieldCapture* capture = internal.Capture;
  capture->SetInputData(internal.Mesh);
  capture->SetTextureData(internal.Texture);
  capture->SetRig(view);
  capture->SetProjectors(lightField->GetProjectors());
  capture->SetProjectorMasks(internal.Painting ? internal.Working.Get() : internal.Masks());
  capture->SetPalette(lightField->GetPalette());
  capture->Modified();
  capture->Update();
  vtkLightField* coded = capture->GetOutput();
  vtkDataArray* pass = coded->GetPass(vtkLightField::CODED);
  if (capture->GetErrorCode() != 0 || !pass)
  {
    internal.Simulated->Initialize();
    internal.SimulatedActor->VisibilityOff();
    return;
  }
  internal.Simulated->SetDimensions(coded->GetWidth(), coded->GetHeight(), 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->DeepCopy(pass);
  rgb->SetName("Coded");
  internal.Simulated->GetPointData()->SetScalars(rgb);
  const int* mask = internal.Shown->GetDimensions();
  internal.SimulatedActor->SetPosition(std::ceil(1.05 * mask[0]), 0.0, 0.0);
  this->LastSimulationTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

//------------------------------------------------------------------------------
bool vtkProjectorView::BeginStroke(int x, int y)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = this->GetRenderer();
  if (!renderer || !internal.HasMask(this->Projector))
  {
    return false;
  }
  renderer->SetDisplayPoint(x, y, 0.0);
  renderer->DisplayToWorld();
  const double* world = renderer->GetWorldPoint();
  const double w = world[3] != 0.0 ? world[3] : 1.0;
  const double i = world[0] / w, j = world[1] / w;
  const int* dims = internal.Masks()->GetDimensions();
  if (i < -0.5 || j < -0.5 || i >= dims[0] - 0.5 || j >= dims[1] - 0.5)
  {
    return false;
  }
  internal.Working->DeepCopy(internal.Masks());
  internal.Painting = true;
  internal.Last[0] = i;
  internal.Last[1] = j;
  this->ContinueStroke(x, y);
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorView::ContinueStroke(int x, int y)
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = this->GetRenderer();
  renderer->SetDisplayPoint(x, y, 0.0);
  renderer->DisplayToWorld();
  const double* world = renderer->GetWorldPoint();
  const double w = world[3] != 0.0 ? world[3] : 1.0;
  const double to[2] = { world[0] / w, world[1] / w };
  const int* dims = internal.Working->GetDimensions();
  const vtkIdType pixels = static_cast<vtkIdType>(dims[0]) * dims[1];
  unsigned char colour[3] = { 0, 0, 0 };
  vtkUnsignedCharArray* palette = internal.LightField->GetPalette();
  if (palette && this->BrushLabel < palette->GetNumberOfTuples())
  {
    palette->GetTypedTuple(this->BrushLabel, colour);
  }
  unsigned char* rgb =
    lfd::GetMaskColours(internal.Working)->GetPointer(3 * this->Projector * pixels);
  // The brush sweeps a capsule: every pixel within BrushRadius of the
  // segment from the last position to this one.
  const double r = this->BrushRadius;
  const double* from = internal.Last;
  const double d[2] = { to[0] - from[0], to[1] - from[1] };
  const double length2 = d[0] * d[0] + d[1] * d[1];
  const int i0 = std::max(0, static_cast<int>(std::ceil(std::min(from[0], to[0]) - r)));
  const int i1 = std::min(dims[0] - 1, static_cast<int>(std::floor(std::max(from[0], to[0]) + r)));
  const int j0 = std::max(0, static_cast<int>(std::ceil(std::min(from[1], to[1]) - r)));
  const int j1 = std::min(dims[1] - 1, static_cast<int>(std::floor(std::max(from[1], to[1]) + r)));
  for (int j = j0; j <= j1; ++j)
  {
    for (int i = i0; i <= i1; ++i)
    {
      const double f = length2 > 0.0
        ? std::min(1.0, std::max(0.0, ((i - from[0]) * d[0] + (j - from[1]) * d[1]) / length2))
        : 0.0;
      const double dx = i - (from[0] + f * d[0]);
      const double dy = j - (from[1] + f * d[1]);
      if (dx * dx + dy * dy <= r * r)
      {
        std::copy_n(colour, 3, rgb + 3 * (static_cast<vtkIdType>(j) * dims[0] + i));
      }
    }
  }
  internal.Last[0] = to[0];
  internal.Last[1] = to[1];
  this->ShowMask();
  this->Simulate();
}

//------------------------------------------------------------------------------
void vtkProjectorView::EndStroke()
{
  Internals& internal = *this->Internal;
  CopySlice(internal.Working, this->Projector, internal.StrokeMask);
  internal.Painting = false;
  internal.ShownTime = 0; // show what the light field holds after the event
  int projector = this->Projector;
  this->InvokeEvent(MaskStrokeEvent, &projector);
}

//------------------------------------------------------------------------------
bool vtkProjectorView::WriteMask(int projector, const char* fileName)
{
  Internals& internal = *this->Internal;
  if (!internal.HasMask(projector))
  {
    vtkErrorMacro("Cannot write " << (fileName ? fileName : "(no file name)")
                                  << ": the light field has no mask for projector " << projector
                                  << ".");
    return false;
  }
  vtkNew<vtkImageData> mask;
  CopySlice(internal.Masks(), projector, mask);
  vtkNew<vtkImageFileWriter> writer;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  writer->SetFileName(fileName);
  writer->SetInputData(mask);
  writer->Write();
  if (errors->HasError() || writer->GetErrorCode() != 0)
  {
    vtkErrorMacro(<< errors->GetErrorMessage());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorView::ResetCamera()
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = this->GetRenderer();
  if (!renderer)
  {
    return;
  }
  this->Refresh();
  const int* mask = internal.Shown->GetDimensions();
  double width = mask[0], height = mask[1];
  if (internal.SimulatedActor->GetVisibility())
  {
    const int* simulated = internal.Simulated->GetDimensions();
    width = internal.SimulatedActor->GetPosition()[0] + simulated[0];
    height = std::max<double>(height, simulated[1]);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  const double cx = 0.5 * (width - 1.0), cy = 0.5 * (height - 1.0);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 10.0 * std::max(width, height));
  camera->SetViewUp(0.0, 1.0, 0.0);
  const double aspect = renderer->GetTiledAspectRatio();
  camera->SetParallelScale(0.5 * std::max(height, width / std::max(aspect, 1e-6)));
  renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
bool vtkProjectorView::HandleEvent(unsigned long event, int x, int y)
{
  if (event == vtkCommand::LeftButtonPressEvent)
  {
    vtkRenderer* renderer = this->GetRenderer();
    return renderer && renderer->IsInViewport(x, y) && this->BeginStroke(x, y);
  }
  if (!this->Internal->Painting)
  {
    return false;
  }
  if (event == vtkCommand::MouseMoveEvent)
  {
    this->ContinueStroke(x, y);
  }
  else
  {
    this->EndStroke();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Projector: " << this->Projector << "\n";
  os << indent << "BrushRadius: " << this->BrushRadius << "\n";
  os << indent << "BrushLabel: " << this->BrushLabel << "\n";
  os << indent << "SimulationView: " << this->SimulationView << "\n";
  os << indent << "LastSimulationTime: " << this->LastSimulationTime << " ms\n";
}
