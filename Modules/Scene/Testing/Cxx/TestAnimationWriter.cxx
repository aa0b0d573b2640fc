// vtkLightFieldAnimationWriter on a small analytic scene (a textured disc
// seen by a ring of cameras, one box sliding sideways over 2 keyframes):
// the exact files of a 4-frame export, frames bitwise equal to the logic's
// renders at the same times, the MP4's frame count and padded size
// (ffprobe), the contact sheet, a cancel after frame 2 (from a
// ProgressEvent observer) that leaves nothing behind and an existing
// folder untouched, and refused folders with one error naming them. The
// ParaView outputs of the same scene: the animation's series (frames as
// .vti, the cage as .vtu, their .pvd collections) and the scene export of
// vtkLightFieldSceneExporter (rig frusta, cage, light field, vtk.js).
#include "lfdIOTestUtilities.h"
#include "lfdPinholeCamera.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkImageFileReader.h"
#include "vtkLightField.h"
#include "vtkLightFieldAnimationWriter.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldSceneExporter.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using lfdtest::Check;
using lfdtest::CheckEqual;

namespace
{
const int Width = 25; // odd: the MP4 is padded to 26 x 20
const int Height = 19;

/// The disc |p| < 1 in the plane z = 0: its colour where the camera's pixel
/// ray meets it.
bool Disc(const lfd::PinholeCamera& camera, int x, int y, unsigned char rgb[3])
{
  const glm::dvec3 o = camera.Center();
  const glm::dvec3 d = camera.RayDirection({ x, y });
  const double s = std::abs(d.z) < 1e-12 ? -1.0 : -o.z / d.z;
  const glm::dvec3 p = o + s * d;
  const double rho = std::hypot(p.x, p.y);
  if (s <= 0.0 || rho >= 1.0)
  {
    return false;
  }
  rgb[0] = static_cast<unsigned char>(std::lround(128 + 100 * std::sin(9 * rho)));
  rgb[1] = static_cast<unsigned char>(std::lround(128 + 100 * std::cos(5 * p.x)));
  rgb[2] = static_cast<unsigned char>(std::lround(60 + 90 * (p.y + 1)));
  return true;
}

/// A ring of 48 views of 40 x 40 pixels around the disc, label 1 on it.
void MakeLightField(vtkLightField* lightField)
{
  const int size = 40, views = 48;
  const double center[3] = { 0.0, 0.0, 0.0 }, axis[3] = { 0.0, 1.0, 0.0 }, height = 0.0;
  lightField->SetLayout(size, size, views);
  lightField->GetRig()->MakeCylinder(center, axis, 4.0, views, 1, &height, size, size, 40.0);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::COAXIAL));
  auto* label = vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::LABEL));
  for (int v = 0; v < views; ++v)
  {
    const lfd::PinholeCamera& camera = lightField->GetRig()->GetCamera(v);
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        // Rows bottom first, as captured (vtkLightField, "Row order").
        const vtkIdType id = (static_cast<vtkIdType>(v) * size + (size - 1 - y)) * size + x;
        unsigned char c[3] = { 0, 0, 0 };
        label->SetValue(id, Disc(camera, x, y, c) ? 1 : 0);
        std::copy(c, c + 3, rgb->GetPointer(3 * id));
      }
    }
  }
}

/// The scene: one box around the disc, at rest at time 0, slid 0.4 along x at time 1.
void MakeScene(vtkLightFieldSceneLogic* logic, vtkLightField* lightField)
{
  logic->SetLightField(lightField);
  const double bounds[6] = { -1.1, 1.1, -1.1, 1.1, -0.3, 0.3 };
  Check(logic->BuildCageFromSlabs(bounds, 1, 2, 1), "one box around the disc");
  Check(logic->SetKeyframe(0.0), "keyframe 0: rest");
  for (vtkIdType p = 0; p < logic->GetCage()->GetNumberOfPoints(); ++p)
  {
    double point[3];
    logic->GetCage()->GetDeformedPoint(p, point);
    logic->MovePoint(p, point[0] + 0.4, point[1], point[2]);
  }
  Check(logic->SetKeyframe(1.0), "keyframe 1: slid along x");
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.5, 0.2, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(32.0);
  Check(logic->SetCamera(camera) && logic->SetSize(Width, Height), "the scene's view");
}

std::vector<std::string> Listing(const std::string& folder)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string Join(const std::vector<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
  {
    text += (text.empty() ? "" : " ") + name;
  }
  return text;
}

/// Every file of a folder with its bytes.
std::map<std::string, std::string> Snapshot(const std::string& folder)
{
  std::map<std::string, std::string> files;
  for (const std::string& name : Listing(folder))
  {
    files[name] = lfdtest::ReadText(folder + "/" + name);
  }
  return files;
}

/// Entries of the folder holding `path` named like its temporaries.
int Temporaries(const std::string& path)
{
  const std::filesystem::path target(path);
  return lfdtest::CountEntries(target.parent_path().string(), target.filename().string() + ".tmp-");
}

/// The MP4's "width,height,frames" (ffprobe), "" when ffprobe fails.
std::string Probe(const std::string& movie)
{
  const std::string command = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                              "stream=width,height,nb_read_frames -of csv=p=0 '" +
    movie + "'";
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r"))
  {
    char buffer[256];
    while (std::fgets(buffer, sizeof(buffer), pipe))
    {
      text += buffer;
    }
    pclose(pipe);
  }
  text.erase(text.find_last_not_of(" \n") + 1);
  return text;
}

/// The ProgressEvents a writer invokes: their texts, and a cancel after one of them.
struct ProgressLog
{
  std::vector<std::string> Texts;
  std::vector<double> Values;
  std::string CancelAfter;
  vtkNew<vtkCallbackCommand> Callback;

  explicit ProgressLog(vtkLightFieldAnimationWriter* writer)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject* caller, unsigned long, void* self, void* callData)
      {
        auto* log = static_cast<ProgressLog*>(self);
        auto* writer = static_cast<vtkLightFieldAnimationWriter*>(caller);
        if (log->Texts.empty() || log->Texts.back() != writer->GetProgressText())
        {
          log->Texts.emplace_back(writer->GetProgressText());
          log->Values.push_back(*static_cast<double*>(callData));
        }
        if (log->CancelAfter == writer->GetProgressText())
        {
          writer->SetAbort(true);
        }
      });
    writer->AddObserver(vtkCommand::ProgressEvent, this->Callback);
  }
};

/// The frames are the logic's own renders at the animation's times, bitwise.
void CheckFrames(vtkLightFieldSceneLogic* logic, vtkLightField* lightField, const std::string& out)
{
  vtkNew<vtkLightFieldRenderer> renderer;
  vtkNew<vtkDeformationCage> cage;
  std::string first;
  for (int f = 0; f < 4; ++f)
  {
    logic->GetCageAtTime(logic->GetAnimationTime(f, 4), lightField, cage);
    logic->ConfigureRenderer(renderer, lightField, cage);
    renderer->Update();
    vtkNew<vtkImageFileReader> reader;
    char name[32];
    std::snprintf(name, sizeof(name), "/frame_%04d.png", f);
    reader->SetFileName((out + name).c_str());
    reader->Update();
    vtkImageData* frame = reader->GetOutput();
    vtkImageData* render = renderer->GetOutput();
    const auto* a = static_cast<unsigned char*>(frame->GetScalarPointer());
    const auto* b = static_cast<unsigned char*>(render->GetScalarPointer());
    const std::size_t bytes = 3 * Width * Height;
    Check(a && b && frame->GetDimensions()[0] == Width && frame->GetDimensions()[1] == Height &&
        frame->GetNumberOfScalarComponents() == 3 && std::equal(a, a + bytes, b),
      std::string("frame ") + std::to_string(f) + " is the logic's render, bitwise");
    const std::string bytesOf(reinterpret_cast<const char*>(b), bytes);
    if (f == 0)
    {
      first = bytesOf;
      int lit = 0;
      for (std::size_t i = 0; i < bytes; i += 3)
      {
        lit += b[i] || b[i + 1] || b[i + 2] ? 1 : 0;
      }
      // 97 of the 475 pixels measured.
      Check(lit > 60, "frame 0 shows the disc: " + std::to_string(lit) + " pixels");
    }
    else if (f == 3)
    {
      Check(bytesOf != first, "frame 3 differs from frame 0 (the box slid)");
    }
  }
}

void TestExport(vtkLightFieldSceneLogic* logic, vtkLightField* lightField, const std::string& out)
{
  const bool movie = vtkLightFieldAnimationWriter::IsMovieEncoderAvailable();
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(logic);
  writer->SetNumberOfFrames(4);
  writer->SetDirectoryName(out.c_str());
  writer->SetContactSheetColumns(3);
  writer->SetContactSheetThumbnailSize(16);
  ProgressLog log(writer);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  Check(writer->Write() && !errors->HasError(), "4 frames exported");
  const std::vector<std::string> expected = movie
    ? std::vector<std::string>{ "animation.mp4",
        "frame_0000.png",
        "frame_0001.png",
        "frame_0002.png",
        "frame_0003.png" }
    : std::vector<std::string>{
        "frame_0000.png", "frame_0001.png", "frame_0002.png", "frame_0003.png"
      };
  CheckEqual(Join(Listing(out)), Join(expected), "the exported files");
  CheckEqual(Temporaries(out), 0, "no temporary left");
  CheckEqual(writer->GetNumberOfFramesWritten(), 4, "frames written");
  Check(writer->GetMovieWritten() == movie, "the movie is written when ffmpeg is installed");
  const std::string steps = movie ? "frame 1/4 frame 2/4 frame 3/4 frame 4/4 encoding "
                                    "animation.mp4 done"
                                  : "frame 1/4 frame 2/4 frame 3/4 frame 4/4 done";
  CheckEqual(Join(log.Texts), steps, "the progress texts");
  CheckEqual(log.Values.front(), movie ? 0.2 : 0.25, "the first frame's progress");
  CheckEqual(log.Values.back(), 1.0, "the last progress");
  int sheet[3];
  writer->GetContactSheet()->GetDimensions(sheet);
  CheckEqual(sheet[0] * 1000 + sheet[1], 48032, "contact sheet: 2 rows of 3 thumbnails of 16");
  CheckFrames(logic, lightField, out);
  if (movie)
  {
    CheckEqual(Probe(out + "/animation.mp4"),
      std::string("26,20,4"),
      "the MP4: the odd size padded to even, 4 frames (ffprobe)");
  }
  else
  {
    std::cout << "skip the MP4 checks: ffmpeg is not installed\n";
  }

  // Again with the contact sheet in the folder, and without the movie: the
  // folder of the first export is replaced.
  writer->SetWriteContactSheet(true);
  writer->SetWriteMovie(false);
  Check(writer->Write(), "the export replaces its own folder");
  CheckEqual(Join(Listing(out)),
    std::string("contact_sheet.png frame_0000.png frame_0001.png frame_0002.png frame_0003.png"),
    "the files with the contact sheet, without the movie");
}

void TestCancel(vtkLightFieldSceneLogic* logic, const std::string& scratch)
{
  const std::string out = scratch + "/existing";
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(logic);
  writer->SetNumberOfFrames(4);
  writer->SetSize(12, 10);
  writer->SetDirectoryName(out.c_str());
  Check(writer->Write(), "an existing export (12 x 10)");
  const auto before = Snapshot(out);

  ProgressLog log(writer);
  log.CancelAfter = "frame 2/4";
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  writer->SetSize(0, 0);
  Check(!writer->Write() && writer->GetAborted() && !errors->HasError(),
    "cancelled after frame 2: Write() fails without an error");
  CheckEqual(writer->GetNumberOfFramesWritten(), 2, "frames rendered before the cancel");
  CheckEqual(Join(log.Texts), std::string("frame 1/4 frame 2/4"), "no progress after the cancel");
  Check(Snapshot(out) == before, "the existing folder is untouched, byte for byte");
  CheckEqual(Temporaries(out), 0, "no temporary left after the cancel");

  if (vtkLightFieldAnimationWriter::IsMovieEncoderAvailable())
  {
    log.CancelAfter = "encoding animation.mp4";
    Check(!writer->Write() && writer->GetAborted() && !writer->GetMovieWritten() &&
        Snapshot(out) == before && Temporaries(out) == 0,
      "cancelled while encoding: the existing folder is untouched, no temporary left");
    log.CancelAfter = "frame 2/4";
  }

  const std::string fresh = scratch + "/fresh";
  writer->SetDirectoryName(fresh.c_str());
  Check(!writer->Write() && writer->GetAborted(), "a cancelled export into a new folder");
  Check(!std::filesystem::exists(fresh) && Temporaries(fresh) == 0,
    "a cancelled export creates no folder and no temporary");
  log.CancelAfter.clear();
  Check(writer->Write() && !writer->GetAborted() && Listing(fresh).size() >= 4,
    "Write() clears the cancel when it starts");
}

void TestRefusedFolders(vtkLightFieldSceneLogic* logic, const std::string& scratch)
{
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(logic);
  writer->SetNumberOfFrames(2);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  const auto refuse = [&](const std::string& out, const std::vector<std::string>& parts)
  {
    errors->Clear();
    writer->SetDirectoryName(out.c_str());
    const bool written = writer->Write();
    lfdtest::CheckFailure(out, !written, errors->GetErrorMessage(), parts);
    CheckEqual(errors->GetNumberOfErrors(), 1, "one error");
  };
  // A folder inside a file cannot be created (whoever runs the test).
  const std::string file = scratch + "/file.txt";
  lfdtest::WriteText(file, "a file");
  refuse(file + "/anim", { file + "/anim: cannot create", "Not a directory" });
  refuse(file, { file + ": exists and is not a folder" });
  const std::string mine = scratch + "/mine";
  std::filesystem::create_directories(mine);
  lfdtest::WriteText(mine + "/notes.txt", "keep");
  refuse(mine,
    { mine + ": holds 'notes.txt', which an animation export does not write",
      "choose a new or empty one" });
  CheckEqual(Join(Listing(mine)), std::string("notes.txt"), "a folder of the user's is kept");
  CheckEqual(lfdtest::ReadText(file), std::string("a file"), "the file is kept");
}
}

/// Bytes of two arrays differing (-1 when either is missing or sizes differ).
vtkIdType DifferingBytes(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetDataSize() != b->GetDataSize() || a->GetDataType() != b->GetDataType())
  {
    return -1;
  }
  const auto* x = static_cast<const unsigned char*>(a->GetVoidPointer(0));
  const auto* y = static_cast<const unsigned char*>(b->GetVoidPointer(0));
  const vtkIdType size = a->GetDataSize() * a->GetDataTypeSize();
  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < size; ++i)
  {
    differing += x[i] != y[i] ? 1 : 0;
  }
  return differing;
}

/// The ParaView series of a 4-frame export: frame_NNNN.vti are the logic's
/// renders, cage_NNNN.vtu its cages at the same times, both listed with
/// those times in their .pvd.
void TestParaViewSeries(vtkLightFieldSceneLogic* logic,
  vtkLightField* lightField,
  const std::string& out)
{
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(logic);
  writer->SetLightField(lightField);
  writer->SetDirectoryName(out.c_str());
  writer->SetNumberOfFrames(4);
  writer->WriteMovieOff();
  writer->WriteParaViewOn();
  Check(writer->Write(), "the ParaView series is written");
  CheckEqual(Join(Listing(out)),
    std::string("animation.pvd cage.pvd cage_0000.vtu cage_0001.vtu cage_0002.vtu cage_0003.vtu "
                "frame_0000.png frame_0000.vti frame_0001.png frame_0001.vti frame_0002.png "
                "frame_0002.vti frame_0003.png frame_0003.vti"),
    "the ParaView export's files");
  const std::string pvd = lfdtest::ReadText(out + "/cage.pvd");
  Check(
    pvd.find("<DataSet timestep=\"1\" part=\"0\" file=\"cage_0003.vtu\"/>") != std::string::npos,
    "cage.pvd lists the last cage at time 1");
  Check(
    lfdtest::ReadText(out + "/animation.pvd").find("file=\"frame_0002.vti\"") != std::string::npos,
    "animation.pvd lists the frames");

  const double time = logic->GetAnimationTime(2, 4);
  vtkNew<vtkDeformationCage> cage;
  Check(logic->GetCageAtTime(time, lightField, cage), "the cage of frame 2");
  vtkNew<vtkLightFieldRenderer> renderer;
  logic->ConfigureRenderer(renderer, lightField, cage);
  renderer->Update();
  vtkNew<vtkXMLImageDataReader> frame;
  frame->SetFileName((out + "/frame_0002.vti").c_str());
  frame->Update();
  for (const char* name : { "Radiance", "Label", "Depth" })
  {
    CheckEqual(DifferingBytes(frame->GetOutput()->GetPointData()->GetArray(name),
                 renderer->GetOutput()->GetPointData()->GetArray(name)),
      vtkIdType(0),
      std::string("frame_0002.vti ") + name + " bytes differing from the render");
  }
  vtkNew<vtkXMLUnstructuredGridReader> grid;
  grid->SetFileName((out + "/cage_0002.vtu").c_str());
  grid->Update();
  CheckEqual(
    DifferingBytes(grid->GetOutput()->GetPoints()->GetData(), cage->GetPoints()->GetData()),
    vtkIdType(0),
    "cage_0002.vtu points differing from the logic's cage");
  Check(grid->GetOutput()->GetPointData()->GetArray("RestPosition") &&
      grid->GetOutput()->GetCellData()->GetArray("Label"),
    "cage_0002.vtu has RestPosition and Label");
}

/// vtkLightFieldSceneExporter: rig.vtp (5 polygons a view, "View"),
/// cage.vtu (the current cage), lightfield.vti (the passes, bitwise) and
/// the vtk.js scene; a folder of the user's is refused.
void TestSceneExport(vtkLightFieldSceneLogic* logic,
  vtkLightField* lightField,
  const std::string& scratch)
{
  const std::string out = scratch + "/scene-export";
  vtkNew<vtkLightFieldSceneExporter> exporter;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(exporter);
  exporter->SetSceneLogic(logic);
  exporter->SetLightField(lightField);
  exporter->SetDirectoryName(out.c_str());
  Check(exporter->Write(), "the scene export: " + std::string(errors->GetErrorMessage()));
  CheckEqual(Join(Listing(out)),
    std::string("cage.vtu lightfield.vti rig.vtp vtkjs"),
    "the scene export's files");
  Check(std::filesystem::is_regular_file(out + "/vtkjs/index.json"), "vtkjs/index.json");

  vtkNew<vtkXMLPolyDataReader> rig;
  rig->SetFileName((out + "/rig.vtp").c_str());
  rig->Update();
  CheckEqual(rig->GetOutput()->GetNumberOfCells(), vtkIdType(5 * 48), "rig.vtp: 5 polygons a view");
  vtkDataArray* view = rig->GetOutput()->GetCellData()->GetArray("View");
  Check(view && view->GetRange()[0] == 0 && view->GetRange()[1] == 47, "rig.vtp: View 0..47");

  vtkNew<vtkXMLUnstructuredGridReader> cage;
  cage->SetFileName((out + "/cage.vtu").c_str());
  cage->Update();
  CheckEqual(DifferingBytes(
               cage->GetOutput()->GetPoints()->GetData(), logic->GetCage()->GetPoints()->GetData()),
    vtkIdType(0),
    "cage.vtu points differing from the current cage");

  vtkNew<vtkXMLImageDataReader> stack;
  stack->SetFileName((out + "/lightfield.vti").c_str());
  stack->Update();
  int dims[3];
  stack->GetOutput()->GetDimensions(dims);
  Check(dims[0] == 40 && dims[1] == 40 && dims[2] == 48, "lightfield.vti: 40 x 40 x 48");
  for (int pass : { vtkLightField::COAXIAL, vtkLightField::LABEL })
  {
    const char* name = vtkLightField::GetPassName(pass);
    CheckEqual(
      DifferingBytes(stack->GetOutput()->GetPointData()->GetArray(name), lightField->GetPass(pass)),
      vtkIdType(0),
      std::string("lightfield.vti ") + name + " bytes differing");
  }

  // A folder of the user's is never swept away.
  const std::string mine = scratch + "/mine";
  std::filesystem::create_directories(mine);
  lfdtest::WriteText(mine + "/notes.txt", "mine");
  exporter->SetDirectoryName(mine.c_str());
  errors->Clear();
  const bool written = exporter->Write();
  lfdtest::CheckFailure("export into a folder of the user's",
    !written,
    errors->GetErrorMessage(),
    { mine, "notes.txt" });
  CheckEqual(lfdtest::ReadText(mine + "/notes.txt"), std::string("mine"), "the user's file kept");
}

int TestAnimationWriter(int, char*[])
{
  vtkNew<vtkLightField> lightField;
  MakeLightField(lightField);
  vtkNew<vtkLightFieldSceneLogic> logic;
  MakeScene(logic, lightField);
  const std::string scratch = lfdtest::ScratchFolder("AnimationWriter");
  TestExport(logic, lightField, scratch + "/anim");
  TestCancel(logic, scratch);
  TestRefusedFolders(logic, scratch);
  TestParaViewSeries(logic, lightField, scratch + "/paraview");
  TestSceneExport(logic, lightField, scratch);
  return lfdtest::Result();
}
