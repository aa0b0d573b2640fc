/**
 * @file   lfdJsonFields.h
 * @brief  checked access to the fields of a JSON document (private to LFD::IO)
 *
 * The readers of lightfield.json and scene.json validate every field they
 * use. These helpers take the field's path ("views[3].K") with the value and
 * throw lfd::io::FieldError with a message that says what was expected and
 * what was found, so that the reader reports one line naming the file and the
 * field.
 */
#ifndef lfdJsonFields_h
#define lfdJsonFields_h

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace lfd
{
namespace io
{
// Insertion-ordered: files keep the documented key order, provenance its own.
using Json = nlohmann::ordered_json;

/// The version of lightfield.json this code reads and writes.
constexpr int LightFieldManifestVersion = 1;

/**
 * A field that is missing or malformed: what() is the complete message
 * "field \"path\": problem".
 */
class FieldError : public std::runtime_error
{
public:
  FieldError(const std::string& field, const std::string& problem);
};

/**
 * Parses `path` as JSON. On failure returns false and sets `error` to
 * "<path>: <reason>": not a regular file (a directory, FIFO or device is
 * refused without being opened), not JSON (the parser's line and column),
 * or nested deeper than lfd::MaximumJsonDepth (checked while parsing, so a
 * hostile file can overflow neither the parser nor later recursive code).
 */
bool ParseJsonFile(const std::string& path, Json& document, std::string& error);

/**
 * ParseJsonText() parses text held in memory with the same depth bound; on
 * failure returns false and sets `error` to the reason.
 */
bool ParseJsonText(const std::string& text, Json& document, std::string& error);

/**
 * Path of a member / an element, for messages ("cage" + "points" ->
 * "cage.points", "views" + 3 -> "views[3]").
 */
std::string MemberPath(const std::string& parent, const char* key);
std::string ElementPath(const std::string& parent, size_t index);

/**
 * The member `key` of the object `object` (at path `parent`); throws when
 * `object` is not an object or the member is missing.
 */
const Json& RequireMember(const Json& object, const std::string& parent, const char* key);

/**
 * The member `key`, or nullptr when it is absent or null.
 */
const Json* FindMember(const Json& object, const std::string& parent, const char* key);

///@{
/**
 * Typed values. Numbers must be finite; integers must be integral and within
 * [minimum, maximum].
 */
double GetNumber(const Json& value, const std::string& path);
long long GetInteger(const Json& value,
  const std::string& path,
  long long minimum,
  long long maximum);
std::string GetString(const Json& value, const std::string& path);
///@}

/**
 * A string that names a file: non-empty and without NUL characters (which
 * would silently cut the name short in every system call).
 */
std::string GetPath(const Json& value, const std::string& path);

/**
 * An array of exactly `length` finite numbers (any length when `length` is 0).
 */
std::vector<double> GetNumbers(const Json& value, const std::string& path, size_t length);

/**
 * An array of points [[x,y,z], ...], flattened.
 */
std::vector<double> GetPoints(const Json& value, const std::string& path);

/**
 * The JSON type of a value in words ("a string", "an array of 8 elements").
 */
std::string Describe(const Json& value);
}
}

#endif
