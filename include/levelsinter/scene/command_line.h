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
      version,
      print_parameters
    };

    Action      action = Action::run;
    std::string scene_file;
    // ("Section/subsection/entry", "value") pairs from --set, in order.
    std::vector<std::pair<std::string, std::string>> overrides;
    // --overwrite: replace an earlier run in the output directory.
    bool overwrite = false;
    // --resume DIRECTORY: continue the run there from its newest checkpoint;
    // the scene is DIRECTORY/parameters.prm.
    std::string resume_directory;

    static CommandLine
    parse(int argc, char **argv);

    static std::string
    usage();
  };

  /**
   * @p message about a value, prefixed with where the values it names came
   * from: each --set of an entry the message names in quotes (the last one
   * per entry; 'Section/Entry', or 'Entry' in the section of the entry the
   * message is about), and the scene file unless a --set gave that entry.
   */
  std::string
  with_source(
    const std::string                                      &message,
    const std::string                                      &scene_file,
    const std::vector<std::pair<std::string, std::string>> &overrides);

  /**
   * Declare all entries in @p prm, read @p scene_file (if not empty) and
   * apply the overrides, without checking the values: the entries as the
   * user gave them. Throws std::runtime_error naming the file or the --set.
   */
  void
  read_scene_entries(
    ParameterHandler                                       &prm,
    const std::string                                      &scene_file,
    const std::vector<std::pair<std::string, std::string>> &overrides);

  /**
   * Declare all entries, read @p scene_file (if not empty), apply the
   * overrides and check everything. Any problem throws std::runtime_error
   * whose message names the file, the line or entry, and what is allowed.
   */
  SceneParameters
  read_scene(const std::string &scene_file,
             const std::vector<std::pair<std::string, std::string>> &overrides);

  /**
   * The same, leaving every entry with its effective value (the file's or
   * an override's, else the default) in @p prm, which this function
   * declares: what --print-parameters shows and parameters.prm records. A
   * relative Geometry/Particle file is made absolute there, so that the
   * record can be run again from anywhere.
   */
  SceneParameters
  read_scene(ParameterHandler  &prm,
             const std::string &scene_file,
             const std::vector<std::pair<std::string, std::string>> &overrides);
} // namespace levelsinter
