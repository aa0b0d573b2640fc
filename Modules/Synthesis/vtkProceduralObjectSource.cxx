#include "vtkProceduralObjectSource.h"

#include "lfdRequestGuard.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <string>

vtkStandardNewMacro(vtkProceduralObjectSource);

namespace
{
using RGB = std::array<double, 3>;
using ColorFunction = std::function<RGB(const double x[3])>;

constexpr int Checks = 8;
constexpr int FigureTextureSize = 256;

RGB Mix(const RGB& a, const RGB& b, double t)
{
  return { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) };
}

// A capped cylinder along +Y.
vtkSmartPointer<vtkPolyData> MakeCylinder(const double center[3],
  double radius,
  double height,
  int resolution)
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetCenter(center);
  cylinder->SetRadius(radius);
  cylinder->SetHeight(height);
  cylinder->SetResolution(resolution);
  cylinder->CappingOn();
  cylinder->Update();
  vtkSmartPointer<vtkPolyData> part = cylinder->GetOutput();
  part->GetPointData()->SetTCoords(nullptr);
  return part;
}

void SetLabel(vtkPolyData* part, int label)
{
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  labels->SetNumberOfTuples(part->GetNumberOfCells());
  labels->FillValue(label);
  part->GetCellData()->AddArray(labels);
}

void SetPointColors(vtkPolyData* part, const ColorFunction& color)
{
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(part->GetNumberOfPoints());
  for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
  {
    double x[3];
    part->GetPoint(i, x);
    const RGB c = color(x);
    for (int k = 0; k < 3; ++k)
    {
      colors->SetTypedComponent(
        i, k, static_cast<unsigned char>(vtkMath::ClampValue(c[k], 0.0, 255.0) + 0.5));
    }
  }
  part->GetPointData()->AddArray(colors);
}

// A part of the fish: an ellipsoid with the given centre and semi-axes,
// poles along X so the stripes across the long axis of the fish follow the
// latitude rings, with point colours and a cell label.
vtkSmartPointer<vtkPolyData> MakeFishPart(const double center[3],
  const double semiAxes[3],
  int resolution,
  const ColorFunction& color,
  int label)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(std::max(resolution / 2, 4));
  vtkNew<vtkTransform> transform;
  transform->Translate(center);
  transform->Scale(semiAxes);
  transform->RotateY(90.0);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(sphere->GetOutputPort());
  place->SetTransform(transform);
  place->Update();
  vtkSmartPointer<vtkPolyData> part = place->GetOutput();
  SetPointColors(part, color);
  SetLabel(part, label);
  return part;
}

// Texture coordinates wrapped around the vertical axis through `axisPoint`:
// s = |azimuth| / pi runs 0 -> 1 -> 0 around the part, so the wrap has no
// seam; t = (y - y0) / (y1 - y0) over the height of the whole figure.
void SetCylindricalTCoords(vtkPolyData* part, const double axisPoint[3], double y0, double y1)
{
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(part->GetNumberOfPoints());
  for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
  {
    double x[3];
    part->GetPoint(i, x);
    const double azimuth = std::atan2(x[0] - axisPoint[0], x[2] - axisPoint[2]);
    tcoords->SetTypedComponent(i, 0, static_cast<float>(std::abs(azimuth) / vtkMath::Pi()));
    tcoords->SetTypedComponent(i, 1, static_cast<float>((x[1] - y0) / (y1 - y0)));
  }
  part->GetPointData()->SetTCoords(tcoords);
}

vtkSmartPointer<vtkPolyData> Triangulate(vtkAppendPolyData* append)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(append->GetOutputPort());
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  return triangles->GetOutput();
}

vtkSmartPointer<vtkPolyData> MakeCheckerboard(int resolution)
{
  const int cellsPerCheck = (resolution + Checks - 1) / Checks;
  const int cells = Checks * cellsPerCheck;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5, -0.5, 0.0);
  plane->SetPoint1(0.5, -0.5, 0.0);
  plane->SetPoint2(-0.5, 0.5, 0.0);
  plane->SetResolution(cells, cells);
  plane->Update();
  vtkSmartPointer<vtkPolyData> board = plane->GetOutput();
  board->GetPointData()->SetTCoords(nullptr);

  // vtkPlaneSource numbers its quads row by row along Point1.
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(board->GetNumberOfCells());
  for (vtkIdType id = 0; id < board->GetNumberOfCells(); ++id)
  {
    const int i = static_cast<int>(id % cells) / cellsPerCheck;
    const int j = static_cast<int>(id / cells) / cellsPerCheck;
    const unsigned char value = (i + j) % 2 == 0 ? 255 : 0;
    for (int k = 0; k < 3; ++k)
    {
      colors->SetTypedComponent(id, k, value);
    }
  }
  board->GetCellData()->AddArray(colors);
  SetLabel(board, 1);

  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(board);
  return Triangulate(append);
}

vtkSmartPointer<vtkPolyData> MakeFish(int resolution)
{
  const double headCenter[3] = { 0.40, 0.02, 0.0 };
  const double headAxes[3] = { 0.20, 0.16, 0.10 };
  const double bodyCenter[3] = { 0.0, 0.0, 0.0 };
  const double bodyAxes[3] = { 0.36, 0.20, 0.12 };
  const double tailCenter[3] = { -0.46, 0.0, 0.0 };
  const double tailAxes[3] = { 0.16, 0.20, 0.025 };

  auto head = MakeFishPart(
    headCenter,
    headAxes,
    resolution,
    [](const double x[3]) -> RGB
    {
      // A yellow head with a fine dot pattern and a black-and-white eye on
      // each side.
      const RGB yellow = { 240, 205, 70 };
      const RGB ochre = { 190, 140, 30 };
      const double dots = std::sin(60.0 * x[1]) * std::sin(60.0 * x[0]);
      RGB c = dots > 0.6 ? ochre : yellow;
      const double eye = std::hypot(x[0] - 0.47, x[1] - 0.06);
      if (eye < 0.035)
      {
        c = { 10, 10, 10 };
      }
      else if (eye < 0.055)
      {
        c = { 250, 250, 250 };
      }
      return c;
    },
    1);

  auto body = MakeFishPart(
    bodyCenter,
    bodyAxes,
    resolution,
    [](const double x[3]) -> RGB
    {
      // Orange with dark vertical stripes and a pale belly.
      const RGB orange = { 235, 120, 35 };
      const RGB stripe = { 70, 35, 25 };
      const RGB belly = { 245, 235, 210 };
      RGB c = std::sin(40.0 * x[0]) > 0.55 ? stripe : orange;
      if (x[1] < -0.08)
      {
        c = Mix(c, belly, std::min(1.0, (-0.08 - x[1]) / 0.06));
      }
      return c;
    },
    2);

  auto tail = MakeFishPart(
    tailCenter,
    tailAxes,
    resolution,
    [](const double x[3]) -> RGB
    {
      // A blue fin with light rays fanning out from the body.
      const RGB blue = { 50, 70, 190 };
      const RGB ray = { 150, 180, 250 };
      const double angle = std::atan2(x[1], -0.30 - x[0]);
      return std::sin(18.0 * angle) > 0.0 ? ray : blue;
    },
    3);

  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(head);
  append->AddInputData(body);
  append->AddInputData(tail);
  return Triangulate(append);
}

vtkSmartPointer<vtkPolyData> MakeFigure(int resolution)
{
  const double yMin = -0.575;
  const double yMax = 0.58;
  const double headCenter[3] = { 0.0, 0.45, 0.0 };
  vtkNew<vtkSphereSource> headSource;
  headSource->SetCenter(headCenter);
  headSource->SetRadius(0.13);
  headSource->SetThetaResolution(resolution);
  headSource->SetPhiResolution(std::max(resolution / 2, 4));
  headSource->Update();
  vtkSmartPointer<vtkPolyData> head = headSource->GetOutput();
  SetCylindricalTCoords(head, headCenter, yMin, yMax);
  SetLabel(head, 1);

  const double torsoCenter[3] = { 0.0, 0.18, 0.0 };
  auto torso = MakeCylinder(torsoCenter, 0.16, 0.40, resolution);
  SetCylindricalTCoords(torso, torsoCenter, yMin, yMax);
  SetLabel(torso, 2);

  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(head);
  append->AddInputData(torso);
  for (double side : { -1.0, 1.0 })
  {
    const double legCenter[3] = { 0.08 * side, -0.30, 0.0 };
    auto leg = MakeCylinder(legCenter, 0.06, 0.55, std::max(resolution / 2, 8));
    SetCylindricalTCoords(leg, legCenter, yMin, yMax);
    SetLabel(leg, 3);
    append->AddInputData(leg);
  }
  return Triangulate(append);
}

// Side of the texture image: the figure's texture, or one white pixel.
int TextureSide(int object)
{
  return object == vtkProceduralObjectSource::FIGURE ? FigureTextureSize : 1;
}

// Checks of 32 pixels (cream / red), navy bands every 64 rows and thin dark
// lines every 16 columns: detail at several scales for the resampling tests.
void FillFigureTexture(vtkImageData* image)
{
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < FigureTextureSize; ++j)
  {
    for (int i = 0; i < FigureTextureSize; ++i)
    {
      RGB c = ((i / 32 + j / 32) % 2 == 0) ? RGB{ 240, 225, 190 } : RGB{ 190, 40, 40 };
      if (j % 64 < 8)
      {
        c = { 30, 40, 120 };
      }
      if (i % 16 < 2)
      {
        c = Mix(c, RGB{ 0, 0, 0 }, 0.4);
      }
      unsigned char* p = pixels + 3 * (j * FigureTextureSize + i);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = static_cast<unsigned char>(c[k] + 0.5);
      }
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkProceduralObjectSource::vtkProceduralObjectSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
int vtkProceduralObjectSource::GetTextureSize()
{
  return FigureTextureSize;
}

//------------------------------------------------------------------------------
const char* vtkProceduralObjectSource::GetObjectAsString()
{
  switch (this->Object)
  {
    case CHECKERBOARD:
      return "checkerboard";
    case FISH:
      return "fish";
    case FIGURE:
      return "figure";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
int vtkProceduralObjectSource::GetObjectFromString(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string lower(name);
  std::transform(lower.begin(),
    lower.end(),
    lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "checkerboard")
  {
    return CHECKERBOARD;
  }
  if (lower == "fish")
  {
    return FISH;
  }
  if (lower == "figure")
  {
    return FIGURE;
  }
  return -1;
}

//------------------------------------------------------------------------------
vtkImageData* vtkProceduralObjectSource::GetTextureOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkProceduralObjectSource::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkImageData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkProceduralObjectSource::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* textureInfo = outputVector->GetInformationObject(1);
  const int size = TextureSide(this->Object);
  const int extent[6] = { 0, size - 1, 0, size - 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  textureInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  textureInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  textureInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(textureInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkProceduralObjectSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkPolyData* mesh = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* texture = vtkImageData::GetData(outputVector, 1);
  if (!mesh || !texture)
  {
    vtkErrorMacro("Missing output data object (port 0 vtkPolyData, port 1 "
                  "vtkImageData).");
    return 0;
  }

  vtkSmartPointer<vtkPolyData> object;
  switch (this->Object)
  {
    case CHECKERBOARD:
      object = MakeCheckerboard(this->Resolution);
      break;
    case FISH:
      object = MakeFish(this->Resolution);
      break;
    case FIGURE:
      object = MakeFigure(this->Resolution);
      break;
    default:
      vtkErrorMacro("Unknown object " << this->Object << ".");
      return 0;
  }
  mesh->ShallowCopy(object);

  const int size = TextureSide(this->Object);
  texture->SetExtent(0, size - 1, 0, size - 1, 0, 0);
  texture->SetOrigin(0.0, 0.0, 0.0);
  texture->SetSpacing(1.0, 1.0, 1.0);
  texture->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  texture->GetPointData()->GetScalars()->SetName("Texture");
  if (this->Object == FIGURE)
  {
    FillFigureTexture(texture);
  }
  else
  {
    auto* white = static_cast<unsigned char*>(texture->GetScalarPointer());
    std::fill(white, white + 3, static_cast<unsigned char>(255));
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkProceduralObjectSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Object: " << this->GetObjectAsString() << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkProceduralObjectSource);
