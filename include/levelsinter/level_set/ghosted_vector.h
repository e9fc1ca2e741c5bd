#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The last step of filling a distributed field node by node: @p owned
   * (locally owned entries set with operator()) is compressed, the
   * @p constraints (hanging nodes) set its constrained entries, and the
   * field is returned with the ghost entries of @p relevant, so that every
   * cell a rank sees can read it. Collective.
   */
  inline TrilinosWrappers::MPI::Vector
  ghosted_from_owned(TrilinosWrappers::MPI::Vector   &owned,
                     const AffineConstraints<double> &constraints,
                     const IndexSet                  &relevant)
  {
    owned.compress(VectorOperation::insert);
    constraints.distribute(owned);
    TrilinosWrappers::MPI::Vector ghosted(owned.locally_owned_elements(),
                                          relevant,
                                          owned.get_mpi_communicator());
    ghosted = owned;
    return ghosted;
  }
} // namespace levelsinter
