#include "lfdStudioViews.h"

#include "vtkCamera.h"
#include "vtkDeformationCage.h"
#include "vtkGantryCameraView.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkProjectorView.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRigView.h"
#include "vtkTextActor.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <initializer_list>

namespace
{
/// The colour of label `label` in `palette` (vtkGantryCameraView::GetShownPalette).
void LabelColour(vtkUnsignedCharArray* palette, int label, unsigned char rgb[3])
{
  const vtkIdType entry = std::clamp<vtkIdType>(label, 0, palette->GetNumberOfTuples() - 1);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = palette->GetTypedComponent(entry, c);
  }
}

/// The number of projector masks of `lightField` (0 without one).
int ProjectorCount(vtkLightField* lightField)
{
  vtkImageData* masks = lightField ? lightField->GetProjectorMasks() : nullptr;
  return masks ? masks->GetDimensions()[2] : 0;
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
  this->Camera->SetRenderer(this->CameraRenderer);
  this->Projector->SetRenderer(this->ProjectorRenderer);
  this->Rig->SetRenderer(this->RigRenderer);
  for (vtkRenderer* renderer :
    { this->CameraRenderer.Get(), this->ProjectorRenderer.Get(), this->RigRenderer.Get() })
  {
    renderer->SetBackground(0.12, 0.12, 0.14);
  }
  // The rig and projector views take clicks and strokes in their viewports
  // ahead of the camera style; SetLayout() enables them when shown.
  this->Rig->SetInteractor(window->GetInteractor());
  this->Projector->SetInteractor(window->GetInteractor());
  this->Projector->AddObserver(
    vtkProjectorView::MaskStrokeEvent, this, &lfdStudioViews::ApplyStroke);
  this->SetLayout(MAIN_ONLY);
}

//------------------------------------------------------------------------------
lfdStudioViews::~lfdStudioViews()
{
  this->Rig->Off();
  this->Projector->Off();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetLayout(int layout)
{
  this->CurrentLayout = std::clamp(layout, 0, static_cast<int>(FOUR_UP));
  for (vtkRenderer* renderer : { this->Main.Get(),
         this->CameraRenderer.Get(),
         this->ProjectorRenderer.Get(),
         this->RigRenderer.Get() })
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
    this->CameraRenderer->SetViewport(0.5, 0.0, 1.0, 1.0);
    this->Window->AddRenderer(this->CameraRenderer);
  }
  else
  {
    // Four-up as in ParaView / 3D Slicer: main top left, camera top right,
    // projector bottom left, rig bottom right.
    this->Main->SetViewport(0.0, 0.5, 0.5, 1.0);
    this->CameraRenderer->SetViewport(0.5, 0.5, 1.0, 1.0);
    this->ProjectorRenderer->SetViewport(0.0, 0.0, 0.5, 0.5);
    this->RigRenderer->SetViewport(0.5, 0.0, 1.0, 0.5);
    this->Window->AddRenderer(this->CameraRenderer);
    this->Window->AddRenderer(this->ProjectorRenderer);
    this->Window->AddRenderer(this->RigRenderer);
  }
  const bool fourUp = this->CurrentLayout == FOUR_UP;
  this->Rig->SetEnabled(fourUp);
  this->Projector->SetEnabled(fourUp);
  // The shown views fit their viewports' new aspect ratios (a renderer out
  // of the window has none).
  if (this->CurrentLayout != MAIN_ONLY)
  {
    this->Camera->ResetCamera();
  }
  if (fourUp)
  {
    this->Projector->ResetCamera();
    this->Rig->ResetCamera();
  }
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
  for (vtkCalibrationView* view :
    std::initializer_list<vtkCalibrationView*>{ this->Camera, this->Projector, this->Rig })
  {
    view->SetLightField(lightField);
  }
  if (lightField)
  {
    this->Rig->SetObjectBounds(this->Editor->GetMapper()->GetBounds());
  }
  else
  {
    this->Rig->ClearObjectBounds();
  }
  // A synthetic capture's object, re-rendered live under the painted masks.
  this->Projector->SimulateRecordedObject();
  this->SetCameraView(this->GetCameraView());
  this->SetProjector(this->GetProjector());
  this->SetLayout(this->CurrentLayout);
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
  this->Camera->SetCage(cage);
  this->Rig->SetCage(cage);
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
  view = std::clamp(view, 0, std::max(views - 1, 0));
  this->Camera->SetView(view);
  this->Projector->SetSimulationView(view);
  this->Rig->SetCurrentView(this->LightField ? view : -1);
}

//------------------------------------------------------------------------------
int lfdStudioViews::GetCameraView()
{
  return this->Camera->GetView();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetPass(int pass)
{
  this->Camera->SetPass(std::clamp(pass, 0, static_cast<int>(vtkGantryCameraView::NORMALISED)));
}

//------------------------------------------------------------------------------
int lfdStudioViews::GetPass()
{
  return this->Camera->GetPass();
}

//------------------------------------------------------------------------------
void lfdStudioViews::SetProjector(int projector)
{
  const int count = ProjectorCount(this->LightField);
  this->Projector->SetProjector(std::clamp(projector, 0, std::max(count - 1, 0)));
}

//------------------------------------------------------------------------------
int lfdStudioViews::GetProjector()
{
  return this->Projector->GetProjector();
}

//------------------------------------------------------------------------------
void lfdStudioViews::GetLabelColour(int label, unsigned char rgb[3])
{
  vtkNew<vtkUnsignedCharArray> palette;
  vtkGantryCameraView::GetShownPalette(this->LightField, this->Logic->GetCage(), palette);
  LabelColour(palette, label, rgb);
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
double lfdStudioViews::GetCoverage()
{
  return this->LightField ? this->Camera->GetCoverage() : -1.0;
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
vtkGantryCameraView* lfdStudioViews::GetGantryCameraView()
{
  return this->Camera;
}

//------------------------------------------------------------------------------
vtkProjectorView* lfdStudioViews::GetProjectorView()
{
  return this->Projector;
}

//------------------------------------------------------------------------------
vtkRigView* lfdStudioViews::GetRigView()
{
  return this->Rig;
}

//------------------------------------------------------------------------------
void lfdStudioViews::ApplyStroke(vtkObject*, unsigned long, void*)
{
  // A refused stroke is reported by the logic; the view then shows the
  // light field's mask again.
  this->Logic->SetProjectorMask(this->Projector->GetProjector(), this->Projector->GetStrokeMask());
}
