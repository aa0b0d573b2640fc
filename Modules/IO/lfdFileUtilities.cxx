#include "lfdFileUtilities.h"

#include <filesystem>
#include <system_error>

#include <unistd.h> // getpid

namespace fs = std::filesystem;

namespace lfd
{
namespace io
{

//------------------------------------------------------------------------------
std::string TrimSeparators(const std::string& path)
{
  std::string trimmed = path;
  while (trimmed.size() > 1 && (trimmed.back() == '/' || trimmed.back() == '\\'))
  {
    trimmed.pop_back();
  }
  return trimmed;
}

//------------------------------------------------------------------------------
std::string TemporaryFileName(const std::string& path)
{
  const fs::path target(path);
  fs::path temporary = target;
  temporary.replace_filename(
    target.stem().string() + ".tmp-" + std::to_string(::getpid()) + target.extension().string());
  return temporary.string();
}

//------------------------------------------------------------------------------
std::string TemporaryDirectoryName(const std::string& path)
{
  return TrimSeparators(path) + ".tmp-" + std::to_string(::getpid());
}

//------------------------------------------------------------------------------
void RemoveQuietly(const std::string& path)
{
  std::error_code ec;
  fs::remove_all(path, ec);
}

//------------------------------------------------------------------------------
bool CommitFile(const std::string& temporary, const std::string& path, std::string& error)
{
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec)
  {
    error = "cannot rename " + temporary + " to " + path + ": " + ec.message();
    RemoveQuietly(temporary);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool CommitDirectory(const std::string& temporary, const std::string& path, std::string& error)
{
  const std::string target = TrimSeparators(path);
  std::error_code ec;
  std::string aside;
  if (fs::exists(target, ec))
  {
    aside = target + ".old-" + std::to_string(::getpid());
    RemoveQuietly(aside);
    fs::rename(target, aside, ec);
    if (ec)
    {
      error = "cannot move the existing " + target + " aside: " + ec.message();
      RemoveQuietly(temporary);
      return false;
    }
  }
  fs::rename(temporary, target, ec);
  if (ec)
  {
    error = "cannot rename " + temporary + " to " + target + ": " + ec.message();
    RemoveQuietly(temporary);
    if (!aside.empty())
    {
      std::error_code restore;
      fs::rename(aside, target, restore);
    }
    return false;
  }
  if (!aside.empty())
  {
    RemoveQuietly(aside);
  }
  return true;
}

//------------------------------------------------------------------------------
std::string ParentFolder(const std::string& path)
{
  return fs::path(path).parent_path().string();
}

//------------------------------------------------------------------------------
std::string ResolvePath(const std::string& folder, const std::string& relative)
{
  const fs::path p(relative);
  if (p.is_absolute() || folder.empty())
  {
    return p.lexically_normal().string();
  }
  return (fs::path(folder) / p).lexically_normal().string();
}
}
}
