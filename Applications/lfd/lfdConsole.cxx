#include "lfdConsole.h"

#include "lfdFileUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <unistd.h>

// Last: Xlib's macros (Status, Bool, None) must not reach the VTK headers.
#include <X11/Xlib.h>

namespace
{
/// SetConsoleQuiet(): nothing said, not even progress.
bool Quiet = false;

struct ProgressState
{
  std::string What;
  int LastStep = -1;
  bool Terminal = false;
  /// The step an object says it is on (ShowSteps()); empty for an algorithm.
  std::function<std::string(vtkObject*)> Step;
  std::string LastText;
};

void OnProgress(vtkObject* caller, unsigned long event, void* clientData, void* callData)
{
  auto* state = static_cast<ProgressState*>(clientData);
  if (event == vtkCommand::DeleteEvent)
  {
    delete state;
    return;
  }
  if (Quiet)
  {
    return;
  }
  const double progress = *static_cast<double*>(callData);
  const int percent = static_cast<int>(100.0 * progress + 0.5);
  const std::string text = state->Step ? state->Step(caller) : std::string();
  if (state->Terminal)
  {
    const int width = 30;
    const int filled = static_cast<int>(width * progress + 0.5);
    std::fprintf(stderr,
      "\r%-12s [%s%s] %3d%% %s\033[K",
      state->What.c_str(),
      std::string(filled, '#').c_str(),
      std::string(width - filled, '.').c_str(),
      percent,
      text.c_str());
    if (percent >= 100)
    {
      std::fputc('\n', stderr);
    }
    std::fflush(stderr);
  }
  else if (state->Step)
  {
    // A log gets each step once, in words.
    if (text != state->LastText)
    {
      state->LastText = text;
      std::fprintf(stderr, "%s: %s\n", state->What.c_str(), text.c_str());
    }
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
CommandErrors::CommandErrors()
{
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  this->DisplayMode = window->GetDisplayMode();
  window->SetDisplayModeToNever();
  this->Errors->Observe(window);
  // A warning is said when it comes, not kept for the end.
  vtkNew<vtkCallbackCommand> warn;
  warn->SetCallback(
    [](vtkObject*, unsigned long, void*, void* callData)
    {
      PrintWarning(
        vtkLightFieldErrorObserver::StripLocation(callData ? static_cast<char*>(callData) : ""));
    });
  this->WarningTag = window->AddObserver(vtkCommand::WarningEvent, warn, 1.0f);
  // vtkLogger would print every error a second time, with a timestamp.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

CommandErrors::~CommandErrors()
{
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  window->RemoveObserver(this->WarningTag);
  this->Errors->StopObserving();
  window->SetDisplayMode(this->DisplayMode);
}

void CommandErrors::Refuse(const std::string& message)
{
  if (this->Refusal.empty())
  {
    this->Refusal = message;
  }
}

int CommandErrors::Finish()
{
  const std::string first =
    this->Errors->HasError() ? this->Errors->GetErrorMessage() : this->Refusal;
  if (first.empty())
  {
    return 0;
  }
  PrintError(first);
  return 1;
}

void SetConsoleQuiet(bool quiet)
{
  Quiet = quiet;
}

void PrintError(const std::string& message)
{
  if (Quiet)
  {
    return;
  }
  std::cerr << "lfd: error: " << lfd::io::NameTargets(message) << std::endl;
}

void PrintWarning(const std::string& message)
{
  if (Quiet)
  {
    return;
  }
  std::cerr << "lfd: warning: " << lfd::io::NameTargets(message) << std::endl;
}

void PrintWarnings(vtkLightFieldErrorObserver* errors)
{
  for (int i = 0; i < errors->GetNumberOfWarnings(); ++i)
  {
    PrintWarning(errors->GetWarning(i));
  }
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

namespace
{
void Observe(vtkObject* object, ProgressState* state)
{
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnProgress);
  callback->SetClientData(state);
  object->AddObserver(vtkCommand::ProgressEvent, callback);
  object->AddObserver(vtkCommand::DeleteEvent, callback);
}
}

void ShowProgress(vtkObject* object, const std::string& what)
{
  Observe(object, new ProgressState{ what, -1, isatty(fileno(stderr)) != 0 });
}

void ShowSteps(vtkObject* object,
  const std::string& what,
  const std::function<std::string(vtkObject*)>& step)
{
  Observe(object, new ProgressState{ what, -1, isatty(fileno(stderr)) != 0, step });
}
}
