#include "vtkMiddleburyImporter.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdLimits.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkMiddleburyImporter);

namespace
{
const char* const FieldNames[21] = { "k11",
  "k12",
  "k13",
  "k21",
  "k22",
  "k23",
  "k31",
  "k32",
  "k33",
  "r11",
  "r12",
  "r13",
  "r21",
  "r22",
  "r23",
  "r31",
  "r32",
  "r33",
  "t1",
  "t2",
  "t3" };

struct ParEntry
{
  int Line = 0;
  std::string Name;
  std::string Image;
  double Values[21];
};

// A malformed par file: the message already names file and line.
struct ParError : std::runtime_error
{
  ParError(const std::string& file, int line, const std::string& problem)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + problem)
  {
  }
};

std::vector<std::string> Tokens(const std::string& line)
{
  std::istringstream stream(line);
  std::vector<std::string> tokens;
  std::string token;
  while (stream >> token)
  {
    tokens.push_back(token);
  }
  return tokens;
}

// Parses the whole par file (throws ParError, or std::runtime_error when it
// cannot be opened).
std::vector<ParEntry> ParseParFile(const std::string& path)
{
  std::string problem;
  if (!lfd::io::CheckRegularFile(path, problem))
  {
    throw std::runtime_error(path + ": " + problem);
  }
  std::ifstream stream(path);
  if (!stream)
  {
    throw std::runtime_error(path + ": cannot open the file for reading");
  }
  const std::string folder = lfd::io::ParentFolder(path);
  std::string text;
  int lineNumber = 0;
  long long announced = -1;
  int announcedLine = 0;
  std::vector<ParEntry> entries;
  while (std::getline(stream, text))
  {
    ++lineNumber;
    const std::vector<std::string> tokens = Tokens(text);
    if (tokens.empty())
    {
      continue;
    }
    if (announced < 0)
    {
      char* end = nullptr;
      errno = 0;
      announced = std::strtoll(tokens[0].c_str(), &end, 10);
      if (tokens.size() != 1 || *end != '\0' || errno != 0 || announced < 1)
      {
        throw ParError(path,
          lineNumber,
          "expected the number of images (a positive integer), found \"" + text + "\"");
      }
      announcedLine = lineNumber;
      continue;
    }
    if (tokens.size() != 22)
    {
      throw ParError(path,
        lineNumber,
        "expected 22 fields (image name, k11..k33, r11..r33, t1 t2 t3), found " +
          std::to_string(tokens.size()));
    }
    ParEntry entry;
    entry.Line = lineNumber;
    entry.Name = tokens[0];
    entry.Image = lfd::io::ResolvePath(folder, tokens[0]);
    for (int f = 0; f < 21; ++f)
    {
      const std::string& token = tokens[f + 1];
      char* end = nullptr;
      entry.Values[f] = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0')
      {
        throw ParError(path,
          lineNumber,
          std::string("field ") + FieldNames[f] + " is not a number: \"" + token + "\"");
      }
      if (!std::isfinite(entry.Values[f]))
      {
        throw ParError(path,
          lineNumber,
          std::string("field ") + FieldNames[f] + " is not finite: \"" + token + "\"");
      }
    }
    entries.push_back(entry);
  }
  if (announced < 0)
  {
    throw ParError(path, 1, "the file is empty (expected the number of images)");
  }
  if (static_cast<long long>(entries.size()) != announced)
  {
    throw ParError(path,
      announcedLine,
      "announces " + std::to_string(announced) + " images but " + std::to_string(entries.size()) +
        " calibration lines follow");
  }
  // The rig's one validation, as the dataset reader applies it: the
  // importer never produces a light field its own reader would refuse.
  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(static_cast<int>(entries.size()));
  for (size_t i = 0; i < entries.size(); ++i)
  {
    const double* v = entries[i].Values;
    rig->SetView(static_cast<int>(i), v, v + 9, v + 18);
  }
  std::string field;
  const int invalid = rig->FindInvalidView(field, problem);
  if (invalid >= 0)
  {
    const std::string fields = field == "K" ? "k11..k33" : field == "R" ? "r11..r33" : "t1 t2 t3";
    throw ParError(path, entries[invalid].Line, field.empty() ? problem : fields + ": " + problem);
  }
  return entries;
}

// Parses the par file that FileName names. On failure returns false with the
// vtkErrorCode and the one-line message.
bool LoadParFile(const char* fileName,
  std::vector<ParEntry>& entries,
  unsigned long& errorCode,
  std::string& error)
{
  if (!fileName || !*fileName)
  {
    errorCode = vtkErrorCode::NoFileNameError;
    error = "vtkMiddleburyImporter: no FileName set";
    return false;
  }
  try
  {
    entries = ParseParFile(fileName);
  }
  catch (const ParError& e)
  {
    errorCode = vtkErrorCode::FileFormatError;
    error = e.what();
    return false;
  }
  catch (const std::exception& e)
  {
    errorCode = vtkErrorCode::FileNotFoundError;
    error = e.what();
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
struct vtkMiddleburyImporter::Internals
{
  std::vector<ParEntry> Parsed;
};

//------------------------------------------------------------------------------
vtkMiddleburyImporter::vtkMiddleburyImporter()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkMiddleburyImporter::~vtkMiddleburyImporter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkMiddleburyImporter::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  std::vector<ParEntry>& entries = this->Internal->Parsed;
  entries = std::vector<ParEntry>();
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  if (!LoadParFile(this->FileName, entries, errorCode, error))
  {
    this->Fail(output, errorCode, error);
    return 0;
  }
  lfd::io::ImageHeader header;
  if (!lfd::io::ReadImageHeader(entries[0].Image, header, error, errorCode))
  {
    this->Fail(output,
      errorCode,
      std::string(this->FileName) + ":" + std::to_string(entries[0].Line) + ": image " +
        entries[0].Image + ": " + error);
    return 0;
  }
  // An image header may announce any size: the coaxial pass it implies is
  // checked before it is allocated.
  const std::string tooLarge = lfd::CheckLightFieldSize(
    header.Width, header.Height, static_cast<std::int64_t>(entries.size()), 3);
  if (!tooLarge.empty())
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      std::string(this->FileName) + ":" + std::to_string(entries[0].Line) + ": image " +
        entries[0].Image + ": the light field is too large to import: " + tooLarge);
    return 0;
  }
  SetOutputLayout(outputs, header.Width, header.Height, static_cast<int>(entries.size()));
  return 1;
}

//------------------------------------------------------------------------------
int vtkMiddleburyImporter::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  const std::vector<ParEntry>& entries = this->Internal->Parsed;
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  const std::string parFile = this->FileName;

  const int views = static_cast<int>(entries.size());
  // Every header is checked (size, channels, bit depth) before the coaxial
  // pass is allocated.
  std::vector<lfd::io::ImageHeader> headers(entries.size());
  for (int i = 0; i < views; ++i)
  {
    const ParEntry& entry = entries[i];
    const std::string where =
      parFile + ":" + std::to_string(entry.Line) + ": image " + entry.Image + ": ";
    lfd::io::ImageHeader& header = headers[i];
    if (!lfd::io::ReadImageHeader(entry.Image, header, error, errorCode))
    {
      this->Fail(output, errorCode, where + error);
      return 0;
    }
    if (header.Width != headers[0].Width || header.Height != headers[0].Height)
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        where + "image is " + std::to_string(header.Width) + "x" + std::to_string(header.Height) +
          ", the first image (" + entries[0].Name + ") is " + std::to_string(headers[0].Width) +
          "x" + std::to_string(headers[0].Height));
      return 0;
    }
    if ((header.Channels != 1 && header.Channels < 3) || header.ScalarType != VTK_UNSIGNED_CHAR)
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        where + "image has " + lfd::io::DescribePixels(header.Channels, header.ScalarType) +
          ", expected 8-bit grey (1 channel) or colour (3 or 4)");
      return 0;
    }
  }
  const int width = headers[0].Width;
  const int height = headers[0].Height;
  output->Initialize();
  output->SetLayout(width, height, views);
  vtkDataArray* coaxial = output->AllocatePass(vtkLightField::COAXIAL);
  this->UpdateProgress(0.0);
  for (int i = 0; i < views; ++i)
  {
    if (!lfd::io::ReadViewPixels(entries[i].Image, headers[i], coaxial, i, error))
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        parFile + ":" + std::to_string(entries[i].Line) + ": image " + entries[i].Image + ": " +
          error);
      return 0;
    }
    this->UpdateProgress(0.95 * (i + 1) / views);
  }

  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(views);
  rig->SetImageSize(width, height);
  for (int i = 0; i < views; ++i)
  {
    const double* v = entries[i].Values;
    rig->SetView(i, v, v + 9, v + 18);
    rig->SetViewName(i, entries[i].Name.c_str());
  }
  std::string noCylinder;
  if (this->FitRigCylinder && views >= 3 && !rig->FitCylinder(noCylinder))
  {
    vtkWarningMacro(<< parFile << ": the camera centres do not determine a cylinder; "
                    << "the rig is imported without a cylinder fit.");
  }
  output->SetRig(rig);
  const lfd::io::Json provenance = { { "importer", "vtkMiddleburyImporter" },
    { "source", parFile },
    { "format", "Middlebury multi-view stereo par file" } };
  output->SetProvenance(provenance.dump().c_str());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkMiddleburyImporter::DescribeFailure(const std::string& problem)
{
  return (this->FileName ? std::string(this->FileName) : std::string("vtkMiddleburyImporter")) +
    ": " + problem;
}

//------------------------------------------------------------------------------
void vtkMiddleburyImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FitRigCylinder: " << (this->FitRigCylinder ? "On" : "Off") << "\n";
}
