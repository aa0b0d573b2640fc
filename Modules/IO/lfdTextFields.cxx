#include "lfdTextFields.h"

#include "lfdFileUtilities.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lfd
{
namespace io
{
std::vector<std::string> ReadTextLines(const std::string& path)
{
  std::string problem;
  if (!CheckRegularFile(path, problem))
  {
    throw std::runtime_error(path + ": " + problem);
  }
  std::ifstream stream(path);
  if (!stream)
  {
    throw std::runtime_error(path + ": cannot open the file for reading");
  }
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(stream, line))
  {
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> SplitFields(const std::string& line)
{
  std::istringstream stream(line);
  std::vector<std::string> fields;
  std::string field;
  while (stream >> field)
  {
    fields.push_back(field);
  }
  return fields;
}

bool ParseFiniteNumber(const std::string& token, double& value, std::string& problem)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  if (end == token.c_str() || *end != '\0')
  {
    problem = "is not a number: \"" + token + "\"";
    return false;
  }
  if (!std::isfinite(value))
  {
    problem = "is not finite: \"" + token + "\"";
    return false;
  }
  return true;
}

bool ParseInteger(const std::string& token,
  long long minimum,
  long long maximum,
  long long& value,
  std::string& problem)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(token.c_str(), &end, 10);
  if (end == token.c_str() || *end != '\0' || errno != 0 || value < minimum || value > maximum)
  {
    problem = "is not an integer from " + std::to_string(minimum) + " to " +
      std::to_string(maximum) + ": \"" + token + "\"";
    return false;
  }
  return true;
}
}
}
