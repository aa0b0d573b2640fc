#include "lfdJsonFields.h"

#include "lfdFileUtilities.h"
#include "lfdLimits.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

namespace lfd
{
namespace io
{

//------------------------------------------------------------------------------
FieldError::FieldError(const std::string& field, const std::string& problem)
  : std::runtime_error("field \"" + field + "\": " + problem)
{
}

namespace
{
// Thrown from the parser callback when the nesting gets too deep.
struct TooDeep : std::runtime_error
{
  TooDeep()
    : std::runtime_error("nested deeper than " + std::to_string(lfd::MaximumJsonDepth) +
        " levels of arrays and objects")
  {
  }
};

// Parses `input` (a stream or a string) with the nesting bounded: the
// callback sees each array or object start with the number of enclosing
// containers, before the parser descends into it.
template<typename Input>
bool ParseBounded(Input&& input, Json& document, std::string& error)
{
  const Json::parser_callback_t bound = [](int depth, Json::parse_event_t event, Json&)
  {
    if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
      depth >= lfd::MaximumJsonDepth)
    {
      throw TooDeep();
    }
    return true;
  };
  try
  {
    document = Json::parse(std::forward<Input>(input), bound);
  }
  catch (const TooDeep& e)
  {
    error = e.what();
    return false;
  }
  catch (const Json::exception& e)
  {
    // Parse errors ("[json.exception.parse_error.101] parse error at line L,
    // column C: ..."), out-of-range numbers ("1e999") and invalid UTF-8.
    std::string what = e.what();
    const std::string::size_type start = what.find("] ");
    error = "not valid JSON: " + (start == std::string::npos ? what : what.substr(start + 2));
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool ParseJsonFile(const std::string& path, Json& document, std::string& error)
{
  std::string problem;
  if (!CheckRegularFile(path, problem))
  {
    error = path + ": " + problem;
    return false;
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    error = path + ": cannot open the file for reading";
    return false;
  }
  if (!ParseBounded(stream, document, problem))
  {
    error = path + ": " + problem;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ParseJsonText(const std::string& text, Json& document, std::string& error)
{
  return ParseBounded(text, document, error);
}

//------------------------------------------------------------------------------
std::string MemberPath(const std::string& parent, const char* key)
{
  return parent.empty() ? std::string(key) : parent + "." + key;
}

//------------------------------------------------------------------------------
std::string ElementPath(const std::string& parent, size_t index)
{
  return parent + "[" + std::to_string(index) + "]";
}

//------------------------------------------------------------------------------
std::string Describe(const Json& value)
{
  switch (value.type())
  {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array of " + std::to_string(value.size()) + " elements";
    case Json::value_t::string:
      return "the string " + value.dump();
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "the number " + value.dump();
    default:
      return "an unsupported value";
  }
}

//------------------------------------------------------------------------------
const Json* FindMember(const Json& object, const std::string& parent, const char* key)
{
  if (!object.is_object())
  {
    throw FieldError(
      parent.empty() ? "(document)" : parent, "expected an object, found " + Describe(object));
  }
  auto it = object.find(key);
  if (it == object.end() || it->is_null())
  {
    return nullptr;
  }
  return &*it;
}

//------------------------------------------------------------------------------
const Json& RequireMember(const Json& object, const std::string& parent, const char* key)
{
  const Json* member = FindMember(object, parent, key);
  if (!member)
  {
    throw FieldError(MemberPath(parent, key), "missing");
  }
  return *member;
}

//------------------------------------------------------------------------------
double GetNumber(const Json& value, const std::string& path)
{
  if (!value.is_number())
  {
    throw FieldError(path, "expected a number, found " + Describe(value));
  }
  const double number = value.get<double>();
  if (!std::isfinite(number))
  {
    throw FieldError(path, "expected a finite number");
  }
  return number;
}

//------------------------------------------------------------------------------
long long GetInteger(const Json& value,
  const std::string& path,
  long long minimum,
  long long maximum)
{
  const double number = GetNumber(value, path);
  if (number != std::floor(number) || number < static_cast<double>(minimum) ||
    number > static_cast<double>(maximum))
  {
    std::ostringstream expected;
    expected << "expected an integer in [" << minimum << ", " << maximum << "], found "
             << Describe(value);
    throw FieldError(path, expected.str());
  }
  return static_cast<long long>(number);
}

//------------------------------------------------------------------------------
std::string GetString(const Json& value, const std::string& path)
{
  if (!value.is_string())
  {
    throw FieldError(path, "expected a string, found " + Describe(value));
  }
  return value.get<std::string>();
}

//------------------------------------------------------------------------------
std::string GetPath(const Json& value, const std::string& path)
{
  const std::string text = GetString(value, path);
  if (text.empty())
  {
    throw FieldError(path, "expected a file name, found an empty string");
  }
  if (text.find('\0') != std::string::npos)
  {
    throw FieldError(path, "a file name must not contain a NUL character");
  }
  return text;
}

//------------------------------------------------------------------------------
std::vector<double> GetNumbers(const Json& value, const std::string& path, size_t length)
{
  if (!value.is_array() || (length > 0 && value.size() != length))
  {
    throw FieldError(path,
      "expected an array of " + (length > 0 ? std::to_string(length) + " " : std::string()) +
        "numbers, found " + Describe(value));
  }
  std::vector<double> numbers;
  numbers.reserve(value.size());
  for (size_t i = 0; i < value.size(); ++i)
  {
    numbers.push_back(GetNumber(value[i], ElementPath(path, i)));
  }
  return numbers;
}

//------------------------------------------------------------------------------
std::vector<double> GetPoints(const Json& value, const std::string& path)
{
  if (!value.is_array())
  {
    throw FieldError(path, "expected an array of [x, y, z] points, found " + Describe(value));
  }
  std::vector<double> coordinates;
  coordinates.reserve(3 * value.size());
  for (size_t i = 0; i < value.size(); ++i)
  {
    const std::vector<double> point = GetNumbers(value[i], ElementPath(path, i), 3);
    coordinates.insert(coordinates.end(), point.begin(), point.end());
  }
  return coordinates;
}
}
}
