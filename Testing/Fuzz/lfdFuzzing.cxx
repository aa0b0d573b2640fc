// The scratch folder of the fuzz targets and their structure-aware mutator:
// lightfield.json and scene.json are JSON, and byte mutations of JSON mostly
// produce syntax errors that the parser refuses at once. The mutator parses
// the input, changes one value the way a malformed file would (a number to 0,
// -1, huge or a NaN spelled as a string, a value of another type, a key
// removed or moved, nesting deepened, an array resized, a path swapped for a
// device or a folder) and writes the JSON back, so the fuzzer reaches the
// readers' validation. Inputs that are not JSON (par files, COLMAP models)
// and one mutation in eight go to libFuzzer's byte mutator.
#include "lfdFuzzing.h"

#include "vtkObject.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include <unistd.h>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t maxSize);

namespace
{
namespace fs = std::filesystem;

fs::path& ScratchFolder()
{
  static fs::path folder;
  return folder;
}

void RemoveScratchFolder()
{
  std::error_code ec;
  fs::remove_all(ScratchFolder(), ec);
}

const fs::path& Scratch()
{
  fs::path& folder = ScratchFolder();
  if (folder.empty())
  {
    vtkObject::GlobalWarningDisplayOff();
    folder = fs::temp_directory_path() / ("lfd-fuzz-" + std::to_string(getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    fs::copy(LFD_FUZZ_IMAGES, folder, fs::copy_options::recursive);
    std::atexit(RemoveScratchFolder);
  }
  return folder;
}

// Every value of the document, parents before children.
void Collect(nlohmann::json& value, std::vector<nlohmann::json*>& values)
{
  values.push_back(&value);
  if (value.is_structured())
  {
    for (auto& child : value)
    {
      Collect(child, values);
    }
  }
}

// One change to `value`, chosen by `rng`.
void Mutate(nlohmann::json& value, nlohmann::json& root, std::mt19937& rng)
{
  static const double numbers[] = {
    0.0, -1.0, 1.0, 0.5, 1e308, -1e308, 1e-308, 255.5, 65536.0, 1048576.0, 4294967296.0
  };
  static const int64_t integers[] = { 0,
    -1,
    1,
    255,
    256,
    65535,
    65536,
    1048576,
    2147483647,
    2147483648LL,
    4294967296LL,
    INT64_MAX,
    INT64_MIN };
  static const char* strings[] = { "NaN",
    "Infinity",
    "-inf",
    "",
    ".",
    "..",
    "/",
    "/dev/zero",
    "/proc/self/fd/0",
    "coaxial",
    "coaxial/view_0001.png",
    "label/view_0000.png",
    "lightfield.json",
    "auto",
    "a\0b" };
  const auto pick = [&rng](size_t n) { return static_cast<size_t>(rng() % n); };
  switch (pick(7))
  {
    case 0: // a number at an edge
      if (value.is_number_integer() && pick(2))
      {
        value = integers[pick(std::size(integers))];
      }
      else
      {
        value = numbers[pick(std::size(numbers))];
      }
      break;
    case 1: // a string where a value was (NaN as a string, a path, a device)
    {
      const size_t i = pick(std::size(strings));
      value = i + 1 == std::size(strings) ? std::string("a\0b", 3) : std::string(strings[i]);
      break;
    }
    case 2: // another type
    {
      const nlohmann::json others[] = {
        nullptr, true, 1, -7, "x", nlohmann::json::array(), nlohmann::json::object()
      };
      value = others[pick(std::size(others))];
      break;
    }
    case 3: // a key removed, or a value copied under a key of another object
      if (value.is_object() && !value.empty())
      {
        auto member = std::next(value.begin(), static_cast<long>(pick(value.size())));
        if (pick(2))
        {
          value.erase(member);
        }
        else
        {
          std::vector<nlohmann::json*> values;
          Collect(root, values);
          nlohmann::json* target = values[pick(values.size())];
          if (target->is_object())
          {
            (*target)[member.key()] = member.value();
          }
        }
      }
      break;
    case 4: // deeper nesting
      value = pick(2) ? nlohmann::json::array({ value }) : nlohmann::json{ { "value", value } };
      break;
    case 5: // an array resized: emptied, shortened, lengthened
      if (value.is_array())
      {
        if (value.empty() || pick(3) == 0)
        {
          value = nlohmann::json::array();
        }
        else if (pick(2))
        {
          value.erase(value.begin() + static_cast<long>(pick(value.size())));
        }
        else
        {
          const nlohmann::json last = value.back();
          for (size_t n = 1 + pick(16); n > 0; --n)
          {
            value.push_back(last);
          }
        }
      }
      break;
    default: // a value copied from elsewhere in the document
    {
      std::vector<nlohmann::json*> values;
      Collect(root, values);
      const nlohmann::json copy = *values[pick(values.size())];
      value = copy;
      break;
    }
  }
}
}

std::string lfdfuzz::WriteInput(const uint8_t* data, size_t size, const std::string& name)
{
  const fs::path path = Scratch() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
    .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path.string();
}

const char* const lfdfuzz::FileSeparator = "\n--- next file ---\n";

std::string lfdfuzz::WriteInputFiles(const uint8_t* data,
  size_t size,
  const std::string& folder,
  const std::vector<std::string>& names)
{
  const fs::path path = Scratch() / folder;
  fs::create_directories(path);
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator(FileSeparator);
  size_t start = 0;
  for (const std::string& name : names)
  {
    std::error_code ec;
    fs::remove(path / name, ec);
    if (start == std::string::npos)
    {
      continue;
    }
    const size_t end = input.find(separator, start);
    std::ofstream(path / name, std::ios::binary | std::ios::trunc)
      << input.substr(start, end == std::string::npos ? std::string::npos : end - start);
    start = end == std::string::npos ? end : end + separator.size();
  }
  return path.string();
}

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data,
  size_t size,
  size_t maxSize,
  unsigned int seed)
{
  std::mt19937 rng(seed);
  nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
  if (document.is_discarded() || rng() % 8 == 0)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  std::vector<nlohmann::json*> values;
  Collect(document, values);
  Mutate(*values[rng() % values.size()], document, rng);
  const std::string text = document.dump();
  if (text.size() > maxSize)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  std::memcpy(data, text.data(), text.size());
  return text.size();
}
