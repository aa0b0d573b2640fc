#include "vtkLightFieldCapture.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightField.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldCapture);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Rig, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightFieldCapture, RowHeights, vtkDoubleArray);

namespace
{
// Default row spacing as a fraction of the radius: rows ~3 degrees of
// elevation apart keep the object near the image centre in every row.
constexpr double DefaultRowSpacingFraction = 0.05;
// Fraction of the half field of view the framed object may fill.
constexpr double FramingMargin = 0.9;

// The "RGB" albedo array of a mesh (uint8, 3 components) in its point or
// cell data, or nullptr.
vtkDataArray* FindAlbedo(vtkDataSetAttributes* attributes)
{
  vtkDataArray* rgb = attributes->GetArray("RGB");
  return rgb && rgb->GetDataType() == VTK_UNSIGNED_CHAR && rgb->GetNumberOfComponents() == 3
    ? rgb
    : nullptr;
}

// Near and far planes that hold the bounds, seen from `camera`.
void SetTightClippingRange(vtkCamera* camera, const double bounds[6])
{
  double position[3], focal[3], forward[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  vtkMath::Subtract(focal, position, forward);
  vtkMath::Normalize(forward);
  double dmin = VTK_DOUBLE_MAX;
  double dmax = -VTK_DOUBLE_MAX;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[3] = {
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]
    };
    double d[3];
    vtkMath::Subtract(x, position, d);
    const double along = vtkMath::Dot(d, forward);
    dmin = std::min(dmin, along);
    dmax = std::max(dmax, along);
  }
  if (dmax <= 0.0)
  {
    // Nothing in front of the camera: any valid range renders background.
    camera->SetClippingRange(0.01, 1.0);
    return;
  }
  const double margin = 1e-3 * (dmax - dmin) + 1e-6 * dmax;
  const double farPlane = dmax + margin;
  const double nearPlane = std::max(dmin - margin, 1e-3 * farPlane);
  camera->SetClippingRange(nearPlane, farPlane);
}

// Bounds of the volume the rig must see (the 8 bounds corners) as a sphere
// about `center`.
double BoundingRadius(const double bounds[6], const double center[3])
{
  double radius = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[3] = {
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]
    };
    radius = std::max(radius, std::sqrt(vtkMath::Distance2BetweenPoints(x, center)));
  }
  return radius;
}
}

//------------------------------------------------------------------------------
vtkLightFieldCapture::vtkLightFieldCapture()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkLightFieldCapture::~vtkLightFieldCapture()
{
  this->SetRig(nullptr);
  this->SetRowHeights(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::SetCenter(double x, double y, double z)
{
  if (this->Center[0] != x || this->Center[1] != y || this->Center[2] != z || this->AutoCenter)
  {
    this->Center[0] = x;
    this->Center[1] = y;
    this->Center[2] = z;
    this->AutoCenter = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::SetCenter(const double center[3])
{
  this->SetCenter(center[0], center[1], center[2]);
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::SetInputData(vtkPolyData* mesh)
{
  this->SetInputDataInternal(0, mesh);
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::SetTextureConnection(vtkAlgorithmOutput* texture)
{
  this->SetInputConnection(1, texture);
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::SetTextureData(vtkImageData* texture)
{
  this->SetInputDataInternal(1, texture);
}

//------------------------------------------------------------------------------
int vtkLightFieldCapture::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    return 1;
  }
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkLightFieldCapture::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  int width = this->Width;
  int height = this->Height;
  int views = 0;
  if (this->Rig)
  {
    width = this->Rig->GetImageSize()[0];
    height = this->Rig->GetImageSize()[1];
    views = this->Rig->GetNumberOfViews();
    if (views < 1 || width < 1 || height < 1)
    {
      vtkErrorMacro("The given rig has " << views << " views of " << width << " x " << height
                                         << " pixels; it needs at least one view and a size.");
      return 0;
    }
  }
  else
  {
    const int rows = (this->RowHeights && this->RowHeights->GetNumberOfTuples() > 0)
      ? static_cast<int>(this->RowHeights->GetNumberOfTuples())
      : this->NumberOfRows;
    views = rows * this->ViewsPerRing;
  }
  SetOutputLayout(outputVector, width, height, views);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldCapture::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // The whole mesh and the whole texture, whatever part of the light field
  // is asked for: every view sees all of them.
  vtkInformation* meshInfo = inputVector[0]->GetInformationObject(0);
  meshInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  meshInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  meshInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  if (inputVector[1]->GetNumberOfInformationObjects() > 0)
  {
    vtkInformation* textureInfo = inputVector[1]->GetInformationObject(0);
    if (textureInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      textureInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        textureInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
        6);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldCapture::BuildRig(const double bounds[6], vtkCameraRig* rig)
{
  double center[3] = { this->Center[0], this->Center[1], this->Center[2] };
  if (this->AutoCenter)
  {
    for (int c = 0; c < 3; ++c)
    {
      center[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
    }
  }
  double axis[3] = { this->Axis[0], this->Axis[1], this->Axis[2] };
  if (vtkMath::Normalize(axis) == 0.0)
  {
    vtkErrorMacro("Axis (" << this->Axis[0] << ", " << this->Axis[1] << ", " << this->Axis[2]
                           << ") has no direction.");
    return false;
  }

  // Heights as a function of the radius: explicit, absolute spacing, or a
  // spacing proportional to the radius.
  const bool explicitHeights = this->RowHeights && this->RowHeights->GetNumberOfTuples() > 0;
  const int rows =
    explicitHeights ? static_cast<int>(this->RowHeights->GetNumberOfTuples()) : this->NumberOfRows;
  auto heightsFor = [&](double radius)
  {
    std::vector<double> heights(rows);
    for (int r = 0; r < rows; ++r)
    {
      if (explicitHeights)
      {
        heights[r] = this->RowHeights->GetValue(r);
      }
      else
      {
        const double spacing =
          this->RowSpacing > 0.0 ? this->RowSpacing : DefaultRowSpacingFraction * radius;
        heights[r] = (r - 0.5 * (rows - 1)) * spacing;
      }
    }
    return heights;
  };

  double radius = this->Radius;
  if (radius <= 0.0)
  {
    // Frame the bounding sphere: from the farthest row, the sphere must fit
    // in the narrower half field of view (with a margin). The offset of the
    // sphere's centre seen from a row at height h is atan(h / r).
    const double sphere = BoundingRadius(bounds, center);
    if (sphere <= 0.0)
    {
      vtkErrorMacro("The mesh bounds are a single point; set Radius explicitly.");
      return false;
    }
    const double tanHalf = std::tan(0.5 * vtkMath::RadiansFromDegrees(this->ViewAngle));
    const double halfFov = FramingMargin *
      std::atan(tanHalf * std::min(1.0, static_cast<double>(this->Width) / this->Height));
    auto fits = [&](double r)
    {
      double hmax = 0.0;
      for (double h : heightsFor(r))
      {
        hmax = std::max(hmax, std::abs(h));
      }
      const double distance = std::hypot(r, hmax);
      return sphere < distance && std::atan(hmax / r) + std::asin(sphere / distance) <= halfFov;
    };
    double low = sphere;
    double high = 2.0 * sphere;
    int doublings = 0;
    while (!fits(high) && ++doublings < 60)
    {
      low = high;
      high *= 2.0;
    }
    if (doublings >= 60)
    {
      vtkErrorMacro("Cannot frame the mesh: the rows are too far apart for a view angle of "
        << this->ViewAngle << " degrees; reduce RowSpacing or widen ViewAngle.");
      return false;
    }
    for (int i = 0; i < 50; ++i)
    {
      const double mid = 0.5 * (low + high);
      (fits(mid) ? high : low) = mid;
    }
    radius = high;
  }

  const std::vector<double> heights = heightsFor(radius);
  rig->MakeCylinder(center,
    axis,
    radius,
    this->ViewsPerRing,
    rows,
    heights.data(),
    this->Width,
    this->Height,
    this->ViewAngle);
  if (rig->GetNumberOfViews() != rows * this->ViewsPerRing)
  {
    vtkErrorMacro("Building the cylinder rig failed.");
    return false;
  }
  if (this->ViewsPerRing >= 3)
  {
    rig->FitCylinder();
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLightFieldCapture::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkImageData* textureImage = vtkImageData::GetData(inputVector[1]);
  vtkLightField* output = vtkLightField::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input mesh (port 0) or output light field.");
    return 0;
  }
  if (input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input mesh has no cells.");
    return 0;
  }
  double bounds[6];
  input->GetBounds(bounds);

  vtkNew<vtkCameraRig> rig;
  if (this->Rig)
  {
    rig->DeepCopy(this->Rig);
  }
  else if (!this->BuildRig(bounds, rig))
  {
    return 0;
  }
  const int width = rig->GetImageSize()[0];
  const int height = rig->GetImageSize()[1];
  const int views = rig->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;

  output->SetLayout(width, height, views);
  output->SetRig(rig);
  std::ostringstream provenance;
  provenance << "{\"generator\": \"vtkLightFieldCapture\", \"light\": \""
             << (this->SceneFixedLight ? "scene-fixed" : "coaxial")
             << "\", \"ambient\": " << this->Ambient << "}";
  output->SetProvenance(provenance.str().c_str());
  auto* coaxial = this->CaptureCoaxial
    ? static_cast<unsigned char*>(output->AllocatePass(vtkLightField::COAXIAL)->GetVoidPointer(0))
    : nullptr;
  auto* label = this->CaptureLabel
    ? static_cast<unsigned char*>(output->AllocatePass(vtkLightField::LABEL)->GetVoidPointer(0))
    : nullptr;
  auto* depth = this->CaptureDepth
    ? static_cast<float*>(output->AllocatePass(vtkLightField::DEPTH)->GetVoidPointer(0))
    : nullptr;

  // Coaxial pass: albedo from the texture, the "RGB" array or white.
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(input);
  vtkNew<vtkPolyDataMapper> shadedMapper;
  shadedMapper->SetInputData(mesh);
  shadedMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> shaded;
  shaded->SetMapper(shadedMapper);
  vtkProperty* material = shaded->GetProperty();
  material->SetColor(1.0, 1.0, 1.0);
  material->SetAmbient(this->Ambient);
  material->SetDiffuse(1.0 - this->Ambient);
  material->SetSpecular(0.0);
  vtkNew<vtkTexture> texture;
  if (textureImage && mesh->GetPointData()->GetTCoords())
  {
    vtkNew<vtkImageData> image;
    image->ShallowCopy(textureImage);
    texture->SetInputData(image);
    texture->InterpolateOn();
    texture->RepeatOn();
    shaded->SetTexture(texture);
  }
  else if (vtkDataArray* rgb = FindAlbedo(mesh->GetPointData()))
  {
    shadedMapper->ScalarVisibilityOn();
    shadedMapper->SetScalarModeToUsePointFieldData();
    shadedMapper->SelectColorArray(rgb->GetName());
    shadedMapper->SetColorModeToDirectScalars();
  }
  else if (vtkDataArray* cellRgb = FindAlbedo(mesh->GetCellData()))
  {
    shadedMapper->ScalarVisibilityOn();
    shadedMapper->SetScalarModeToUseCellFieldData();
    shadedMapper->SelectColorArray(cellRgb->GetName());
    shadedMapper->SetColorModeToDirectScalars();
  }

  // Label pass: each cell coloured (label, label, label), read back exactly.
  vtkNew<vtkUnsignedCharArray> labelColors;
  labelColors->SetName("LabelColor");
  labelColors->SetNumberOfComponents(3);
  labelColors->SetNumberOfTuples(mesh->GetNumberOfCells());
  vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    const double value = labels ? labels->GetComponent(cell, 0) : 1.0;
    if (!(value >= 0.0 && value <= 255.0) || value != std::floor(value))
    {
      vtkErrorMacro("Cell " << cell << " of the input mesh has Label " << value
                            << "; labels must be integers in [0, 255].");
      return 0;
    }
    const auto byte = static_cast<unsigned char>(value);
    const unsigned char color[3] = { byte, byte, byte };
    labelColors->SetTypedTuple(cell, color);
  }
  vtkNew<vtkPolyData> labelMesh;
  labelMesh->CopyStructure(mesh);
  labelMesh->GetCellData()->AddArray(labelColors);
  vtkNew<vtkPolyDataMapper> flatMapper;
  flatMapper->SetInputData(labelMesh);
  flatMapper->ScalarVisibilityOn();
  flatMapper->SetScalarModeToUseCellFieldData();
  flatMapper->SelectColorArray("LabelColor");
  flatMapper->SetColorModeToDirectScalars();
  flatMapper->InterpolateScalarsBeforeMappingOff();
  vtkNew<vtkActor> flat;
  flat->SetMapper(flatMapper);
  flat->GetProperty()->LightingOff();
  flat->GetProperty()->SetInterpolationToFlat();
  flat->GetProperty()->SetAmbient(0.0);
  flat->GetProperty()->SetDiffuse(1.0);

  // One offscreen window for all views; no multisampling, so every pixel
  // of the Label pass belongs to exactly one cell.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetAlphaBitPlanes(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->AutomaticLightCreationOff();
  renderer->TwoSidedLightingOn();
  renderer->UseFXAAOff();
  renderer->AddActor(shaded);
  renderer->AddActor(flat);
  window->AddRenderer(renderer);

  // A point light, not a spotlight, not attenuated (DESIGN.md section 5).
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0);
  lamp->SetAttenuationValues(1.0, 0.0, 0.0);
  lamp->SetColor(1.0, 1.0, 1.0);
  lamp->SetIntensity(1.0);
  renderer->AddLight(lamp);
  double fixedLamp[3];
  rig->GetCameraCenter(0, fixedLamp);

  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkUnsignedCharArray> rgbBuffer;
  for (int view = 0; view < views && !this->GetAbortExecute(); ++view)
  {
    rig->ApplyToCamera(view, camera);
    SetTightClippingRange(camera, bounds);
    const vtkIdType slice = view * pixels;

    if (coaxial)
    {
      shaded->VisibilityOn();
      flat->VisibilityOff();
      lamp->SetPosition(this->SceneFixedLight ? fixedLamp : camera->GetPosition());
      lamp->SetFocalPoint(camera->GetFocalPoint());
      window->Render();
      // Rows come back bottom row first: vtkLightField's row order.
      window->GetPixelData(0, 0, width - 1, height - 1, 0, rgbBuffer, 0);
      std::copy_n(rgbBuffer->GetPointer(0), 3 * pixels, coaxial + 3 * slice);
    }

    if (label || depth)
    {
      shaded->VisibilityOff();
      flat->VisibilityOn();
      window->Render();
      if (label)
      {
        window->GetPixelData(0, 0, width - 1, height - 1, 0, rgbBuffer, 0);
        const unsigned char* red = rgbBuffer->GetPointer(0);
        for (vtkIdType p = 0; p < pixels; ++p)
        {
          label[slice + p] = red[3 * p];
        }
      }
      if (depth)
      {
        // Window depth d in [0, 1] back to the camera-space distance along
        // the optical axis of the perspective frustum [n, f].
        float* z = depth + slice;
        window->GetZbufferData(0, 0, width - 1, height - 1, z);
        double range[2];
        camera->GetClippingRange(range);
        const double n = range[0];
        const double f = range[1];
        for (vtkIdType p = 0; p < pixels; ++p)
        {
          const double ndc = 2.0 * z[p] - 1.0;
          z[p] = z[p] >= 1.0f ? 0.0f : static_cast<float>(2.0 * n * f / (f + n - ndc * (f - n)));
        }
      }
    }
    this->UpdateProgress(static_cast<double>(view + 1) / views);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ViewsPerRing: " << this->ViewsPerRing << "\n";
  os << indent << "NumberOfRows: " << this->NumberOfRows << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "RowSpacing: " << this->RowSpacing << "\n";
  os << indent << "RowHeights: ";
  if (this->RowHeights)
  {
    for (vtkIdType r = 0; r < this->RowHeights->GetNumberOfTuples(); ++r)
    {
      os << this->RowHeights->GetValue(r) << " ";
    }
    os << "\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "ViewAngle: " << this->ViewAngle << "\n";
  os << indent << "Axis: (" << this->Axis[0] << ", " << this->Axis[1] << ", " << this->Axis[2]
     << ")\n";
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
  os << indent << "AutoCenter: " << this->AutoCenter << "\n";
  os << indent << "CaptureCoaxial: " << this->CaptureCoaxial << "\n";
  os << indent << "CaptureLabel: " << this->CaptureLabel << "\n";
  os << indent << "CaptureDepth: " << this->CaptureDepth << "\n";
  os << indent << "SceneFixedLight: " << this->SceneFixedLight << "\n";
  os << indent << "Ambient: " << this->Ambient << "\n";
  os << indent << "Rig: ";
  if (this->Rig)
  {
    os << "\n";
    this->Rig->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
}
