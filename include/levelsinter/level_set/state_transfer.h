#pragma once

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <variant>
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
   * the owner's business). Block vectors (a velocity-pressure system's
   * displacement) keep their blocks: their owner sizes them on the new
   * DoFs, ghosted, when it distributes the DoFs again.
   */
  template <int dim>
  class StateTransfer
  {
  public:
    using Vector      = TrilinosWrappers::MPI::Vector;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /**
     * Keep @p vectors (ghosted, sized to @p dof_handler) across the next
     * mesh change. The DoFHandler must be the object the owner distributes
     * again afterwards, alive until interpolate(). The order of the calls
     * is the order of a checkpoint's data: a restart repeats it. If given,
     * @p written is called once interpolate() or deserialize() has written
     * them (their owner learns that they hold a known state).
     */
    void
    add(const DoFHandler<dim>       &dof_handler,
        const std::vector<Vector *> &vectors,
        const std::function<void()> &written = {});

    /** The same for block vectors, whose owner sizes them on the new DoFs. */
    void
    add(const DoFHandler<dim>            &dof_handler,
        const std::vector<BlockVector *> &vectors);

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
    // The vectors of one DoFHandler and their transfer.
    template <class VectorType>
    struct Entry
    {
      using Transfer =
        parallel::distributed::SolutionTransfer<dim, VectorType>;
      const DoFHandler<dim>     *dof_handler;
      std::vector<VectorType *>  vectors;
      std::unique_ptr<Transfer>  transfer;
      std::vector<std::function<void()>> written;
    };
    std::vector<std::variant<Entry<Vector>, Entry<BlockVector>>> entries;

    template <class VectorType>
    void
    add_entry(const DoFHandler<dim>           &dof_handler,
              const std::vector<VectorType *> &vectors,
              const std::function<void()>     &written);

    // A SolutionTransfer for the entry, given its vectors for a mesh change
    // or a checkpoint.
    template <class VectorType>
    static void
    attach(Entry<VectorType> &entry, const bool for_serialization);

    // Fill the entries' vectors, ghosted and with hanging nodes distributed,
    // from owned-only vectors that the entry's transfer writes
    // (@p deserialize: from the checkpoint, else by interpolation).
    template <class VectorType>
    static void
    fill_vectors(Entry<VectorType> &entry, const bool deserialize);
  };
} // namespace levelsinter
