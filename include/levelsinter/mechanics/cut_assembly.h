#pragma once

#include <deal.II/base/numbers.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_interface_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/mechanics/stokes_assemblers.h>
#include <levelsinter/mechanics/stokes_cell_data.h>

#include <vector>

// What the cut discretisations of the velocity-pressure problem
// (ExtendedPressureStokes, SolidElasticStokes) share in their assembly.
namespace levelsinter
{
  using namespace dealii;

  /** Complete the @p contribution of @p cell gathered in @p data
   * (symmetrise()) and add it (matrix and right-hand side, and the Schur
   * approximation's block) through @p constraints. */
  template <int dim, typename CellIterator>
  void
  add_cell_contribution(const StokesCellData<dim>           &data,
                        const CellIterator                  &cell,
                        const AffineConstraints<double>     &constraints,
                        CellContribution                    &contribution,
                        TrilinosWrappers::BlockSparseMatrix &matrix,
                        TrilinosWrappers::MPI::BlockVector  &rhs,
                        TrilinosWrappers::BlockSparseMatrix &schur)
  {
    symmetrise(data, contribution);
    cell->get_dof_indices(contribution.dof_indices);
    constraints.distribute_local_to_global(contribution.matrix,
                                           contribution.rhs,
                                           contribution.dof_indices,
                                           matrix,
                                           rhs);
    constraints.distribute_local_to_global(contribution.schur,
                                           contribution.dof_indices,
                                           schur);
  }

  /** Exchange the entries added on other ranks' rows. */
  inline void
  compress_system(TrilinosWrappers::BlockSparseMatrix &matrix,
                  TrilinosWrappers::MPI::BlockVector  &rhs,
                  TrilinosWrappers::BlockSparseMatrix &schur)
  {
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    schur.compress(VectorOperation::add);
  }

  /** The face values of the ghost penalties on @p fe: normal gradients
   * at 2 Gauss points per direction (exact for the Q1 products). */
  template <int dim>
  FEInterfaceValues<dim>
  penalty_face_values(const FiniteElement<dim> &fe)
  {
    return FEInterfaceValues<dim>(box_mapping<dim>(),
                                  fe,
                                  QGauss<dim - 1>(2),
                                  update_gradients | update_JxW_values |
                                    update_normal_vectors |
                                    update_quadrature_points);
  }

  /**
   * @p callback(cell, face, neighbor, neighbor_is_coarser) on each interior
   * face of @p dofs that can carry a ghost penalty, once over all ranks:
   * from the finer side, or at one level from the lower cell id (the lower
   * rank across a partition boundary), and only in the interface band (at
   * @p band_level or finer), which holds the interface between two mesh
   * changes. The sparsity pattern and the assembly of a cut discretisation
   * (ExtendedPressureStokes, SolidElasticStokes) visit the same faces.
   */
  template <int dim, typename Callback>
  void
  for_each_penalty_face(const DoFHandler<dim> &dofs,
                        const unsigned int     band_level,
                        const Callback        &callback)
  {
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() >= int(band_level))
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            if (neighbor->has_children() ||
                neighbor->level() < int(band_level))
              continue;
            const bool coarser = cell->neighbor_is_coarser(f);
            if (!coarser &&
                (neighbor->is_locally_owned() ?
                   neighbor->id() < cell->id() :
                   neighbor->subdomain_id() < cell->subdomain_id()))
              continue;
            callback(cell, f, neighbor, coarser);
          }
  }

  /** Reinit @p values on the face @p f of @p cell shared with
   * @p neighbor, as for_each_penalty_face() hands it over. */
  template <int dim, typename CellIterator, typename NeighborIterator>
  void
  reinit_penalty_face(FEInterfaceValues<dim> &values,
                      const CellIterator     &cell,
                      const unsigned int      f,
                      const NeighborIterator &neighbor,
                      const bool              neighbor_is_coarser)
  {
    if (neighbor_is_coarser)
      {
        const auto [nf, nsf] = cell->neighbor_of_coarser_neighbor(f);
        values.reinit(
          cell, f, numbers::invalid_unsigned_int, neighbor, nf, nsf);
      }
    else
      values.reinit(cell,
                    f,
                    numbers::invalid_unsigned_int,
                    neighbor,
                    cell->neighbor_of_neighbor(f),
                    numbers::invalid_unsigned_int);
  }

  /**
   * The interface DoFs of @p values (reinit on a face of two cells of the
   * element @p fe) that belong to component @p component: their numbers
   * among the interface DoFs in @p local and their global indices in
   * @p global.
   */
  template <int dim>
  void
  component_interface_dofs(const FEInterfaceValues<dim>         &values,
                           const FiniteElement<dim>             &fe,
                           const unsigned int                    component,
                           std::vector<unsigned int>            &local,
                           std::vector<types::global_dof_index> &global)
  {
    local.clear();
    global.clear();
    const auto all = values.get_interface_dof_indices();
    for (unsigned int i = 0; i < values.n_current_interface_dofs(); ++i)
      {
        const auto on_cells = values.interface_dof_to_dof_indices(i);
        const unsigned int k = on_cells[0] != numbers::invalid_unsigned_int ?
                                 on_cells[0] :
                                 on_cells[1];
        if (fe.system_to_component_index(k).first == component)
          {
            local.push_back(i);
            global.push_back(all[i]);
          }
      }
  }
} // namespace levelsinter
