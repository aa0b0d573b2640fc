/**
 * @class   vtkLightFieldAnimationWriter
 * @brief   renders a scene's keyframed animation into a folder of frames,
 * an MP4 and a contact sheet, with progress and cancel
 *
 * The one animation export of every front end: `lfd animate`, `lfd demo`,
 * the Studio's export dialog and Python all use it. Write() renders
 * NumberOfFrames frames of the scene of a vtkLightFieldSceneLogic, evenly
 * from its first to its last keyframe time
 * (vtkLightFieldSceneLogic::GetAnimationTime), each frame through the
 * logic's cage at that time (Catmull-Rom through the keyframes,
 * GetCageAtTime) and the scene's view (ConfigureRenderer), so a frame is
 * bitwise the image a vtkLightFieldRenderer configured by the logic
 * renders at the same time: the deformed light field of the paper
 * (Chen et al. 2005, Sec. 5, Fig. 13's swimming fish).
 *
 * The folder DirectoryName receives:
 * - frame_NNNN.png (frame_0000.png first; 4 digits, more past 9999), the
 *   scene's image size unless SetSize() overrides it;
 * - animation.mp4 when WriteMovie is on (the default) and `ffmpeg` is found
 *   on the PATH: H.264 (libx264), pixel format yuv420p (what players
 *   expect), FrameRate frames per second; yuv420p needs even sizes, so an
 *   odd width or height is padded with one black column or row
 *   (`pad=ceil(iw/2)*2:ceil(ih/2)*2`). Without ffmpeg no movie is written
 *   and GetMovieWritten() is false; it is not an error;
 * - contact_sheet.png when WriteContactSheet is on: a grid of
 *   ContactSheetColumns thumbnails of ContactSheetThumbnailSize pixels,
 *   first frame top left. The sheet is assembled in every Write()
 *   (GetContactSheet()) for a caller that writes it elsewhere;
 * - for ParaView, when WriteParaView is on (default off): frame_NNNN.vti
 *   (each frame with its "Radiance", "Label" and "Depth" arrays) listed
 *   with their scene times in animation.pvd, and, when the scene has a
 *   cage, the cage of each frame, cage_NNNN.vtu (deformed points,
 *   "RestPosition", "Label"), listed in cage.pvd: open both in ParaView
 *   and play them together (lfdParaViewFiles.h).
 *
 * Nothing is ever half-written: the folder is staged under a temporary
 * sibling name and renamed onto DirectoryName only when complete
 * (lfd::scene::StagedFolder). An existing DirectoryName may hold only such
 * files (a folder of the user's is refused) and is untouched unless the
 * export succeeds.
 *
 * Progress: StartEvent, then a ProgressEvent (call data: a double in
 * [0, 1]; GetProgress(), GetProgressText()) after each frame ("frame 3/48"),
 * before the encoding ("encoding animation.mp4", repeated about every 0.1 s
 * while ffmpeg runs, so that a progress dialog stays responsive) and at the
 * end ("done", 1), then EndEvent. Cancel: SetAbort(true), e.g. from a ProgressEvent
 * observer or a progress dialog's Cancel button, stops the export before
 * the next frame (or kills ffmpeg): Write() returns false, GetAborted() is
 * true, no error is reported, the staged folder is removed and an existing
 * DirectoryName is untouched. Write() clears the flag when it starts.
 *
 * Across processes (`mpirun -np N lfd animate`, or any
 * vtkMultiProcessController given to SetController()): every process calls
 * Write() with the same scene, light field and settings; process p renders
 * the frames f with f % N == p, N consecutive frames a round, into the
 * folder process 0 stages, so that every process must reach DirectoryName
 * (on a cluster: a shared file system). After each round every process
 * sends process 0 the outcome of its frame and its thumbnail; process 0
 * reports the progress, writes the contact sheet and the ParaView
 * collections, encodes the movie and renames the folder. The files are
 * those of a single process, bitwise: each frame is rendered by the same
 * code from the same inputs. An error on any process (the first in frame
 * order) is reported by process 0 alone; a cancel on any process stops
 * them all after the round; Write() returns the same result on every
 * process. DirectoryName is used on process 0 only; the contact sheet is
 * assembled on process 0 only.
 *
 * Errors: Write() returns false and reports one line with vtkErrorMacro (an
 * ErrorEvent a vtkLightFieldErrorObserver collects): the scene logic's own
 * refusal of a keyframe's cage as it said it (naming the scene file and the
 * box), the frame that failed to render ("rendering frame 2 failed"), the
 * file that failed to be written, the folder refused, or ffmpeg's failure
 * naming the movie.
 *
 * @sa vtkLightFieldSceneLogic vtkLightFieldRenderer
 */
#ifndef vtkLightFieldAnimationWriter_h
#define vtkLightFieldAnimationWriter_h

#include "lfdSceneModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkLightField;
class vtkLightFieldSceneLogic;
class vtkMultiProcessController;

class LFDSCENE_EXPORT vtkLightFieldAnimationWriter : public vtkObject
{
public:
  static vtkLightFieldAnimationWriter* New();
  vtkTypeMacro(vtkLightFieldAnimationWriter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene whose keyframes are animated (its cage, camera and render
   * settings). Required.
   */
  void SetSceneLogic(vtkLightFieldSceneLogic* logic);
  vtkGetObjectMacro(SceneLogic, vtkLightFieldSceneLogic);
  ///@}

  ///@{
  /**
   * The light field to render; null (the default): the one the scene names
   * (vtkLightFieldSceneLogic::GetLightField()).
   */
  void SetLightField(vtkLightField* lightField);
  vtkGetObjectMacro(LightField, vtkLightField);
  ///@}

  ///@{
  /**
   * The processes the frames are split across (see the class description),
   * e.g. a vtkMPIController; null (the default) or a single process: this
   * process renders every frame.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * The output folder (replaced when the export is complete). Required on
   * process 0.
   */
  vtkSetStringMacro(DirectoryName);
  vtkGetStringMacro(DirectoryName);
  ///@}

  ///@{
  /**
   * Number of frames, 1 to 100000 (an hour at 24 frames/s). Default 48.
   */
  vtkSetClampMacro(NumberOfFrames, int, 1, 100000);
  vtkGetMacro(NumberOfFrames, int);
  ///@}

  ///@{
  /**
   * The frame size in pixels; 0 (the default) takes the scene's width or
   * height. At most lfd::MaximumRenderSize.
   */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * Encode animation.mp4 with ffmpeg when it is found on the PATH (default
   * on), at FrameRate frames per second (1 to 240, default 24).
   */
  vtkSetMacro(WriteMovie, bool);
  vtkGetMacro(WriteMovie, bool);
  vtkBooleanMacro(WriteMovie, bool);
  vtkSetClampMacro(FrameRate, int, 1, 240);
  vtkGetMacro(FrameRate, int);
  ///@}

  ///@{
  /**
   * Write contact_sheet.png into the folder (default off), and the sheet's
   * layout: ContactSheetColumns thumbnails per row (1 to 64, default 6) of
   * ContactSheetThumbnailSize pixels square (8 to 1024, default 128).
   */
  vtkSetMacro(WriteContactSheet, bool);
  vtkGetMacro(WriteContactSheet, bool);
  vtkBooleanMacro(WriteContactSheet, bool);
  vtkSetClampMacro(ContactSheetColumns, int, 1, 64);
  vtkGetMacro(ContactSheetColumns, int);
  vtkSetClampMacro(ContactSheetThumbnailSize, int, 8, 1024);
  vtkGetMacro(ContactSheetThumbnailSize, int);
  ///@}

  ///@{
  /**
   * Write the ParaView time series (frames as .vti, the cage as .vtu, each
   * listed in a .pvd; see the class description). Default off.
   */
  vtkSetMacro(WriteParaView, bool);
  vtkGetMacro(WriteParaView, bool);
  vtkBooleanMacro(WriteParaView, bool);
  ///@}

  ///@{
  /**
   * Cancels the running export before its next frame (or stops ffmpeg).
   * Safe to set from an observer of this writer's events.
   */
  vtkSetMacro(Abort, bool);
  vtkGetMacro(Abort, bool);
  vtkBooleanMacro(Abort, bool);
  ///@}

  /**
   * Renders and writes the animation. True when the folder is complete and
   * in place; false after an error (reported) or a cancel (GetAborted()).
   */
  bool Write();

  ///@{
  /**
   * The last Write(): whether it was cancelled, how many frames it wrote,
   * whether it encoded animation.mp4, and its contact sheet (RGB, rows
   * bottom first; empty before the first complete Write()).
   */
  vtkGetMacro(Aborted, bool);
  vtkGetMacro(NumberOfFramesWritten, int);
  vtkGetMacro(MovieWritten, bool);
  vtkImageData* GetContactSheet();
  ///@}

  ///@{
  /**
   * The export's progress in [0, 1] and what it is doing ("frame 3/48",
   * "encoding animation.mp4", "done"), as of the last ProgressEvent.
   */
  vtkGetMacro(Progress, double);
  const char* GetProgressText();
  ///@}

  /**
   * True when `ffmpeg` is found on the PATH (an MP4 can be encoded).
   */
  static bool IsMovieEncoderAvailable();

protected:
  vtkLightFieldAnimationWriter();
  ~vtkLightFieldAnimationWriter() override;

  vtkLightFieldSceneLogic* SceneLogic = nullptr;
  vtkLightField* LightField = nullptr;
  vtkMultiProcessController* Controller = nullptr;
  char* DirectoryName = nullptr;
  int NumberOfFrames = 48;
  int Size[2] = { 0, 0 };
  bool WriteMovie = true;
  int FrameRate = 24;
  bool WriteContactSheet = false;
  int ContactSheetColumns = 6;
  int ContactSheetThumbnailSize = 128;
  bool WriteParaView = false;
  bool Abort = false;
  bool Aborted = false;
  int NumberOfFramesWritten = 0;
  bool MovieWritten = false;
  double Progress = 0.0;

private:
  vtkLightFieldAnimationWriter(const vtkLightFieldAnimationWriter&) = delete;
  void operator=(const vtkLightFieldAnimationWriter&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
