/**
 * @file   lfdProcessAgreement.h
 * @brief  the processes of one job (e.g. `mpirun -np N lfd animate`) going
 *         on together or stopping together with one error
 *
 * When each process checks its own inputs, they must agree before a
 * collective step, or the ones that passed would wait forever for the ones
 * that stopped. Used by vtkLightFieldAnimationWriter and the `lfd` command
 * line. Not wrapped (std:: types).
 */
#ifndef lfdProcessAgreement_h
#define lfdProcessAgreement_h

#include "lfdSceneModule.h" // For export macro

#include <string> // For std::string

class vtkMultiProcessController;

namespace lfd
{
namespace scene
{
/**
 * The first non-empty `error` of the processes of `controller` (process 0's
 * first, then by process index), returned on every process; "" when every
 * process passed. Every process must call it. Without a controller, or with
 * one process, `error` itself.
 */
LFDSCENE_EXPORT std::string AgreeOnError(vtkMultiProcessController* controller,
  const std::string& error);

/**
 * Process 0's `text`, returned on every process (the others' `text` is not
 * used). Every process must call it. Without a controller, `text` itself.
 */
LFDSCENE_EXPORT std::string ShareText(vtkMultiProcessController* controller,
  const std::string& text);
}
}

#endif
