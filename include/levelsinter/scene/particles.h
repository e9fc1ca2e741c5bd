#pragma once

#include <string>
#include <vector>

namespace levelsinter
{
  /**
   * Particles are rows (x, y[, z], r) until the dimension is known; these
   * functions read and check them and report errors with the place they
   * come from (entry name, or file and line).
   */
  std::vector<std::vector<double>>
  parse_inline_particles(const std::string &text,
                         const unsigned int dim,
                         const std::string &entry_name);

  /**
   * Read a CSV file with a header line and rows "x,y,r" (2D) or "x,y,z,r"
   * (3D). Blank lines and lines starting with '#' are skipped.
   */
  std::vector<std::vector<double>>
  read_particle_file(const std::string &file_name, const unsigned int dim);

  /**
   * A particle may stick out of the box only through a face it is symmetric
   * about: one its centre lies on, or one across which the list holds its
   * mirror image (a symmetry plane between two particles; the image itself
   * may then have its centre outside). Otherwise it must be inside.
   */
  void
  check_particles_in_domain(const std::vector<std::vector<double>> &particles,
                            const std::vector<double> &lower_corner,
                            const std::vector<double> &upper_corner);
} // namespace levelsinter
