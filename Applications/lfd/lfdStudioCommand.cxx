// `lfd studio`: starts LightField Studio, the executable installed next to lfd.
#include "lfdCommands.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace lfd::cli
{
void AddStudioCommand(CLI::App& app, NumericOptions&, std::vector<Command>& commands)
{
  // The Studio's own options, given on as they are (it checks them).
  static const char* const forwarded[][2] = {
    { "--layout", "views: main, camera or four-up" },
    { "--view", "the gantry camera view's captured view" },
    { "--pass", "the gantry camera view's pass (Coaxial, Label...)" },
    { "--projector", "the projector view's projector" },
    { "--screenshot", "write a PNG of the window once it has drawn, then exit" },
  };
  auto arguments = std::make_shared<std::vector<std::string>>(std::size(forwarded) + 1);
  auto* studio = app.add_subcommand("studio",
    "open LightField Studio (the Qt application LightFieldStudio next to lfd) on FILE: a scene "
    "(scene.json) or a light field (*.lf); needs an X display");
  studio->add_option("file", arguments->back(), "scene.json or light field to open");
  for (size_t i = 0; i < std::size(forwarded); ++i)
  {
    studio->add_option(forwarded[i][0], (*arguments)[i], forwarded[i][1]);
  }
  commands.push_back({ studio,
    [arguments]
    {
      // The Studio replaces this process, so its exit status is lfd's.
      const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
      const std::string path = (self.parent_path() / "LightFieldStudio").string();
      std::vector<std::string> words = { path };
      for (size_t i = 0; i < std::size(forwarded); ++i)
      {
        if (!(*arguments)[i].empty())
        {
          words.insert(words.end(), { forwarded[i][0], (*arguments)[i] });
        }
      }
      if (!arguments->back().empty())
      {
        words.push_back(arguments->back());
      }
      std::vector<char*> argv;
      for (std::string& word : words)
      {
        argv.push_back(word.data());
      }
      argv.push_back(nullptr);
      execv(path.c_str(), argv.data());
      Fail("cannot start " + path + ": " + std::strerror(errno));
    },
    true });
}
}
