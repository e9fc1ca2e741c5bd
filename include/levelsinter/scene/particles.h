#pragma once

#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * Particles (and pores, the balls cut out of the solid) are rows
   * (x, y[, z], r) until the dimension is known; these functions read and
   * check them and report errors with the place they come from (entry
   * name, or file and line) and @p item_name ("particle", "pore").
   */
  std::vector<std::vector<double>>
  parse_inline_particles(const std::string &text,
                         const unsigned int dim,
                         const std::string &entry_name,
                         const std::string &item_name = "particle");

  /**
   * Read a CSV file with a header line naming the columns x, y, r (2D) or
   * x, y, z, r (3D) in any order (case-insensitive, spaces trimmed), then
   * one particle per row. Blank lines and lines starting with '#' are
   * skipped. A header that does not name exactly these columns is an error
   * naming the file and line.
   */
  std::vector<std::vector<double>>
  read_particle_file(const std::string &file_name,
                     const unsigned int dim,
                     const std::string &item_name = "particle");

  /**
   * Two particles with the same centre (to 1e-12 of the larger radius)
   * are an error naming both: one hides the other, or the list was pasted
   * twice.
   */
  void
  check_distinct_centres(const std::vector<std::vector<double>> &particles);

  /**
   * A particle may stick out of the box only through a face it is symmetric
   * about: one its centre lies on, or one across which the list holds its
   * mirror image (a symmetry plane between two particles; the image itself
   * may then have its centre outside). Otherwise it must be inside.
   */
  void
  check_particles_in_domain(const std::vector<std::vector<double>> &particles,
                            const std::vector<double> &lower_corner,
                            const std::vector<double> &upper_corner,
                            const std::string &item_name = "particle");
} // namespace levelsinter
