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

/// True once any VTK error has been reported.
bool ErrorReported();

/// Prints "lfd: error: <message>" on stderr, once per distinct message.
void ReportError(const std::string& message);

/**
 * Shows the algorithm's progress events on stderr, labelled `what`: a bar
 * redrawn in place on a terminal, one line per 10% otherwise (logs).
 */
void ShowProgress(vtkAlgorithm* algorithm, const std::string& what);
}

#endif
