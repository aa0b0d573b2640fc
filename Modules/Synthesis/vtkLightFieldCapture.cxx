#include "vtkLightFieldCapture.h"

#include "lfdPerspectiveDepth.h"
#include "lfdPinholeCamera.h"
#include "lfdProjectorMasks.h"
#include "lfdViewCoverage.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDeformationCage.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLandmarkTransform.h"
#include "vtkLight.h"
#include "vtkLightField.h"
#include "vtkLinearTransform.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProceduralObjectSource.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldCapture);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Rig, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightFieldCapture, RowHeights, vtkDoubleArray);
vtkCxxSetObjectMacro(vtkLightFieldCapture, RowElevations, vtkDoubleArray);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Eyes, vtkPoints);
vtkCxxSetObjectMacro(vtkLightFieldCapture, EyeTargets, vtkPoints);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Projectors, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightFieldCapture, ProjectorMasks, vtkImageData);
vtkCxxSetObjectMacro(vtkLightFieldCapture, Palette, vtkUnsignedCharArray);

namespace
{
// Default row spacing as a fraction of the radius: rows ~3 degrees of
// elevation apart keep the object near the image centre in every row.
constexpr double DefaultRowSpacingFraction = 0.05;
// Largest |elevation| of a row in degrees: tan() grows without bound at 90.
constexpr double MaximumElevation = 89.0;

/// Where the rows of a cylinder rig go, as a function of its radius (the
/// framing searches the radius): explicit heights, elevations, rows that
/// cover what eyes see, or evenly spaced rows (vtkLightFieldCapture's
/// documentation).
struct RowPlacement
{
  std::vector<double> Explicit;
  std::vector<double> Elevations; // degrees
  int Count = 1;
  double Spacing = 0.0; // 0: DefaultRowSpacingFraction x radius
  std::vector<glm::dvec3> Eyes;
  std::vector<glm::dvec3> Targets;
  glm::dvec3 Center{ 0.0 };
  glm::dvec3 Axis{ 0.0, 1.0, 0.0 };
  double Margin = 0.0; // x radius

  std::vector<double> Heights(double radius) const
  {
    if (!this->Explicit.empty())
    {
      return this->Explicit;
    }
    std::vector<double> heights;
    for (double elevation : this->Elevations)
    {
      heights.push_back(radius * std::tan(vtkMath::RadiansFromDegrees(elevation)));
    }
    if (!heights.empty())
    {
      return heights;
    }
    const double spacing = this->Spacing > 0.0 ? this->Spacing : DefaultRowSpacingFraction * radius;
    double low = -0.5 * (this->Count - 1) * spacing;
    double high = -low;
    // The heights where the eyes' rays enter the cylinder (Sec. 6.2: where
    // the renderer looks them up), with the margin.
    const lfd::Cylinder cylinder{ this->Center, this->Axis, radius };
    for (const glm::dvec3& eye : this->Eyes)
    {
      for (const glm::dvec3& target : this->Targets)
      {
        glm::dvec3 entry;
        if (lfd::RayEntry(cylinder, eye, target, entry))
        {
          const double h = glm::dot(entry - this->Center, this->Axis);
          low = std::min(low, h - this->Margin * radius);
          high = std::max(high, h + this->Margin * radius);
        }
      }
    }
    if (this->Count == 1)
    {
      return { 0.5 * (low + high) };
    }
    for (int r = 0; r < this->Count; ++r)
    {
      heights.push_back(low + (high - low) * r / (this->Count - 1));
    }
    return heights;
  }
};
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

namespace
{
// Projector masks for the capture: a copy of the painted ones (checked
// against the projectors), or room for the ones generated from the mesh
// labels and the palette. Returns the problem in words, empty when ready.
std::string PrepareProjectorMasks(vtkPolyData* mesh,
  vtkImageData* painted,
  vtkUnsignedCharArray* palette,
  vtkCameraRig* projectors,
  vtkImageData* masks,
  vtkUnsignedCharArray*& maskArray)
{
  const int projectorCount = projectors->GetNumberOfViews();
  const int projectorWidth = projectors->GetImageSize()[0];
  const int projectorHeight = projectors->GetImageSize()[1];
  if (painted)
  {
    const int* dims = painted->GetDimensions();
    maskArray = lfd::GetMaskColours(painted);
    if (!maskArray || dims[0] != projectorWidth || dims[1] != projectorHeight ||
      dims[2] != projectorCount)
    {
      return "vtkLightFieldCapture: the projector masks are " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
        (maskArray ? "" : " without RGB uint8 scalars") +
        "; the projectors need RGB uint8 masks of " + std::to_string(projectorWidth) + "x" +
        std::to_string(projectorHeight) + "x" + std::to_string(projectorCount);
    }
    masks->DeepCopy(painted);
    maskArray =
      vtkUnsignedCharArray::SafeDownCast(masks->GetPointData()->GetArray(maskArray->GetName()));
    maskArray->SetName("Mask");
    return std::string();
  }
  if (!palette || palette->GetNumberOfComponents() != 3 || palette->GetNumberOfTuples() < 2)
  {
    return "vtkLightFieldCapture: projectors without painted masks need a Palette (3 x uint8 per "
           "label, entry 0 = unlabelled) to generate their masks from the mesh labels";
  }
  if (vtkDataArray* parts = mesh->GetCellData()->GetArray("Label"))
  {
    double range[2];
    parts->GetRange(range, 0);
    if (range[1] >= palette->GetNumberOfTuples())
    {
      return "vtkLightFieldCapture: the mesh has part label " +
        std::to_string(static_cast<long long>(range[1])) + " but the palette colours only " +
        std::to_string(palette->GetNumberOfTuples() - 1) +
        " labels; give a palette with one colour per part";
    }
  }
  masks->SetDimensions(projectorWidth, projectorHeight, projectorCount);
  vtkNew<vtkUnsignedCharArray> generated;
  generated->SetName("Mask");
  generated->SetNumberOfComponents(3);
  generated->SetNumberOfTuples(masks->GetNumberOfPoints());
  masks->GetPointData()->SetScalars(generated);
  maskArray = generated;
  return std::string();
}

// The Label pass colour of every cell, (label, label, label), read back
// exactly. Returns the problem in words, empty when every label is valid.
std::string ColourLabels(vtkPolyData* mesh, vtkUnsignedCharArray* colours)
{
  colours->SetName("LabelColor");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(mesh->GetNumberOfCells());
  vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    const double value = labels ? labels->GetComponent(cell, 0) : 1.0;
    if (!(value >= 0.0 && value <= 255.0) || value != std::floor(value))
    {
      std::ostringstream problem;
      problem << "Cell " << cell << " of the input mesh has Label " << value
              << "; labels must be integers in [0, 255].";
      return problem.str();
    }
    const auto byte = static_cast<unsigned char>(value);
    const unsigned char color[3] = { byte, byte, byte };
    colours->SetTypedTuple(cell, color);
  }
  return std::string();
}

// The output's passes, null when not captured.
struct PassBuffers
{
  unsigned char* Coaxial = nullptr;
  unsigned char* Label = nullptr;
  float* Depth = nullptr;
  unsigned char* Coded = nullptr;
  unsigned char* Flood = nullptr;
};

/**
 * The offscreen studio of a capture: one window for all views, the shaded
 * actor (the Coaxial pass: albedo from the texture, the "RGB" array or
 * white), the flat label actor (the Label pass) and the lamp, and the
 * render of each pass of each view.
 */
class CaptureStudio
{
public:
  CaptureStudio(vtkLightFieldCapture* capture,
    vtkPolyData* mesh,
    vtkImageData* textureImage,
    vtkUnsignedCharArray* labelColours,
    const double bounds[6])
    : Capture(capture)
    , Bounds(bounds)
  {
    this->SetUpShaded(mesh, textureImage);
    this->SetUpFlat(mesh, labelColours);
    // No multisampling, so every pixel of the Label pass belongs to exactly
    // one cell.
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetAlphaBitPlanes(0);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Renderer->AutomaticLightCreationOff();
    this->Renderer->TwoSidedLightingOn();
    this->Renderer->UseFXAAOff();
    this->Renderer->AddActor(this->Shaded);
    this->Renderer->AddActor(this->Flat);
    this->Window->AddRenderer(this->Renderer);
    // A point light, not a spotlight, not attenuated (DESIGN.md section 5).
    this->Lamp->SetLightTypeToSceneLight();
    this->Lamp->SetPositional(true);
    this->Lamp->SetConeAngle(180.0);
    this->Lamp->SetAttenuationValues(1.0, 0.0, 0.0);
    this->Lamp->SetColor(1.0, 1.0, 1.0);
    this->Lamp->SetIntensity(1.0);
    this->Renderer->AddLight(this->Lamp);
    this->Camera = this->Renderer->GetActiveCamera();
  }

  /// Points the camera at view `view` of `rig`, clipped tightly to the bounds.
  void View(vtkCameraRig* rig, int view)
  {
    rig->ApplyToCamera(view, this->Camera);
    SetTightClippingRange(this->Camera, this->Bounds);
  }

  void SetSize(int width, int height) { this->Window->SetSize(width, height); }

  /// Renders the shaded mesh lit from `lamp` and reads the RGB pixels
  /// (bottom row first: vtkLightField's row order).
  void RenderShaded(const double lamp[3], vtkUnsignedCharArray* rgb, int width, int height)
  {
    this->ShowShaded();
    this->Lamp->SetPosition(lamp);
    this->Lamp->SetFocalPoint(this->Camera->GetFocalPoint());
    this->Window->Render();
    this->Window->GetPixelData(0, 0, width - 1, height - 1, 0, rgb, 0);
  }

  /// Shows the shaded mesh only (the projector passes light it themselves).
  void ShowShaded()
  {
    this->Shaded->VisibilityOn();
    this->Flat->VisibilityOff();
  }

  /// Renders the flat label colours (the caller reads pixels or depth).
  void RenderLabels()
  {
    this->Shaded->VisibilityOff();
    this->Flat->VisibilityOn();
    this->Window->Render();
  }

  /// Window depth d in [0, 1] back to the camera-space distance along the
  /// optical axis of the perspective frustum [n, f]; 0 where nothing is seen.
  void ReadDepth(int width, int height, float* z)
  {
    this->Window->GetZbufferData(0, 0, width - 1, height - 1, z);
    double range[2];
    this->Camera->GetClippingRange(range);
    const double n = range[0];
    const double f = range[1];
    for (vtkIdType p = 0; p < static_cast<vtkIdType>(width) * height; ++p)
    {
      z[p] = z[p] >= 1.0f ? 0.0f : static_cast<float>(lfd::WindowDepthToDistance(z[p], n, f));
    }
  }

  void ReadPixels(int width, int height, vtkUnsignedCharArray* rgb)
  {
    this->Window->GetPixelData(0, 0, width - 1, height - 1, 0, rgb, 0);
  }

  vtkCamera* GetCamera() const { return this->Camera; }
  vtkLight* GetLamp() { return this->Lamp; }
  vtkProperty* GetMaterial() { return this->Shaded->GetProperty(); }
  void Render() { this->Window->Render(); }

private:
  void SetUpShaded(vtkPolyData* mesh, vtkImageData* textureImage);

  void SetUpFlat(vtkPolyData* mesh, vtkUnsignedCharArray* labelColours);

  vtkLightFieldCapture* Capture;
  const double* Bounds;
  vtkNew<vtkPolyDataMapper> ShadedMapper;
  vtkNew<vtkActor> Shaded;
  vtkNew<vtkTexture> Texture;
  vtkNew<vtkPolyData> LabelMesh;
  vtkNew<vtkPolyDataMapper> FlatMapper;
  vtkNew<vtkActor> Flat;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Lamp;
  vtkCamera* Camera = nullptr;
};

void CaptureStudio::SetUpFlat(vtkPolyData* mesh, vtkUnsignedCharArray* labelColours)
{
  this->LabelMesh->CopyStructure(mesh);
  this->LabelMesh->GetCellData()->AddArray(labelColours);
  this->FlatMapper->SetInputData(this->LabelMesh);
  this->FlatMapper->ScalarVisibilityOn();
  this->FlatMapper->SetScalarModeToUseCellFieldData();
  this->FlatMapper->SelectColorArray("LabelColor");
  this->FlatMapper->SetColorModeToDirectScalars();
  this->FlatMapper->InterpolateScalarsBeforeMappingOff();
  this->Flat->SetMapper(this->FlatMapper);
  this->Flat->GetProperty()->LightingOff();
  this->Flat->GetProperty()->SetInterpolationToFlat();
  this->Flat->GetProperty()->SetAmbient(0.0);
  this->Flat->GetProperty()->SetDiffuse(1.0);
}

void CaptureStudio::SetUpShaded(vtkPolyData* mesh, vtkImageData* textureImage)
{
  this->ShadedMapper->SetInputData(mesh);
  this->ShadedMapper->ScalarVisibilityOff();
  this->Shaded->SetMapper(this->ShadedMapper);
  vtkProperty* material = this->Shaded->GetProperty();
  material->SetColor(1.0, 1.0, 1.0);
  material->SetAmbient(this->Capture->GetAmbient());
  material->SetDiffuse(1.0 - this->Capture->GetAmbient());
  material->SetSpecular(0.0);
  if (textureImage && mesh->GetPointData()->GetTCoords())
  {
    vtkNew<vtkImageData> image;
    image->ShallowCopy(textureImage);
    this->Texture->SetInputData(image);
    this->Texture->InterpolateOn();
    this->Texture->RepeatOn();
    this->Shaded->SetTexture(this->Texture);
  }
  else if (vtkDataArray* rgb = FindAlbedo(mesh->GetPointData()))
  {
    this->ShadedMapper->ScalarVisibilityOn();
    this->ShadedMapper->SetScalarModeToUsePointFieldData();
    this->ShadedMapper->SelectColorArray(rgb->GetName());
    this->ShadedMapper->SetColorModeToDirectScalars();
  }
  else if (vtkDataArray* cellRgb = FindAlbedo(mesh->GetCellData()))
  {
    this->ShadedMapper->ScalarVisibilityOn();
    this->ShadedMapper->SetScalarModeToUseCellFieldData();
    this->ShadedMapper->SelectColorArray(cellRgb->GetName());
    this->ShadedMapper->SetColorModeToDirectScalars();
  }
}

/**
 * The projector passes (Coded, Flood) of a capture: each projector's depth
 * map (its visibility) and, without painted masks, its generated mask; then
 * per view the Lambertian irradiance of each projector times its mask
 * colour, masked by its visibility.
 */
class ProjectorSimulation
{
public:
  ProjectorSimulation(vtkLightFieldCapture* capture,
    vtkCameraRig* projectors,
    vtkUnsignedCharArray* maskArray)
    : Capture(capture)
    , Projectors(projectors)
    , MaskArray(maskArray)
    , Count(projectors->GetNumberOfViews())
    , Width(projectors->GetImageSize()[0])
    , Height(projectors->GetImageSize()[1])
    , Pixels(static_cast<vtkIdType>(Width) * Height)
    , Depth(Pixels * Count)
    , Random(static_cast<unsigned int>(capture->GetNoiseSeed()))
    , Noise(0.0, capture->GetProjectorNoise())
  {
  }

  /// Each projector's depth map, and its generated mask: the palette colour
  /// of the label it sees at each of its pixels.
  void RenderDepthMaps(CaptureStudio& studio, int width, int height);

  /**
   * The Coded and Flood pixels of the view the studio's camera shows, a
   * `width` x `height` camera `camera`, into `coded` and `flood` (3 x
   * width x height each). The studio renders it at n x n times the pixels
   * (n = Supersample, prefiltered as the Coaxial pass), whose camera-z
   * depth is `z`: each pixel is the mean of its n x n samples' light (a
   * camera integrates it over the pixel), then room light and noise.
   */
  void CaptureView(CaptureStudio& studio,
    const lfd::PinholeCamera& camera,
    int width,
    int height,
    const float* z,
    unsigned char* coded,
    unsigned char* flood)
  {
    const int n = this->Capture->GetSupersample();
    const int fineWidth = n * width;
    const int fineHeight = n * height;
    const vtkIdType finePixels = static_cast<vtkIdType>(fineWidth) * fineHeight;
    // The albedo (unlit) for the room light, if any, then each projector.
    studio.ShowShaded();
    vtkProperty* material = studio.GetMaterial();
    material->SetAmbient(0.0);
    material->SetDiffuse(1.0);
    const double room = this->Capture->GetProjectorAmbient();
    if (room > 0.0)
    {
      material->LightingOff();
      studio.Render();
      studio.ReadPixels(fineWidth, fineHeight, this->Albedo);
      material->LightingOn();
    }
    this->CodedSum.assign(3 * finePixels, 0.0);
    this->FloodSum.assign(3 * finePixels, 0.0);
    // The surface point each sample sees, from the depth, through the
    // camera of the n x n finer pixel grid over the same image.
    lfd::PinholeCamera fine = camera;
    fine.K[0] *= n;
    fine.K[1] *= n;
    fine.K[2][0] = n * (camera.K[2][0] + 0.5) - 0.5;
    fine.K[2][1] = n * (camera.K[2][1] + 0.5) - 0.5;
    const lfd::PinholeCamera::Unprojection unproject = fine.GetUnprojection();
    this->Surface.resize(finePixels);
    for (vtkIdType q = 0; q < finePixels; ++q)
    {
      const glm::dvec2 pixel(
        static_cast<double>(q % fineWidth), static_cast<double>(fineHeight - 1 - q / fineWidth));
      this->Surface[q] = unproject(pixel, static_cast<double>(z[q]));
    }
    for (int p = 0; p < this->Count; ++p)
    {
      this->AddProjector(studio, p, fineWidth, fineHeight, z);
    }
    material->SetAmbient(this->Capture->GetAmbient());
    material->SetDiffuse(1.0 - this->Capture->GetAmbient());
    const bool noisy = this->Capture->GetProjectorNoise() > 0.0;
    auto expose = [&](double value)
    {
      value += noisy ? this->Noise(this->Random) : 0.0;
      return static_cast<unsigned char>(std::lround(std::min(255.0, std::max(0.0, value))));
    };
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        double sum[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const vtkIdType q = static_cast<vtkIdType>(y * n + j) * fineWidth + x * n + i;
            for (int c = 0; c < 3; ++c)
            {
              const double ambient = room > 0.0 ? room * this->Albedo->GetValue(3 * q + c) : 0.0;
              sum[c] += this->CodedSum[3 * q + c] + ambient;
              sum[3 + c] += this->FloodSum[3 * q + c] + ambient;
            }
          }
        }
        const vtkIdType pixel = 3 * (static_cast<vtkIdType>(y) * width + x);
        for (int c = 0; c < 3; ++c)
        {
          coded[pixel + c] = expose(sum[c] / (n * n));
          flood[pixel + c] = expose(sum[3 + c] / (n * n));
        }
      }
    }
  }

private:
  /// Projector `p`'s irradiance x mask colour at every pixel whose surface
  /// point it sees, added to the sums.
  void AddProjector(CaptureStudio& studio, int p, int width, int height, const float* z);

  vtkLightFieldCapture* Capture;
  vtkCameraRig* Projectors;
  vtkUnsignedCharArray* MaskArray;
  const int Count;
  const int Width;
  const int Height;
  const vtkIdType Pixels;
  std::vector<float> Depth;
  std::vector<glm::dvec3> Surface;
  std::vector<double> CodedSum;
  std::vector<double> FloodSum;
  vtkNew<vtkUnsignedCharArray> Buffer;
  vtkNew<vtkUnsignedCharArray> Albedo;
  std::mt19937 Random;
  std::normal_distribution<double> Noise;
};

void ProjectorSimulation::AddProjector(CaptureStudio& studio,
  int p,
  int width,
  int height,
  const float* z)
{
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  const lfd::PinholeCamera& projector = this->Projectors->GetCamera(p);
  const glm::dvec3 lampPosition = projector.Center();
  const glm::dvec3 lampTarget = lampPosition + projector.Forward();
  studio.GetLamp()->SetPosition(lampPosition.x, lampPosition.y, lampPosition.z);
  studio.GetLamp()->SetFocalPoint(lampTarget.x, lampTarget.y, lampTarget.z);
  studio.Render();
  studio.ReadPixels(width, height, this->Buffer);
  const float* mapDepth = this->Depth.data() + p * this->Pixels;
  const double footprint = 1.0 / projector.K[0][0];
  for (vtkIdType q = 0; q < pixels; ++q)
  {
    if (!(z[q] > 0.0f))
    {
      continue;
    }
    const glm::dvec3& X = this->Surface[q];
    glm::dvec2 pixel;
    if (!projector.Project(X, pixel))
    {
      continue;
    }
    const long u = std::lround(pixel.x);
    const long v = std::lround(pixel.y);
    if (u < 0 || v < 0 || u >= this->Width || v >= this->Height)
    {
      continue;
    }
    // Seen by the projector: no surface in front of X along its ray
    // (tolerance: a few projector pixels of slope, plus 0.5 %).
    const vtkIdType projected = (this->Height - 1 - v) * this->Width + u;
    const double along = (projector.R * X + projector.t).z;
    const double seen = mapDepth[projected];
    if (!(seen > 0.0) || along > seen + along * (0.005 + 3.0 * footprint))
    {
      continue;
    }
    const unsigned char* colour = this->MaskArray->GetPointer(3 * (p * this->Pixels + projected));
    for (int c = 0; c < 3; ++c)
    {
      const double irradiance = this->Buffer->GetValue(3 * q + c);
      this->CodedSum[3 * q + c] += irradiance * colour[c] / 255.0;
      this->FloodSum[3 * q + c] += irradiance;
    }
  }
}

void ProjectorSimulation::RenderDepthMaps(CaptureStudio& studio, int width, int height)
{
  studio.SetSize(this->Width, this->Height);
  for (int p = 0; p < this->Count; ++p)
  {
    studio.View(this->Projectors, p);
    studio.RenderLabels();
    studio.ReadDepth(this->Width, this->Height, this->Depth.data() + p * this->Pixels);
    if (!this->Capture->GetProjectorMasks())
    {
      studio.ReadPixels(this->Width, this->Height, this->Buffer);
      vtkUnsignedCharArray* palette = this->Capture->GetPalette();
      const vtkIdType colours = palette->GetNumberOfTuples();
      for (vtkIdType q = 0; q < this->Pixels; ++q)
      {
        const vtkIdType part = this->Buffer->GetValue(3 * q);
        for (int c = 0; c < 3; ++c)
        {
          this->MaskArray->SetTypedComponent(
            p * this->Pixels + q, c, part < colours ? palette->GetTypedComponent(part, c) : 0);
        }
      }
    }
  }
  studio.SetSize(width, height);
}
// The output's layout, rig, provenance, projectors, palette and passes.
PassBuffers SetUpOutput(vtkLightFieldCapture* capture,
  vtkLightField* output,
  vtkCameraRig* rig,
  vtkCameraRig* projectors,
  vtkImageData* masks)
{
  output->SetLayout(rig->GetImageSize()[0], rig->GetImageSize()[1], rig->GetNumberOfViews());
  output->SetRig(rig);
  std::ostringstream provenance;
  provenance << "{\"generator\": \"vtkLightFieldCapture\", \"light\": \""
             << (capture->GetSceneFixedLight() ? "scene-fixed" : "coaxial")
             << "\", \"ambient\": " << capture->GetAmbient();
  if (capture->GetSupersample() > 1)
  {
    provenance << ", \"supersample\": " << capture->GetSupersample();
  }
  // Built-in object names are plain words (vtkProceduralObjectSource): no
  // JSON escaping needed; anything else is not recorded.
  const char* object = capture->GetObjectName();
  if (object && vtkProceduralObjectSource::GetObjectFromString(object) >= 0)
  {
    provenance << ", \"object\": \"" << object << "\"";
  }
  provenance << "}";
  output->SetProvenance(provenance.str().c_str());
  auto bytes = [output](int pass)
  { return static_cast<unsigned char*>(output->AllocatePass(pass)->GetVoidPointer(0)); };
  PassBuffers passes;
  passes.Coaxial = capture->GetCaptureCoaxial() ? bytes(vtkLightField::COAXIAL) : nullptr;
  passes.Label = capture->GetCaptureLabel() ? bytes(vtkLightField::LABEL) : nullptr;
  passes.Depth = capture->GetCaptureDepth()
    ? static_cast<float*>(output->AllocatePass(vtkLightField::DEPTH)->GetVoidPointer(0))
    : nullptr;
  if (projectors)
  {
    output->SetProjectors(projectors);
    output->SetProjectorMasks(masks);
  }
  if (capture->GetPalette())
  {
    vtkNew<vtkUnsignedCharArray> palette;
    palette->DeepCopy(capture->GetPalette());
    output->SetPalette(palette);
  }
  passes.Coded = projectors ? bytes(vtkLightField::CODED) : nullptr;
  passes.Flood = projectors ? bytes(vtkLightField::FLOOD) : nullptr;
  return passes;
}

// The mean of each n x n block of the RGB image `fine` (n width x n height,
// bottom row first) into `rgb` (width x height, the same row order): a box
// filter over each coarse pixel's footprint, rounded to the nearest level.
void BoxDownsample(const unsigned char* fine, int n, int width, int height, unsigned char* rgb)
{
  const int fineWidth = n * width;
  const int samples = n * n;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      int sum[3] = { 0, 0, 0 };
      for (int j = 0; j < n; ++j)
      {
        const unsigned char* row =
          fine + 3 * (static_cast<vtkIdType>(y * n + j) * fineWidth + x * n);
        for (int i = 0; i < 3 * n; ++i)
        {
          sum[i % 3] += row[i];
        }
      }
      unsigned char* pixel = rgb + 3 * (static_cast<vtkIdType>(y) * width + x);
      for (int c = 0; c < 3; ++c)
      {
        pixel[c] = static_cast<unsigned char>((sum[c] + samples / 2) / samples);
      }
    }
  }
}

// Renders every view of the rig into the passes.
void CaptureViews(vtkLightFieldCapture* capture,
  CaptureStudio& studio,
  vtkCameraRig* rig,
  const PassBuffers& passes,
  ProjectorSimulation* simulation)
{
  const int width = rig->GetImageSize()[0];
  const int height = rig->GetImageSize()[1];
  const int views = rig->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  double fixedLamp[3];
  rig->GetCameraCenter(0, fixedLamp);
  vtkNew<vtkUnsignedCharArray> rgbBuffer;
  std::vector<float> viewDepth(simulation && !passes.Depth ? pixels : 0);
  std::vector<float> fineDepth;
  for (int view = 0; view < views && !capture->GetAbortExecute(); ++view)
  {
    studio.View(rig, view);
    const vtkIdType slice = view * pixels;
    if (passes.Coaxial)
    {
      // Prefiltered: the same frustum through n x n times the pixels, each
      // pixel the mean of its samples; Label and Depth stay point-sampled.
      const int n = capture->GetSupersample();
      studio.SetSize(n * width, n * height);
      studio.RenderShaded(
        capture->GetSceneFixedLight() ? fixedLamp : studio.GetCamera()->GetPosition(),
        rgbBuffer,
        n * width,
        n * height);
      BoxDownsample(rgbBuffer->GetPointer(0), n, width, height, passes.Coaxial + 3 * slice);
      studio.SetSize(width, height);
    }
    float* z = passes.Depth ? passes.Depth + slice : (simulation ? viewDepth.data() : nullptr);
    if (passes.Label || z)
    {
      studio.RenderLabels();
      if (passes.Label)
      {
        studio.ReadPixels(width, height, rgbBuffer);
        const unsigned char* red = rgbBuffer->GetPointer(0);
        for (vtkIdType p = 0; p < pixels; ++p)
        {
          passes.Label[slice + p] = red[3 * p];
        }
      }
      if (z)
      {
        studio.ReadDepth(width, height, z);
      }
    }
    if (simulation)
    {
      // Prefiltered as the Coaxial pass: the projectors light the n x n
      // samples of each pixel, seen at their own depths.
      const int n = capture->GetSupersample();
      const float* sampled = z;
      if (n > 1)
      {
        studio.SetSize(n * width, n * height);
        studio.RenderLabels();
        fineDepth.resize(pixels * n * n);
        studio.ReadDepth(n * width, n * height, fineDepth.data());
        sampled = fineDepth.data();
      }
      simulation->CaptureView(studio,
        rig->GetCamera(view),
        width,
        height,
        sampled,
        passes.Coded + 3 * slice,
        passes.Flood + 3 * slice);
      studio.SetSize(width, height);
    }
    capture->UpdateProgress(static_cast<double>(view + 1) / views);
  }
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
  this->SetRowElevations(nullptr);
  this->SetEyes(nullptr);
  this->SetEyeTargets(nullptr);
  this->SetProjectors(nullptr);
  this->SetObjectName(nullptr);
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
    views = this->GetNumberOfRigRows() * this->ViewsPerRing;
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
int vtkLightFieldCapture::GetNumberOfRigRows()
{
  if (this->RowHeights && this->RowHeights->GetNumberOfTuples() > 0)
  {
    return static_cast<int>(this->RowHeights->GetNumberOfTuples());
  }
  if (this->RowElevations && this->RowElevations->GetNumberOfTuples() > 0)
  {
    return static_cast<int>(this->RowElevations->GetNumberOfTuples());
  }
  return this->NumberOfRows;
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

  RowPlacement placement;
  placement.Center = glm::dvec3(center[0], center[1], center[2]);
  placement.Axis = glm::dvec3(axis[0], axis[1], axis[2]);
  placement.Count = this->NumberOfRows;
  placement.Spacing = this->RowSpacing;
  placement.Margin = this->RowMargin;
  if (this->RowHeights && this->RowHeights->GetNumberOfTuples() > 0)
  {
    for (vtkIdType r = 0; r < this->RowHeights->GetNumberOfTuples(); ++r)
    {
      placement.Explicit.push_back(this->RowHeights->GetValue(r));
    }
  }
  else if (this->RowElevations && this->RowElevations->GetNumberOfTuples() > 0)
  {
    for (vtkIdType r = 0; r < this->RowElevations->GetNumberOfTuples(); ++r)
    {
      const double elevation = this->RowElevations->GetValue(r);
      if (!(std::abs(elevation) <= MaximumElevation))
      {
        vtkErrorMacro("RowElevations: row " << r << " at " << elevation
                                            << " degrees; an elevation is in [-" << MaximumElevation
                                            << ", " << MaximumElevation << "] degrees.");
        return false;
      }
      placement.Elevations.push_back(elevation);
    }
  }
  else if (this->Eyes && this->Eyes->GetNumberOfPoints() > 0)
  {
    for (vtkIdType e = 0; e < this->Eyes->GetNumberOfPoints(); ++e)
    {
      const double* eye = this->Eyes->GetPoint(e);
      placement.Eyes.emplace_back(eye[0], eye[1], eye[2]);
    }
    const std::array<glm::dvec3, 9> probes = lfd::BoundsProbes(bounds);
    placement.Targets.assign(probes.begin(), probes.end());
    for (vtkIdType t = 0; this->EyeTargets && t < this->EyeTargets->GetNumberOfPoints(); ++t)
    {
      const double* target = this->EyeTargets->GetPoint(t);
      placement.Targets.emplace_back(target[0], target[1], target[2]);
    }
  }
  const int rows = this->GetNumberOfRigRows();

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
      for (double h : placement.Heights(r))
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
      vtkErrorMacro("Cannot frame the mesh: the rows span too wide a range of heights for a view "
                    "angle of "
        << this->ViewAngle
        << " degrees; give fewer or closer rows (NumberOfRows, RowSpacing, RowHeights, "
           "RowElevations; lfd synth --rows, --row-spacing, --row-heights, --elevations), a "
           "wider ViewAngle (--view-angle) or a Radius (--radius).");
      return false;
    }
    for (int i = 0; i < 50; ++i)
    {
      const double mid = 0.5 * (low + high);
      (fits(mid) ? high : low) = mid;
    }
    radius = high;
  }

  std::vector<double> heights = placement.Heights(radius);
  std::vector<double> sorted = heights;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
  {
    vtkErrorMacro("Two rows at the same height "
      << *std::adjacent_find(sorted.begin(), sorted.end())
      << " (RowHeights or RowElevations): give each row its own height.");
    return false;
  }
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
  // The views are rendered by vtkCamera, an ideal pinhole: a distorted rig
  // would get undistorted images that its own calibration then misreads.
  if (rig->HasDistortion() || (this->Projectors && this->Projectors->HasDistortion()))
  {
    vtkErrorMacro("The " << (rig->HasDistortion() ? "rig" : "projector rig")
                         << " has lens distortion; vtkLightFieldCapture renders ideal pinhole "
                            "views only: give cameras without distortion.");
    return 0;
  }

  // Projectors: their rig and masks (painted or generated).
  vtkNew<vtkCameraRig> projectors;
  const bool project = this->BuildProjectors(rig, projectors);
  vtkNew<vtkImageData> masks;
  vtkUnsignedCharArray* maskArray = nullptr;
  if (project)
  {
    const std::string problem = PrepareProjectorMasks(
      input, this->ProjectorMasks, this->Palette, projectors, masks, maskArray);
    if (!problem.empty())
    {
      this->Fail(output, vtkErrorCode::UnknownError, problem);
      return 0;
    }
  }
  const PassBuffers passes =
    SetUpOutput(this, output, rig, project ? projectors.GetPointer() : nullptr, masks);

  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(input);
  vtkNew<vtkUnsignedCharArray> labelColours;
  const std::string badLabel = ColourLabels(mesh, labelColours);
  if (!badLabel.empty())
  {
    vtkErrorMacro(<< badLabel);
    return 0;
  }
  CaptureStudio studio(this, mesh, textureImage, labelColours, bounds);
  const int width = rig->GetImageSize()[0];
  const int height = rig->GetImageSize()[1];
  studio.SetSize(width, height);
  std::unique_ptr<ProjectorSimulation> simulation;
  if (project)
  {
    simulation.reset(new ProjectorSimulation(this, projectors, maskArray));
    simulation->RenderDepthMaps(studio, width, height);
  }
  CaptureViews(this, studio, rig, passes, simulation.get());
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldCapture::AppendRestEyes(vtkDeformationCage* cage,
  const double eye[3],
  vtkPoints* eyes)
{
  for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
  {
    double rest[24], deformed[24];
    if (!cage->GetRestCorners(box, rest) || !cage->GetDeformedCorners(box, deformed))
    {
      continue;
    }
    vtkNew<vtkPoints> from, to;
    for (int corner = 0; corner < 8; ++corner)
    {
      from->InsertNextPoint(rest + 3 * corner);
      to->InsertNextPoint(deformed + 3 * corner);
    }
    vtkNew<vtkLandmarkTransform> map;
    map->SetSourceLandmarks(from);
    map->SetTargetLandmarks(to);
    map->SetModeToAffine();
    map->Update();
    double restEye[3];
    map->GetLinearInverse()->TransformPoint(eye, restEye);
    eyes->InsertNextPoint(restEye);
  }
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
  os << indent << "RowElevations: ";
  for (vtkIdType r = 0; this->RowElevations && r < this->RowElevations->GetNumberOfTuples(); ++r)
  {
    os << this->RowElevations->GetValue(r) << " ";
  }
  os << (this->RowElevations ? "\n" : "(none)\n");
  os << indent << "Eyes: " << (this->Eyes ? this->Eyes->GetNumberOfPoints() : 0) << "\n";
  os << indent << "EyeTargets: " << (this->EyeTargets ? this->EyeTargets->GetNumberOfPoints() : 0)
     << "\n";
  os << indent << "RowMargin: " << this->RowMargin << "\n";
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
  os << indent << "Supersample: " << this->Supersample << "\n";
  os << indent << "ObjectName: " << (this->ObjectName ? this->ObjectName : "(none)") << "\n";
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
