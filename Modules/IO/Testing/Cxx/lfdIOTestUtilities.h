// Helpers shared by the LFD::IO tests: checks that print what they compare,
// expected-failure checks on one-line error messages, and scratch folders.
#ifndef lfdIOTestUtilities_h
#define lfdIOTestUtilities_h

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace lfdtest
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline bool Check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

template<typename T>
bool CheckEqual(const T& actual, const T& expected, const std::string& what)
{
  const bool ok = actual == expected;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << actual << " (expected " << expected
            << ")\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

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

inline int Result()
{
  std::cout << (Failures() ? "FAILED: " : "PASSED")
            << (Failures() ? std::to_string(Failures()) + " check(s)" : std::string()) << "\n";
  return Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
}

#endif
