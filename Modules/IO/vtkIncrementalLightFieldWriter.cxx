#include "vtkIncrementalLightFieldWriter.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdLightFieldManifest.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

vtkStandardNewMacro(vtkIncrementalLightFieldWriter);

namespace fs = std::filesystem;

namespace
{
using lfd::io::Json;

constexpr const char* PlanFile = "capture.json";
constexpr const char* ManifestFile = "lightfield.json";

// capture.json: the manifest of every planned view, so a resumed capture is
// known to continue the same plan.
Json PlanDocument(vtkLightField* plan, const std::vector<int>& passes)
{
  std::vector<lfd::io::ImageFile> masks;
  Json document;
  document["format"] = "lfd-capture";
  document["version"] = 1;
  document["plan"] =
    lfd::io::BuildLightFieldManifest(plan, passes, plan->GetNumberOfViews(), masks);
  return document;
}
}

//------------------------------------------------------------------------------
vtkIncrementalLightFieldWriter::vtkIncrementalLightFieldWriter() = default;

//------------------------------------------------------------------------------
vtkIncrementalLightFieldWriter::~vtkIncrementalLightFieldWriter()
{
  this->SetDirectory(nullptr);
}

//------------------------------------------------------------------------------
void vtkIncrementalLightFieldWriter::SetPlan(vtkLightField* plan)
{
  if (this->Plan != plan)
  {
    this->Plan = plan;
    this->Open = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightField* vtkIncrementalLightFieldWriter::GetPlan()
{
  return this->Plan;
}

//------------------------------------------------------------------------------
void vtkIncrementalLightFieldWriter::AddPass(int pass)
{
  this->Passes.push_back(pass);
  this->Open = false;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkIncrementalLightFieldWriter::RemoveAllPasses()
{
  this->Passes.clear();
  this->Open = false;
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkIncrementalLightFieldWriter::GetNumberOfPasses() const
{
  return static_cast<int>(this->Passes.size());
}

//------------------------------------------------------------------------------
int vtkIncrementalLightFieldWriter::GetPass(int index) const
{
  return index >= 0 && index < this->GetNumberOfPasses() ? this->Passes[index] : -1;
}

//------------------------------------------------------------------------------
int vtkIncrementalLightFieldWriter::GetNumberOfPlannedViews()
{
  return this->Plan ? this->Plan->GetNumberOfViews() : 0;
}

//------------------------------------------------------------------------------
std::string vtkIncrementalLightFieldWriter::CheckPlan()
{
  if (!this->Directory || !*this->Directory)
  {
    this->Fail("vtkIncrementalLightFieldWriter: no Directory set");
    return std::string();
  }
  const std::string directory = lfd::io::TrimSeparators(this->Directory);
  if (!this->Plan)
  {
    this->Fail(directory + ": no capture plan set");
    return std::string();
  }
  std::vector<int> held;
  const std::string invalid = lfd::io::CheckLightFieldInput(this->Plan, directory, held);
  if (!invalid.empty())
  {
    this->Fail(invalid);
    return std::string();
  }
  if (this->Passes.empty())
  {
    this->Fail(directory + ": the capture plan has no passes");
    return std::string();
  }
  for (size_t i = 0; i < this->Passes.size(); ++i)
  {
    const int pass = this->Passes[i];
    if (pass < 0 || pass >= vtkLightField::NUMBER_OF_PASSES ||
      vtkLightField::GetPassScalarType(pass) != VTK_UNSIGNED_CHAR ||
      vtkLightField::GetPassComponents(pass) != 3 ||
      std::count(this->Passes.begin(), this->Passes.begin() + i, pass) > 0)
    {
      this->Fail(directory + ": pass " + std::to_string(pass) +
        " cannot be photographed (expected Coaxial, Coded or Flood, each once)");
      return std::string();
    }
  }
  return directory;
}

//------------------------------------------------------------------------------
bool vtkIncrementalLightFieldWriter::Start()
{
  this->Open = false;
  const std::string directory = this->CheckPlan();
  if (directory.empty())
  {
    return false;
  }
  std::error_code ec;
  if (fs::exists(directory, ec) &&
    !(fs::is_directory(directory, ec) && fs::is_empty(directory, ec)))
  {
    return this->Fail(
      directory + ": exists; resume that capture, or choose a new name (it is never replaced)");
  }
  // The projector masks are written once, with the plan.
  std::vector<lfd::io::ImageFile> masks;
  lfd::io::BuildLightFieldManifest(this->Plan, this->Passes, 0, masks);
  const std::string temporary = lfd::io::TemporaryDirectoryName(directory);
  lfd::io::RemoveQuietly(temporary);
  std::string error;
  for (int pass : this->Passes)
  {
    fs::create_directories(
      (fs::path(temporary) / lfd::io::LightFieldImageName(pass, 0)).parent_path(), ec);
  }
  for (const lfd::io::ImageFile& mask : masks)
  {
    const std::string path = (fs::path(temporary) / mask.Name).string();
    fs::create_directories(fs::path(path).parent_path(), ec);
    const vtkIdType offset = static_cast<vtkIdType>(mask.Width) * mask.Height * 3 * mask.Slice;
    if (ec ||
      !lfd::io::WriteImagePixels(path,
        mask.Width,
        mask.Height,
        3,
        VTK_UNSIGNED_CHAR,
        mask.Array->GetVoidPointer(offset),
        error))
    {
      lfd::io::RemoveQuietly(temporary);
      return this->Fail(directory + ": " + mask.Name + ": " + (ec ? ec.message() : error));
    }
  }
  const std::string plan = PlanDocument(this->Plan, this->Passes).dump(2) + "\n";
  if (ec ||
    !lfd::io::WriteFileContents(
      (fs::path(temporary) / PlanFile).string(), plan.data(), plan.size(), error) ||
    !lfd::io::CommitDirectory(temporary, directory, error))
  {
    lfd::io::RemoveQuietly(temporary);
    return this->Fail(directory + ": " + (ec ? ec.message() : error));
  }
  this->NumberOfCompleteViews = 0;
  this->Frames.assign(vtkLightField::NUMBER_OF_PASSES, nullptr);
  this->Open = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkIncrementalLightFieldWriter::Resume()
{
  this->Open = false;
  const std::string directory = this->CheckPlan();
  if (directory.empty())
  {
    return false;
  }
  const std::string planPath = (fs::path(directory) / PlanFile).string();
  Json started;
  std::string error;
  if (!lfd::io::ParseJsonFile(planPath, started, error))
  {
    return this->Fail(planPath + ": " + error + " (not a capture started by lfd capture)");
  }
  if (started != PlanDocument(this->Plan, this->Passes))
  {
    return this->Fail(planPath +
      ": the capture was started with another plan (views, passes, rig or projectors differ)");
  }
  int complete = 0;
  const std::string manifestPath = (fs::path(directory) / ManifestFile).string();
  std::error_code ec;
  if (fs::exists(manifestPath, ec))
  {
    Json manifest;
    if (!lfd::io::ParseJsonFile(manifestPath, manifest, error))
    {
      return this->Fail(manifestPath + ": " + error);
    }
    const Json* views = manifest.is_object() ? lfd::io::FindMember(manifest, "", "views") : nullptr;
    complete = views && views->is_array() ? static_cast<int>(views->size()) : -1;
    std::vector<lfd::io::ImageFile> masks;
    if (complete < 0 || complete > this->Plan->GetNumberOfViews() ||
      manifest != lfd::io::BuildLightFieldManifest(this->Plan, this->Passes, complete, masks))
    {
      return this->Fail(manifestPath + ": does not list the first views of the capture plan");
    }
  }
  for (int view = 0; view < complete; ++view)
  {
    for (int pass : this->Passes)
    {
      const std::string image = lfd::io::LightFieldImageName(pass, view);
      if (!lfd::io::CheckRegularFile((fs::path(directory) / image).string(), error))
      {
        return this->Fail(directory + ": " + image + ": " + error);
      }
    }
  }
  this->NumberOfCompleteViews = complete;
  this->Frames.assign(vtkLightField::NUMBER_OF_PASSES, nullptr);
  this->Open = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkIncrementalLightFieldWriter::SetViewFrame(int pass, vtkImageData* frame)
{
  const std::string directory =
    this->Directory ? this->Directory : "vtkIncrementalLightFieldWriter";
  if (!this->Open)
  {
    return this->Fail(directory + ": not started (Start() or Resume() first)");
  }
  if (std::find(this->Passes.begin(), this->Passes.end(), pass) == this->Passes.end())
  {
    return this->Fail(directory + ": pass " + std::to_string(pass) + " is not planned");
  }
  const int* dims = frame ? frame->GetDimensions() : nullptr;
  vtkDataArray* scalars = frame ? frame->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetDataType() != VTK_UNSIGNED_CHAR ||
    scalars->GetNumberOfComponents() != 3 || dims[0] != this->Plan->GetWidth() ||
    dims[1] != this->Plan->GetHeight() || dims[2] != 1)
  {
    return this->Fail(directory + ": the " + vtkLightField::GetPassName(pass) +
      " photograph of view " + std::to_string(this->NumberOfCompleteViews) +
      " is not an RGB uint8 image of " + std::to_string(this->Plan->GetWidth()) + "x" +
      std::to_string(this->Plan->GetHeight()) + " pixels");
  }
  this->Frames[pass] = frame;
  return true;
}

//------------------------------------------------------------------------------
bool vtkIncrementalLightFieldWriter::CommitView()
{
  const std::string directory =
    this->Directory ? this->Directory : "vtkIncrementalLightFieldWriter";
  const int view = this->NumberOfCompleteViews;
  if (!this->Open || view >= this->Plan->GetNumberOfViews())
  {
    return this->Fail(directory + ": no view left to commit (" + std::to_string(view) + " of " +
      std::to_string(this->GetNumberOfPlannedViews()) + " complete)");
  }
  const int width = this->Plan->GetWidth();
  const int height = this->Plan->GetHeight();
  const size_t rowBytes = static_cast<size_t>(width) * 3;
  std::vector<unsigned char> bottomFirst(rowBytes * height);
  std::string error;
  for (int pass : this->Passes)
  {
    vtkImageData* frame = this->Frames[pass];
    if (!frame)
    {
      return this->Fail(directory + ": view " + std::to_string(view) + " has no " +
        vtkLightField::GetPassName(pass) + " photograph");
    }
    // Frames come top row first, the image files' writer takes vtkLightField's order.
    const auto* pixels =
      static_cast<const unsigned char*>(frame->GetPointData()->GetScalars()->GetVoidPointer(0));
    for (int y = 0; y < height; ++y)
    {
      std::memcpy(&bottomFirst[rowBytes * (height - 1 - y)], pixels + rowBytes * y, rowBytes);
    }
    const std::string name = lfd::io::LightFieldImageName(pass, view);
    const std::string path = (fs::path(directory) / name).string();
    const std::string temporary = lfd::io::TemporaryFileName(path);
    if (!lfd::io::WriteImagePixels(
          temporary, width, height, 3, VTK_UNSIGNED_CHAR, bottomFirst.data(), error) ||
      !lfd::io::CommitFile(temporary, path, error))
    {
      lfd::io::RemoveQuietly(temporary);
      return this->Fail(directory + ": " + name + ": " + error);
    }
  }
  std::vector<lfd::io::ImageFile> masks;
  const std::string manifest =
    lfd::io::BuildLightFieldManifest(this->Plan, this->Passes, view + 1, masks).dump(2) + "\n";
  if (!lfd::io::WriteFileAtomically((fs::path(directory) / ManifestFile).string(), manifest, error))
  {
    return this->Fail(directory + ": " + ManifestFile + ": " + error);
  }
  this->Frames.assign(vtkLightField::NUMBER_OF_PASSES, nullptr);
  this->NumberOfCompleteViews = view + 1;
  return true;
}

//------------------------------------------------------------------------------
bool vtkIncrementalLightFieldWriter::Fail(const std::string& message)
{
  vtkErrorMacro(<< message);
  return false;
}

//------------------------------------------------------------------------------
void vtkIncrementalLightFieldWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Directory: " << (this->Directory ? this->Directory : "(none)") << "\n";
  os << indent << "Plan: " << this->Plan.Get() << "\n";
  os << indent << "Passes:";
  for (int pass : this->Passes)
  {
    os << " " << vtkLightField::GetPassName(pass);
  }
  os << "\n" << indent << "NumberOfCompleteViews: " << this->NumberOfCompleteViews << "\n";
}
