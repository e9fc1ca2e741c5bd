#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/affine_constraints.h>

#include <levelsinter/level_set/state_transfer.h>

#include <algorithm>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  void
  StateTransfer<dim>::add(const DoFHandler<dim>       &dof_handler,
                          const std::vector<Vector *> &vectors)
  {
    for (const Vector *v : vectors)
      if (v->size() != dof_handler.n_dofs())
        throw std::logic_error(
          "StateTransfer::add: a vector is not sized to its DoFHandler");
    auto entry = std::find_if(entries.begin(),
                              entries.end(),
                              [&](const Entry &e) {
                                return e.dof_handler == &dof_handler;
                              });
    if (entry == entries.end())
      entries.push_back({&dof_handler, vectors, nullptr});
    else
      entry->vectors.insert(entry->vectors.end(),
                            vectors.begin(),
                            vectors.end());
  }

  template <int dim>
  void
  StateTransfer<dim>::prepare_for_coarsening_and_refinement()
  {
    attach([](Transfer &transfer, const std::vector<const Vector *> &in) {
      transfer.prepare_for_coarsening_and_refinement(in);
    });
  }

  template <int dim>
  void
  StateTransfer<dim>::interpolate()
  {
    fill_vectors([](Entry &entry, std::vector<Vector *> &out) {
      entry.transfer->interpolate(out);
    });
  }

  template <int dim>
  void
  StateTransfer<dim>::prepare_for_serialization()
  {
    attach([](Transfer &transfer, const std::vector<const Vector *> &in) {
      transfer.prepare_for_serialization(in);
    });
  }

  template <int dim>
  void
  StateTransfer<dim>::attach(
    const std::function<void(Transfer &, const std::vector<const Vector *> &)>
      &prepare)
  {
    for (Entry &entry : entries)
      {
        entry.transfer = std::make_unique<Transfer>(*entry.dof_handler);
        const std::vector<const Vector *> in(entry.vectors.begin(),
                                             entry.vectors.end());
        prepare(*entry.transfer, in);
      }
  }

  template <int dim>
  void
  StateTransfer<dim>::deserialize()
  {
    fill_vectors([](Entry &entry, std::vector<Vector *> &out) {
      Transfer transfer(*entry.dof_handler);
      transfer.deserialize(out);
    });
  }

  template <int dim>
  void
  StateTransfer<dim>::fill_vectors(
    const std::function<void(Entry &, std::vector<Vector *> &)> &fill)
  {
    for (Entry &entry : entries)
      {
        const DoFHandler<dim> &dofs     = *entry.dof_handler;
        const MPI_Comm         comm     = dofs.get_communicator();
        const IndexSet        &owned    = dofs.locally_owned_dofs();
        const IndexSet         relevant =
          DoFTools::extract_locally_relevant_dofs(dofs);
        AffineConstraints<double> hanging_nodes(relevant);
        DoFTools::make_hanging_node_constraints(dofs, hanging_nodes);
        hanging_nodes.close();

        // SolutionTransfer writes owned-only vectors.
        std::vector<Vector>   owned_vectors(entry.vectors.size());
        std::vector<Vector *> out;
        for (Vector &v : owned_vectors)
          {
            v.reinit(owned, comm);
            out.push_back(&v);
          }
        fill(entry, out);
        for (unsigned int i = 0; i < out.size(); ++i)
          {
            hanging_nodes.distribute(owned_vectors[i]);
            entry.vectors[i]->reinit(owned, relevant, comm);
            *entry.vectors[i] = owned_vectors[i];
          }
        entry.transfer.reset();
      }
  }

  template class StateTransfer<2>;
  template class StateTransfer<3>;
} // namespace levelsinter
