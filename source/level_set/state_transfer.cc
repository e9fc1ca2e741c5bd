#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/affine_constraints.h>

#include <levelsinter/level_set/state_transfer.h>

#include <algorithm>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    using Vector      = TrilinosWrappers::MPI::Vector;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    // An owned-only vector laid out as @p target will be on @p dofs (a
    // block vector's owner has sized it already).
    void
    reinit_owned(Vector &owned, const Vector &, const IndexSet &locally_owned,
                 const MPI_Comm comm)
    {
      owned.reinit(locally_owned, comm);
    }

    void
    reinit_owned(BlockVector &owned, const BlockVector &target,
                 const IndexSet &, const MPI_Comm comm)
    {
      std::vector<IndexSet> partitioning;
      for (unsigned int b = 0; b < target.n_blocks(); ++b)
        partitioning.push_back(target.block(b).locally_owned_elements());
      owned.reinit(partitioning, comm);
    }

    // @p target ghosted with the values of @p owned.
    void
    assign_ghosted(Vector &target, const Vector &owned,
                   const IndexSet &locally_owned, const IndexSet &relevant,
                   const MPI_Comm comm)
    {
      target.reinit(locally_owned, relevant, comm);
      target = owned;
    }

    void
    assign_ghosted(BlockVector &target, const BlockVector &owned,
                   const IndexSet &, const IndexSet &, const MPI_Comm)
    {
      target = owned;
    }
  } // namespace

  template <int dim>
  template <class VectorType>
  void
  StateTransfer<dim>::add_entry(const DoFHandler<dim>           &dof_handler,
                                const std::vector<VectorType *> &vectors,
                                const std::function<void()>     &written)
  {
    for (const VectorType *v : vectors)
      if (v->size() != dof_handler.n_dofs())
        throw std::logic_error(
          "StateTransfer::add: a vector is not sized to its DoFHandler");
    // One entry per DoFHandler.
    Entry<VectorType> *entry = nullptr;
    for (auto &variant : entries)
      if (auto *e = std::get_if<Entry<VectorType>>(&variant);
          e && e->dof_handler == &dof_handler)
        entry = e;
    if (!entry)
      entry = &std::get<Entry<VectorType>>(
        entries.emplace_back(Entry<VectorType>{&dof_handler, {}, nullptr, {}}));
    entry->vectors.insert(entry->vectors.end(), vectors.begin(), vectors.end());
    if (written)
      entry->written.push_back(written);
  }

  template <int dim>
  void
  StateTransfer<dim>::add(const DoFHandler<dim>       &dof_handler,
                          const std::vector<Vector *> &vectors,
                          const std::function<void()> &written)
  {
    add_entry(dof_handler, vectors, written);
  }

  template <int dim>
  void
  StateTransfer<dim>::add(const DoFHandler<dim>            &dof_handler,
                          const std::vector<BlockVector *> &vectors)
  {
    add_entry(dof_handler, vectors, {});
  }

  template <int dim>
  template <class VectorType>
  void
  StateTransfer<dim>::attach(Entry<VectorType> &entry,
                             const bool         for_serialization)
  {
    entry.transfer =
      std::make_unique<typename Entry<VectorType>::Transfer>(*entry.dof_handler);
    const std::vector<const VectorType *> in(entry.vectors.begin(),
                                             entry.vectors.end());
    if (for_serialization)
      entry.transfer->prepare_for_serialization(in);
    else
      entry.transfer->prepare_for_coarsening_and_refinement(in);
  }

  template <int dim>
  void
  StateTransfer<dim>::prepare_for_coarsening_and_refinement()
  {
    for (auto &variant : entries)
      std::visit([](auto &entry) { attach(entry, false); }, variant);
  }

  template <int dim>
  void
  StateTransfer<dim>::interpolate()
  {
    for (auto &variant : entries)
      std::visit([](auto &entry) { fill_vectors(entry, false); }, variant);
  }

  template <int dim>
  void
  StateTransfer<dim>::prepare_for_serialization()
  {
    for (auto &variant : entries)
      std::visit([](auto &entry) { attach(entry, true); }, variant);
  }

  template <int dim>
  void
  StateTransfer<dim>::deserialize()
  {
    for (auto &variant : entries)
      std::visit([](auto &entry) { fill_vectors(entry, true); }, variant);
  }

  template <int dim>
  template <class VectorType>
  void
  StateTransfer<dim>::fill_vectors(Entry<VectorType> &entry,
                                   const bool         deserialize)
  {
    const DoFHandler<dim> &dofs     = *entry.dof_handler;
    const MPI_Comm         comm     = dofs.get_communicator();
    const IndexSet        &owned    = dofs.locally_owned_dofs();
    const IndexSet         relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    AffineConstraints<double> hanging_nodes(relevant);
    DoFTools::make_hanging_node_constraints(dofs, hanging_nodes);
    hanging_nodes.close();

    // SolutionTransfer writes owned-only vectors.
    std::vector<VectorType>   owned_vectors(entry.vectors.size());
    std::vector<VectorType *> out;
    for (unsigned int i = 0; i < owned_vectors.size(); ++i)
      {
        reinit_owned(owned_vectors[i], *entry.vectors[i], owned, comm);
        out.push_back(&owned_vectors[i]);
      }
    if (deserialize)
      {
        typename Entry<VectorType>::Transfer transfer(dofs);
        transfer.deserialize(out);
      }
    else
      entry.transfer->interpolate(out);
    for (unsigned int i = 0; i < out.size(); ++i)
      {
        hanging_nodes.distribute(owned_vectors[i]);
        assign_ghosted(*entry.vectors[i], owned_vectors[i], owned, relevant,
                       comm);
      }
    entry.transfer.reset();
    for (const auto &written : entry.written)
      written();
  }

  template class StateTransfer<2>;
  template class StateTransfer<3>;
} // namespace levelsinter
