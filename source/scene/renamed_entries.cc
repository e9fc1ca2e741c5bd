#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/scene/renamed_entries.h>

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // Enter the sections of 'A/B/entry', call f(entry), leave them again
    // (also when f throws).
    void
    at_path(ParameterHandler                             &prm,
            const std::string                            &path,
            const std::function<void(const std::string &)> &f)
    {
      auto sections = Utilities::split_string_list(path, '/');
      const std::string entry = sections.back();
      sections.pop_back();
      for (const auto &s : sections)
        prm.enter_subsection(s);
      try
        {
          f(entry);
        }
      catch (...)
        {
          for (std::size_t i = 0; i < sections.size(); ++i)
            prm.leave_subsection();
          throw;
        }
      for (std::size_t i = 0; i < sections.size(); ++i)
        prm.leave_subsection();
    }

    // The handler reports entries as mangled paths ("Viscous_20flow.Solver":
    // characters other than letters and digits as _XX in hex, sections
    // separated by '.'); turn them back into 'Viscous flow/Solver'.
    std::string
    demangle(const std::string &key)
    {
      std::string path;
      for (std::size_t i = 0; i < key.size(); ++i)
        if (key[i] == '_' && i + 2 < key.size() &&
            std::isxdigit(key[i + 1]) && std::isxdigit(key[i + 2]))
          {
            path += char(std::stoi(key.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          path += key[i] == '.' ? '/' : key[i];
      return path;
    }
  } // namespace

  void
  declare_renamed_entries(ParameterHandler                &prm,
                          const std::vector<RenamedEntry> &renamed)
  {
    for (const auto &r : renamed)
      at_path(prm, r.old_path, [&](const std::string &entry) {
        prm.declare_entry(entry,
                          "",
                          Patterns::Anything(),
                          "Deprecated: use '" + r.new_path + "'.",
                          /*has_to_be_set=*/true);
      });
  }

  std::vector<RenamedEntry>
  move_renamed_entries(ParameterHandler                &prm,
                       const std::vector<RenamedEntry> &renamed)
  {
    std::set<std::string> not_given;
    for (const auto &key : prm.get_entries_wrongly_not_set())
      not_given.insert(demangle(key));
    std::vector<RenamedEntry> used;
    for (const auto &r : renamed)
      {
        if (not_given.count(r.old_path) > 0)
          continue;
        std::string value;
        at_path(prm, r.old_path, [&](const std::string &entry) {
          value = prm.get(entry);
        });
        // parameters.prm lists the deprecated entries empty: nothing given.
        if (value.empty())
          continue;
        try
          {
            at_path(prm, r.new_path, [&](const std::string &entry) {
              prm.set(entry, value);
            });
          }
        catch (const ExceptionBase &)
          {
            throw std::runtime_error("entry '" + r.old_path +
                                     "' (deprecated, now '" + r.new_path +
                                     "'): '" + value +
                                     "' is not an allowed value (see "
                                     "levelsinter --print-parameters)");
          }
        used.push_back(r);
      }
    return used;
  }

  std::string
  deprecation_warning(const RenamedEntry &entry)
  {
    return "'" + entry.old_path + "' is deprecated, use '" + entry.new_path +
           "'";
  }
} // namespace levelsinter
