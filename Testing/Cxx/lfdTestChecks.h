// The checks every C++ test executable shares: one failure count per test
// process (the test driver runs one test per process), checks that print
// what they compare ("ok   " or "FAIL " first), and the exit code. One
// definition here keeps the test files free of same-named helpers, so that
// a unity build can batch them into one translation unit.
#ifndef lfdTestChecks_h
#define lfdTestChecks_h

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace lfdtest
{
/// Checks that failed in this process.
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

/// Prints "ok   what" or "FAIL what"; counts a failure.
inline bool Check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

/// Prints the measured `value` next to its `limit`; counts a failure.
inline void Check(bool ok, const std::string& what, double value, double limit)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (limit " << limit << ")\n";
  Failures() += ok ? 0 : 1;
}

/// Prints what was measured; counts a failure when `ok` is false.
template<typename T>
bool Expect(bool ok, const std::string& what, const T& value)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << "\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

/// `actual` must equal `expected`.
template<typename T>
bool CheckEqual(const T& actual, const T& expected, const std::string& what)
{
  const bool ok = actual == expected;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << actual << " (expected " << expected
            << ")\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

/// `value` must be within `tolerance` of `expected`.
inline bool Expect(const std::string& what, double value, double expected, double tolerance = 1e-9)
{
  const bool ok = std::abs(value - expected) <= tolerance;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (expected " << expected
            << ")\n";
  Failures() += ok ? 0 : 1;
  return ok;
}

/// Prints the count of failed checks; the test's exit code.
inline int Result()
{
  std::cout << (Failures() ? "FAILED: " : "PASSED")
            << (Failures() ? std::to_string(Failures()) + " check(s)" : std::string()) << "\n";
  return Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
}

#endif
