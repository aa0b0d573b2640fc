/**
 * @file   lfdConsole.h
 * @brief  How the `lfd` tool talks to a terminal: the errors of a command
 *         said as one line, warnings, and progress bars for long algorithms.
 */
#ifndef lfdConsole_h
#define lfdConsole_h

#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"

#include <functional>
#include <string>

class vtkObject;

namespace lfd
{
/**
 * The error channel of one `lfd` command run (main() owns one per run).
 * While it exists VTK's output window displays nothing: every error or
 * warning that no object observer took comes to this run's
 * vtkLightFieldErrorObserver instead. Finish() says the run's first error
 * as its one line, "lfd: error: <message>"; warnings are said as they come.
 */
class CommandErrors
{
public:
  CommandErrors();
  ~CommandErrors();
  CommandErrors(const CommandErrors&) = delete;
  void operator=(const CommandErrors&) = delete;

  /**
   * A refusal of the tool's own (the message a command stopped with); it is
   * the run's error unless VTK reported one first.
   */
  void Refuse(const std::string& message);

  /**
   * Says the first error, if any; returns the exit status: 1 after an error,
   * 0 otherwise.
   */
  int Finish();

private:
  vtkNew<vtkLightFieldErrorObserver> Errors;
  unsigned long WarningTag = 0;
  int DisplayMode = 0;
  std::string Refusal;
};

/**
 * Quiet: PrintError(), PrintWarning() and the progress print nothing. The processes of an
 * MPI job other than process 0 are quiet: process 0 speaks for the job
 * (lfd::cli::ProcessGroup).
 */
void SetConsoleQuiet(bool quiet);

/**
 * Prints "lfd: error: <message>" on stderr, a temporary name replaced by
 * the name the user gave (lfd::io::NameTargets()).
 */
void PrintError(const std::string& message);

/// Prints "lfd: warning: <message>" on stderr, as PrintError().
void PrintWarning(const std::string& message);

/// Prints the warnings `errors` recorded.
void PrintWarnings(vtkLightFieldErrorObserver* errors);

/**
 * True when an X display can be opened (DISPLAY set and the server answers):
 * VTK's OpenGL windows abort the process without one.
 */
bool DisplayAvailable();

/**
 * Shows the progress events of an algorithm (or of any object that sends
 * them: vtkLightFieldTiler) on stderr, labelled `what`: a bar
 * redrawn in place on a terminal, one line per 10% otherwise (logs).
 */
void ShowProgress(vtkObject* object, const std::string& what);

/**
 * Shows the progress events of an object that says which step it is on
 * (`step`, e.g. "frame 3/48" of vtkLightFieldAnimationWriter), labelled
 * `what`: the bar and the step on a terminal, one line "<what>: <step>" per
 * new step otherwise (logs).
 */
void ShowSteps(vtkObject* object,
  const std::string& what,
  const std::function<std::string(vtkObject*)>& step);
}

#endif
