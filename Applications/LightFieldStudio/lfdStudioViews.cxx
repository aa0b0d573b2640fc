#include "lfdStudioViews.h"

#include "vtkActor.h"
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
#include "vtkLightField.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkOutlineSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <string>

namespace
{
/// The palette colours label `label` is drawn with: the light field's
/// palette, or the default one (vtkLabelPalette) when there is no light field.
void LabelColour(vtkUnsignedCharArray* palette, int label, unsigned char rgb[3])
{
  const vtkIdType entry = std::clamp<vtkIdType>(label, 0, palette->GetNumberOfTuples() - 1);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = palette->GetTypedComponent(entry, c);
  }
}

vtkSmartPointer<vtkUnsignedCharArray> Palette(vtkLightField* lightField)
{
  if (lightField && lightField->GetPalette())
  {
    return lightField->GetPalette();
  }
  vtkNew<vtkLabelPalette> labels;
  auto palette = vtkSmartPointer<vtkUnsignedCharArray>::New();
  labels->Build(palette);
  return palette;
}

/// The 12 edges of each box of `cage` (deformed corners, vtkHexahedron
/// order), each coloured by its box's label.
vtkSmartPointer<vtkPolyData> CageEdgeLines(vtkDeformationCage* cage, vtkUnsignedCharArray* palette)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetName("Colours");
  const vtkIdType boxes = cage ? cage->GetNumberOfBoxes() : 0;
  for (vtkIdType box = 0; box < boxes; ++box)
  {
    double corners[24];
    if (!cage->GetDeformedCorners(box, corners))
    {
      continue;
    }
    const vtkIdType first = points->GetNumberOfPoints();
    for (int c = 0; c < 8; ++c)
    {
      points->InsertNextPoint(corners + 3 * c);
    }
    unsigned char rgb[3];
    LabelColour(palette, cage->GetBoxLabel(box), rgb);
    for (vtkIdType edge = 0; edge < 12; ++edge)
    {
      const vtkIdType* corner = vtkHexahedron::GetEdgeArray(edge);
      const vtkIdType ends[2] = { first + corner[0], first + corner[1] };
      lines->InsertNextCell(2, ends);
      colours->InsertNextTypedTuple(rgb);
    }
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->GetCellData()->SetScalars(colours);
  return poly;
}

/// One slice (`slice` of the k index) of `array` on a W x H x N image, as an
/// RGB image: RGB arrays as they are, a label through the palette, other
/// one-component arrays in grey scaled to their range over the slice.
vtkSmartPointer<vtkImageData> SliceAsRGB(vtkDataArray* array,
  int width,
  int height,
  int slice,
  bool isLabel,
  vtkUnsignedCharArray* palette)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  const vtkIdType offset = count * slice;
  const int components = array->GetNumberOfComponents();
  double top = 0.0;
  if (components == 1 && !isLabel)
  {
    for (vtkIdType i = 0; i < count; ++i)
    {
      top = std::max(top, array->GetComponent(offset + i, 0));
    }
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    unsigned char out[3];
    if (components >= 3)
    {
      for (int c = 0; c < 3; ++c)
      {
        out[c] = static_cast<unsigned char>(array->GetComponent(offset + i, c));
      }
    }
    else if (isLabel)
    {
      LabelColour(palette, static_cast<int>(array->GetComponent(offset + i, 0)), out);
    }
    else
    {
      const double value = top > 0.0 ? array->GetComponent(offset + i, 0) / top : 0.0;
      out[0] = out[1] = out[2] = static_cast<unsigned char>(255.0 * value);
    }
    rgb->SetTypedTuple(i, out);
  }
  return image;
}

/// Frames a 2D image view: parallel projection, the whole image in the
/// viewport as it is laid out now.
void FrameImage(vtkRenderer* renderer, vtkImageData* image)
{
  if (!image)
  {
    return;
  }
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  int dims[3];
  image->GetDimensions(dims);
  const double aspect = renderer->GetRenderWindow() ? renderer->GetTiledAspectRatio() : 1.0;
  camera->SetParallelScale(
    0.5 * std::max(dims[1], 1) * std::max(1.0, dims[0] / (aspect * dims[1])));
}

void SetCaption(vtkTextActor* caption, const std::string& text)
{
  caption->SetInput(text.c_str());
  caption->GetTextProperty()->SetFontSize(14);
  // In the caption's own viewport, whatever the layout.
  caption->GetPositionCoordinate()->SetCoordinateSystemToViewport();
  caption->SetPosition(8, 8);
}

/// An actor drawing `poly` with its cell or point colours, lines `width` wide.
void ShowPolyData(vtkActor* actor, vtkPolyData* poly, double width)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetColorModeToDirectScalars();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(width);
  actor->GetProperty()->SetPointSize(6);
  actor->GetProperty()->SetLighting(false);
}

/// Centres of the views of `rig` (coloured by ring row through the
/// palette) and of `projectors` (white), as vertices.
vtkSmartPointer<vtkPolyData> RigCentres(vtkCameraRig* rig,
  vtkCameraRig* projectors,
  vtkUnsignedCharArray* palette)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  const auto add = [&](vtkCameraRig* cameras, bool byRow)
  {
    for (int i = 0; cameras && i < cameras->GetNumberOfViews(); ++i)
    {
      double centre[3];
      cameras->GetCameraCenter(i, centre);
      const vtkIdType id = points->InsertNextPoint(centre);
      vertices->InsertNextCell(1, &id);
      unsigned char rgb[3] = { 255, 255, 255 };
      if (byRow)
      {
        LabelColour(palette, std::max(cameras->GetRow(i), 0) + 1, rgb);
      }
      colours->InsertNextTypedTuple(rgb);
    }
  };
  add(rig, rig && rig->HasCylinder());
  add(projectors, false);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(vertices);
  poly->GetCellData()->SetScalars(colours);
  return poly;
}
}

//------------------------------------------------------------------------------
lfdStudioViews::lfdStudioViews(vtkLightFieldSceneLogic* logic, vtkRenderWindow* window)
  : Logic(logic)
  , Window(window)
{
  this->Editor->SetLogic(logic);
  this->Editor->SetRenderer(this->Main);
  // The Studio's Edit menu has Ctrl+Z / Ctrl+Shift+Z.
  this->Editor->UndoKeysOff();
  this->Camera->AddActor(this->CameraImage);
  this->Camera->AddActor2D(this->CameraCaption);
  this->ProjectorView->AddActor(this->ProjectorImage);
  this->ProjectorView->AddActor2D(this->ProjectorCaption);
  this->Rig->AddActor(this->RigCameras);
  this->Rig->AddActor(this->RigCageEdges);
  this->Rig->AddActor(this->RigBounds);
  for (vtkRenderer* renderer : { this->Camera.Get(), this->ProjectorView.Get(), this->Rig.Get() })
  {
    renderer->SetBackground(0.12, 0.12, 0.14);
  }
  this->SetLayout(MAIN_ONLY);
}

//------------------------------------------------------------------------------
lfdStudioViews::~lfdStudioViews() = default;

//------------------------------------------------------------------------------
void lfdStudioViews::SetLayout(int layout)
{
  this->CurrentLayout = std::clamp(layout, 0, static_cast<int>(FOUR_UP));
  for (vtkRenderer* renderer :
    { this->Main.Get(), this->Camera.Get(), this->ProjectorView.Get(), this->Rig.Get() })
  {
    this->Window->RemoveRenderer(renderer);
  }
  this->Window->AddRenderer(this->Main);
  if (this->CurrentLayout == MAIN_ONLY)
  {
    this->Main->SetViewport(0.0, 0.0, 1.0, 1.0);
  }
  else if (this->CurrentLayout == MAIN_AND_CAMERA)
  {
    this->Main->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->Camera->SetViewport(0.5, 0.0, 1.0, 1.0);
    this->Window->AddRenderer(this->Camera);
  }
  else
  {
    // Four-up as in ParaView / 3D Slicer: main top left, camera top right,
    // projector bottom left, rig bottom right.
    this->Main->SetViewport(0.0, 0.5, 0.5, 1.0);
    this->Camera->SetViewport(0.5, 0.5, 1.0, 1.0);
    this->ProjectorView->SetViewport(0.0, 0.0, 0.5, 0.5);
    this->Rig->SetViewport(0.5, 0.0, 1.0, 0.5);
    this->Window->AddRenderer(this->Camera);
    this->Window->AddRenderer(this->ProjectorView);
    this->Window->AddRenderer(this->Rig);
  }
  FrameImage(this->Camera, vtkImageData::SafeDownCast(this->CameraImage->GetInput()));
  FrameImage(this->ProjectorView, vtkImageData::SafeDownCast(this->ProjectorImage->GetInput()));
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetLightField(vtkLightField* lightField)
{
  this->LightField = lightField;
  // The editor reads the light field through the logic (and says why not);
  // without one there is nothing to edit on.
  if (lightField)
  {
    this->Editor->Initialize();
  }
  this->SetCameraView(this->CameraView);
  this->SetProjector(this->Projector);
  this->UpdateRig();
}

//------------------------------------------------------------------------------
void lfdStudioViews::ShowCage(double time, vtkDeformationCage* cage)
{
  if (this->LightField && time >= 0.0)
  {
    this->Editor->ShowTime(time);
  }
  else if (this->LightField)
  {
    this->Editor->ShowCurrentCage();
  }
  ShowPolyData(this->RigCageEdges, CageEdgeLines(cage, Palette(this->LightField)), 1.0);
}

//------------------------------------------------------------------------------
void lfdStudioViews::ResetCamera()
{
  vtkCamera* camera = this->Main->GetActiveCamera();
  camera->DeepCopy(this->Logic->GetScene()->GetCamera());
  this->Main->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetCameraView(int view)
{
  const int views = this->LightField ? this->LightField->GetNumberOfViews() : 0;
  this->CameraView = std::clamp(view, 0, std::max(views - 1, 0));
  this->UpdateCameraImage();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetPass(int pass)
{
  this->Pass = std::clamp(pass, 0, vtkLightField::NUMBER_OF_PASSES - 1);
  this->UpdateCameraImage();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetProjector(int projector)
{
  vtkImageData* masks = this->LightField ? this->LightField->GetProjectorMasks() : nullptr;
  const int count = masks ? masks->GetDimensions()[2] : 0;
  this->Projector = std::clamp(projector, 0, std::max(count - 1, 0));
  this->UpdateProjectorImage();
}

//------------------------------------------------------------------------------
void lfdStudioViews::GetLabelColour(int label, unsigned char rgb[3])
{
  LabelColour(Palette(this->LightField), label, rgb);
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetFrameTimeVisible(bool visible)
{
  this->Editor->GetFrameTimeActor()->SetVisibility(visible);
}

//------------------------------------------------------------------------------
vtkLightField* lfdStudioViews::GetLightField()
{
  return this->LightField;
}

//------------------------------------------------------------------------------
vtkRenderer* lfdStudioViews::GetMainRenderer()
{
  return this->Main;
}

//------------------------------------------------------------------------------
vtkLightFieldEditor* lfdStudioViews::GetEditor()
{
  return this->Editor;
}

//------------------------------------------------------------------------------
void lfdStudioViews::UpdateCameraImage()
{
  vtkDataArray* array = this->LightField ? this->LightField->GetPass(this->Pass) : nullptr;
  this->CameraImage->SetVisibility(array != nullptr);
  const std::string pass = vtkLightField::GetPassName(this->Pass);
  if (!array)
  {
    SetCaption(this->CameraCaption, "no " + pass + " pass");
    return;
  }
  auto image = SliceAsRGB(array,
    this->LightField->GetWidth(),
    this->LightField->GetHeight(),
    this->CameraView,
    this->Pass == vtkLightField::LABEL,
    Palette(this->LightField));
  this->CameraImage->SetInputData(image);
  FrameImage(this->Camera, image);
  SetCaption(this->CameraCaption, "view " + std::to_string(this->CameraView) + ", " + pass);
}

//------------------------------------------------------------------------------
void lfdStudioViews::UpdateProjectorImage()
{
  vtkImageData* masks = this->LightField ? this->LightField->GetProjectorMasks() : nullptr;
  vtkDataArray* mask = masks ? masks->GetPointData()->GetArray("Mask") : nullptr;
  this->ProjectorImage->SetVisibility(mask != nullptr);
  if (!mask)
  {
    SetCaption(this->ProjectorCaption, "no projectors");
    return;
  }
  int dims[3];
  masks->GetDimensions(dims);
  auto image = SliceAsRGB(mask, dims[0], dims[1], this->Projector, false, nullptr);
  this->ProjectorImage->SetInputData(image);
  FrameImage(this->ProjectorView, image);
  SetCaption(this->ProjectorCaption, "projector " + std::to_string(this->Projector) + " mask");
}

//------------------------------------------------------------------------------
void lfdStudioViews::UpdateRig()
{
  vtkCameraRig* rig = this->LightField ? this->LightField->GetRig() : nullptr;
  vtkCameraRig* projectors = this->LightField ? this->LightField->GetProjectors() : nullptr;
  ShowPolyData(this->RigCameras, RigCentres(rig, projectors, Palette(this->LightField)), 1.0);
  vtkNew<vtkOutlineSource> bounds;
  if (this->LightField)
  {
    bounds->SetBounds(this->Editor->GetMapper()->GetBounds());
  }
  bounds->Update();
  ShowPolyData(this->RigBounds, bounds->GetOutput(), 1.0);
  this->RigBounds->GetProperty()->SetColor(0.7, 0.7, 0.7);
  // Looking down on the ring at an angle, so it shows as a ring.
  vtkCamera* camera = this->Rig->GetActiveCamera();
  if (rig && rig->HasCylinder())
  {
    double zero[3], quarter[3];
    rig->GetAzimuthFrame(zero, quarter);
    const double* centre = rig->GetCenter();
    camera->SetFocalPoint(centre[0], centre[1], centre[2]);
    camera->SetPosition(centre[0] + zero[0], centre[1] + zero[1], centre[2] + zero[2]);
    camera->SetViewUp(rig->GetAxis());
  }
  camera->OrthogonalizeViewUp();
  camera->Elevation(35.0);
  camera->OrthogonalizeViewUp();
  this->Rig->ResetCamera();
}
