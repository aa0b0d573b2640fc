#include "vtkLightFieldCapture.h"

#include "lfdPerspectiveDepth.h"
#include "lfdPinholeCamera.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
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
#include <random>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldCapture);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Rig, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightFieldCapture, RowHeights, vtkDoubleArray);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Projectors, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightFieldCapture, ProjectorMasks, vtkImageData);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Palette, vtkUnsignedCharArray);

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
  this->SetProjectors(nullptr);
  this->SetProjectorMasks(nullptr);
  this->SetPalette(nullptr);
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
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldCapture::BuildProjectors(vtkCameraRig* rig, vtkCameraRig* projectors)
{
  if (this->Projectors)
  {
    projectors->DeepCopy(this->Projectors);
    return projectors->GetNumberOfViews() > 0;
  }
  const int count = this->NumberOfProjectors;
  if (count == 0 || rig->GetNumberOfViews() == 0)
  {
    return false;
  }
  // The views of the middle ring in azimuth order (all views, in order,
  // when the rig has no fitted cylinder).
  std::vector<int> ring;
  const int middle = rig->GetNumberOfRows() / 2;
  for (int i = 0; i < rig->GetNumberOfViews(); ++i)
  {
    if (rig->GetNumberOfRows() == 0 || rig->GetRow(i) == middle)
    {
      ring.push_back(i);
    }
  }
  if (rig->GetNumberOfRows() > 0)
  {
    std::sort(ring.begin(),
      ring.end(),
      [rig](int a, int b) { return rig->GetAzimuth(a) < rig->GetAzimuth(b); });
  }
  const int width = this->ProjectorWidth > 0 ? this->ProjectorWidth : rig->GetImageSize()[0];
  const int height = this->ProjectorHeight > 0 ? this->ProjectorHeight : rig->GetImageSize()[1];
  projectors->SetNumberOfViews(count);
  projectors->SetImageSize(width, height);
  for (int p = 0; p < count; ++p)
  {
    const int view = ring[static_cast<size_t>((p + 0.5) * ring.size() / count) % ring.size()];
    // The camera's pose and field of view at the projector's resolution.
    lfd::PinholeCamera projector = rig->GetCamera(view);
    const double sx = static_cast<double>(width) / rig->GetImageSize()[0];
    const double sy = static_cast<double>(height) / rig->GetImageSize()[1];
    projector.K[0][0] *= sx;
    projector.K[2][0] = (projector.K[2][0] + 0.5) * sx - 0.5;
    projector.K[1][1] *= sy;
    projector.K[2][1] = (projector.K[2][1] + 0.5) * sy - 0.5;
    projectors->SetView(p, projector);
    std::string name = "projector_" + std::to_string(p);
    projectors->SetViewName(p, name.c_str());
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLightFieldCapture::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->ClearError();
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
    // The output rig is fitted once, here (the given one is left as it is).
    std::string noCylinder;
    if (!rig->HasCylinder())
    {
      rig->FitCylinder(noCylinder);
    }
  }
  else if (!this->BuildRig(bounds, rig))
  {
    return 0;
  }
  const int width = rig->GetImageSize()[0];
  const int height = rig->GetImageSize()[1];
  const int views = rig->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;

  // Projectors: their rig, masks (painted or generated) and passes.
  vtkNew<vtkCameraRig> projectors;
  const bool project = this->BuildProjectors(rig, projectors);
  const int projectorCount = project ? projectors->GetNumberOfViews() : 0;
  const int projectorWidth = project ? projectors->GetImageSize()[0] : 0;
  const int projectorHeight = project ? projectors->GetImageSize()[1] : 0;
  const vtkIdType projectorPixels = static_cast<vtkIdType>(projectorWidth) * projectorHeight;
  vtkNew<vtkImageData> masks;
  vtkUnsignedCharArray* maskArray = nullptr;
  if (project)
  {
    if (this->ProjectorMasks)
    {
      const int* dims = this->ProjectorMasks->GetDimensions();
      vtkDataArray* painted = this->ProjectorMasks->GetPointData()->GetArray("Mask");
      painted = painted ? painted : this->ProjectorMasks->GetPointData()->GetScalars();
      maskArray = vtkUnsignedCharArray::SafeDownCast(painted);
      if (!maskArray || maskArray->GetNumberOfComponents() != 3 || dims[0] != projectorWidth ||
        dims[1] != projectorHeight || dims[2] != projectorCount)
      {
        this->Fail(output,
          vtkErrorCode::UnknownError,
          "vtkLightFieldCapture: the projector masks are " + std::to_string(dims[0]) + "x" +
            std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
            (maskArray ? "" : " without RGB uint8 scalars") +
            "; the projectors need RGB uint8 masks of " + std::to_string(projectorWidth) + "x" +
            std::to_string(projectorHeight) + "x" + std::to_string(projectorCount));
        return 0;
      }
      masks->DeepCopy(this->ProjectorMasks);
      maskArray =
        vtkUnsignedCharArray::SafeDownCast(masks->GetPointData()->GetArray(maskArray->GetName()));
      maskArray->SetName("Mask");
    }
    else if (!this->Palette || this->Palette->GetNumberOfComponents() != 3 ||
      this->Palette->GetNumberOfTuples() < 2)
    {
      this->Fail(output,
        vtkErrorCode::UnknownError,
        "vtkLightFieldCapture: projectors without painted masks need a Palette (3 x uint8 per "
        "label, entry 0 = unlabelled) to generate their masks from the mesh labels");
      return 0;
    }
    else
    {
      if (vtkDataArray* parts = input->GetCellData()->GetArray("Label"))
      {
        double range[2];
        parts->GetRange(range, 0);
        if (range[1] >= this->Palette->GetNumberOfTuples())
        {
          this->Fail(output,
            vtkErrorCode::UnknownError,
            "vtkLightFieldCapture: the mesh has part label " +
              std::to_string(static_cast<long long>(range[1])) + " but the palette colours only " +
              std::to_string(this->Palette->GetNumberOfTuples() - 1) +
              " labels; give a palette with one colour per part");
          return 0;
        }
      }
      masks->SetDimensions(projectorWidth, projectorHeight, projectorCount);
      vtkNew<vtkUnsignedCharArray> generated;
      generated->SetName("Mask");
      generated->SetNumberOfComponents(3);
      generated->SetNumberOfTuples(masks->GetNumberOfPoints());
      masks->GetPointData()->SetScalars(generated);
      maskArray = generated;
    }
  }
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

  if (project)
  {
    output->SetProjectors(projectors);
    output->SetProjectorMasks(masks);
  }
  if (this->Palette)
  {
    vtkNew<vtkUnsignedCharArray> palette;
    palette->DeepCopy(this->Palette);
    output->SetPalette(palette);
  }
  auto* coded = project
    ? static_cast<unsigned char*>(output->AllocatePass(vtkLightField::CODED)->GetVoidPointer(0))
    : nullptr;
  auto* flood = project
    ? static_cast<unsigned char*>(output->AllocatePass(vtkLightField::FLOOD)->GetVoidPointer(0))
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

  // Window depth d in [0, 1] back to the camera-space distance along the
  // optical axis of the perspective frustum [n, f]; 0 where nothing is seen.
  auto readDepth = [&](int w, int h, float* z)
  {
    window->GetZbufferData(0, 0, w - 1, h - 1, z);
    double range[2];
    camera->GetClippingRange(range);
    const double n = range[0];
    const double f = range[1];
    for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
    {
      z[p] = z[p] >= 1.0f ? 0.0f : static_cast<float>(lfd::WindowDepthToDistance(z[p], n, f));
    }
  };

  // Each projector's depth map (its visibility), and its generated mask:
  // the palette colour of the label it sees at each of its pixels.
  std::vector<float> projectorDepth(projectorPixels * projectorCount);
  if (project)
  {
    window->SetSize(projectorWidth, projectorHeight);
    shaded->VisibilityOff();
    flat->VisibilityOn();
    for (int p = 0; p < projectorCount; ++p)
    {
      projectors->ApplyToCamera(p, camera);
      SetTightClippingRange(camera, bounds);
      window->Render();
      readDepth(projectorWidth, projectorHeight, projectorDepth.data() + p * projectorPixels);
      if (!this->ProjectorMasks)
      {
        window->GetPixelData(0, 0, projectorWidth - 1, projectorHeight - 1, 0, rgbBuffer, 0);
        const vtkIdType colours = this->Palette->GetNumberOfTuples();
        for (vtkIdType q = 0; q < projectorPixels; ++q)
        {
          const vtkIdType part = rgbBuffer->GetValue(3 * q);
          for (int c = 0; c < 3; ++c)
          {
            maskArray->SetTypedComponent(p * projectorPixels + q,
              c,
              part < colours ? this->Palette->GetTypedComponent(part, c) : 0);
          }
        }
      }
    }
    window->SetSize(width, height);
  }
  std::vector<float> viewDepth(project && !depth ? pixels : 0);
  vtkNew<vtkUnsignedCharArray> albedo;
  std::vector<glm::dvec3> surface(project ? pixels : 0);
  std::vector<double> codedSum(project ? 3 * pixels : 0), floodSum(project ? 3 * pixels : 0);
  std::mt19937 random(static_cast<unsigned int>(this->NoiseSeed));
  std::normal_distribution<double> noise(0.0, this->ProjectorNoise);

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

    float* z = depth ? depth + slice : (project ? viewDepth.data() : nullptr);
    if (label || z)
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
      if (z)
      {
        readDepth(width, height, z);
      }
    }

    if (project)
    {
      // The albedo (unlit) for the room light, if any, then each
      // projector's Lambertian irradiance x albedo, masked by its visibility.
      shaded->VisibilityOn();
      flat->VisibilityOff();
      material->SetAmbient(0.0);
      material->SetDiffuse(1.0);
      if (this->ProjectorAmbient > 0.0)
      {
        material->LightingOff();
        window->Render();
        window->GetPixelData(0, 0, width - 1, height - 1, 0, albedo, 0);
        material->LightingOn();
      }
      std::fill(codedSum.begin(), codedSum.end(), 0.0);
      std::fill(floodSum.begin(), floodSum.end(), 0.0);
      // The surface point each pixel sees, from the depth.
      const lfd::PinholeCamera::Unprojection unproject = rig->GetCamera(view).GetUnprojection();
      for (vtkIdType q = 0; q < pixels; ++q)
      {
        const glm::dvec2 pixel(
          static_cast<double>(q % width), static_cast<double>(height - 1 - q / width));
        surface[q] = unproject(pixel, static_cast<double>(z[q]));
      }
      for (int p = 0; p < projectorCount; ++p)
      {
        const lfd::PinholeCamera& projector = projectors->GetCamera(p);
        const glm::dvec3 lampPosition = projector.Center();
        const glm::dvec3 lampTarget = lampPosition + projector.Forward();
        lamp->SetPosition(lampPosition.x, lampPosition.y, lampPosition.z);
        lamp->SetFocalPoint(lampTarget.x, lampTarget.y, lampTarget.z);
        window->Render();
        window->GetPixelData(0, 0, width - 1, height - 1, 0, rgbBuffer, 0);
        const float* mapDepth = projectorDepth.data() + p * projectorPixels;
        const double footprint = 1.0 / projector.K[0][0];
        for (vtkIdType q = 0; q < pixels; ++q)
        {
          if (!(z[q] > 0.0f))
          {
            continue;
          }
          const glm::dvec3& X = surface[q];
          glm::dvec2 pixel;
          if (!projector.Project(X, pixel))
          {
            continue;
          }
          const long u = std::lround(pixel.x);
          const long v = std::lround(pixel.y);
          if (u < 0 || v < 0 || u >= projectorWidth || v >= projectorHeight)
          {
            continue;
          }
          // Seen by the projector: no surface in front of X along its ray
          // (tolerance: a few projector pixels of slope, plus 0.5 %).
          const vtkIdType projected = (projectorHeight - 1 - v) * projectorWidth + u;
          const double along = (projector.R * X + projector.t).z;
          const double seen = mapDepth[projected];
          if (!(seen > 0.0) || along > seen + along * (0.005 + 3.0 * footprint))
          {
            continue;
          }
          const unsigned char* colour =
            maskArray->GetPointer(3 * (p * projectorPixels + projected));
          for (int c = 0; c < 3; ++c)
          {
            const double irradiance = rgbBuffer->GetValue(3 * q + c);
            codedSum[3 * q + c] += irradiance * colour[c] / 255.0;
            floodSum[3 * q + c] += irradiance;
          }
        }
      }
      material->SetAmbient(this->Ambient);
      material->SetDiffuse(1.0 - this->Ambient);
      auto expose = [&](double value)
      {
        value += this->ProjectorNoise > 0.0 ? noise(random) : 0.0;
        return static_cast<unsigned char>(std::lround(std::min(255.0, std::max(0.0, value))));
      };
      for (vtkIdType i = 0; i < 3 * pixels; ++i)
      {
        const double room =
          this->ProjectorAmbient > 0.0 ? this->ProjectorAmbient * albedo->GetValue(i) : 0.0;
        coded[3 * slice + i] = expose(codedSum[i] + room);
        flood[3 * slice + i] = expose(floodSum[i] + room);
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
  os << indent << "NumberOfProjectors: " << this->NumberOfProjectors << "\n";
  os << indent << "ProjectorWidth: " << this->ProjectorWidth << "\n";
  os << indent << "ProjectorHeight: " << this->ProjectorHeight << "\n";
  os << indent << "Projectors: " << (this->Projectors ? "set" : "(none)") << "\n";
  os << indent << "ProjectorMasks: " << (this->ProjectorMasks ? "set" : "(none)") << "\n";
  os << indent << "Palette: " << (this->Palette ? "set" : "(none)") << "\n";
  os << indent << "ProjectorAmbient: " << this->ProjectorAmbient << "\n";
  os << indent << "ProjectorNoise: " << this->ProjectorNoise << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
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
