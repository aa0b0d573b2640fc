#include "lfdConsole.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <unistd.h>
#include <utility>
#include <vector>

// Last: Xlib's macros (Status, Bool, None) must not reach the VTK headers.
#include <X11/Xlib.h>

namespace
{
bool errorReported = false;
std::set<std::string> reported;
std::vector<std::pair<std::string, std::string>> aliases; // temporary, target

std::string ApplyAliases(std::string message)
{
  for (const auto& alias : aliases)
  {
    for (std::size_t at = message.find(alias.first); at != std::string::npos;
         at = message.find(alias.first, at + alias.second.size()))
    {
      message.replace(at, alias.first.size(), alias.second);
    }
  }
  return message;
}

}

namespace lfd
{
std::string StripLocation(const char* text)
{
  std::string message(text ? text : "");
  const std::size_t address = message.find("): ");
  if (message.rfind("ERROR: In ", 0) == 0 || message.rfind("Warning: In ", 0) == 0)
  {
    if (address != std::string::npos)
    {
      message = message.substr(address + 3);
    }
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}
}

namespace
{
using lfd::StripLocation;

class ConsoleOutputWindow : public vtkOutputWindow
{
public:
  static ConsoleOutputWindow* New();
  vtkTypeMacro(ConsoleOutputWindow, vtkOutputWindow);

  void DisplayErrorText(const char* text) override
  {
    const std::string message = StripLocation(text);
    // The executive follows an algorithm's own error with "Algorithm
    // vtkX(0x...) returned failure for request: <information dump>": say
    // only that it failed, and only when the algorithm itself said nothing.
    if (message.rfind("Algorithm ", 0) == 0 &&
      message.find(" returned failure for request") != std::string::npos)
    {
      if (!lfd::ErrorReported())
      {
        lfd::ReportError(message.substr(10, message.find('(') - 10) + " failed");
      }
      return;
    }
    lfd::ReportError(message);
  }
  void DisplayWarningText(const char* text) override { lfd::ReportWarning(StripLocation(text)); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { std::cout << text; }
  void DisplayDebugText(const char*) override {}
};
vtkStandardNewMacro(ConsoleOutputWindow);

struct ProgressState
{
  std::string What;
  int LastStep = -1;
  bool Terminal = false;
};

void OnProgress(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* state = static_cast<ProgressState*>(clientData);
  if (event == vtkCommand::DeleteEvent)
  {
    delete state;
    return;
  }
  const double progress = *static_cast<double*>(callData);
  const int percent = static_cast<int>(100.0 * progress + 0.5);
  if (state->Terminal)
  {
    const int width = 30;
    const int filled = static_cast<int>(width * progress + 0.5);
    std::fprintf(stderr,
      "\r%-12s [%s%s] %3d%%",
      state->What.c_str(),
      std::string(filled, '#').c_str(),
      std::string(width - filled, '.').c_str(),
      percent);
    if (percent >= 100)
    {
      std::fputc('\n', stderr);
    }
    std::fflush(stderr);
  }
  else if (percent / 10 != state->LastStep)
  {
    state->LastStep = percent / 10;
    std::fprintf(stderr, "%s: %d%%\n", state->What.c_str(), percent);
  }
}
}

namespace lfd
{
void InstallConsoleOutput()
{
  vtkNew<ConsoleOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  // vtkLogger would print every error a second time, with a timestamp.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

bool ErrorReported()
{
  return errorReported;
}

void ReportError(const std::string& message)
{
  errorReported = true;
  const std::string text = ApplyAliases(message);
  if (reported.insert(text).second) // an error a class logged and returned is said once
  {
    std::cerr << "lfd: error: " << text << std::endl;
  }
}

void ReportWarning(const std::string& message)
{
  std::cerr << "lfd: warning: " << ApplyAliases(message) << std::endl;
}

void AliasPath(const std::string& temporary, const std::string& target)
{
  aliases.emplace_back(temporary, target);
}

bool DisplayAvailable()
{
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    return false;
  }
  Display* display = XOpenDisplay(name);
  if (!display)
  {
    return false;
  }
  XCloseDisplay(display);
  return true;
}

void ShowProgress(vtkAlgorithm* algorithm, const std::string& what)
{
  auto* state = new ProgressState{ what, -1, isatty(fileno(stderr)) != 0 };
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnProgress);
  callback->SetClientData(state);
  algorithm->AddObserver(vtkCommand::ProgressEvent, callback);
  algorithm->AddObserver(vtkCommand::DeleteEvent, callback);
}
}
