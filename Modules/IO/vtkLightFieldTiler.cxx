#include "vtkLightFieldTiler.h"

#include "lfdFileUtilities.h"
#include "lfdLightFieldManifest.h"
#include "vtkDataArray.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightFieldTiler);

//------------------------------------------------------------------------------
vtkLightFieldTiler::vtkLightFieldTiler() = default;

//------------------------------------------------------------------------------
vtkLightFieldTiler::~vtkLightFieldTiler()
{
  this->SetFileName(nullptr);
  this->SetDirectory(nullptr);
}

//------------------------------------------------------------------------------
bool vtkLightFieldTiler::Write()
{
  if (!this->Directory || !*this->Directory)
  {
    vtkErrorMacro("vtkLightFieldTiler: no Directory set");
    return false;
  }
  const std::string directory = lfd::io::TrimSeparators(this->Directory);
  // The manifest, the rig and the projector masks, without any pass: what
  // the manifest of the tiled dataset is built from.
  vtkNew<vtkLightFieldReader> reader;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(reader);
  reader->SetFileName(this->FileName);
  reader->ReadNoPasses();
  reader->Update();
  if (errors->HasError())
  {
    vtkErrorMacro(<< errors->GetErrorMessage());
    return false;
  }
  vtkLightField* plan = reader->GetOutput();
  const int views = plan->GetNumberOfViews();

  // Each image is read into its pass's one-view array just before it is
  // written (ImageFile::Read), in the order vtkLightFieldWriter writes them.
  std::vector<int> passes;
  std::vector<vtkSmartPointer<vtkDataArray>> pixels;
  std::vector<lfd::io::ImageFile> files;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (!reader->GetImageFileName(pass, 0))
    {
      continue;
    }
    passes.push_back(pass);
    pixels.push_back(vtkSmartPointer<vtkDataArray>::Take(
      vtkDataArray::CreateDataArray(vtkLightField::GetPassScalarType(pass))));
    vtkDataArray* view = pixels.back();
    for (int v = 0; v < views; ++v)
    {
      files.push_back({ lfd::io::LightFieldImageName(pass, v, true),
        view,
        0,
        plan->GetWidth(),
        plan->GetHeight(),
        [&reader, &errors, pass, v, view](std::string& error)
        {
          if (!reader->ReadView(pass, v, view))
          {
            error = errors->GetErrorMessage();
            return false;
          }
          return true;
        } });
    }
  }
  const lfd::io::Json manifest = lfd::io::BuildLightFieldManifest(plan, passes, views, files, true);
  const lfd::io::WriteFailure failure = lfd::io::WriteLightFieldDataset(directory,
    manifest,
    files,
    this->TileSize,
    [this](double done) { this->InvokeEvent(vtkCommand::ProgressEvent, &done); });
  if (failure.Code != 0)
  {
    vtkErrorMacro(<< failure.Message);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldTiler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Directory: " << (this->Directory ? this->Directory : "(none)") << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
}
