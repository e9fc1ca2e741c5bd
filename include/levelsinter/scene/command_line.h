#pragma once

#include <levelsinter/scene/scene_parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  /**
   * What the user asked for on the command line. Parsing is strict: an
   * unknown flag or a malformed `--set` is an error.
   */
  struct CommandLine
  {
    enum class Action
    {
      run,
      help,
      print_parameters
    };

    Action      action = Action::run;
    std::string scene_file;
    // ("Section/subsection/entry", "value") pairs from --set, in order.
    std::vector<std::pair<std::string, std::string>> overrides;

    static CommandLine
    parse(int argc, char **argv);

    static std::string
    usage();
  };

  /**
   * Declare all entries, read @p scene_file (if not empty), apply the
   * overrides and check everything. Any problem throws std::runtime_error
   * whose message names the file, the line or entry, and what is allowed.
   */
  SceneParameters
  read_scene(const std::string &scene_file,
             const std::vector<std::pair<std::string, std::string>> &overrides);
} // namespace levelsinter
