#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>

#include <array>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Moments of the interface {alpha_h = 0} weighted with the level set's
   * shape function phi_j of each node j, in the scene's measure: what
   * NormalGradientExtension needs to judge the interface in a node's patch
   * (how much of it, whether it is one sheet, on which side it bends).
   */
  template <int dim>
  struct InterfaceMoments
  {
    /** int_Gamma phi_j ds. */
    TrilinosWrappers::MPI::Vector mass;
    /** int_Gamma n phi_j ds, one vector per axis. */
    std::array<TrilinosWrappers::MPI::Vector, dim> normal;
    /** int_Gamma x phi_j ds, one vector per axis. */
    std::array<TrilinosWrappers::MPI::Vector, dim> position;
    /** int_Gamma (n . x) phi_j ds. */
    TrilinosWrappers::MPI::Vector normal_position;
  };

  /**
   * The normal flux xi = grad p . n of a harmonic field p on the interface
   * {alpha_h = 0}, n pointing out of the solid, extracted variationally
   * (Green's formula; Babuska & Miller's flux extraction): for Laplace p = 0
   * in the solid S and every test function w,
   *
   *   int_Gamma xi w ds = int_S grad p . grad w dx,
   *
   * so for a test function w that is a sum of the level set's Q1 shape
   * functions phi_j, with the interface mass lumped,
   *
   *   xi_w = sum_j int_S grad p_h . grad phi_j dx / sum_j int_Gamma phi_j ds
   *
   * (NormalGradientExtension sums over the nodes of the cells at a node).
   *
   * Both integrals use the sharp cut-cell quadrature (deal.II NonMatching)
   * in the scene's measure (r dr dz in an axisymmetric scene, where Green's
   * formula holds for the axisymmetric Laplacian). The volume integral
   * reads p only in the solid and averages grad p_h over w's support
   * instead of reading it at one point: no interior offset, no atmosphere
   * (doc/numerics.md, "Volume diffusion: xi as the boundary flux").
   *
   * Accumulated here per node j as the two integrals: @p moments gets the
   * interface's moments weighted with phi_j (InterfaceMoments) and @p flux
   * int_S grad p . grad phi_j over the locally owned cells (ghosted
   * vectors with writable ghosts; the caller compresses with
   * VectorOperation::add and divides where the surface mass is large
   * enough for the quotient to be meaningful). p is component
   * @p component of @p field on @p field_dofs, a DoFHandler on the level
   * set's mesh whose component is Q1 on each cell.
   */
  template <int dim>
  void
  add_boundary_flux(const LevelSetField<dim>            &level_set,
                    const DoFHandler<dim>               &field_dofs,
                    const unsigned int                   component,
                    const TrilinosWrappers::MPI::Vector &field,
                    InterfaceMoments<dim>               &moments,
                    TrilinosWrappers::MPI::Vector       &flux);
} // namespace levelsinter
