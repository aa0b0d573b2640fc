#include "lfdConsole.h"

#include "lfdFileUtilities.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

// Last: Xlib's macros (Status, Bool, None) must not reach the VTK headers.
#include <X11/Xlib.h>

namespace
{
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

void PrintError(const std::string& message)
{
  std::cerr << "lfd: error: " << lfd::io::NameTargets(message) << std::endl;
}

void PrintWarning(const std::string& message)
{
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
