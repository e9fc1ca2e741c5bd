#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The rigid-body motions of a Q1 velocity (the first dim components of
   * the element of @p dofs): dim translations and dim(dim-1)/2 rotations
   * about the centre of the bounding box of the mesh, one vector per mode,
   * with the entries of the velocity DoFs of @p owned_velocity in the order
   * of that index set. They span the kernel of eps(v):eps(w) and are the
   * near-null space an aggregation AMG needs for the viscous block: with
   * a 1e-6 atmosphere every particle is almost free to translate and rotate.
   */
  template <int dim>
  std::vector<std::vector<double>>
  rigid_body_modes(const DoFHandler<dim> &dofs, const IndexSet &owned_velocity);
} // namespace levelsinter
