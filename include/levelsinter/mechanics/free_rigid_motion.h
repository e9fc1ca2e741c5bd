#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <levelsinter/level_set/level_set_field.h>

#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The rigid motions of the box that the symmetry planes (colorized face
   * ids) leave free, i.e. whose velocity is tangential to every plane: a
   * translation along e_k iff no plane has normal e_k; a rotation about e_k
   * iff every plane has normal e_k (in 2D the one rotation, about z, iff
   * there is no plane). A free-surface Stokes problem with a
   * self-equilibrated load determines the velocity up to these.
   */
  struct FreeRigidMotions
  {
    std::vector<unsigned int> translations; // axes k
    std::vector<unsigned int> rotations;    // axes k (2D: 2, about z)

    FreeRigidMotions(const unsigned int                      dim,
                     const std::vector<types::boundary_id> &symmetry_planes);

    /**
     * Velocity at @p x of mode @p m (translations first, then rotations
     * about the axis through @p centre).
     */
    template <int dim>
    Tensor<1, dim>
    mode(const unsigned int m,
         const Point<dim>  &x,
         const Point<dim>  &centre) const;

    unsigned int
    size() const
    {
      return translations.size() + rotations.size();
    }
  };

  /**
   * Subtract from the velocity (the first dim components of @p dofs'
   * element, Q1) its rigid part over the solid {alpha < 0}: the L2(solid)
   * projection onto the free motions (their span does not depend on the
   * rotation centre). Pinning the free motions at box corners selects one member
   * of the family of solutions, in which the particles drift with whatever
   * velocity the atmosphere has at the pins; this selects the member whose
   * solid has no net translation or rotation, which is what free particles
   * in a still atmosphere do. The pressure is unaffected.
   */
  template <int dim>
  void
  remove_free_rigid_motion(const DoFHandler<dim>              &dofs,
                           const LevelSetField<dim>           &level_set,
                           const FreeRigidMotions             &motions,
                           TrilinosWrappers::MPI::BlockVector &solution);

  /**
   * The velocity constraints every velocity-pressure discretisation shares,
   * into @p constraints (cleared and reinitialised on @p relevant_dofs, not
   * closed): hanging nodes (all components), zero normal velocity on the
   * symmetry planes (box faces with colorized ids 2k, 2k+1 have normal
   * e_k) and the pins of the free rigid motions at box corners: with the
   * lower corner a, b = a + L_x e_x and c = a + L_y e_y, v_k(a) = 0
   * removes the translation along e_k, v_y(b) = 0 the rotation about z,
   * v_z(b) = 0 the one about y and v_z(c) = 0 the one about x. The
   * capillary load is self-equilibrated, so the pins carry no reaction:
   * they only select one member of the family of solutions
   * (remove_free_rigid_motion() then selects the physical one). The
   * velocity is components 0..dim-1 of @p dofs' element.
   */
  template <int dim>
  void
  make_velocity_constraints(const DoFHandler<dim>                 &dofs,
                            const IndexSet                        &relevant_dofs,
                            const std::vector<types::boundary_id> &symmetry,
                            const FreeRigidMotions                &motions,
                            AffineConstraints<double>             &constraints);
} // namespace levelsinter
