#include "vtkLightFieldSceneExporter.h"

#include "lfdFileUtilities.h"
#include "lfdParaViewFiles.h"
#include "lfdStagedFolder.h"
#include "vtkActor.h"
#include "vtkCameraFrustumSource.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkGeometryFilter.h"
#include "vtkImageData.h"
#include "vtkJSONSceneExporter.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightFieldSceneExporter);
vtkCxxSetObjectMacro(vtkLightFieldSceneExporter, SceneLogic, vtkLightFieldSceneLogic);
vtkCxxSetObjectMacro(vtkLightFieldSceneExporter, LightField, vtkLightField);

namespace
{
/// The files of an export folder (fnmatch globs): what Write() writes.
std::vector<std::string> ExportFilePatterns()
{
  return { "rig.vtp", "projectors.vtp", "cage.vtu", "lightfield.vti", "vtkjs" };
}

/// The frusta of `rig` (camera centres, image rectangles at a depth chosen
/// from the rig).
vtkSmartPointer<vtkPolyData> Frusta(vtkCameraRig* rig)
{
  vtkNew<vtkCameraFrustumSource> frusta;
  frusta->SetRig(rig);
  frusta->Update();
  return frusta->GetOutput();
}

/// An actor of `data` (drawn as its edges when `wireframe`) in `renderer`.
void AddActor(vtkRenderer* renderer, vtkPolyData* data, const double rgb[3], bool wireframe)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  if (wireframe)
  {
    actor->GetProperty()->SetRepresentationToWireframe();
  }
  renderer->AddActor(actor);
}

/// The rig (and the cage when given) as a vtk.js scene in `folder`.
bool WriteVtkJsScene(vtkPolyData* rig,
  vtkUnstructuredGrid* cage,
  const std::string& folder,
  std::string& error)
{
  vtkNew<vtkRenderer> renderer;
  const double rigColour[3] = { 0.35, 0.6, 1.0 };
  AddActor(renderer, rig, rigColour, false);
  if (cage)
  {
    vtkNew<vtkGeometryFilter> surface;
    surface->SetInputData(cage);
    surface->Update();
    const double cageColour[3] = { 1.0, 0.85, 0.2 };
    AddActor(renderer, surface->GetOutput(), cageColour, true);
  }
  // The exporter walks the window's renderers and props; nothing is drawn.
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  vtkNew<vtkJSONSceneExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->SetFileName(folder.c_str());
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(exporter);
  exporter->Write();
  errors->StopObserving();
  if (errors->HasError())
  {
    error = folder + ": " + errors->GetErrorMessage();
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkLightFieldSceneExporter::vtkLightFieldSceneExporter() = default;

//------------------------------------------------------------------------------
vtkLightFieldSceneExporter::~vtkLightFieldSceneExporter()
{
  this->SetSceneLogic(nullptr);
  this->SetLightField(nullptr);
  this->SetDirectoryName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneExporter::Write()
{
  if (!this->SceneLogic || !this->DirectoryName || !*this->DirectoryName)
  {
    vtkErrorMacro(<< (this->SceneLogic ? "no DirectoryName to export the scene into"
                                       : "no SceneLogic to export"));
    return false;
  }
  vtkLightField* lightField = this->LightField;
  vtkNew<vtkLightFieldErrorObserver> errors;
  if (!lightField)
  {
    errors->Observe(this->SceneLogic);
    lightField = this->SceneLogic->GetLightField();
    errors->StopObserving();
    if (!lightField)
    {
      vtkErrorMacro(<< errors->GetErrorMessage());
      return false;
    }
  }
  vtkSmartPointer<vtkDeformationCage> cage;
  if (this->SceneLogic->HasCage())
  {
    cage = vtkSmartPointer<vtkDeformationCage>::New();
    errors->Observe(this->SceneLogic);
    const bool valid = this->SceneLogic->GetCurrentCage(lightField, cage);
    errors->StopObserving();
    if (!valid)
    {
      vtkErrorMacro(<< errors->GetErrorMessage());
      return false;
    }
  }

  lfd::scene::StagedFolder folder;
  std::string error;
  if (!folder.Open(this->DirectoryName, "a scene export", ExportFilePatterns(), error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  const std::string path = folder.GetPath() + "/";
  vtkSmartPointer<vtkPolyData> rig = Frusta(lightField->GetRig());
  bool ok = lfd::scene::WriteXMLData(rig, path + "rig.vtp", error);
  vtkCameraRig* projectors = lightField->GetProjectors();
  if (ok && projectors && projectors->GetNumberOfViews() > 0)
  {
    ok = lfd::scene::WriteXMLData(Frusta(projectors), path + "projectors.vtp", error);
  }
  if (ok && cage)
  {
    // A plain grid: ParaView reads the arrays, not the cage class.
    vtkNew<vtkUnstructuredGrid> grid;
    grid->ShallowCopy(cage);
    ok = lfd::scene::WriteXMLData(grid, path + "cage.vtu", error);
  }
  if (ok && this->WriteLightField)
  {
    vtkNew<vtkImageData> stack;
    stack->ShallowCopy(lightField);
    ok = lfd::scene::WriteXMLData(stack, path + "lightfield.vti", error);
  }
  if (ok && this->WriteVtkJs)
  {
    ok = WriteVtkJsScene(rig, cage, path + "vtkjs", error);
  }
  if (ok && !folder.Commit(error))
  {
    error = std::string(this->DirectoryName) + ": " + error;
    ok = false;
  }
  if (!ok)
  {
    // Files are named as the user knows them: the target, not the staging.
    vtkErrorMacro(<< lfd::io::NameTargets(error));
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneLogic: " << this->SceneLogic << "\n";
  os << indent << "LightField: " << this->LightField << "\n";
  os << indent << "DirectoryName: " << (this->DirectoryName ? this->DirectoryName : "(none)")
     << "\n";
  os << indent << "WriteLightField: " << this->WriteLightField << "\n";
  os << indent << "WriteVtkJs: " << this->WriteVtkJs << "\n";
}
