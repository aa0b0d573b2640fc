#include "vtkGantryCameraView.h"

#include "lfdColour.h"
#include "lfdPinholeCamera.h"
#include "vtkActor.h"
#include "vtkBoxCoverageCheck.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkHexahedron.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkLabelPalette.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkGantryCameraView);

namespace
{
std::array<unsigned char, 3> LabelColour(vtkUnsignedCharArray* palette, int label)
{
  if (palette && label >= 0 && label < palette->GetNumberOfTuples())
  {
    return { palette->GetTypedComponent(label, 0),
      palette->GetTypedComponent(label, 1),
      palette->GetTypedComponent(label, 2) };
  }
  const unsigned char level = label == 0 ? 0 : 255;
  return { level, level, level };
}

// One view of a pass as an RGB image (rows as stored: bottom first).
void FillPassImage(vtkLightField* lightField,
  vtkUnsignedCharArray* palette,
  int view,
  int pass,
  vtkUnsignedCharArray* rgb)
{
  const vtkIdType pixels = static_cast<vtkIdType>(lightField->GetWidth()) * lightField->GetHeight();
  const vtkIdType offset = view * pixels;
  rgb->FillValue(0);
  auto set = [rgb](vtkIdType p, double r, double g, double b)
  {
    rgb->SetTypedComponent(p, 0, static_cast<unsigned char>(std::lround(r)));
    rgb->SetTypedComponent(p, 1, static_cast<unsigned char>(std::lround(g)));
    rgb->SetTypedComponent(p, 2, static_cast<unsigned char>(std::lround(b)));
  };
  if (pass == vtkGantryCameraView::NORMALISED)
  {
    vtkDataArray* coded = lightField->GetPass(vtkLightField::CODED);
    vtkDataArray* flood = lightField->GetPass(vtkLightField::FLOOD);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      double value[3];
      for (int c = 0; c < 3; ++c)
      {
        const double w = flood->GetComponent(offset + p, c);
        value[c] = w > 0.0 ? lfd::NormaliseByFlood(coded->GetComponent(offset + p, c), w) : 0.0;
      }
      set(p, value[0], value[1], value[2]);
    }
    return;
  }
  vtkDataArray* data = lightField->GetPass(pass);
  if (pass == vtkLightField::LABEL)
  {
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const auto colour = LabelColour(palette, static_cast<int>(data->GetComponent(offset + p, 0)));
      set(p, colour[0], colour[1], colour[2]);
    }
    return;
  }
  if (pass == vtkLightField::DEPTH)
  {
    // Near surfaces bright, far ones dim, no surface black.
    double range[2] = { VTK_DOUBLE_MAX, 0.0 };
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const double d = data->GetComponent(offset + p, 0);
      if (d > 0.0)
      {
        range[0] = std::min(range[0], d);
        range[1] = std::max(range[1], d);
      }
    }
    const double span = std::max(range[1] - range[0], 1e-12);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const double d = data->GetComponent(offset + p, 0);
      const double level = d > 0.0 ? 55.0 + 200.0 * (range[1] - d) / span : 0.0;
      set(p, level, level, level);
    }
    return;
  }
  const bool colour = data->GetNumberOfComponents() >= 3;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const double r = data->GetComponent(offset + p, 0);
    set(p,
      r,
      colour ? data->GetComponent(offset + p, 1) : r,
      colour ? data->GetComponent(offset + p, 2) : r);
  }
}

const char* PassLabel(int pass)
{
  return pass == vtkGantryCameraView::NORMALISED ? "Normalised B'"
                                                 : vtkLightField::GetPassName(pass);
}
}

struct vtkGantryCameraView::Internals
{
  vtkSmartPointer<vtkDeformationCage> Cage;
  vtkNew<vtkImageData> Image;
  vtkNew<vtkImageData> Outside;
  vtkNew<vtkPolyData> Boxes;
  vtkNew<vtkImageActor> ImageActor;
  vtkNew<vtkImageActor> OutsideActor;
  vtkNew<vtkActor> BoxActor;
  vtkNew<vtkTextActor> Caption;
  vtkNew<vtkBoxCoverageCheck> Check;
  vtkIdType OutsidePixels = 0;
  bool CoverageValid = false;
  // Modification times the shown state was built from.
  vtkMTimeType ImageTime = 0;
  vtkMTimeType BoxTime = 0;
  vtkMTimeType CoverageTime = 0;

  Internals()
  {
    this->ImageActor->GetMapper()->SetInputData(this->Image);
    this->ImageActor->InterpolateOff();
    this->OutsideActor->GetMapper()->SetInputData(this->Outside);
    this->OutsideActor->InterpolateOff();
    this->OutsideActor->SetPosition(0.0, 0.0, 0.25);
    vtkNew<vtkPolyDataMapper> boxMapper;
    boxMapper->SetInputData(this->Boxes);
    boxMapper->SetScalarModeToUseCellData();
    boxMapper->SetColorModeToDirectScalars();
    this->BoxActor->SetMapper(boxMapper);
    this->BoxActor->GetProperty()->SetLineWidth(2.0);
    this->BoxActor->GetProperty()->LightingOff();
    this->BoxActor->SetPosition(0.0, 0.0, 0.5);
    this->Caption->GetTextProperty()->SetFontSize(14);
    this->Caption->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    // In the view's own viewport, wherever the renderer sits in the window.
    this->Caption->GetPositionCoordinate()->SetCoordinateSystemToViewport();
    this->Caption->GetPositionCoordinate()->SetValue(6.0, 6.0);
  }

  // The rest boxes' key: their positions and connectivity, and the labels.
  vtkMTimeType CageTime() const
  {
    if (!this->Cage || this->Cage->GetNumberOfBoxes() == 0)
    {
      return 0;
    }
    vtkMTimeType time = this->Cage->GetCells() ? this->Cage->GetCells()->GetMTime() : 0;
    if (vtkDataArray* rest = this->Cage->GetRestPositions())
    {
      time = std::max(time, rest->GetMTime());
    }
    if (vtkDataArray* labels = this->Cage->GetCellData()->GetArray("Label"))
    {
      time = std::max(time, labels->GetMTime());
    }
    return time;
  }

  static vtkMTimeType LightFieldTime(vtkLightField* lightField)
  {
    if (!lightField)
    {
      return 0;
    }
    vtkMTimeType time = lightField->GetMTime();
    for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
    {
      if (vtkDataArray* data = lightField->GetPass(pass))
      {
        time = std::max(time, data->GetMTime());
      }
    }
    return std::max(time, lightField->GetRig()->GetMTime());
  }
};

//------------------------------------------------------------------------------
vtkGantryCameraView::vtkGantryCameraView()
  : Internal(new Internals)
{
  Internals& internal = *this->Internal;
  vtkProp* props[] = {
    internal.ImageActor, internal.OutsideActor, internal.BoxActor, internal.Caption
  };
  for (vtkProp* prop : props)
  {
    this->AddViewProp(prop);
  }
}

//------------------------------------------------------------------------------
vtkGantryCameraView::~vtkGantryCameraView() = default;

//------------------------------------------------------------------------------
void vtkGantryCameraView::LightFieldChanged()
{
  this->Internal->Check->SetInputData(this->GetLightField());
  this->Internal->ImageTime = this->Internal->BoxTime = this->Internal->CoverageTime = 0;
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::SetCage(vtkDeformationCage* cage)
{
  this->Internal->Cage = cage;
  this->Internal->Check->SetCageData(cage);
  this->Internal->BoxTime = this->Internal->CoverageTime = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkGantryCameraView::GetCage()
{
  return this->Internal->Cage;
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::SetView(int view)
{
  if (view != this->View)
  {
    this->View = view;
    this->Internal->ImageTime = this->Internal->BoxTime = 0;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::SetPass(int pass)
{
  if (pass != this->Pass)
  {
    this->Pass = pass;
    this->Internal->ImageTime = 0;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::SetShowBoxes(bool show)
{
  this->ShowBoxes = show;
  this->Internal->BoxActor->SetVisibility(show);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::SetShowOutside(bool show)
{
  this->ShowOutside = show;
  this->Internal->OutsideActor->SetVisibility(show);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::Refresh()
{
  Internals& internal = *this->Internal;
  const vtkMTimeType lightField = Internals::LightFieldTime(this->GetLightField());
  const vtkMTimeType cage = std::max(lightField, internal.CageTime());
  const vtkMTimeType self = this->GetMTime();
  if (internal.CoverageTime == 0 || internal.CoverageTime < cage)
  {
    this->UpdateCoverage();
    internal.CoverageTime = std::max<vtkMTimeType>(cage, 1);
    internal.ImageTime = 0;
  }
  if (internal.BoxTime == 0 || internal.BoxTime < std::max(cage, self))
  {
    this->UpdateBoxes();
    internal.BoxTime = std::max<vtkMTimeType>(std::max(cage, self), 1);
  }
  if (internal.ImageTime == 0 || internal.ImageTime < std::max(lightField, self))
  {
    this->UpdateImage();
    internal.ImageTime = std::max<vtkMTimeType>(std::max(lightField, self), 1);
  }
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::UpdateCoverage()
{
  Internals& internal = *this->Internal;
  internal.CoverageValid = false;
  vtkLightField* lightField = this->GetLightField();
  if (!lightField || !internal.Cage || internal.Cage->GetNumberOfBoxes() == 0 ||
    !lightField->GetPass(vtkLightField::LABEL))
  {
    return;
  }
  internal.Check->Modified();
  internal.Check->Update();
  internal.CoverageValid =
    internal.Check->GetOutsideMask()->GetNumberOfPoints() == lightField->GetNumberOfPoints();
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::UpdateImage()
{
  Internals& internal = *this->Internal;
  vtkLightField* lightField = this->GetLightField();
  const int width = lightField ? lightField->GetWidth() : 0;
  const int height = lightField ? lightField->GetHeight() : 0;
  const int views = lightField ? lightField->GetNumberOfViews() : 0;
  const int view = std::max(0, std::min(this->View, views - 1));
  internal.Image->SetDimensions(std::max(width, 1), std::max(height, 1), 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(internal.Image->GetNumberOfPoints());
  rgb->FillValue(0);
  const bool normalised = this->Pass == NORMALISED;
  const bool present = lightField && views > 0 &&
    (normalised
        ? lightField->GetPass(vtkLightField::CODED) && lightField->GetPass(vtkLightField::FLOOD)
        : lightField->GetPass(this->Pass) != nullptr);
  if (present)
  {
    vtkNew<vtkUnsignedCharArray> palette;
    vtkGantryCameraView::GetShownPalette(lightField, internal.Cage, palette);
    FillPassImage(lightField, palette, view, this->Pass, rgb);
  }
  else if (lightField && views > 0)
  {
    vtkErrorMacro("The light field has no "
      << (normalised ? "Coded and Flood passes" : PassLabel(this->Pass))
      << (normalised ? "" : " pass") << " to show.");
  }
  internal.Image->GetPointData()->SetScalars(rgb);

  // The labelled pixels outside their boxes, magenta over the photo.
  internal.Outside->SetDimensions(std::max(width, 1), std::max(height, 1), 1);
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(internal.Outside->GetNumberOfPoints());
  rgba->FillValue(0);
  internal.OutsidePixels = 0;
  if (internal.CoverageValid && views > 0)
  {
    vtkDataArray* outside = internal.Check->GetOutsideMask()->GetPointData()->GetScalars();
    const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      if (outside->GetComponent(view * pixels + p, 0) != 0)
      {
        const unsigned char magenta[4] = { 255, 0, 255, 255 };
        rgba->SetTypedTuple(p, magenta);
        ++internal.OutsidePixels;
      }
    }
  }
  internal.Outside->GetPointData()->SetScalars(rgba);

  std::ostringstream caption;
  caption << "view " << view << "  " << PassLabel(this->Pass);
  if (internal.CoverageValid && views > 0)
  {
    caption.setf(std::ios::fixed);
    caption.precision(3);
    caption << "  coverage " << internal.Check->GetViewCoverage(view);
  }
  internal.Caption->SetInput(caption.str().c_str());
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::UpdateBoxes()
{
  Internals& internal = *this->Internal;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colors");
  colours->SetNumberOfComponents(3);
  vtkLightField* lightField = this->GetLightField();
  vtkDeformationCage* cage = internal.Cage;
  const int views = lightField ? lightField->GetRig()->GetNumberOfViews() : 0;
  if (cage && views > 0 && lightField->GetHeight() > 0)
  {
    vtkNew<vtkUnsignedCharArray> palette;
    vtkGantryCameraView::GetShownPalette(lightField, cage, palette);
    const int view = std::max(0, std::min(this->View, views - 1));
    const lfd::PinholeCamera& camera = lightField->GetRig()->GetCamera(view);
    const double top = lightField->GetHeight() - 1.0; // OpenCV y to VTK row
    for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
    {
      double rest[24];
      if (!cage->GetRestCorners(box, rest))
      {
        continue;
      }
      const auto colour = LabelColour(palette, cage->GetBoxLabel(box));
      for (vtkIdType e = 0; e < 12; ++e)
      {
        const vtkIdType* edge = vtkHexahedron::GetEdgeArray(e);
        const glm::dvec3 a(rest[3 * edge[0]], rest[3 * edge[0] + 1], rest[3 * edge[0] + 2]);
        const glm::dvec3 b(rest[3 * edge[1]], rest[3 * edge[1] + 1], rest[3 * edge[1] + 2]);
        // A polyline through the projected samples, broken where a sample
        // is behind the camera.
        std::vector<vtkIdType> run;
        auto flush = [&]()
        {
          if (run.size() >= 2)
          {
            lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
            colours->InsertNextTypedTuple(colour.data());
          }
          run.clear();
        };
        for (int s = 0; s < this->EdgeSamples; ++s)
        {
          const double f = static_cast<double>(s) / (this->EdgeSamples - 1);
          glm::dvec2 pixel;
          if (camera.Project(a + f * (b - a), pixel))
          {
            run.push_back(points->InsertNextPoint(pixel.x, top - pixel.y, 0.0));
          }
          else
          {
            flush();
          }
        }
        flush();
      }
    }
  }
  internal.Boxes->Initialize();
  internal.Boxes->SetPoints(points);
  internal.Boxes->SetLines(lines);
  internal.Boxes->GetCellData()->SetScalars(colours);
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::ResetCamera()
{
  Internals& internal = *this->Internal;
  vtkRenderer* renderer = this->GetRenderer();
  if (!renderer)
  {
    return;
  }
  this->Refresh();
  const int* dims = internal.Image->GetDimensions();
  vtkCamera* camera = renderer->GetActiveCamera();
  const double cx = 0.5 * (dims[0] - 1), cy = 0.5 * (dims[1] - 1);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 10.0 * std::max(dims[0], dims[1]));
  camera->SetViewUp(0.0, 1.0, 0.0);
  // The whole image in the viewport, whatever its aspect.
  const double aspect = renderer->GetTiledAspectRatio();
  camera->SetParallelScale(0.5 * std::max<double>(dims[1], dims[0] / std::max(aspect, 1e-6)));
  renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::GetShownPalette(vtkLightField* lightField,
  vtkDeformationCage* cage,
  vtkUnsignedCharArray* palette)
{
  if (lightField && lightField->GetPalette())
  {
    palette->DeepCopy(lightField->GetPalette());
    return;
  }
  int largest = 1;
  for (vtkIdType box = 0; cage && box < cage->GetNumberOfBoxes(); ++box)
  {
    largest = std::max(largest, cage->GetBoxLabel(box));
  }
  vtkLabelPalette::BuildDefault(largest, palette);
}

//------------------------------------------------------------------------------
double vtkGantryCameraView::GetCoverage()
{
  this->Refresh();
  Internals& internal = *this->Internal;
  if (!internal.CoverageValid)
  {
    return -1.0;
  }
  return internal.Check->GetViewCoverage(
    std::max(0, std::min(this->View, this->GetLightField()->GetNumberOfViews() - 1)));
}

//------------------------------------------------------------------------------
vtkBoxCoverageCheck* vtkGantryCameraView::GetCoverageCheck()
{
  this->Refresh();
  return this->Internal->Check;
}

//------------------------------------------------------------------------------
vtkImageData* vtkGantryCameraView::GetImage()
{
  this->Refresh();
  return this->Internal->Image;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkGantryCameraView::GetProjectedBoxes()
{
  this->Refresh();
  return this->Internal->Boxes;
}

//------------------------------------------------------------------------------
vtkIdType vtkGantryCameraView::GetNumberOfOutsidePixels()
{
  this->Refresh();
  return this->Internal->OutsidePixels;
}

//------------------------------------------------------------------------------
void vtkGantryCameraView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "View: " << this->View << "\n";
  os << indent << "Pass: " << PassLabel(this->Pass) << "\n";
  os << indent << "ShowBoxes: " << this->ShowBoxes << "\n";
  os << indent << "ShowOutside: " << this->ShowOutside << "\n";
  os << indent << "EdgeSamples: " << this->EdgeSamples << "\n";
}
