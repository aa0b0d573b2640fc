/**
 * @file   lfdStagedFolder.h
 * @brief  a multi-file output folder written under a temporary name and
 *         renamed onto its target only when complete
 *
 * The one implementation behind every multi-file output: the animation
 * export (vtkLightFieldAnimationWriter, hence the Studio's export dialog)
 * and the `lfd` command line's output folders (`lfd demo`, `lfd animate`).
 * Public for the command line, not wrapped (std:: types).
 */
#ifndef lfdStagedFolder_h
#define lfdStagedFolder_h

#include "lfdSceneModule.h" // For export macro

#include <string> // For std::string
#include <vector> // For std::vector

namespace lfd
{
namespace scene
{
/**
 * The folder is written under a temporary sibling name
 * (lfd::io::TemporaryDirectoryName) and renamed onto its target by Commit()
 * only when complete: a writer that fails or is cancelled leaves neither a
 * partial folder nor the temporary (Discard(), or the destructor), and an
 * existing target is replaced only on success. Since the whole target is
 * replaced, an existing one must hold nothing but files the writer writes
 * (`patterns`, fnmatch globs): a folder of the user's is never swept away.
 */
class LFDSCENE_EXPORT StagedFolder
{
public:
  StagedFolder() = default;
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  void operator=(const StagedFolder&) = delete;

  /**
   * Checks the target and creates the empty temporary. On failure returns
   * false and sets `error`, one line naming the target ("<target>: holds
   * 'notes.txt', which <writer> does not write; ..."); nothing is created.
   */
  bool Open(const std::string& target,
    const std::string& writer,
    const std::vector<std::string>& patterns,
    std::string& error);

  /// Where the writer writes (empty before Open()).
  const std::string& GetPath() const { return this->Temporary; }

  /// The folder Commit() replaces.
  const std::string& GetTarget() const { return this->Target; }

  /**
   * Replaces the target with the complete folder; on failure the target is
   * as it was, the temporary removed and `error` says why (without a name).
   */
  bool Commit(std::string& error);

  /// Removes the temporary (a failed or cancelled write); the target is untouched.
  void Discard();

private:
  std::string Target;
  std::string Temporary;
};

/**
 * The files of an animation folder (fnmatch globs): its frames
 * frame_NNNN.png, animation.mp4, contact_sheet.png and the ParaView series
 * (frame_NNNN.vti, cage_NNNN.vtu, animation.pvd, cage.pvd).
 */
LFDSCENE_EXPORT std::vector<std::string> AnimationFilePatterns();
}
}

#endif
