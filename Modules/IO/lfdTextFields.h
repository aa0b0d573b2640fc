/**
 * @file   lfdTextFields.h
 * @brief  whitespace-separated text formats (Middlebury par files, COLMAP text models): fields
 *         and numbers checked one by one (private to LFD::IO)
 */
#ifndef lfdTextFields_h
#define lfdTextFields_h

#include <string>
#include <vector>

namespace lfd
{
namespace io
{
/**
 * The lines of the text file `path` (line n is element n - 1). Throws
 * std::runtime_error "<path>: <problem>" when it is not a regular file
 * (lfd::io::CheckRegularFile) or cannot be opened.
 */
std::vector<std::string> ReadTextLines(const std::string& path);

/**
 * The whitespace-separated fields of a line.
 */
std::vector<std::string> SplitFields(const std::string& line);

/**
 * Parses the whole of `token` as a finite number. On failure returns false
 * and sets `problem` to "is not a number: \"<token>\"" or "is not finite:
 * \"<token>\"".
 */
bool ParseFiniteNumber(const std::string& token, double& value, std::string& problem);

/**
 * Parses the whole of `token` as an integer in [minimum, maximum]. On
 * failure returns false and sets `problem` ("is not an integer from 1 to 9:
 * \"<token>\"").
 */
bool ParseInteger(const std::string& token,
  long long minimum,
  long long maximum,
  long long& value,
  std::string& problem);
}
}

#endif
