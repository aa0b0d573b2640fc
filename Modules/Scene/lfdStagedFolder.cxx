#include "lfdStagedFolder.h"

#include "lfdFileUtilities.h"

#include <algorithm>
#include <filesystem>

#include <fnmatch.h>

namespace lfd
{
namespace scene
{
//------------------------------------------------------------------------------
StagedFolder::~StagedFolder()
{
  this->Discard();
}

//------------------------------------------------------------------------------
bool StagedFolder::Open(const std::string& target,
  const std::string& writer,
  const std::vector<std::string>& patterns,
  std::string& error)
{
  namespace fs = std::filesystem;
  this->Discard();
  this->Target = lfd::io::TrimSeparators(target);
  std::error_code code;
  const fs::file_status status = fs::status(this->Target, code);
  if (fs::exists(status) && !fs::is_directory(status))
  {
    error = this->Target + ": exists and is not a folder";
    return false;
  }
  if (fs::is_directory(status))
  {
    for (const fs::directory_entry& entry : fs::directory_iterator(this->Target, code))
    {
      const std::string name = entry.path().filename().string();
      if (std::none_of(patterns.begin(),
            patterns.end(),
            [&name](const std::string& pattern)
            { return fnmatch(pattern.c_str(), name.c_str(), 0) == 0; }))
      {
        error = this->Target + ": holds '" + name + "', which " + writer +
          " does not write; it replaces the whole folder, so choose a new or empty one";
        return false;
      }
    }
  }
  const std::string temporary = lfd::io::TemporaryDirectoryName(this->Target);
  lfd::io::RemoveQuietly(temporary);
  if (!fs::create_directories(temporary, code))
  {
    error = this->Target + ": cannot create " + temporary + ": " + code.message();
    return false;
  }
  this->Temporary = temporary;
  return true;
}

//------------------------------------------------------------------------------
bool StagedFolder::Commit(std::string& error)
{
  // CommitDirectory() removes the temporary on failure too.
  const bool committed = lfd::io::CommitDirectory(this->Temporary, this->Target, error);
  this->Temporary.clear();
  return committed;
}

//------------------------------------------------------------------------------
void StagedFolder::Discard()
{
  if (!this->Temporary.empty())
  {
    lfd::io::RemoveQuietly(this->Temporary);
    this->Temporary.clear();
  }
}

//------------------------------------------------------------------------------
std::vector<std::string> AnimationFilePatterns()
{
  // Frame numbers have 4 digits or more (frame_%04d.png); the ParaView
  // series (vtkLightFieldAnimationWriter::SetWriteParaView) likewise.
  return { "frame_[0-9][0-9][0-9][0-9]*.png",
    "animation.mp4",
    "contact_sheet.png",
    "frame_[0-9][0-9][0-9][0-9]*.vti",
    "cage_[0-9][0-9][0-9][0-9]*.vtu",
    "animation.pvd",
    "cage.pvd" };
}
}
}
