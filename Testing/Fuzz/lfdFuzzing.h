// Shared by the libFuzzer targets of Testing/Fuzz: the per-process scratch
// folder the inputs are written into (one file, or several files from one
// input), and the structure-aware mutator (lfdFuzzing.cxx defines
// LLVMFuzzerCustomMutator for every target).
#ifndef lfdFuzzing_h
#define lfdFuzzing_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lfdfuzz
{
/**
 * Writes the fuzzer's input to `name` inside the scratch folder and returns
 * its path. The folder is made on first use (under TMPDIR, one per process)
 * and holds a copy of Testing/Fuzz/images, so the seed inputs name images
 * that exist (coaxial/view_0000.png ...); it is removed at exit. VTK's error
 * display is turned off there too: refusing an input is the expected outcome,
 * only a crash, a sanitizer report or a hang is a finding.
 */
std::string WriteInput(const uint8_t* data, size_t size, const std::string& name);

/// The line that separates the files of a multi-file input (WriteInputFiles()).
extern const char* const FileSeparator;

/**
 * Writes an input that holds several files, separated by FileSeparator
 * (a COLMAP model: cameras then images), as the files `names`, in order,
 * in the subfolder `folder` of the scratch folder, and returns that
 * subfolder's path. Parts beyond the names are dropped; a name without its
 * part (the separator mutated away) is not there, whatever an earlier input
 * left.
 */
std::string WriteInputFiles(const uint8_t* data,
  size_t size,
  const std::string& folder,
  const std::vector<std::string>& names);
}

#endif
