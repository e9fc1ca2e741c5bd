#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <levelsinter/mechanics/block_schur_preconditioner.h>
#include <levelsinter/mechanics/velocity_pressure_operator.h>

#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  void
  VelocityPressureOperator<dim>::add_vertex_velocities(
    VelocityField<dim> &velocity) const
  {
    // Same mesh, Q1 in both spaces: the first dim vertex DoFs of every
    // discretisation's element are the velocity components.
    const BlockVector &v = solution();
    velocity.add_vertex_values(dof_handler(),
                               [&](const auto &cell, const unsigned int vertex) {
      Tensor<1, dim> value;
      for (unsigned int c = 0; c < dim; ++c)
        value[c] = v(cell->vertex_dof_index(vertex, c));
      return value;
    });
  }

  template <int dim>
  void
  VelocityPressureOperator<dim>::advance_displacement(const double dt)
  {
    // On the velocity block; the pressure block of the vector is unused.
    // Both operands without ghosts: Trilinos adds vectors of one layout.
    BlockVector          &displaced = displacement();
    std::vector<IndexSet> owned;
    for (unsigned int b = 0; b < displaced.n_blocks(); ++b)
      owned.push_back(displaced.block(b).locally_owned_elements());
    const MPI_Comm comm = dof_handler().get_communicator();
    BlockVector    sum(owned, comm), velocity(owned, comm);
    sum      = displaced;
    velocity = solution();
    sum.block(0).add(dt, velocity.block(0));
    displaced = sum;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  VelocityPressureOperator<dim>::plain_solution() const
  {
    // The blocks are numbered as the DoFHandler (velocity block first), so
    // the global indices carry over.
    const DoFHandler<dim> &dofs  = dof_handler();
    const IndexSet         owned = dofs.locally_owned_dofs();
    TrilinosWrappers::MPI::Vector plain(owned, dofs.get_communicator());
    for (const auto i : owned)
      plain(i) = solution()(i);
    plain.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector ghosted(
      owned,
      DoFTools::extract_locally_relevant_dofs(dofs),
      dofs.get_communicator());
    ghosted = plain;
    return ghosted;
  }

  template <int dim>
  std::vector<std::string>
  VelocityPressureOperator<dim>::pressure_names(const std::string &prefix) const
  {
    if (pressure_component(Phase::solid) == pressure_component(Phase::fluid))
      return {prefix + "_pressure"};
    return {prefix + "_solid_pressure", prefix + "_fluid_pressure"};
  }

  unsigned int
  solve_block_system(const TrilinosWrappers::BlockSparseMatrix &matrix,
                     const TrilinosWrappers::SparseMatrix      &schur,
                     const std::vector<std::vector<double>>    &velocity_modes,
                     const unsigned int                         dim,
                     const TrilinosWrappers::MPI::BlockVector  &rhs,
                     TrilinosWrappers::MPI::BlockVector        &solution,
                     const double                               tolerance,
                     const unsigned int max_iterations,
                     const bool         smoothed_aggregation,
                     const unsigned int smoother_sweeps)
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;
    const BlockSchurPreconditioner preconditioner(matrix,
                                                  schur,
                                                  velocity_modes,
                                                  dim,
                                                  smoothed_aggregation,
                                                  smoother_sweeps);
    SolverControl control(max_iterations, tolerance * rhs.l2_norm());
    SolverFGMRES<BlockVector> solver(
      control, SolverFGMRES<BlockVector>::AdditionalData(100));
    try
      {
        if (rhs.l2_norm() > 0)
          solver.solve(matrix, solution, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "velocity-pressure solve: FGMRES did not reach the relative "
                << "residual " << tolerance << " in " << e.last_step
                << " iterations (residual " << e.last_residual / rhs.l2_norm()
                << "); raise 'Viscous flow/Maximum solver iterations'";
        throw std::runtime_error(message.str());
      }
    return control.last_step();
  }

  template class VelocityPressureOperator<2>;
  template class VelocityPressureOperator<3>;
} // namespace levelsinter
