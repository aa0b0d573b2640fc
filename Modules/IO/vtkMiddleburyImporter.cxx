#include "vtkMiddleburyImporter.h"

#include "lfdFileUtilities.h"
#include "lfdTextFields.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <climits>
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

// Parses the whole par file, image names resolved against `folder` (throws
// ParError, or std::runtime_error when it cannot be opened).
std::vector<ParEntry> ParseParFile(const std::string& path, const std::string& folder)
{
  const std::vector<std::string> lines = lfd::io::ReadTextLines(path);
  std::string problem;
  long long announced = -1;
  int announcedLine = 0;
  std::vector<ParEntry> entries;
  for (size_t index = 0; index < lines.size(); ++index)
  {
    const std::string& text = lines[index];
    const int lineNumber = static_cast<int>(index) + 1;
    const std::vector<std::string> tokens = lfd::io::SplitFields(text);
    if (tokens.empty())
    {
      continue;
    }
    if (announced < 0)
    {
      if (tokens.size() != 1 || !lfd::io::ParseInteger(tokens[0], 1, LLONG_MAX, announced, problem))
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
      std::string problem;
      if (!lfd::io::ParseFiniteNumber(token, entry.Values[f], problem))
      {
        throw ParError(path, lineNumber, std::string("field ") + FieldNames[f] + " " + problem);
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
  return entries;
}
}

//------------------------------------------------------------------------------
vtkMiddleburyImporter::vtkMiddleburyImporter() = default;

//------------------------------------------------------------------------------
vtkMiddleburyImporter::~vtkMiddleburyImporter() = default;

//------------------------------------------------------------------------------
bool vtkMiddleburyImporter::ParseCalibration(std::vector<CalibratedView>& views,
  unsigned long& errorCode,
  std::string& error)
{
  std::vector<ParEntry> entries;
  try
  {
    entries = ParseParFile(this->FileName, this->GetImageFolder());
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
  for (const ParEntry& entry : entries)
  {
    CalibratedView view;
    view.Where = std::string(this->FileName) + ":" + std::to_string(entry.Line);
    view.Name = entry.Name;
    view.Image = entry.Image;
    std::copy(entry.Values, entry.Values + 9, view.K);
    std::copy(entry.Values + 9, entry.Values + 18, view.R);
    std::copy(entry.Values + 18, entry.Values + 21, view.t);
    views.push_back(view);
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkMiddleburyImporter::GetFormatDescription()
{
  return "Middlebury multi-view stereo par file";
}

//------------------------------------------------------------------------------
std::string vtkMiddleburyImporter::DescribeField(const std::string& field)
{
  return field == "K" ? "k11..k33" : field == "R" ? "r11..r33" : "t1 t2 t3";
}

//------------------------------------------------------------------------------
void vtkMiddleburyImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
