#pragma once

#include <deal.II/base/data_out_base.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/velocity_field.h>

#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  /**
   * Writes alpha, the velocity, the refinement level and the owning MPI rank
   * as a ParaView series: fields_NNNNN.pvtu/.vtu listed in fields.pvd, and/or
   * fields_NNNNN.h5 listed in fields.xdmf. The index files are rewritten
   * after every output so that a run that stops early stays readable.
   */
  template <int dim>
  class FieldOutput
  {
  public:
    FieldOutput(const std::string &directory,
                const bool         write_vtu,
                const bool         write_xdmf);

    void
    write(const unsigned int        step,
          const double              time,
          const LevelSetField<dim> &level_set,
          const VelocityField<dim> &velocity);

  private:
    std::string                              directory;
    bool                                     write_vtu;
    bool                                     write_xdmf;
    unsigned int                             counter = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<XDMFEntry>                   xdmf_entries;
  };
} // namespace levelsinter
