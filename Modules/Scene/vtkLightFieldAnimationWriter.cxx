#include "vtkLightFieldAnimationWriter.h"

#include "lfdFileUtilities.h"
#include "lfdLimits.h"
#include "lfdParaViewFiles.h"
#include "lfdProcessAgreement.h"
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
#include "vtkMultiProcessController.h"
#include "vtkMultiProcessStream.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtksys/Process.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cstdio>
#include <future>
#include <string>
#include <thread>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLightFieldAnimationWriter);
vtkCxxSetObjectMacro(vtkLightFieldAnimationWriter, SceneLogic, vtkLightFieldSceneLogic);
vtkCxxSetObjectMacro(vtkLightFieldAnimationWriter, LightField, vtkLightField);
vtkCxxSetObjectMacro(vtkLightFieldAnimationWriter, Controller, vtkMultiProcessController);

namespace
{
const char* const MovieName = "animation.mp4";
const char* const ContactSheetName = "contact_sheet.png";

const char* const FrameCollectionName = "animation.pvd";
const char* const CageCollectionName = "cage.pvd";

// Message tags between the processes of one export (lfdProcessAgreement uses 28410).
const int OutcomeTag = 28411;
const int ThumbnailTag = 28412;

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
  /// Where the frames go: the staged folder of process 0.
  std::string FolderPath;
  vtkNew<vtkLightFieldRenderer> Renderer;
  vtkNew<vtkDeformationCage> Cage;
  /// Process 0's ffmpeg ("" when no movie is encoded), and the progress steps.
  std::string Ffmpeg;
  double Steps = 1.0;
  /// A frame written: its error ("" when written), its thumbnail.
  struct Saved
  {
    std::string Error;
    vtkSmartPointer<vtkImageData> Thumbnail;
  };
  /**
   * This process's frame of the round from `First` (-1: none): written and
   * its thumbnail made on a thread of its own (Saving) while the next
   * round renders, or its refusal to render (Error).
   */
  struct Round
  {
    int First = -1;
    std::string Error;
    std::future<Saved> Saving;
  };

  /// Sets the progress and invokes ProgressEvent.
  static void Report(vtkLightFieldAnimationWriter* self, double progress, const std::string& text)
  {
    self->Progress = progress;
    self->Internal->ProgressText = text;
    self->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  }

  /// This process's index and the number of processes (0 and 1 without a controller).
  static int Rank(vtkLightFieldAnimationWriter* self)
  {
    return self->Controller ? self->Controller->GetLocalProcessId() : 0;
  }
  static int Processes(vtkLightFieldAnimationWriter* self)
  {
    return self->Controller ? self->Controller->GetNumberOfProcesses() : 1;
  }

  /// "" when the settings can be exported (and, on process 0, the folder is
  /// staged), else the refusal; sets the light field to render.
  static std::string CheckSettings(vtkLightFieldAnimationWriter* self, vtkLightField*& lightField);

  /// Renders frame `frame` into the renderer's output; "" or the error.
  static std::string Render(vtkLightFieldAnimationWriter* self,
    vtkLightField* lightField,
    int frame);

  /**
   * This process's frame of the round from `first` rendered, then written
   * on a thread of its own (Save): the next round renders meanwhile.
   */
  static Round RenderRound(vtkLightFieldAnimationWriter* self,
    vtkLightField* lightField,
    int first);

  /**
   * Writes `image` as frame `frame` into `folder` (PNG; for ParaView too
   * when `paraView`, with `cage`, the cage it was rendered through, unless
   * nullptr) and makes its `thumb` x `thumb` thumbnail. Touches nothing
   * else: it runs while the next frame renders.
   */
  static Saved Save(const std::string& folder,
    int frame,
    vtkImageData* image,
    bool paraView,
    vtkUnstructuredGrid* cage,
    int thumb);

  /// Writes `image` to `path` (PNG); "" or the error naming the file.
  static std::string WriteImage(vtkImageData* image, const std::string& path);

  /// Writes animation.pvd (and cage.pvd) listing every frame (and cage).
  static bool WriteCollections(vtkLightFieldAnimationWriter* self);

  /**
   * The round of frames [first, first + Processes()) rendered and written
   * (`round`, this process's: waited for), one a process: process 0
   * collects the outcomes in frame order (thumbnails, progress, the first
   * error, which it reports) and every process learns whether to go on.
   * False when the export stops (an error or a cancel).
   */
  static bool FinishRound(vtkLightFieldAnimationWriter* self, Round& round);

  /// Encodes the frames with ffmpeg; false after an error or a cancel.
  static bool Encode(vtkLightFieldAnimationWriter* self, const std::string& ffmpeg);

  /// Process 0's closing steps: contact sheet, collections, movie, rename.
  static bool Finish(vtkLightFieldAnimationWriter* self);
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
  this->SetController(nullptr);
  this->SetDirectoryName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldAnimationWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneLogic: " << this->SceneLogic << "\n";
  os << indent << "LightField: " << this->LightField << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
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
std::string vtkLightFieldAnimationWriter::Internals::Render(vtkLightFieldAnimationWriter* self,
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
      return lfd::io::NameTargets(errors->GetErrorMessage());
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
    return errors->HasError() ? std::string(errors->GetErrorMessage())
                              : "rendering frame " + std::to_string(frame) + " failed";
  }
  return std::string();
}

//------------------------------------------------------------------------------
vtkLightFieldAnimationWriter::Internals::Round vtkLightFieldAnimationWriter::Internals::RenderRound(
  vtkLightFieldAnimationWriter* self,
  vtkLightField* lightField,
  int first)
{
  Internals& internal = *self->Internal;
  Round round;
  round.First = first;
  const int frame = first + Rank(self);
  if (frame >= self->NumberOfFrames)
  {
    return round; // (no frame for this process in the last round)
  }
  round.Error = Render(self, lightField, frame);
  if (!round.Error.empty())
  {
    return round;
  }
  // What the thread writes is its own: the frame's arrays (the renderer
  // renders the next frame into new ones while they are held) and a copy
  // of the cage (the next frame's is computed into internal.Cage).
  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(internal.Renderer->GetOutput());
  vtkSmartPointer<vtkUnstructuredGrid> cage;
  if (self->WriteParaView && self->SceneLogic->HasCage())
  {
    cage = vtkSmartPointer<vtkUnstructuredGrid>::New();
    cage->DeepCopy(internal.Cage);
  }
  round.Saving = std::async(std::launch::async,
    [folder = internal.FolderPath,
      frame,
      image,
      paraView = self->WriteParaView,
      cage,
      thumb = self->ContactSheetThumbnailSize]
    { return Save(folder, frame, image, paraView, cage, thumb); });
  return round;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldAnimationWriter::Internals::WriteImage(vtkImageData* image,
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
    return lfd::io::NameTargets(
      errors->HasError() ? std::string(errors->GetErrorMessage()) : "writing " + path + " failed");
  }
  return std::string();
}

//------------------------------------------------------------------------------
vtkLightFieldAnimationWriter::Internals::Saved vtkLightFieldAnimationWriter::Internals::Save(
  const std::string& folder,
  int frame,
  vtkImageData* image,
  bool paraView,
  vtkUnstructuredGrid* cage,
  int thumb)
{
  Saved saved;
  saved.Error = WriteImage(image, FramePath(folder, frame));
  if (saved.Error.empty() && paraView)
  {
    std::string error;
    bool ok =
      lfd::scene::WriteXMLData(image, folder + "/" + StepName("frame", frame, "vti"), error);
    if (ok && cage)
    {
      // The cage this frame was rendered through, as a plain grid.
      ok = lfd::scene::WriteXMLData(cage, folder + "/" + StepName("cage", frame, "vtu"), error);
    }
    if (!ok)
    {
      saved.Error = lfd::io::NameTargets(error);
    }
  }
  if (!saved.Error.empty())
  {
    return saved;
  }
  vtkNew<vtkImageResize> resize;
  resize->SetInputData(image);
  resize->SetOutputDimensions(thumb, thumb, 1);
  resize->Update();
  saved.Thumbnail = vtkSmartPointer<vtkImageData>::New();
  saved.Thumbnail->DeepCopy(resize->GetOutput());
  return saved;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::WriteCollections(vtkLightFieldAnimationWriter* self)
{
  // The steps of every frame, whichever process wrote it.
  std::vector<std::pair<double, std::string>> frameSteps, cageSteps;
  for (int frame = 0; frame < self->NumberOfFrames; ++frame)
  {
    const double time = self->SceneLogic->GetAnimationTime(frame, self->NumberOfFrames);
    frameSteps.emplace_back(time, StepName("frame", frame, "vti"));
    if (self->SceneLogic->HasCage())
    {
      cageSteps.emplace_back(time, StepName("cage", frame, "vtu"));
    }
  }
  const std::string folder = self->Internal->FolderPath + "/";
  std::string error;
  const bool ok = lfd::scene::WriteCollection(folder + FrameCollectionName, frameSteps, error) &&
    (cageSteps.empty() ||
      lfd::scene::WriteCollection(folder + CageCollectionName, cageSteps, error));
  if (!ok)
  {
    vtkErrorWithObjectMacro(self, << lfd::io::NameTargets(error));
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::FinishRound(vtkLightFieldAnimationWriter* self,
  Round& round)
{
  Internals& internal = *self->Internal;
  const int first = round.First;
  const Saved saved = round.Saving.valid() ? round.Saving.get() : Saved{ round.Error, nullptr };
  vtkMultiProcessController* controller = self->Controller;
  const int frames = self->NumberOfFrames;
  const int rank = Rank(self);
  const int thumb = self->ContactSheetThumbnailSize;
  const vtkIdType thumbBytes = 3 * static_cast<vtkIdType>(thumb) * thumb;
  int goOn = 1;
  if (rank != 0)
  {
    vtkMultiProcessStream stream;
    stream << saved.Error << self->Abort;
    controller->Send(stream, 0, OutcomeTag);
    if (saved.Thumbnail)
    {
      controller->Send(static_cast<unsigned char*>(saved.Thumbnail->GetScalarPointer()),
        thumbBytes,
        0,
        ThumbnailTag);
    }
    controller->Broadcast(&goOn, 1, 0);
    return goOn != 0;
  }
  std::string error;
  bool abort = false;
  for (int process = 0; process < Processes(self); ++process)
  {
    std::string theirs = saved.Error;
    bool theirAbort = self->Abort;
    vtkSmartPointer<vtkImageData> thumbnail = saved.Thumbnail;
    const bool rendered = first + process < frames;
    if (process > 0)
    {
      vtkMultiProcessStream stream;
      controller->Receive(stream, process, OutcomeTag);
      stream >> theirs >> theirAbort;
      thumbnail = nullptr;
      if (rendered && theirs.empty())
      {
        thumbnail = vtkSmartPointer<vtkImageData>::New();
        thumbnail->SetDimensions(thumb, thumb, 1);
        thumbnail->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
        controller->Receive(static_cast<unsigned char*>(thumbnail->GetScalarPointer()),
          thumbBytes,
          process,
          ThumbnailTag);
      }
    }
    abort = abort || theirAbort;
    if (!rendered || !error.empty())
    {
      continue;
    }
    if (!theirs.empty())
    {
      error = theirs;
      continue;
    }
    internal.Thumbnails.push_back(thumbnail);
    self->NumberOfFramesWritten = first + process + 1;
    Report(self,
      self->NumberOfFramesWritten / internal.Steps,
      "frame " + std::to_string(self->NumberOfFramesWritten) + "/" + std::to_string(frames));
  }
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(self, << error);
  }
  // An observer of the progress may have cancelled.
  self->Aborted = error.empty() && (abort || self->Abort);
  goOn = error.empty() && !self->Aborted;
  if (controller && Processes(self) > 1)
  {
    controller->Broadcast(&goOn, 1, 0);
  }
  return goOn != 0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldAnimationWriter::Internals::Encode(vtkLightFieldAnimationWriter* self,
  const std::string& ffmpeg)
{
  const std::string folder = self->Internal->Folder.GetPath();
  const std::string movie = folder + "/" + MovieName;
  const std::string rate = std::to_string(self->FrameRate);
  const std::string frames = folder + "/frame_%04d.png";
  // x264 writes its thread count into the movie and takes it from the cores
  // this process may use: under mpirun process 0 is bound to one core. The
  // machine's cores give the same movie either way.
  const std::string threads = std::to_string(std::max(1U, std::thread::hardware_concurrency()));
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
    "-threads",
    threads.c_str(),
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
bool vtkLightFieldAnimationWriter::Internals::Finish(vtkLightFieldAnimationWriter* self)
{
  Internals& internal = *self->Internal;
  AssembleContactSheet(internal.Thumbnails,
    self->ContactSheetColumns,
    self->ContactSheetThumbnailSize,
    internal.ContactSheet);
  const std::string error = self->WriteContactSheet
    ? WriteImage(internal.ContactSheet, internal.FolderPath + "/" + ContactSheetName)
    : std::string();
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(self, << error);
    return false;
  }
  if (self->WriteParaView && !WriteCollections(self))
  {
    return false;
  }
  if (!self->Abort && !internal.Ffmpeg.empty())
  {
    Report(self, self->NumberOfFrames / internal.Steps, std::string("encoding ") + MovieName);
    self->MovieWritten = Encode(self, internal.Ffmpeg);
    if (!self->MovieWritten)
    {
      return false;
    }
  }
  if (self->Abort)
  {
    self->Aborted = true;
    return false;
  }
  std::string why;
  if (!internal.Folder.Commit(why))
  {
    vtkErrorWithObjectMacro(self, << self->DirectoryName << ": " << why);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldAnimationWriter::Internals::CheckSettings(
  vtkLightFieldAnimationWriter* self,
  vtkLightField*& lightField)
{
  const bool root = Rank(self) == 0;
  if (!self->SceneLogic)
  {
    return "no SceneLogic to animate";
  }
  if (root && (!self->DirectoryName || !*self->DirectoryName))
  {
    return "no DirectoryName to write the animation into";
  }
  for (const int size : self->Size)
  {
    if (size < 0 || size > lfd::MaximumRenderSize)
    {
      return (self->DirectoryName ? self->DirectoryName : std::string()) + ": frame size " +
        std::to_string(size) + " is not 0 (the scene's) or in [1, " +
        std::to_string(lfd::MaximumRenderSize) + "]";
    }
  }
  lightField = self->LightField;
  if (!lightField)
  {
    vtkNew<vtkLightFieldErrorObserver> errors;
    errors->Observe(self->SceneLogic);
    lightField = self->SceneLogic->GetLightField();
    errors->StopObserving();
    if (!lightField)
    {
      return errors->GetErrorMessage();
    }
  }
  std::string error;
  if (root &&
    !self->Internal->Folder.Open(
      self->DirectoryName, "an animation export", lfd::scene::AnimationFilePatterns(), error))
  {
    return error;
  }
  return std::string();
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
  internal.ContactSheet->Initialize();
  const int rank = Internals::Rank(this);
  const int processes = Internals::Processes(this);
  vtkLightField* lightField = nullptr;
  // Every process goes on, or all stop with the first refusal, said once.
  const std::string error =
    lfd::scene::AgreeOnError(this->Controller, Internals::CheckSettings(this, lightField));
  if (!error.empty())
  {
    if (rank == 0)
    {
      vtkErrorMacro(<< error);
    }
    internal.Folder.Discard();
    return false;
  }
  internal.FolderPath = lfd::scene::ShareText(this->Controller, internal.Folder.GetPath());
  internal.Ffmpeg =
    rank == 0 && this->WriteMovie ? vtksys::SystemTools::FindProgram("ffmpeg") : std::string();
  const int frames = this->NumberOfFrames;
  internal.Steps = frames + (internal.Ffmpeg.empty() ? 0 : 1);
  this->Progress = 0.0;
  internal.ProgressText.clear();
  this->InvokeEvent(vtkCommand::StartEvent);
  // A cancel from a StartEvent observer of process 0 stops before any frame.
  int goOn = !this->Abort;
  if (processes > 1)
  {
    this->Controller->Broadcast(&goOn, 1, 0);
  }
  this->Aborted = !goOn;
  // Each round's frame is written, and its thumbnail made, on a thread of
  // its own while the next round renders; the round is finished (progress,
  // errors, cancel) once written. (The demo's swim, 96 frames on 2 cores:
  // 51-53 -> 41-44 ms a frame: the PNG compression and the thumbnail, on
  // one core, had kept the next frame from rendering on both.)
  Internals::Round written;
  for (int first = 0; goOn && first < frames; first += processes)
  {
    Internals::Round rendered = Internals::RenderRound(this, lightField, first);
    if (written.First >= 0)
    {
      goOn = Internals::FinishRound(this, written);
    }
    written = std::move(rendered);
  }
  if (written.First >= 0)
  {
    if (goOn)
    {
      goOn = Internals::FinishRound(this, written);
    }
    else if (written.Saving.valid())
    {
      written.Saving.wait(); // (rendered after the stop: dropped with the folder)
    }
  }
  bool complete = goOn;
  if (rank == 0)
  {
    complete = complete && Internals::Finish(this);
    internal.Folder.Discard();
  }
  if (processes > 1)
  {
    // Every process returns process 0's outcome.
    int outcome[4] = { complete, this->Aborted, this->MovieWritten, this->NumberOfFramesWritten };
    this->Controller->Broadcast(outcome, 4, 0);
    complete = outcome[0] != 0;
    this->Aborted = outcome[1] != 0;
    this->MovieWritten = outcome[2] != 0;
    this->NumberOfFramesWritten = outcome[3];
  }
  if (complete && rank == 0)
  {
    Internals::Report(this, 1.0, "done");
  }
  this->InvokeEvent(vtkCommand::EndEvent);
  return complete;
}
