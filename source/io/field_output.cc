#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <levelsinter/io/field_output.h>

#include <cstdio>
#include <fstream>

namespace levelsinter
{
  template <int dim>
  FieldOutput<dim>::FieldOutput(const std::string &directory,
                                const bool         write_vtu,
                                const bool         write_xdmf)
    : directory(directory)
    , write_vtu(write_vtu)
    , write_xdmf(write_xdmf)
  {}

  template <int dim>
  void
  FieldOutput<dim>::write(
    const unsigned int,
    const double                               time,
    const LevelSetField<dim>                  &level_set,
    const VelocityField<dim>                  &velocity,
    const std::function<void(DataOut<dim> &)> &add_fields)
  {
    if (!write_vtu && !write_xdmf)
      return;
    const MPI_Comm comm = level_set.dof_handler().get_communicator();
    const auto    &tria = level_set.dof_handler().get_triangulation();

    DataOut<dim> data_out;
    data_out.attach_dof_handler(level_set.dof_handler());
    data_out.add_data_vector(level_set.alpha(), "alpha");
    const std::vector<std::string> names(dim, "velocity");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(velocity.dof_handler(),
                             velocity.values(),
                             names,
                             interpretation);
    add_fields(data_out);
    dealii::Vector<float> level(tria.n_active_cells());
    dealii::Vector<float> rank(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          level(cell->active_cell_index()) = cell->level();
          rank(cell->active_cell_index()) = cell->subdomain_id();
        }
    data_out.add_data_vector(level, "level");
    data_out.add_data_vector(rank, "mpi_rank");
    data_out.build_patches();

    const std::string stem =
      "fields_" + Utilities::int_to_string(counter, 5);
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

    if (write_vtu)
      {
        // One .vtu for all ranks (MPI-IO), indexed by a .pvtu and the .pvd.
        const std::string pvtu = data_out.write_vtu_with_pvtu_record(
          directory + "/", "fields", counter, comm, 5, 1);
        pvd_records.emplace_back(time, pvtu);
        if (root)
          {
            const std::string pvd = directory + "/fields.pvd";
            std::ofstream     out(pvd + ".tmp");
            DataOutBase::write_pvd_record(out, pvd_records);
            out.close();
            std::rename((pvd + ".tmp").c_str(), pvd.c_str());
          }
      }
    if (write_xdmf)
      {
        DataOutBase::DataOutFilter filter(
          DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/true,
                                          /*xdmf_hdf5_output=*/true));
        data_out.write_filtered_data(filter);
        data_out.write_hdf5_parallel(filter, directory + "/" + stem + ".h5", comm);
        xdmf_entries.push_back(
          data_out.create_xdmf_entry(filter, stem + ".h5", time, comm));
        data_out.write_xdmf_file(xdmf_entries,
                                 directory + "/fields.xdmf",
                                 comm);
      }
    ++counter;
  }

  template class FieldOutput<2>;
  template class FieldOutput<3>;
} // namespace levelsinter
