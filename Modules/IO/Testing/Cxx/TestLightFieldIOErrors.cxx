// Every malformed light-field dataset must fail with one line naming the
// file and the field; failed writes must leave nothing that looks valid.
#include "lfdFileUtilities.h"
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>

#include <unistd.h> // getpid

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace TestLightFieldIOErrorsHelpers
{
constexpr int Width = 6;
constexpr int Height = 4;
constexpr int Views = 3;

vtkSmartPointer<vtkLightField> MakeLightField(int fill)
{
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->SetLayout(Width, Height, Views);
  lightField->AllocatePass(vtkLightField::COAXIAL)->Fill(fill);
  lightField->AllocatePass(vtkLightField::LABEL)->Fill(1);
  vtkNew<vtkCameraRig> rig;
  const double center[3] = { 0, 0, 0 };
  const double axis[3] = { 0, 1, 0 };
  const double height = 0.0;
  rig->MakeCylinder(center, axis, 1.0, Views, 1, &height, Width, Height, 30.0);
  lightField->SetRig(rig);
  return lightField;
}

bool Write(vtkLightField* lightField, const std::string& directory, std::string& message)
{
  vtkNew<vtkLightFieldWriter> writer;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(writer);
  writer->SetInputData(lightField);
  writer->SetDirectory(directory.c_str());
  const int ok = writer->Write();
  message = catcher->GetErrorMessage();
  return ok == 1 && writer->GetErrorCode() == 0;
}

// Reads `path`; returns true on success, the error message in `message`.
bool Read(const std::string& path, std::string& message, int* views = nullptr)
{
  vtkNew<vtkLightFieldReader> reader;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  message = catcher->GetErrorMessage();
  const bool empty = reader->GetOutput()->GetNumberOfPoints() == 0 &&
    reader->GetOutput()->GetPointData()->GetNumberOfArrays() == 0;
  if (views)
  {
    *views = reader->GetOutput()->GetNumberOfViews();
  }
  if (reader->GetErrorCode() != 0 && !empty)
  {
    std::cout << "FAIL the output of a failed read is not empty\n";
    ++lfdtest::Failures();
  }
  return reader->GetErrorCode() == 0;
}

// Copies of a valid dataset whose manifest is edited, and the check that
// each fails to read with one line naming the manifest and the field.
struct Cases
{
  std::string Folder;
  std::string Valid;
  Json Manifest;
  int Number = 0;
  std::string Message;

  // A copy of the valid dataset whose manifest is edited by `edit` (or
  // replaced by `text` when given).
  std::string Variant(const std::function<void(Json&)>& edit, const std::string& text = "")
  {
    const std::string directory = this->Folder + "/case" + std::to_string(++this->Number) + ".lf";
    fs::copy(this->Valid, directory, fs::copy_options::recursive);
    Json edited = this->Manifest;
    if (edit)
    {
      edit(edited);
    }
    lfdtest::WriteText(directory + "/lightfield.json", text.empty() ? edited.dump(2) : text);
    return directory;
  }

  void ExpectFailure(const std::string& name,
    const std::string& directory,
    std::vector<std::string> parts)
  {
    const bool ok = Read(directory, this->Message);
    parts.insert(parts.begin(), directory + "/lightfield.json");
    lfdtest::CheckFailure(name, !ok, this->Message, parts);
  }
};

// The file, its JSON and the header fields.
void CheckHeaderErrors(Cases& cases)
{
  lfdtest::CheckFailure("missing dataset",
    !Read(cases.Folder + "/nothing.lf", cases.Message),
    cases.Message,
    { cases.Folder + "/nothing.lf", "file not found" });
  {
    std::string text = cases.Manifest.dump(2);
    text.replace(text.find("\"height\""), 0, "\"oops\" ");
    cases.ExpectFailure("bad JSON", cases.Variant(nullptr, text), { "not valid JSON", "line 3" });
  }
  cases.ExpectFailure("wrong format",
    cases.Variant([](Json& j) { j["format"] = "lfd-scene"; }),
    { "\"format\"", "lfd-lightfield" });
  cases.ExpectFailure("unsupported version",
    cases.Variant([](Json& j) { j["version"] = 2; }),
    { "\"version\"", "unsupported version 2" });
  cases.ExpectFailure("version as string",
    cases.Variant([](Json& j) { j["version"] = "1"; }),
    { "\"version\"", "number" });
  cases.ExpectFailure(
    "missing width", cases.Variant([](Json& j) { j.erase("width"); }), { "\"width\"", "missing" });
  cases.ExpectFailure(
    "zero height", cases.Variant([](Json& j) { j["height"] = 0; }), { "\"height\"", "integer" });
}

// The views: K, R, t and the lens distortion.
void CheckViewErrors(Cases& cases)
{
  cases.ExpectFailure(
    "missing views", cases.Variant([](Json& j) { j.erase("views"); }), { "\"views\"", "missing" });
  cases.ExpectFailure("K of 8 numbers",
    cases.Variant([](Json& j) { j["views"][1]["K"].erase(8); }),
    { "\"views[1].K\"", "9 numbers" });
  cases.ExpectFailure("missing t",
    cases.Variant([](Json& j) { j["views"][2].erase("t"); }),
    { "\"views[2].t\"", "missing" });
  cases.ExpectFailure("overflowing number in R",
    cases.Variant(nullptr,
      [&cases]
      {
        Json j = cases.Manifest;
        j["views"][0]["R"][2] = 12345.5;
        std::string text = j.dump(2);
        text.replace(text.find("12345.5"), 7, "1e999");
        return text;
      }()),
    { "not valid JSON", "1e999" });
  cases.ExpectFailure("NaN token in K",
    cases.Variant(nullptr,
      [&cases]
      {
        Json j = cases.Manifest;
        j["views"][0]["K"][0] = 12345.5;
        std::string text = j.dump(2);
        text.replace(text.find("12345.5"), 7, "NaN");
        return text;
      }()),
    { "not valid JSON", "line" });
  cases.ExpectFailure("R not a rotation",
    cases.Variant([](Json& j) { j["views"][1]["R"][0] = 2.0; }),
    { "\"views[1].R\"", "rotation" });
  cases.ExpectFailure("string in t",
    cases.Variant([](Json& j) { j["views"][1]["t"][1] = "x"; }),
    { "\"views[1].t[1]\"", "number" });
  cases.ExpectFailure("distortion of 4 numbers",
    cases.Variant(
      [](Json& j) {
        j["views"][1]["distortion"] = Json::array({ -0.2, 0.05, 0.0, 0.0 });
      }),
    { "\"views[1].distortion\"", "array of 5 numbers" });
  cases.ExpectFailure("string in the distortion",
    cases.Variant(
      [](Json& j) {
        j["views"][0]["distortion"] = Json::array({ "k1", 0, 0, 0, 0 });
      }),
    { "\"views[0].distortion[0]\"", "number" });
  // k1 = -3 folds the 6 x 4 image: r (1 - 3 r^2) turns back at distorted
  // radius 0.22, the corners are at 0.48.
  cases.ExpectFailure("folding distortion",
    cases.Variant(
      [](Json& j) {
        j["views"][2]["distortion"] = Json::array({ -3.0, 0, 0, 0, 0 });
      }),
    { "\"views[2].distortion\"", "folds the image" });
}

// The passes, the palette and the image files.
void CheckPassErrors(Cases& cases)
{
  cases.ExpectFailure("unknown pass",
    cases.Variant([](Json& j) { j["passes"]["normals"] = j["passes"]["label"]; }),
    { "\"passes.normals\"", "unknown pass" });
  cases.ExpectFailure("pass list too short",
    cases.Variant([](Json& j) { j["passes"]["label"].erase(2); }),
    { "\"passes.label\"", "array of 3" });
  cases.ExpectFailure("palette value out of range",
    cases.Variant(
      [](Json& j) {
        j["palette"] = Json::array({ Json::array({ 0, 300, 0 }) });
      }),
    { "\"palette[0][1]\"", "[0, 255]" });
  {
    const std::string directory = cases.Variant(nullptr);
    fs::remove(directory + "/coaxial/view_0002.png");
    cases.ExpectFailure("missing image",
      directory,
      { "\"passes.coaxial[2]\"", "coaxial/view_0002.png", "not found" });
  }
  {
    const std::string directory = cases.Variant(nullptr);
    lfdtest::WriteUniformPng(directory + "/coaxial/view_0001.png", Width + 1, Height, 3, 7);
    cases.ExpectFailure("image of the wrong size",
      directory,
      { "\"passes.coaxial[1]\"", "view_0001.png", "7x4", "6x4" });
  }
  {
    const std::string directory = cases.Variant(nullptr);
    lfdtest::WriteUniformPng(directory + "/label/view_0000.png", Width, Height, 3, 7);
    cases.ExpectFailure("label image with 3 channels",
      directory,
      { "\"passes.label[0]\"", "view_0000.png", "3 channels" });
  }
  {
    const std::string directory = cases.Variant(nullptr);
    lfdtest::WriteText(directory + "/label/view_0001.png", "not a png");
    cases.ExpectFailure("corrupt image", directory, { "\"passes.label[1]\"", "view_0001.png" });
  }
  {
    // Images cut short after a sound header fail only as they are decoded,
    // on every thread (vtkLightFieldReader): the message names the first of
    // them in the manifest's order (passes, then views), as a read of one
    // image after the other would, whichever thread failed first.
    const std::string directory = cases.Variant(nullptr);
    for (const char* image :
      { "/coaxial/view_0000.png", "/coaxial/view_0001.png", "/label/view_0000.png" })
    {
      const std::string path = directory + image;
      fs::resize_file(path, fs::file_size(path) - 20); // (IEND's 12 bytes, and into IDAT)
    }
    cases.ExpectFailure(
      "images cut short", directory, { "\"passes.coaxial[0]\"", "coaxial/view_0000.png" });
    lfdtest::CheckEqual(cases.Message.find("view_0001") == std::string::npos &&
        cases.Message.find("label") == std::string::npos,
      true,
      "the message names the first image cut short only");
  }
}

// Writer failures leave nothing that looks valid.
void CheckWriterErrors(const std::string& folder, const std::string& valid)
{
  std::string message;
  {
    const std::string notDataset = folder + "/documents";
    fs::create_directories(notDataset);
    lfdtest::WriteText(notDataset + "/thesis.txt", "precious");
    const bool ok = Write(MakeLightField(20), notDataset, message);
    lfdtest::CheckFailure("write over a folder that is not a dataset",
      !ok,
      message,
      { notDataset, "not a light-field dataset" });
    lfdtest::CheckEqual(lfdtest::ReadText(notDataset + "/thesis.txt"),
      std::string("precious"),
      "the unrelated file is untouched");
    lfdtest::Check(!fs::exists(notDataset + "/lightfield.json"), "no manifest in it");
  }
  {
    vtkSmartPointer<vtkLightField> broken = MakeLightField(30);
    broken->GetRig()->SetNumberOfViews(Views - 1);
    const bool ok = Write(broken, valid, message);
    lfdtest::CheckFailure(
      "write a light field whose rig lacks views", !ok, message, { valid, "rig has 2 views" });
    int views = 0;
    lfdtest::Check(Read(valid, message, &views) && views == Views,
      "the existing dataset is intact after the failed write");
  }
  {
    const std::string blocker = folder + "/afile";
    lfdtest::WriteText(blocker, "x");
    const bool ok = Write(MakeLightField(40), blocker + "/out.lf", message);
    lfdtest::CheckFailure("write below a regular file",
      !ok,
      message,
      { blocker + "/out.lf: cannot create the directory" });
    lfdtest::Check(message.find(".tmp-") == std::string::npos, "the message names the target");
    lfdtest::Check(!fs::exists(blocker + "/out.lf"), "nothing written");
  }
  {
    vtkSmartPointer<vtkLightField> folded = MakeLightField(50);
    const double lens[5] = { -3.0, 0.0, 0.0, 0.0, 0.0 };
    folded->GetRig()->SetDistortion(1, lens);
    const bool ok = Write(folded, folder + "/folded.lf", message);
    lfdtest::CheckFailure("write a rig with a folding distortion",
      !ok,
      message,
      { folder + "/folded.lf", "views[1].distortion", "folds the image" });
    lfdtest::Check(!fs::exists(folder + "/folded.lf"), "nothing written for the folded rig");
  }
}
/// A message about a staged output names the target (how `lfd` reports a
/// failure inside a folder it builds under a temporary name).
void CheckStagedNames(const std::string& folder)
{
  const std::string staged = lfd::io::TemporaryDirectoryName(folder + "/frames");
  const std::string image = lfd::io::TemporaryFileName(folder + "/view.png");
  const std::string other = folder + "/x.tmp-" + std::to_string(::getpid()) + "7.png";
  lfdtest::CheckEqual(lfd::io::NameTargets(staged + "/frame_0001.png: No space left on device; " +
                        image + "; " + other),
    folder + "/frames/frame_0001.png: No space left on device; " + folder + "/view.png; " + other,
    "temporary names replaced by their targets");
  lfd::io::RemoveQuietly(staged);
}
}

int TestLightFieldIOErrors(int, char*[])
{
  using namespace TestLightFieldIOErrorsHelpers;
  Cases cases;
  cases.Folder = lfdtest::ScratchFolder("TestLightFieldIOErrors");
  cases.Valid = cases.Folder + "/valid.lf";
  lfdtest::Check(Write(MakeLightField(10), cases.Valid, cases.Message), "write the valid dataset");
  cases.Manifest = Json::parse(lfdtest::ReadText(cases.Valid + "/lightfield.json"));
  lfdtest::Check(Read(cases.Valid, cases.Message), "the valid dataset reads");
  CheckHeaderErrors(cases);
  CheckViewErrors(cases);
  CheckPassErrors(cases);
  CheckWriterErrors(cases.Folder, cases.Valid);
  CheckStagedNames(cases.Folder);
  lfdtest::CheckEqual(
    lfdtest::CountEntries(cases.Folder, "valid.lf."), 0, "temporary siblings left");
  return lfdtest::Result();
}
