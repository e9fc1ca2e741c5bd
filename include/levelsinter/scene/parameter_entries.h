#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** Throw std::runtime_error "entry 'Section/Entry': what". */
  [[noreturn]] void
  fail_entry(const std::string &entry, const std::string &what);

  /**
   * Throw std::runtime_error "@p what '@p file_name' ..." unless the file is
   * a readable text file: a directory, a file that cannot be opened and one
   * holding binary data (a control character other than white space) are
   * each named as such, so that no raw bytes reach a message.
   */
  void
  check_text_file(const std::string &file_name, const std::string &what);

  /**
   * Read entry @p entry of the current subsection @p section as @p n
   * comma-separated finite numbers (a point or a vector).
   */
  std::vector<double>
  read_coordinates(ParameterHandler  &prm,
                   const std::string &section,
                   const std::string &entry,
                   const unsigned int n);

  /**
   * The value of a Selection entry as one of @p choices (name, value), so
   * that the text of a selection is compared here only.
   */
  template <typename Enum>
  Enum
  read_selection(ParameterHandler                                 &prm,
                 const std::string                                &section,
                 const std::string                                &entry,
                 const std::vector<std::pair<std::string, Enum>> &choices)
  {
    const std::string value = prm.get(entry);
    for (const auto &[name, choice] : choices)
      if (name == value)
        return choice;
    fail_entry(section + "/" + entry,
               "'" + value + "' is not one of the allowed values");
  }
} // namespace levelsinter
