/**
 * @file   lfdFileUtilities.h
 * @brief  atomic replacement of files and directories (private to LFD::IO)
 *
 * Writers never leave a half-written file or dataset that looks valid: they
 * write into a temporary sibling (same folder, so the final rename stays on
 * one file system) and rename it onto the target only when it is complete.
 */
#ifndef lfdFileUtilities_h
#define lfdFileUtilities_h

#include <string>

namespace lfd
{
namespace io
{
/**
 * `path` without trailing separators ("out/" -> "out").
 */
std::string TrimSeparators(const std::string& path);

/**
 * Temporary sibling of a file: "dir/name.tmp-<pid>.ext" (the extension is
 * kept so image libraries still recognise the format).
 */
std::string TemporaryFileName(const std::string& path);

/**
 * Temporary sibling of a directory: "DIR.tmp-<pid>".
 */
std::string TemporaryDirectoryName(const std::string& path);

/**
 * Renames the file `temporary` onto `path` (replacing it). On failure
 * removes `temporary`, returns false and sets `error`.
 */
bool CommitFile(const std::string& temporary, const std::string& path, std::string& error);

/**
 * Replaces the directory `path` by the complete directory `temporary`: an
 * existing `path` is first moved aside, then removed once the new one is in
 * place. On failure the old `path` is restored, `temporary` removed, and
 * `error` set.
 */
bool CommitDirectory(const std::string& temporary, const std::string& path, std::string& error);

/**
 * Removes a file or directory tree, ignoring errors.
 */
void RemoveQuietly(const std::string& path);

/**
 * The folder holding `path` ("" for a bare file name) and `relative` resolved
 * against a folder (absolute paths are returned unchanged).
 */
std::string ParentFolder(const std::string& path);
std::string ResolvePath(const std::string& folder, const std::string& relative);
}
}

#endif
