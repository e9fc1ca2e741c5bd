#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/scene/command_line.h>
#include <levelsinter/scene/parameter_entries.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // deal.II's exceptions carry a long preamble (source file, function);
    // users need only the part that describes their input.
    std::string
    describe(const ExceptionBase &e)
    {
      std::ostringstream out;
      e.print_info(out);
      std::string text = Utilities::trim(out.str());
      // Collapse the multi-line pattern descriptions into one line each.
      std::string result;
      for (const char c : text)
        result += (c == '\n' ? ' ' : c);
      return result;
    }

    void
    apply_override(ParameterHandler  &prm,
                   const std::string &path,
                   const std::string &value)
    {
      auto              parts = Utilities::split_string_list(path, '/');
      const std::string entry = parts.back();
      parts.pop_back();
      unsigned int depth = 0;
      try
        {
          for (const auto &section : parts)
            {
              prm.enter_subsection(section);
              ++depth;
            }
          prm.set(entry, value);
        }
      catch (const ExceptionBase &e)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          throw std::runtime_error("--set '" + path + "=" + value +
                                   "': " + describe(e));
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
    }

  } // namespace

  std::string
  CommandLine::usage()
  {
    return "Usage:\n"
           "  levelsinter [--overwrite] [--set \"Section/entry=value\"]... "
           "SCENE.prm\n"
           "  mpirun -np N levelsinter SCENE.prm\n"
           "  levelsinter --resume OUTPUT_DIRECTORY [--set ...]...\n"
           "                     continue a run from its newest checkpoint "
           "(any number of ranks)\n"
           "  levelsinter --print-parameters [--set ...]... [SCENE.prm]\n"
           "                     every entry with its effective value (the "
           "defaults without a scene)\n"
           "  levelsinter --version\n"
           "  levelsinter --help\n"
           "\n"
           "SCENE.prm is a deal.II parameter file ('set Entry = value' inside "
           "'subsection Name ... end').\n"
           "--set overrides one entry after the file is read; repeat it for "
           "several, e.g.\n"
           "  levelsinter --set \"Mesh refinement/Maximum level=7\" "
           "scene.prm\n"
           "Subsections are separated by '/'; a top-level entry has no '/'.\n"
           "Relative paths: files a scene reads (Geometry/Particle file) "
           "are found beside the\n"
           "scene file; Output/Directory, and any path given with --set, "
           "are relative to the\n"
           "working directory.\n"
           "Outputs (fields, metrics.csv, parameters.prm) go to "
           "Output/Directory. A directory\n"
           "that holds an earlier run is refused unless --overwrite (or "
           "Output/Overwrite = true)\n"
           "is given; then the earlier run's files are removed first.\n"
           "SIGINT, SIGTERM or SIGUSR1 stops the run after the current step "
           "(exit code 130,\n143 or 138), writing a checkpoint first; under "
           "mpirun send SIGUSR1 (doc/user_guide.md).\n";
  }

  CommandLine
  CommandLine::parse(int argc, char **argv)
  {
    CommandLine cl;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          cl.action = Action::help;
        else if (arg == "--version")
          cl.action = Action::version;
        else if (arg == "--print-parameters")
          cl.action = Action::print_parameters;
        else if (arg == "--overwrite")
          cl.overwrite = true;
        else if (arg == "--resume")
          {
            if (i + 1 >= argc)
              throw std::runtime_error(
                "--resume needs the output directory of the run");
            cl.resume_directory = argv[++i];
          }
        else if (arg == "--set")
          {
            if (i + 1 >= argc)
              throw std::runtime_error(
                "--set needs an argument 'Section/entry=value'");
            const std::string assignment = argv[++i];
            const auto        eq         = assignment.find('=');
            const auto        parts =
              Utilities::split_string_list(assignment.substr(0, eq), '/');
            if (eq == std::string::npos || parts.empty() ||
                std::find(parts.begin(), parts.end(), "") != parts.end())
              throw std::runtime_error("--set '" + assignment +
                                       "': expected 'Section/entry=value'");
            // "A / b = 1" is stored as "A/b", the form error messages use.
            std::string path;
            for (const auto &part : parts)
              path += (path.empty() ? "" : "/") + part;
            cl.overrides.emplace_back(
              path, Utilities::trim(assignment.substr(eq + 1)));
          }
        else if (!arg.empty() && arg[0] == '-')
          throw std::runtime_error("unknown option '" + arg +
                                   "' (see levelsinter --help)");
        else if (cl.scene_file.empty())
          cl.scene_file = arg;
        else
          throw std::runtime_error("more than one scene file given: '" +
                                   cl.scene_file + "' and '" + arg + "'");
      }
    if (!cl.resume_directory.empty())
      {
        if (!cl.scene_file.empty())
          throw std::runtime_error(
            "--resume reads the scene from OUTPUT_DIRECTORY/parameters.prm; "
            "give no scene file with it");
        cl.scene_file = cl.resume_directory + "/parameters.prm";
        // Where the run is, wherever it was started from.
        cl.overrides.insert(cl.overrides.begin(),
                            {"Output/Directory", cl.resume_directory});
      }
    if (cl.action == Action::run && cl.scene_file.empty())
      throw std::runtime_error("no scene file given (see levelsinter --help)");
    return cl;
  }

  void
  read_scene_entries(
    ParameterHandler                                       &prm,
    const std::string                                      &scene_file,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    SceneParameters::declare_parameters(prm);
    if (!scene_file.empty())
      {
        check_text_file(scene_file, "scene file");
        try
          {
            prm.parse_input(scene_file);
          }
        catch (const ExceptionBase &e)
          {
            throw std::runtime_error("scene file '" + scene_file +
                                     "': " + describe(e));
          }
      }
    for (const auto &[path, value] : overrides)
      {
        // A file a --set names is the shell's: relative to the working
        // directory, not to the scene file as the scene's own entries.
        const bool input_file =
          path == "Geometry/Particle file" || path == "Geometry/Pore file";
        apply_override(prm,
                       path,
                       input_file && !value.empty() && value.front() != '/' ?
                         std::filesystem::absolute(value)
                           .lexically_normal()
                           .string() :
                         value);
      }
  }

  std::string
  with_source(
    const std::string                                      &message,
    const std::string                                      &scene_file,
    const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    // The entry the message is about ("entry 'Section/Entry': ...") and its
    // section: a rule across entries names the others as 'Entry' if they
    // are in that section, else as 'Section/Entry'.
    std::string entry;
    const auto  from = message.find("entry '");
    if (from != std::string::npos)
      entry = message.substr(from + 7,
                             message.find('\'', from + 7) - (from + 7));
    const std::string section = entry.substr(0, entry.rfind('/') + 1);
    // Every --set of an entry the message names (the last one per entry),
    // and the scene file if the entry the message is about came from it.
    std::vector<std::string> sources;
    std::vector<std::string> seen;
    bool                     entry_overridden = false;
    for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)
      {
        const std::string &path = o->first;
        const std::string  leaf = path.substr(path.rfind('/') + 1);
        const bool         named =
          message.find("'" + path + "'") != std::string::npos ||
          (!section.empty() && path == section + leaf &&
           message.find("'" + leaf + "'") != std::string::npos);
        if (!named ||
            std::find(seen.begin(), seen.end(), path) != seen.end())
          continue;
        seen.push_back(path);
        sources.insert(sources.begin(),
                       "--set '" + path + "=" + o->second + "'");
        // (An old name the message gives after the new: the same entry.)
        entry_overridden =
          entry_overridden || path == entry ||
          message.find("'" + path + "', deprecated") != std::string::npos;
      }
    if (!entry_overridden)
      sources.insert(sources.begin(),
                     scene_file.empty() ? std::string("scene") :
                                          "scene file '" + scene_file + "'");
    std::string result;
    for (const auto &s : sources)
      result += (result.empty() ? "" : ", ") + s;
    return result + ": " + message;
  }

  SceneParameters
  read_scene(ParameterHandler  &prm,
             const std::string &scene_file,
             const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    read_scene_entries(prm, scene_file, overrides);
    const auto  slash = scene_file.rfind('/');
    std::string scene_directory;
    if (!scene_file.empty())
      scene_directory =
        (slash == std::string::npos) ? "." : scene_file.substr(0, slash);

    SceneParameters parameters;
    try
      {
        parameters.parse_parameters(prm, scene_directory);
      }
    catch (const std::runtime_error &e)
      {
        throw std::runtime_error(
          with_source(e.what(), scene_file, overrides));
      }
    if (!parameters.geometry.particle_file.empty())
      {
        prm.enter_subsection("Geometry");
        prm.set("Particle file",
                std::filesystem::absolute(parameters.geometry.particle_file)
                  .lexically_normal()
                  .string());
        prm.leave_subsection();
      }
    return parameters;
  }

  SceneParameters
  read_scene(const std::string &scene_file,
             const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    ParameterHandler prm;
    return read_scene(prm, scene_file, overrides);
  }
} // namespace levelsinter
