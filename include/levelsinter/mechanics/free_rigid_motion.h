#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

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
} // namespace levelsinter
