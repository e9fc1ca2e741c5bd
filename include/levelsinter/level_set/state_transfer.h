#pragma once

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The finite-element vectors that must outlive a change of the mesh: the
   * level set and whatever history the mechanisms keep (the lagged v_s of
   * surface diffusion, later a displacement or stress history). Each entry
   * is a DoFHandler on the one distributed triangulation and ghosted vectors
   * on it; any element works, one SolutionTransfer per DoFHandler (as in
   * step-32).
   *
   * Mesh adaptation:
   *   add() for every field -> prepare_for_coarsening_and_refinement()
   *   -> Triangulation::execute_coarsening_and_refinement()
   *   -> the owners distribute their DoFs again (the same DoFHandler objects)
   *   -> interpolate().
   * A checkpoint uses the same list: prepare_for_serialization() before
   * Triangulation::save(); on restart the same add() calls in the same
   * order, then Triangulation::load(), the owners distribute their DoFs,
   * deserialize().
   *
   * After interpolate() or deserialize() each vector is ghosted on its DoFHandler's new
   * locally owned and relevant DoFs, with the hanging-node constraints of
   * that DoFHandler distributed (no other constraints: boundary values are
   * the owner's business).
   */
  template <int dim>
  class StateTransfer
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /**
     * Keep @p vectors (ghosted, sized to @p dof_handler) across the next
     * mesh change. The DoFHandler must be the object the owner distributes
     * again afterwards, alive until interpolate().
     */
    void
    add(const DoFHandler<dim> &dof_handler, const std::vector<Vector *> &vectors);

    void
    prepare_for_coarsening_and_refinement();

    /** After every DoFHandler of the list has been distributed again. */
    void
    interpolate();

    /** Attach the vectors to the next Triangulation::save(). */
    void
    prepare_for_serialization();

    /** After Triangulation::load() and every DoFHandler distributed. */
    void
    deserialize();

  private:
    using Transfer = parallel::distributed::SolutionTransfer<dim, Vector>;
    struct Entry
    {
      const DoFHandler<dim>    *dof_handler;
      std::vector<Vector *>     vectors;
      std::unique_ptr<Transfer> transfer;
    };
    std::vector<Entry> entries;

    // One SolutionTransfer per entry, given its vectors by @p prepare.
    void
    attach(const std::function<void(Transfer &,
                                    const std::vector<const Vector *> &)>
             &prepare);

    // Fill the entries' vectors, ghosted and with hanging nodes distributed,
    // from owned-only vectors that @p fill writes (interpolate or
    // deserialize).
    void
    fill_vectors(
      const std::function<void(Entry &, std::vector<Vector *> &)> &fill);
  };
} // namespace levelsinter
