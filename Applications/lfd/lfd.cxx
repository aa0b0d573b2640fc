// lfd: the LightField Deform command-line tool.
//
// Every subcommand is a thin layer over the library's VTK algorithms (the
// same classes Python scripts use through `import lfd`): it parses options,
// wires the pipeline, reports progress and turns errors into one line and a
// non-zero exit status. The subcommands live one group per file
// (lfdCommands.h); this file holds the command line itself: parsing,
// suggestions for mistyped words, and main().
#include "lfdCommands.h"
#include "lfdProcessGroup.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
/// Levenshtein distance: how many letters to insert, delete or change.
std::size_t EditDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1) });
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// " (did you mean 'X'?)" for the candidate nearest to `word` when it is
/// close (at most a third of its letters differ), else "".
std::string Suggestion(const std::string& word,
  const std::vector<std::string>& candidates,
  const std::string& prefix = "")
{
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates)
  {
    const std::size_t distance = EditDistance(word, candidate);
    if (distance < bestDistance)
    {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best.empty() ? "" : " (did you mean '" + prefix + best + "'?)";
}

/// "lfd eval loo" for the loo subcommand.
std::string CommandName(const CLI::App* command)
{
  std::string name;
  for (; command; command = command->get_parent())
  {
    name = (command->get_parent() ? command->get_name() : std::string("lfd")) +
      (name.empty() ? "" : " " + name);
  }
  return name;
}

std::vector<std::string> SubcommandNames(const CLI::App* command)
{
  std::vector<std::string> names;
  for (const CLI::App* sub : command->get_subcommands({}))
  {
    names.push_back(sub->get_name());
  }
  return names;
}

/// The deepest subcommand the parser selected (the root when none).
CLI::App* SelectedCommand(CLI::App* app)
{
  for (;;)
  {
    const std::vector<CLI::App*> selected = app->get_subcommands();
    if (selected.empty())
    {
      return app;
    }
    app = selected.front();
  }
}

/**
 * Checks the leading words of the command line name existing commands
 * ("lfd rendr" would otherwise be "A subcommand is required"). Returns the
 * usage error, or "".
 */
std::string CheckCommandWords(CLI::App* app, int argc, char* argv[])
{
  CLI::App* level = app;
  for (int i = 1; i < argc && !level->get_subcommands({}).empty(); ++i)
  {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-')
    {
      break;
    }
    const std::vector<std::string> names = SubcommandNames(level);
    if (std::find(names.begin(), names.end(), word) == names.end())
    {
      std::string list;
      for (const std::string& name : names)
      {
        list += (list.empty() ? "" : ", ") + name;
      }
      const std::string prefix = level == app ? "" : CommandName(level).substr(4) + " ";
      const std::string hint = Suggestion(word, names, prefix);
      return "unknown command '" + prefix + word + "'" +
        (hint.empty() ? " (commands: " + list + ")" : hint);
    }
    level = level->get_subcommand(word);
  }
  return "";
}

/// One line for a command line CLI11 refused.
std::string DescribeParseError(CLI::App* app, const CLI::ParseError& error)
{
  CLI::App* command = SelectedCommand(app);
  const std::string name = CommandName(command);
  if (dynamic_cast<const CLI::RequiredError*>(&error) &&
    std::string(error.what()).find("subcommand") != std::string::npos)
  {
    std::string list;
    for (const std::string& sub : SubcommandNames(command))
    {
      list += (list.empty() ? "" : ", ") + sub;
    }
    return name + ": a command is required: " + list;
  }
  return name + ": " + error.what() + " (see " + name + " --help)";
}

/// Arguments the parser could not place: an unknown option or a surplus word.
std::string DescribeExtras(CLI::App* app)
{
  const std::vector<std::string> extras = app->remaining(true);
  if (extras.empty())
  {
    return "";
  }
  CLI::App* command = SelectedCommand(app);
  const std::string name = CommandName(command);
  const std::string extra = extras.front();
  if (extra.size() > 1 && extra[0] == '-')
  {
    std::vector<std::string> options;
    for (const CLI::Option* option : command->get_options())
    {
      for (const std::string& longName : option->get_lnames())
      {
        options.push_back("--" + longName);
      }
    }
    const std::string word = extra.substr(0, extra.find('='));
    const std::string hint = Suggestion(word, options);
    return name + ": unknown option '" + word + "'" +
      (hint.empty() ? " (see " + name + " --help)" : hint);
  }
  return name + ": unexpected argument '" + extra + "' (see " + name + " --help)";
}

/// Commands that capture or render meshes open an OpenGL window, which
/// aborts the process without an X display: say so first.
void RequireDisplay(const CLI::App* command)
{
  if (lfd::DisplayAvailable())
  {
    return;
  }
  const char* display = std::getenv("DISPLAY");
  const std::string name = CommandName(command);
  Fail(name + " renders with OpenGL and needs an X display (" +
    (display && *display ? "cannot open DISPLAY=" + std::string(display) : "DISPLAY is not set") +
    "); run it as: xvfb-run -a " + name + " ...");
}

/// Footer of every command's --help.
const char* ExitStatusHelp =
  "Exit status: 0 done; 1 refused input or failed (one 'lfd: error:' line, no output "
  "written); 2 malformed command line (unknown command or option, missing argument, value "
  "not among the choices).";

/// Every command: extras collected (reported by DescribeExtras, with a
/// suggestion) and the exit statuses in its --help.
void ConfigureCommands(CLI::App* command)
{
  command->allow_extras();
  command->footer(ExitStatusHelp);
  for (CLI::App* sub : command->get_subcommands({}))
  {
    ConfigureCommands(sub);
  }
}

/// The command named by `path` (its words after `lfd`), or nullptr.
CLI::App* FindCommand(CLI::App* app, const std::vector<std::string>& path)
{
  for (const std::string& word : path)
  {
    CLI::App* next = nullptr;
    for (CLI::App* sub : app->get_subcommands({}))
    {
      next = sub->get_name() == word ? sub : next;
    }
    if (!next)
    {
      return nullptr;
    }
    app = next;
  }
  return app;
}

/// Every command's --help under `app` in turn, depth first.
void PrintAllHelp(const CLI::App* app, const std::string& prefix)
{
  for (const CLI::App* sub : app->get_subcommands({}))
  {
    if (sub->get_name() != "help")
    {
      std::cout << sub->help(prefix) << "\n";
      PrintAllHelp(sub, prefix + " " + sub->get_name());
    }
  }
}

/// `lfd --help`'s text (app.help() would give the help of the command that
/// was parsed, `help` itself).
std::string Overview(const CLI::App& app)
{
  return app.get_formatter()->make_help(&app, "lfd", CLI::AppFormatMode::Normal);
}

/// `lfd help [COMMAND [SUBCOMMAND]]` prints the same text as the command's
/// --help (one source for both); `lfd help all` every command's, the
/// reference manual in one page.
void AddHelpCommand(CLI::App& app, std::vector<Command>& commands)
{
  auto topic = std::make_shared<std::vector<std::string>>();
  auto* help = app.add_subcommand("help",
    "print the help of a command (lfd help render, lfd help split projector), or of every "
    "command (lfd help all)");
  help->add_option("topic", *topic, "a command and its subcommand; 'all' for every command");
  commands.push_back({ help,
    [&app, topic]
    {
      if (topic->size() == 1 && topic->front() == "all")
      {
        std::cout << Overview(app) << "\n";
        PrintAllHelp(&app, "lfd");
        return;
      }
      const CLI::App* command = FindCommand(&app, *topic);
      if (!command)
      {
        std::string known;
        for (const CLI::App* sub : app.get_subcommands({}))
        {
          known += (known.empty() ? "" : ", ") + sub->get_name();
        }
        std::string asked;
        for (const std::string& word : *topic)
        {
          asked += (asked.empty() ? "" : " ") + word;
        }
        Fail("help: no command '" + asked + "' (commands: " + known + ")");
      }
      std::string prefix = "lfd";
      for (size_t i = 0; i + 1 < topic->size(); ++i)
      {
        prefix += " " + (*topic)[i];
      }
      std::cout << (topic->empty() ? Overview(app) : command->help(prefix));
    },
    false });
}

/// The commands, their options and what they run; the run's errors go to
/// `errors`.
int Main(int argc, char* argv[], lfd::CommandErrors& errors)
{
  CLI::App app{ "LightField Deform: capture, render and deform light fields.\n"
                "Run 'lfd <command> --help' for the options of a command." };
  app.require_subcommand(1);
  app.set_version_flag("--version", "lfd " LFD_VERSION, "print the version (lfd X.Y.Z) and exit");
  NumericOptions numbers;
  std::vector<Command> commands;
  AddCaptureCommands(app, numbers, commands);
  AddImportCommands(app, numbers, commands);
  AddTwoPlaneCommands(app, numbers, commands);
  AddRenderCommands(app, numbers, commands);
  AddEvalCommands(app, numbers, commands);
  AddBenchCommand(app, numbers, commands);
  AddDemoCommand(app, numbers, commands);
  AddSplitCommands(app, numbers, commands);
  AddCalibrateCommands(app, numbers, commands);
  AddStudioCommand(app, numbers, commands);
  AddAcquisitionCommands(app, numbers, commands);
  AddCameraSimCommand(app, numbers, commands);
  AddCaptureSessionCommand(app, numbers, commands);
  AddHelpCommand(app, commands);

  ConfigureCommands(&app);
  const std::string unknown = CheckCommandWords(&app, argc, argv);
  if (!unknown.empty())
  {
    lfd::PrintError(unknown);
    return 2;
  }
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::Success& success) // --help, --version
  {
    return app.exit(success);
  }
  catch (const CLI::ParseError& error)
  {
    const std::string extras = DescribeExtras(&app);
    lfd::PrintError(extras.empty() ? DescribeParseError(&app, error) : extras);
    return 2;
  }
  const std::string extras = DescribeExtras(&app);
  if (!extras.empty())
  {
    lfd::PrintError(extras);
    return 2;
  }

  try
  {
    numbers.Convert();
    for (const Command& command : commands)
    {
      if (*command.App)
      {
        ProcessGroup::Check(command.App->get_name().c_str());
        if (command.NeedsDisplay)
        {
          RequireDisplay(command.App);
        }
        command.Run();
      }
    }
  }
  catch (const Failure& failure)
  {
    errors.Refuse(failure.Message);
  }
  // Whatever reported an error, a refusal of ours or any VTK object's
  // message, decides the exit status; the first one is said.
  return errors.Finish();
}
}
}

int main(int argc, char* argv[])
{
  // First and last: MPI under `mpirun` (lfdProcessGroup.h).
  lfd::cli::ProcessGroup processes(&argc, &argv);
  lfd::CommandErrors errors;
  // No exception leaves lfd: whatever escapes a command is one error line.
  try
  {
    return lfd::cli::Main(argc, argv, errors);
  }
  catch (const std::bad_alloc&)
  {
    errors.Refuse("out of memory");
  }
  catch (const std::exception& exception)
  {
    errors.Refuse(exception.what());
  }
  catch (...)
  {
    errors.Refuse("unexpected internal error");
  }
  return errors.Finish();
}
