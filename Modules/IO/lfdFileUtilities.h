/**
 * @file   lfdFileUtilities.h
 * @brief  atomic, durable replacement of files and directories
 *
 * Writers never leave a half-written file or dataset that looks valid, and a
 * failed write (disk full, no permission) never costs the previous file: they
 * write into a temporary sibling (same folder, so the final rename stays on
 * one file system), check every write, flush it to the disk (fsync), and
 * rename it onto the target only when it is complete. Temporaries are named
 * `<target>.tmp-<pid>`; one left behind by a process that no longer runs is
 * removed the next time the same target is written. Error messages name the
 * target, never the temporary.
 *
 * Public (not wrapped): the command line writes its multi-file outputs with
 * TemporaryDirectoryName() and CommitDirectory().
 */
#ifndef lfdFileUtilities_h
#define lfdFileUtilities_h

#include "lfdIOModule.h" // For export macro

#include <cstddef>
#include <string>

namespace lfd
{
namespace io
{
/**
 * `path` without trailing separators ("out/" -> "out").
 */
LFDIO_EXPORT std::string TrimSeparators(const std::string& path);

/**
 * Checks that `path` is an existing regular file (following symbolic links)
 * without opening it, so that a FIFO, a device such as /dev/zero or a
 * directory is refused at once instead of blocking or reading forever. On
 * failure returns false and sets `problem` ("file not found", "is a
 * directory, not a file", ...), without the file name.
 */
LFDIO_EXPORT bool CheckRegularFile(const std::string& path, std::string& problem);

/**
 * Temporary sibling of a file: "dir/name.tmp-<pid>.ext" (the extension is
 * kept so image libraries still recognise the format). Removes stale
 * temporaries of the same target left by processes that no longer run.
 */
LFDIO_EXPORT std::string TemporaryFileName(const std::string& path);

/**
 * Temporary sibling of a directory: "DIR.tmp-<pid>". Removes stale
 * temporaries of the same target left by processes that no longer run, and
 * this process's own earlier one.
 */
LFDIO_EXPORT std::string TemporaryDirectoryName(const std::string& path);

/**
 * `text` (a message) with every temporary name of this process
 * (TemporaryFileName(), TemporaryDirectoryName()) replaced by its target's:
 * an output staged under a temporary name is reported under the name the
 * user gave.
 */
LFDIO_EXPORT std::string NameTargets(std::string text);

/**
 * Creates or truncates `path` and writes `size` bytes, checking every write,
 * the fsync and the close. On failure removes `path`, returns false and sets
 * `error` (the system's reason, e.g. "No space left on device").
 */
LFDIO_EXPORT bool WriteFileContents(const std::string& path,
  const void* data,
  size_t size,
  std::string& error);

/**
 * Replaces the file `path` by `contents`: WriteFileContents() into
 * TemporaryFileName(path), then CommitFile(). On failure `path` is untouched,
 * no temporary is left and `error` says why (without any file name).
 */
LFDIO_EXPORT bool WriteFileAtomically(const std::string& path,
  const std::string& contents,
  std::string& error);

/**
 * Flushes the file `temporary` to the disk and renames it onto `path`
 * (replacing it), then flushes the folder. On failure removes `temporary`,
 * returns false and sets `error` (without any file name).
 */
LFDIO_EXPORT bool CommitFile(const std::string& temporary,
  const std::string& path,
  std::string& error);

/**
 * Replaces the directory `path` by the complete directory `temporary`: every
 * file in `temporary` is flushed to the disk, an existing `path` is moved
 * aside, the new one renamed into place, then the old one removed. On failure
 * the old `path` is restored, `temporary` removed, and `error` set (without
 * any file name).
 */
LFDIO_EXPORT bool CommitDirectory(const std::string& temporary,
  const std::string& path,
  std::string& error);

/**
 * Removes a file or directory tree, ignoring errors.
 */
LFDIO_EXPORT void RemoveQuietly(const std::string& path);

/**
 * The folder holding `path` ("" for a bare file name) and `relative` resolved
 * against a folder (absolute paths are returned unchanged).
 */
LFDIO_EXPORT std::string ParentFolder(const std::string& path);
LFDIO_EXPORT std::string ResolvePath(const std::string& folder, const std::string& relative);
}
}

#endif
