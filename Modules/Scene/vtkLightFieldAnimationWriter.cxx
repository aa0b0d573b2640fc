#include "vtkLightFieldAnimationWriter.h"

#include "lfdFileUtilities.h"
#include "lfdLimits.h"
#include "lfdParaViewFiles.h"
#include "lfdStagedFolder.h"
#include "vtkCommand.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkImageFileWriter.h"
#include "vtkImageResize.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtksys/Process.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLightFieldAnimationWriter);
vtkCxxSetObjectMacro(vtkLightFieldAnimationWriter, SceneLogic, vtkLightFieldSceneLogic);
vtkCxxSetObjectMacro(vtkLightFieldAnimationWriter, LightField, vtkLightField);

namespace
{
const char* const MovieName = "animation.mp4";
const char* const ContactSheetName = "contact_sheet.png";

const char* const FrameCollectionName = "animation.pvd";
const char* const CageCollectionName = "cage.pvd";

/// The name of step `frame`'s file: `stem`_NNNN.`extension`.
std::string StepName(const char* stem, int frame, const char* extension)
{
  char name[64];
  std::snprintf(name, sizeof(name), "%s_%04d.%s", stem, frame, extension);
  return name;
}

/// The file of frame `frame` in `folder`.
std::string FramePath(const std::string& folder, int frame)
{
  return folder + "/" + StepName("frame", frame, "png");
}

/// A grid of the thumbnails, `columns` wide, the first one top left (VTK
/// images are stored bottom row first).
void AssembleContactSheet(const std::vector<vtkSmartPointer<vtkImageData>>& thumbnails,
  int columns,
  int thumb,
  vtkImageData* sheet)
{
  const int rows = (static_cast<int>(thumbnails.size()) + columns - 1) / columns;
  sheet->SetDimensions(columns * thumb, rows * thumb, 1);
  sheet->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(sheet->GetScalarPointer());
  std::fill(out, out + 3 * columns * thumb * rows * thumb, 0);
  for (std::size_t f = 0; f < thumbnails.size(); ++f)
  {
    const auto* in = static_cast<unsigned char*>(thumbnails[f]->GetScalarPointer());
    const int col = static_cast<int>(f) % columns;
    const int row = rows - 1 - static_cast<int>(f) / columns;
    for (int j = 0; j < thumb; ++j)
    {
      std::copy(in + 3 * j * thumb,
        in + 3 * (j + 1) * thumb,
        out + 3 * ((row * thumb + j) * columns * thumb + col * thumb));
    }
  }
}
}

struct vtkLightFieldAnimationWriter::Internals
{
  std::string ProgressText;
  vtkNew<vtkImageData> ContactSheet;
  std::vector<vtkSmartPointer<vtkImageData>> Thumbnails;
  lfd::scene::StagedFolder Folder;
  vtkNew<vtkLightFieldRenderer> Renderer;
  vtkNew<vtkDeformationCage> Cage;
  // The ParaView series: (scene time, file) of each frame and cage written.
  std::vector<std::pair<double, std::string>> FrameSteps;
  std::vector<std::pair<double, std::string>> CageSteps;

  /// Sets the progress and invokes ProgressEvent.
  static void Report(vtkLightFieldAnimationWriter* self, double progress, const std::string& text)
  {
    self->Progress = progress;
    self->Internal->ProgressText = text;
    self->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  }

  /// Renders frame `frame` into the renderer's output.
  static bool Render(vtkLightFieldAnimationWriter* self, vtkLightField* lightField, int frame);

  /// Writes the renderer's output as frame `frame` and keeps its thumbnail.
  static bool Save(vtkLightFieldAnimationWriter* self, int frame);

  /// Writes `image` to `path` (PNG); false after an error naming the file.
  static bool WriteImage(vtkLightFieldAnimationWriter* self,
    vtkImageData* image,
    const std::string& path);

  /// Writes frame `frame` (and its cage when `cage`) for ParaView.
  static bool SaveParaView(vtkLightFieldAnimationWriter* self, int frame, bool cage);

  /// Writes animation.pvd (and cage.pvd) listing the steps written.
  static bool WriteCollections(vtkLightFieldAnimationWriter* self);

  /// Encodes the frames with ffmpeg; false after an error or a cancel.
  static bool Encode(vtkLightFieldAnimationWriter* self, const std::string& ffmpeg);
};

//------------------------------------------------------------------------------
vtkLightFieldAnimationWriter::vtkLightFieldAnimationWriter()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkLightFieldAnimationWriter::~vtkLightFieldAnimationWriter()
{
  this->SetSceneLogic(nullptr);
  this->SetLightField(nullptr);
  this->SetDirectoryName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldAnimationWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneLogic: " << this->SceneLogic << "\n";
  os << indent << "LightField: " << this->LightField << "\n";
  os << indent << "DirectoryName: " << (this->DirectoryName ? this->DirectoryName : "(none)")
     << "\n";
  os << indent << "NumberOfFrames: " << this->NumberOfFrames << "\n";
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << "\n";
  os << indent << "WriteMovie: " << this->WriteMovie << "\n";
  os << indent << "FrameRate: " << this->FrameRate << "\n";
  os << indent << "WriteContactSheet: " << this->WriteContactSheet << "\n";
  os << indent << "ContactSheetColumns: " << this->ContactSheetColumns << "\n";
  os << indent << "ContactSheetThumbnailSize: " << this->ContactSheetThumbnailSize << "\n";
  os << indent << "WriteParaView: " << this->WriteParaView << "\n";
  os << indent << "Abort: " << this->Abort << "\n";
  os << indent << "Aborted: " << this->Aborted << "\n";
  os << indent << "NumberOfFramesWritten: " << this->NumberOfFramesWritten << "\n";
  os << indent << "MovieWritten: " << this->MovieWritten << "\n";
  os << indent << "Progress: " << this->Progress << " (" << this->Internal->ProgressText << ")\n";
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldAnimationWriter::GetContactSheet()
{
  return this->Internal->ContactSheet;
}

//------------------------------------------------------------------------------
const char* vtkLightFieldAnimationWriter::GetProgressText()
{
  return this->Internal->ProgressText.c_str();
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::IsMovieEncoderAvailable()
{
  return !vtksys::SystemTools::FindProgram("ffmpeg").empty();
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::Render(vtkLightFieldAnimationWriter* self,
  vtkLightField* lightField,
  int frame)
{
  Internals& internal = *self->Internal;
  vtkLightFieldSceneLogic* logic = self->SceneLogic;
  vtkDeformationCage* cage = nullptr;
  vtkNew<vtkLightFieldErrorObserver> errors;
  if (logic->HasCage())
  {
    // The logic's refusal (it names the scene file and the box) is said
    // once, as the writer's own.
    errors->Observe(logic);
    const double time = logic->GetAnimationTime(frame, self->NumberOfFrames);
    const bool valid = logic->GetCageAtTime(time, lightField, internal.Cage);
    errors->StopObserving();
    if (!valid)
    {
      vtkErrorWithObjectMacro(self, << lfd::io::NameTargets(errors->GetErrorMessage()));
      return false;
    }
    cage = internal.Cage;
  }
  logic->ConfigureRenderer(internal.Renderer, lightField, cage);
  if (self->Size[0] > 0)
  {
    internal.Renderer->SetWidth(self->Size[0]);
  }
  if (self->Size[1] > 0)
  {
    internal.Renderer->SetHeight(self->Size[1]);
  }
  errors->Observe(internal.Renderer);
  internal.Renderer->Update();
  errors->StopObserving();
  if (internal.Renderer->GetErrorCode() != 0 || errors->HasError())
  {
    vtkErrorWithObjectMacro(self,
      << (errors->HasError() ? std::string(errors->GetErrorMessage())
                             : "rendering frame " + std::to_string(frame) + " failed"));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::WriteImage(vtkLightFieldAnimationWriter* self,
  vtkImageData* image,
  const std::string& path)
{
  vtkNew<vtkImageFileWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  writer->Write();
  errors->StopObserving();
  if (writer->GetErrorCode() != 0 || errors->HasError())
  {
    // The file is named as the user knows it: the target, not the staged folder.
    vtkErrorWithObjectMacro(self,
      << lfd::io::NameTargets(errors->HasError() ? std::string(errors->GetErrorMessage())
                                                 : "writing " + path + " failed"));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::Save(vtkLightFieldAnimationWriter* self, int frame)
{
  vtkImageData* image = self->Internal->Renderer->GetOutput();
  if (!WriteImage(self, image, FramePath(self->Internal->Folder.GetPath(), frame)) ||
    (self->WriteParaView && !SaveParaView(self, frame, self->SceneLogic->HasCage())))
  {
    return false;
  }
  const int thumb = self->ContactSheetThumbnailSize;
  vtkNew<vtkImageResize> resize;
  resize->SetInputData(image);
  resize->SetOutputDimensions(thumb, thumb, 1);
  resize->Update();
  auto thumbnail = vtkSmartPointer<vtkImageData>::New();
  thumbnail->DeepCopy(resize->GetOutput());
  self->Internal->Thumbnails.push_back(thumbnail);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::SaveParaView(vtkLightFieldAnimationWriter* self,
  int frame,
  bool cage)
{
  Internals& internal = *self->Internal;
  const double time = self->SceneLogic->GetAnimationTime(frame, self->NumberOfFrames);
  const std::string folder = internal.Folder.GetPath() + "/";
  std::string error;
  const std::string frameName = StepName("frame", frame, "vti");
  bool ok = lfd::scene::WriteXMLData(internal.Renderer->GetOutput(), folder + frameName, error);
  internal.FrameSteps.emplace_back(time, frameName);
  if (ok && cage)
  {
    // The cage this frame was rendered through, as a plain grid.
    const std::string cageName = StepName("cage", frame, "vtu");
    vtkNew<vtkUnstructuredGrid> grid;
    grid->ShallowCopy(internal.Cage);
    ok = lfd::scene::WriteXMLData(grid, folder + cageName, error);
    internal.CageSteps.emplace_back(time, cageName);
  }
  if (!ok)
  {
    vtkErrorWithObjectMacro(self, << lfd::io::NameTargets(error));
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::WriteCollections(vtkLightFieldAnimationWriter* self)
{
  Internals& internal = *self->Internal;
  const std::string folder = internal.Folder.GetPath() + "/";
  std::string error;
  const bool ok =
    lfd::scene::WriteCollection(folder + FrameCollectionName, internal.FrameSteps, error) &&
    (internal.CageSteps.empty() ||
      lfd::scene::WriteCollection(folder + CageCollectionName, internal.CageSteps, error));
  if (!ok)
  {
    vtkErrorWithObjectMacro(self, << lfd::io::NameTargets(error));
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::Encode(vtkLightFieldAnimationWriter* self,
  const std::string& ffmpeg)
{
  const std::string folder = self->Internal->Folder.GetPath();
  const std::string movie = folder + "/" + MovieName;
  const std::string rate = std::to_string(self->FrameRate);
  const std::string frames = folder + "/frame_%04d.png";
  // H.264 in yuv420p, which every player decodes; yuv420p halves the chroma
  // resolution, so odd sizes are padded to even ones. No shell: any path works.
  const char* command[] = { ffmpeg.c_str(),
    "-nostdin",
    "-y",
    "-loglevel",
    "error",
    "-framerate",
    rate.c_str(),
    "-i",
    frames.c_str(),
    "-vf",
    "pad=ceil(iw/2)*2:ceil(ih/2)*2",
    "-c:v",
    "libx264",
    "-pix_fmt",
    "yuv420p",
    movie.c_str(),
    nullptr };
  vtksysProcess* process = vtksysProcess_New();
  vtksysProcess_SetCommand(process, command);
  vtksysProcess_SetOption(process, vtksysProcess_Option_HideWindow, 1);
  vtksysProcess_Execute(process);
  std::string output;
  bool cancelled = false;
  for (;;)
  {
    char* data = nullptr;
    int length = 0;
    double timeout = 0.1;
    const int pipe = vtksysProcess_WaitForData(process, &data, &length, &timeout);
    if (pipe == vtksysProcess_Pipe_STDOUT || pipe == vtksysProcess_Pipe_STDERR)
    {
      output.append(data, static_cast<std::size_t>(length));
    }
    else if (pipe == vtksysProcess_Pipe_Timeout)
    {
      // Repeated so that a progress dialog stays responsive and can cancel.
      Report(self, self->Progress, self->Internal->ProgressText);
      if (self->Abort && !cancelled)
      {
        vtksysProcess_Kill(process);
        cancelled = true;
      }
    }
    else
    {
      break;
    }
  }
  vtksysProcess_WaitForExit(process, nullptr);
  const bool exited = vtksysProcess_GetState(process) == vtksysProcess_State_Exited &&
    vtksysProcess_GetExitValue(process) == 0;
  const std::string why = vtksysProcess_GetState(process) == vtksysProcess_State_Error
    ? vtksysProcess_GetErrorString(process)
    : output.substr(0, output.find('\n'));
  vtksysProcess_Delete(process);
  if (cancelled)
  {
    self->Aborted = true;
    return false;
  }
  if (!exited)
  {
    vtkErrorWithObjectMacro(self,
      << "ffmpeg could not encode '" << lfd::io::NameTargets(movie) << "'"
      << (why.empty() ? std::string() : ": " + why));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Write()
{
  Internals& internal = *this->Internal;
  this->Abort = false;
  this->Aborted = false;
  this->NumberOfFramesWritten = 0;
  this->MovieWritten = false;
  internal.Thumbnails.clear();
  internal.FrameSteps.clear();
  internal.CageSteps.clear();
  internal.ContactSheet->Initialize();
  if (!this->SceneLogic || !this->DirectoryName || !*this->DirectoryName)
  {
    vtkErrorMacro(<< (this->SceneLogic ? "no DirectoryName to write the animation into"
                                       : "no SceneLogic to animate"));
    return false;
  }
  for (const int size : this->Size)
  {
    if (size < 0 || size > lfd::MaximumRenderSize)
    {
      vtkErrorMacro(<< this->DirectoryName << ": frame size " << size << " is not 0 (the scene's) "
                    << "or in [1, " << lfd::MaximumRenderSize << "]");
      return false;
    }
  }
  vtkLightField* lightField = this->LightField;
  if (!lightField)
  {
    vtkNew<vtkLightFieldErrorObserver> errors;
    errors->Observe(this->SceneLogic);
    lightField = this->SceneLogic->GetLightField();
    errors->StopObserving();
    if (!lightField)
    {
      vtkErrorMacro(<< errors->GetErrorMessage());
      return false;
    }
  }
  std::string error;
  if (!internal.Folder.Open(
        this->DirectoryName, "an animation export", lfd::scene::AnimationFilePatterns(), error))
  {
    vtkErrorMacro(<< error);
    return false;
  }

  const std::string ffmpeg = this->WriteMovie ? vtksys::SystemTools::FindProgram("ffmpeg") : "";
  const int frames = this->NumberOfFrames;
  const double steps = frames + (ffmpeg.empty() ? 0 : 1);
  this->Progress = 0.0;
  internal.ProgressText.clear();
  this->InvokeEvent(vtkCommand::StartEvent);
  // `failed`: an error was reported; a cancel sets Aborted instead.
  bool failed = false;
  for (int f = 0; !failed && f < frames; ++f)
  {
    if (this->Abort)
    {
      this->Aborted = true;
      break;
    }
    failed = !Internals::Render(this, lightField, f) || !Internals::Save(this, f);
    if (!failed)
    {
      this->NumberOfFramesWritten = f + 1;
      Internals::Report(
        this, (f + 1) / steps, "frame " + std::to_string(f + 1) + "/" + std::to_string(frames));
    }
  }
  if (!failed && !this->Aborted)
  {
    AssembleContactSheet(internal.Thumbnails,
      this->ContactSheetColumns,
      this->ContactSheetThumbnailSize,
      internal.ContactSheet);
    failed =
      (this->WriteContactSheet &&
        !Internals::WriteImage(
          this, internal.ContactSheet, internal.Folder.GetPath() + "/" + ContactSheetName)) ||
      (this->WriteParaView && !Internals::WriteCollections(this));
  }
  if (!failed && !this->Aborted && !this->Abort && !ffmpeg.empty())
  {
    Internals::Report(this, frames / steps, std::string("encoding ") + MovieName);
    this->MovieWritten = Internals::Encode(this, ffmpeg);
    failed = !this->MovieWritten && !this->Aborted;
  }
  this->Aborted = this->Aborted || (!failed && this->Abort);
  bool complete = !failed && !this->Aborted;
  if (complete && !internal.Folder.Commit(error))
  {
    vtkErrorMacro(<< this->DirectoryName << ": " << error);
    complete = false;
  }
  internal.Folder.Discard();
  if (complete)
  {
    Internals::Report(this, 1.0, "done");
  }
  this->InvokeEvent(vtkCommand::EndEvent);
  return complete;
}
