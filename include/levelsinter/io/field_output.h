#pragma once

#include <deal.II/base/data_out_base.h>

#include <deal.II/numerics/data_out.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/velocity_field.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace levelsinter
{
  /**
   * Writes alpha, the velocity, the refinement level, the owning MPI rank
   * and the fields of the model's parts (the mechanisms) as a ParaView
   * series: fields_NNNNN.pvtu/.vtu listed in fields.pvd, and/or
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

    /**
     * @p add_fields adds further fields to the DataOut, which has the level
     * set's DoFHandler attached: each vector on another DoFHandler names it.
     */
    void
    write(const unsigned int                               step,
          const double                                     time,
          const LevelSetField<dim>                        &level_set,
          const VelocityField<dim>                        &velocity,
          const std::function<void(DataOut<dim> &)> &add_fields);

    /** The series so far (counter and index records), for checkpoints. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &counter &pvd_records &xdmf_entries;
    }

  private:
    std::string                              directory;
    bool                                     write_vtu;
    bool                                     write_xdmf;
    unsigned int                             counter = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<XDMFEntry>                   xdmf_entries;
  };
} // namespace levelsinter
