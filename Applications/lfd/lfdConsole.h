/**
 * @file   lfdConsole.h
 * @brief  How the `lfd` tool talks to a terminal: one readable line per VTK
 *         error, and progress bars for long algorithms.
 */
#ifndef lfdConsole_h
#define lfdConsole_h

#include <string>

class vtkAlgorithm;

namespace lfd
{
/**
 * Routes VTK's errors and warnings to stderr as single lines
 * ("lfd: error: <message>"), without VTK's source-file prefix, and
 * remembers whether an error was reported.
 */
void InstallConsoleOutput();

/**
 * The message of a VTK error or warning text without VTK's prefix
 * ("ERROR: In <file>, line <n>\n<class> (<address>): ") and trailing blank
 * lines: what an ErrorEvent observer receives, said in one line.
 */
std::string StripLocation(const char* text);

/// True once any VTK error has been reported.
bool ErrorReported();

/// Prints "lfd: error: <message>" on stderr, once per distinct message.
void ReportError(const std::string& message);

/// Prints "lfd: warning: <message>" on stderr.
void ReportWarning(const std::string& message);

/**
 * From now on, messages name `target` where they would name `temporary`: an
 * output staged under a temporary name is reported under the name the user
 * gave.
 */
void AliasPath(const std::string& temporary, const std::string& target);

/**
 * True when an X display can be opened (DISPLAY set and the server answers):
 * VTK's OpenGL windows abort the process without one.
 */
bool DisplayAvailable();

/**
 * Shows the algorithm's progress events on stderr, labelled `what`: a bar
 * redrawn in place on a terminal, one line per 10% otherwise (logs).
 */
void ShowProgress(vtkAlgorithm* algorithm, const std::string& what);
}

#endif
