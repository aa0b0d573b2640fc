#include "lfdFileUtilities.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>    // open
#include <signal.h>   // kill
#include <sys/stat.h> // stat
#include <unistd.h>   // getpid, write, fsync, close

namespace fs = std::filesystem;

namespace lfd
{
namespace io
{
namespace
{
std::string SystemError(int error)
{
  return std::strerror(error);
}

// What this process's temporaries add to their target's name (before any
// extension): ".tmp-<pid>".
std::string TemporaryTag()
{
  return ".tmp-" + std::to_string(::getpid());
}

// True when the process `pid` still runs (or exists and we may not signal
// it); our own id counts as gone: an earlier temporary of ours is stale too.
bool IsRunningProcess(pid_t pid)
{
  return pid > 0 && pid != ::getpid() && (::kill(pid, 0) == 0 || errno == EPERM);
}

// Removes the siblings `<prefix><pid><suffix>` of a target whose process no
// longer runs: what a killed writer left behind.
void RemoveStaleTemporaries(const fs::path& folder,
  const std::string& prefix,
  const std::string& suffix)
{
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec))
  {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + suffix.size() ||
      name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    {
      continue;
    }
    const std::string pid = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!pid.empty() && pid.size() <= 9 &&
      pid.find_first_not_of("0123456789") == std::string::npos &&
      !IsRunningProcess(static_cast<pid_t>(std::stol(pid))))
    {
      RemoveQuietly(it->path().string());
    }
  }
}

// fsync of a file or directory; 0 or the errno.
int SyncPath(const std::string& path, bool directory)
{
  const int fd = ::open(path.c_str(), (directory ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
  if (fd < 0)
  {
    return errno;
  }
  int result = ::fsync(fd) == 0 ? 0 : errno;
  if (::close(fd) != 0 && result == 0)
  {
    result = errno;
  }
  // Some file systems cannot fsync a directory: that is not a failed write.
  return (directory && result == EINVAL) ? 0 : result;
}

// fsync of every file and folder under `root` (and `root`); 0 or the errno.
int SyncTree(const std::string& root)
{
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
  {
    const bool directory = it->is_directory(ec);
    if (const int result = SyncPath(it->path().string(), directory))
    {
      return result;
    }
  }
  if (ec)
  {
    return ec.value();
  }
  return SyncPath(root, true);
}

std::string FolderOf(const std::string& path)
{
  const std::string folder = fs::path(path).parent_path().string();
  return folder.empty() ? std::string(".") : folder;
}
}

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
bool CheckRegularFile(const std::string& path, std::string& problem)
{
  struct stat status;
  if (::stat(path.c_str(), &status) != 0)
  {
    problem = errno == ENOENT ? std::string("file not found") : SystemError(errno);
    return false;
  }
  if (S_ISDIR(status.st_mode))
  {
    problem = "is a directory, not a file";
    return false;
  }
  if (!S_ISREG(status.st_mode))
  {
    problem = "is not a regular file (a FIFO, device or socket)";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string TemporaryFileName(const std::string& path)
{
  const fs::path target(path);
  const std::string stem = target.stem().string() + ".tmp-";
  const std::string extension = target.extension().string();
  RemoveStaleTemporaries(target.parent_path(), stem, extension);
  fs::path temporary = target;
  temporary.replace_filename(target.stem().string() + TemporaryTag() + extension);
  return temporary.string();
}

//------------------------------------------------------------------------------
std::string TemporaryDirectoryName(const std::string& path)
{
  const fs::path target(TrimSeparators(path));
  RemoveStaleTemporaries(target.parent_path(), target.filename().string() + ".tmp-", "");
  return target.string() + TemporaryTag();
}

//------------------------------------------------------------------------------
std::string NameTargets(std::string text)
{
  const std::string tag = TemporaryTag();
  for (std::size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at))
  {
    // ".tmp-12" is not a temporary of process 12 inside ".tmp-123".
    const std::size_t end = at + tag.size();
    if (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])))
    {
      at = end;
      continue;
    }
    text.erase(at, tag.size());
  }
  return text;
}

//------------------------------------------------------------------------------
void RemoveQuietly(const std::string& path)
{
  std::error_code ec;
  fs::remove_all(path, ec);
}

//------------------------------------------------------------------------------
bool WriteFileContents(const std::string& path, const void* data, size_t size, std::string& error)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    error = "cannot create the file: " + SystemError(errno);
    return false;
  }
  const char* bytes = static_cast<const char*>(data);
  int failure = 0;
  while (size > 0 && failure == 0)
  {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0)
    {
      failure = errno == EINTR ? 0 : errno;
      continue;
    }
    bytes += written;
    size -= static_cast<size_t>(written);
  }
  // A full disk may only show at fsync or close (delayed allocation, NFS).
  if (failure == 0 && ::fsync(fd) != 0)
  {
    failure = errno;
  }
  if (::close(fd) != 0 && failure == 0)
  {
    failure = errno;
  }
  if (failure != 0)
  {
    error = "cannot write the file: " + SystemError(failure);
    RemoveQuietly(path);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool WriteFileAtomically(const std::string& path, const std::string& contents, std::string& error)
{
  const std::string temporary = TemporaryFileName(path);
  return WriteFileContents(temporary, contents.data(), contents.size(), error) &&
    CommitFile(temporary, path, error);
}

//------------------------------------------------------------------------------
bool CommitFile(const std::string& temporary, const std::string& path, std::string& error)
{
  if (const int result = SyncPath(temporary, false))
  {
    error = "cannot write the file: " + SystemError(result);
    RemoveQuietly(temporary);
    return false;
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec)
  {
    error = "cannot replace the file: " + ec.message();
    RemoveQuietly(temporary);
    return false;
  }
  // The rename itself is durable only once the folder is flushed.
  if (const int result = SyncPath(FolderOf(path), true))
  {
    error = "cannot flush the folder: " + SystemError(result);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool CommitDirectory(const std::string& temporary, const std::string& path, std::string& error)
{
  const std::string target = TrimSeparators(path);
  if (const int result = SyncTree(temporary))
  {
    error = "cannot write the directory: " + SystemError(result);
    RemoveQuietly(temporary);
    return false;
  }
  std::error_code ec;
  std::string aside;
  if (fs::exists(target, ec))
  {
    aside = target + ".old-" + std::to_string(::getpid());
    RemoveQuietly(aside);
    fs::rename(target, aside, ec);
    if (ec)
    {
      error = "cannot move the existing directory aside: " + ec.message();
      RemoveQuietly(temporary);
      return false;
    }
  }
  fs::rename(temporary, target, ec);
  if (ec)
  {
    error = "cannot replace the directory: " + ec.message();
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
  if (const int result = SyncPath(FolderOf(target), true))
  {
    error = "cannot flush the folder: " + SystemError(result);
    return false;
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
