// Helpers shared by the LFD::IO tests: checks that print what they compare,
// expected-failure checks on one-line error messages, scratch folders and
// uniform PNG images.
#ifndef lfdIOTestUtilities_h
#define lfdIOTestUtilities_h

#include "lfdTestChecks.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace lfdtest
{
inline bool CheckRange(double value, double low, double high, const std::string& what)
{
  const bool ok = value >= low && value <= high;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (expected in [" << low << ", "
            << high << "])\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

/**
 * Checks an expected failure: `failed` must be true, `message` one line that
 * contains every string of `mustContain` (file name, field, line...).
 */
inline void CheckFailure(const std::string& name,
  bool failed,
  const std::string& message,
  const std::vector<std::string>& mustContain)
{
  bool ok = failed && !message.empty() && message.find('\n') == std::string::npos;
  std::string missing;
  for (const std::string& part : mustContain)
  {
    if (message.find(part) == std::string::npos)
    {
      ok = false;
      missing += " \"" + part + "\"";
    }
  }
  std::cout << (ok ? "ok   " : "FAIL ") << name << (failed ? " failed" : " did NOT fail")
            << " with: " << message << "\n";
  if (!missing.empty())
  {
    std::cout << "     the message lacks" << missing << "\n";
  }
  Failures() += ok ? 0 : 1;
}

/// Writes a `width` x `height` PNG of `components` 8-bit channels, all `value`.
inline void WriteUniformPng(const std::string& path,
  int width,
  int height,
  int components,
  int value)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  image->GetPointData()->GetScalars()->Fill(value);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

/**
 * A fresh, empty scratch folder under the test temporary directory.
 */
inline std::string ScratchFolder(const std::string& name)
{
  const std::filesystem::path folder = std::filesystem::path(LFD_TEST_TEMP_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder.string();
}

inline void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream stream(path, std::ios::binary);
  stream << text;
}

inline std::string ReadText(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
}

/**
 * Entries of `folder` whose name starts with `prefix`.
 */
inline int CountEntries(const std::string& folder, const std::string& prefix)
{
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    count += entry.path().filename().string().rfind(prefix, 0) == 0 ? 1 : 0;
  }
  return count;
}
}

#endif
