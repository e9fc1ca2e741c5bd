#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * An entry that moved: scenes and `--set` may still use the old path
   * 'Section/Entry' (top-level entries have no '/'); its value goes to the
   * new path with a deprecation warning.
   */
  struct RenamedEntry
  {
    std::string old_path;
    std::string new_path;
  };

  /**
   * Declare every old path (after the new entries are declared), documented
   * as deprecated. It is declared as 'has to be set', which is how the
   * handler tells afterwards whether a scene or an override gave it.
   */
  void
  declare_renamed_entries(ParameterHandler                &prm,
                          const std::vector<RenamedEntry> &renamed);

  /**
   * Move the value of every old path that was given to its new path
   * (checked against the new entry's pattern; an error names the old path).
   * Returns the renamed entries that were used. If a scene gives both the
   * old and the new path, the old one wins, as the later override would.
   */
  std::vector<RenamedEntry>
  move_renamed_entries(ParameterHandler                &prm,
                       const std::vector<RenamedEntry> &renamed);

  /** "'A/B' is deprecated, use 'C/D'". */
  std::string
  deprecation_warning(const RenamedEntry &entry);
} // namespace levelsinter
