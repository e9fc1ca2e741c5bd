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
  /** @p lines, if given, receives the line number of each row read. */
  std::vector<std::vector<double>>
  read_particle_file(const std::string         &file_name,
                     const unsigned int         dim,
                     const std::string         &item_name = "particle",
                     std::vector<unsigned int> *lines     = nullptr);

  /**
   * Pairs that cannot be a sintering problem are an error naming both
   * particles (numbered from 1 in the merged list) and where each was
   * given (@p origins, one per particle):
   * - one inside the other (centre distance + its radius <= the other's
   *   radius, which includes the same ball twice): it has no surface of
   *   its own, and a neck measured between them would be a cross-section
   *   of the larger one;
   * - centres closer than @p cell (one cell of the interface band): the
   *   two balls differ from one by less than a cell, so the mesh shows
   *   one particle with no neck or gap between them, and their power
   *   cells split one body in two. It is refused rather than warned about
   *   because nothing the run measures about the pair would mean anything,
   *   and it is nearly always a row given twice.
   */
  void
  check_particle_pairs(const std::vector<std::vector<double>> &particles,
                       const std::vector<std::string>         &origins,
                       const double                            cell);

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
