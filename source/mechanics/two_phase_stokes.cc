#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/ghosted_vector.h>
#include <levelsinter/level_set/smoothed_heaviside.h>
#include <levelsinter/mechanics/free_rigid_motion.h>
#include <levelsinter/mechanics/rigid_body_modes.h>
#include <levelsinter/mechanics/schur_layout.h>
#include <levelsinter/mechanics/stokes_terms.h>
#include <levelsinter/mechanics/two_phase_stokes.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  TwoPhaseStokes<dim>::TwoPhaseStokes(const Triangulation<dim> &tria,
                                      const Settings           &settings,
                                      const PhaseLaw<dim>      &phase_law)
    : settings(settings)
    , free_motions(dim, settings.symmetry_boundaries)
    , phase_law(phase_law)
    , finite_element(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1)
    , dofs(tria)
  {}

  template <int dim>
  typename TwoPhaseStokes<dim>::Settings
  TwoPhaseStokes<dim>::Settings::from(
    const ViscousFlowParameters           &parameters,
    const MaterialsParameters             &materials,
    const std::vector<types::boundary_id> &symmetry_planes,
    const unsigned int                     band_level)
  {
    Settings settings;
    settings.surface_tension = materials.surface_tension;
    using Choice  = ViscousFlowParameters::SurfaceTensionForm;
    settings.form = parameters.surface_tension_form == Choice::csf ?
                      SurfaceTensionForm::csf :
                    parameters.surface_tension_form == Choice::sharp ?
                      SurfaceTensionForm::sharp :
                    parameters.surface_tension_form == Choice::sharp_curvature ?
                      SurfaceTensionForm::sharp_curvature :
                      SurfaceTensionForm::csf_curvature;
    settings.interface_half_width_cells = parameters.interface_half_width;
    settings.band_level                 = band_level;
    settings.stabilisation_constant     = parameters.stabilisation_constant;
    settings.external_pressure          = parameters.external_pressure;
    settings.symmetry_boundaries        = symmetry_planes;
    settings.direct_solver =
      parameters.linear_solver == ViscousFlowParameters::LinearSolver::direct;
    settings.tolerance                  = parameters.solver_tolerance;
    settings.max_iterations             = parameters.max_iterations;
    settings.smoothed_aggregation       = parameters.smoothed_aggregation;
    return settings;
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::setup_dofs()
  {
    dofs.distribute_dofs(finite_element);
    std::vector<unsigned int> block_of_component(dim + 1, 0);
    block_of_component[dim] = 1;
    DoFRenumbering::component_wise(dofs, block_of_component);
    const auto per_block =
      DoFTools::count_dofs_per_fe_block(dofs, block_of_component);
    const types::global_dof_index n_v = per_block[0], n_p = per_block[1];

    owned_dofs    = dofs.locally_owned_dofs();
    relevant_dofs = DoFTools::extract_locally_relevant_dofs(dofs);
    owned_partitioning   = {owned_dofs.get_view(0, n_v),
                          owned_dofs.get_view(n_v, n_v + n_p)};
    relevant_partitioning = {relevant_dofs.get_view(0, n_v),
                             relevant_dofs.get_view(n_v, n_v + n_p)};
    make_constraints();
    if (!settings.direct_solver)
      velocity_modes = rigid_body_modes(dofs, owned_partitioning[0]);

    const MPI_Comm comm = dofs.get_communicator();
    if (settings.direct_solver)
      {
        DynamicSparsityPattern dsp(relevant_dofs);
        DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned_dofs,
                                                   comm,
                                                   relevant_dofs);
        monolithic_matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
        monolithic_rhs.reinit(owned_dofs, comm);
      }
    else
      {
        // eps(v):eps(w) couples all velocity components; ASGS couples p-p.
        BlockDynamicSparsityPattern dsp(relevant_partitioning);
        DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned_dofs,
                                                   comm,
                                                   relevant_dofs);
        system_matrix.reinit(owned_partitioning, dsp, comm);
        make_schur_layout(system_matrix,
                          owned_partitioning,
                          relevant_partitioning,
                          constraints,
                          schur_matrix);
      }
    system_rhs.reinit(owned_partitioning, comm);
    ghosted_solution.reinit(owned_partitioning, relevant_partitioning, comm);
    old_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::make_constraints()
  {
    make_velocity_constraints(dofs,
                              relevant_dofs,
                              settings.symmetry_boundaries,
                              free_motions,
                              constraints);
    constraints.close();
  }

  namespace
  {
    // H_h of the balanced force: H_s of the interface level set (a
    // distance, redistanced_level_set()) at the level-set nodes,
    // constrained so that it lies in the continuous pressure space. A node
    // has no cell size: E is that of the finest cells (the form is meant
    // for uniform meshes).
    template <int dim>
    TrilinosWrappers::MPI::Vector
    nodal_solid_fraction(const LevelSetField<dim>            &alpha,
                         const TrilinosWrappers::MPI::Vector &interface_level_set,
                         const double interface_half_width_cells)
    {
      const SmoothedHeaviside heaviside(
        interface_half_width_cells *
        finest_cell_size(alpha.dof_handler().get_triangulation()));
      TrilinosWrappers::MPI::Vector owned(
        alpha.locally_owned(), alpha.dof_handler().get_communicator());
      for (const auto i : alpha.locally_owned())
        owned(i) = heaviside.solid_fraction(interface_level_set(i));
      return ghosted_from_owned(owned,
                                alpha.constraints(),
                                alpha.locally_relevant());
    }
  } // namespace

  template <int dim>
  template <typename MatrixType, typename VectorType>
  void
  TwoPhaseStokes<dim>::assemble_into(
    const LevelSetField<dim>            &alpha,
    const TrilinosWrappers::MPI::Vector &curvature,
    const TrilinosWrappers::MPI::Vector &interface_level_set,
    const double                         surface_time_step,
    MatrixType                          &matrix,
    VectorType                          &rhs)
  {
    matrix = 0;
    rhs    = 0;
    if (!settings.direct_solver)
      schur_matrix = 0;

    // The terms of the operator, chosen once for this assembly.
    const StokesTerms<dim> terms(settings, surface_time_step);
    if (terms.needs_curvature() &&
        (curvature.size() != alpha.dof_handler().n_dofs() ||
         (terms.balanced_force() &&
          interface_level_set.size() != alpha.dof_handler().n_dofs())))
      throw std::runtime_error(
        "viscous flow: the csf-curvature and sharp-curvature surface-tension "
        "forms need a curvature (csf-curvature also an interface level set) "
        "on the level-set DoFs");

    // What the cell data gathers for them.
    using CellData = StokesCellData<dim>;
    const TrilinosWrappers::MPI::Vector solid_fraction =
      terms.balanced_force() ?
        nodal_solid_fraction(alpha,
                             interface_level_set,
                             settings.interface_half_width_cells) :
        TrilinosWrappers::MPI::Vector();
    typename CellData::Inputs inputs{alpha, phase_law, old_displacement};
    if (terms.needs_curvature())
      inputs.curvature = &curvature;
    if (terms.balanced_force())
      inputs.solid_fraction = &solid_fraction;
    terms.set_inputs(inputs);

    // step-32's split: the worker fills a cell's contribution from the
    // cell data, the copier adds it to the global system.
    const auto worker = [&](const auto       &cell,
                            CellData         &data,
                            CellContribution &contribution) {
      data.reinit(cell);
      contribution.reset();
      terms.assemble_bulk(data, contribution);
      terms.assemble_surface(data, contribution);
      symmetrise(data, contribution);
      cell->get_dof_indices(contribution.dof_indices);
    };
    const auto copier = [&](const CellContribution &contribution) {
      constraints.distribute_local_to_global(contribution.matrix,
                                             contribution.rhs,
                                             contribution.dof_indices,
                                             matrix,
                                             rhs);
      if (!settings.direct_solver)
        constraints.distribute_local_to_global(contribution.schur,
                                               contribution.dof_indices,
                                               schur_matrix);
    };
    CellData         data(finite_element, inputs);
    CellContribution contribution(finite_element.dofs_per_cell);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          worker(cell, data, contribution);
          copier(contribution);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    if (!settings.direct_solver)
      schur_matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::assemble(
    const LevelSetField<dim>            &alpha,
    const TrilinosWrappers::MPI::Vector &curvature,
    const TrilinosWrappers::MPI::Vector &interface_level_set,
    const double                         surface_time_step)
  {
    if (settings.direct_solver)
      assemble_into(alpha,
                    curvature,
                    interface_level_set,
                    surface_time_step,
                    monolithic_matrix,
                    monolithic_rhs);
    else
      assemble_into(alpha,
                    curvature,
                    interface_level_set,
                    surface_time_step,
                    system_matrix,
                    system_rhs);
  }

  template <int dim>
  unsigned int
  TwoPhaseStokes<dim>::solve()
  {
    const MPI_Comm comm = dofs.get_communicator();
    BlockVector    owned_solution(owned_partitioning, comm);
    unsigned int   iterations = 0;

    if (settings.direct_solver)
      {
        TrilinosWrappers::MPI::Vector x(owned_dofs, comm);
        SolverControl                 control(1, 0);
        TrilinosWrappers::SolverDirect direct(control);
        direct.solve(monolithic_matrix, x, monolithic_rhs);
        for (const auto i : owned_dofs)
          owned_solution(i) = x(i);
        owned_solution.compress(VectorOperation::insert);
      }
    else
      try
        {
          iterations = solve_block_system(system_matrix,
                                          schur_matrix.block(1, 1),
                                          velocity_modes,
                                          dim,
                                          system_rhs,
                                          owned_solution,
                                          settings.tolerance,
                                          settings.max_iterations,
                                          settings.smoothed_aggregation);
        }
      catch (const std::runtime_error &e)
        {
          // The continuous form also has the direct solver to offer.
          throw std::runtime_error(std::string(e.what()) +
                                   " or use 'Linear solver = direct' for a "
                                   "small 2D scene");
        }
    constraints.distribute(owned_solution);
    ghosted_solution = owned_solution;
    return iterations;
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::remove_rigid_motion(const LevelSetField<dim> &alpha)
  {
    remove_free_rigid_motion(dofs, alpha, free_motions, ghosted_solution);
  }

  template class TwoPhaseStokes<2>;
  template class TwoPhaseStokes<3>;
} // namespace levelsinter
