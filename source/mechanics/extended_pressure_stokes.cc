#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/mechanics/cut_assembly.h>
#include <levelsinter/mechanics/extended_pressure_stokes.h>
#include <levelsinter/mechanics/rigid_body_modes.h>
#include <levelsinter/mechanics/schur_layout.h>
#include <levelsinter/mechanics/solid_elastic_stokes.h>
#include <levelsinter/mechanics/stokes_assemblers.h>
#include <levelsinter/mechanics/stokes_terms.h>

#include <algorithm>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    using Location = NonMatching::LocationToLevelSet;

    // Whether a cell at @p location holds part of @p phase.
    bool
    holds(const Location location, const Phase phase)
    {
      return location != (phase == Phase::solid ? Location::outside :
                                                  Location::inside);
    }

    constexpr std::array<Phase, 2> phases = {{Phase::solid, Phase::fluid}};
  } // namespace

  template <int dim>
  ExtendedPressureStokes<dim>::ExtendedPressureStokes(
    const Triangulation<dim> &tria,
    const Settings           &settings,
    const PhaseLaw<dim>      &phase_law,
    const double              ghost_penalty)
    : settings(settings)
    , free_motions(dim, settings.symmetry_boundaries)
    , phase_law(phase_law)
    , ghost_penalty(ghost_penalty)
    , finite_element(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1, FE_Q<dim>(1), 1)
    , dofs(tria)
  {
    // ViscousFlowParameters refuses these combinations with the entry
    // named; the volume-diffusion mechanics sets the sharp form itself.
    using Form = typename TwoPhaseStokes<dim>::SurfaceTensionForm;
    if ((settings.form != Form::sharp &&
         settings.form != Form::sharp_curvature) ||
        settings.direct_solver)
      throw std::logic_error(
        "the extended pressure needs a sharp surface-tension form and the "
        "iterative solver");
  }

  template <int dim>
  void
  ExtendedPressureStokes<dim>::setup_dofs()
  {
    dofs.distribute_dofs(finite_element);
    std::vector<unsigned int> block_of_component(dim + 2, 1);
    std::fill_n(block_of_component.begin(), dim, 0);
    DoFRenumbering::component_wise(dofs, block_of_component);
    const auto per_block =
      DoFTools::count_dofs_per_fe_block(dofs, block_of_component);
    const types::global_dof_index n_v = per_block[0], n_p = per_block[1];
    const IndexSet owned = dofs.locally_owned_dofs();
    relevant_dofs        = DoFTools::extract_locally_relevant_dofs(dofs);
    owned_partitioning   = {owned.get_view(0, n_v),
                          owned.get_view(n_v, n_v + n_p)};
    relevant_partitioning = {relevant_dofs.get_view(0, n_v),
                             relevant_dofs.get_view(n_v, n_v + n_p)};
    // Without the level set: the zero pressures only remove entries from
    // this pattern.
    make_constraints(nullptr);
    velocity_modes = rigid_body_modes(dofs, owned_partitioning[0]);

    // Cells couple everything but the two pressures with each other; the
    // faces of the ghost penalty couple each pressure with itself across
    // them (for_each_penalty_face()).
    const unsigned int           n = dim + 2;
    Table<2, DoFTools::Coupling> cells(n, n);
    for (unsigned int c = 0; c < n; ++c)
      for (unsigned int d = 0; d < n; ++d)
        cells[c][d] = c >= dim && d >= dim && c != d ? DoFTools::none :
                                                        DoFTools::always;
    const MPI_Comm comm = dofs.get_communicator();
    std::vector<types::global_dof_index> cell_dofs(
      finite_element.dofs_per_cell),
      neighbor_dofs(finite_element.dofs_per_cell), pair;
    {
      BlockDynamicSparsityPattern dsp(relevant_partitioning);
      DoFTools::make_sparsity_pattern(dofs,
                                      cells,
                                      dsp,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));
      for_each_penalty_face(dofs,
                            settings.band_level,
                            [&](const auto &cell,
                                const unsigned int,
                                const auto &neighbor,
                                const bool) {
        cell->get_dof_indices(cell_dofs);
        neighbor->get_dof_indices(neighbor_dofs);
        for (const Phase phase : phases)
          {
            pair.clear();
            for (unsigned int i = 0; i < cell_dofs.size(); ++i)
              if (finite_element.system_to_component_index(i).first ==
                  pressure_component(phase))
                {
                  pair.push_back(cell_dofs[i]);
                  pair.push_back(neighbor_dofs[i]);
                }
            constraints.add_entries_local_to_global(pair, dsp, false);
          }
      });
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 comm,
                                                 relevant_dofs);
      system_matrix.reinit(owned_partitioning, dsp, comm);
    }
    make_schur_layout(system_matrix,
                      owned_partitioning,
                      relevant_partitioning,
                      constraints,
                      schur_matrix);
    system_rhs.reinit(owned_partitioning, comm);
    ghosted_solution.reinit(owned_partitioning, relevant_partitioning, comm);
    old_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
  }

  template <int dim>
  void
  ExtendedPressureStokes<dim>::make_constraints(
    const NonMatching::MeshClassifier<dim> *classifier)
  {
    make_velocity_constraints(dofs,
                              relevant_dofs,
                              settings.symmetry_boundaries,
                              free_motions,
                              constraints);
    if (classifier)
      {
        // A phase's pressure lives on the cells that hold the phase (every
        // cell around a DoF of a locally owned cell is owned or ghost).
        std::array<std::vector<bool>, 2> used;
        for (auto &u : used)
          u.assign(relevant_dofs.n_elements(), false);
        std::vector<types::global_dof_index> indices(
          finite_element.dofs_per_cell);
        const auto pressure_phase = [&](const unsigned int i) {
          return finite_element.system_to_component_index(i).first - dim;
        };
        for (const auto &cell : dofs.active_cell_iterators())
          if (!cell->is_artificial())
            {
              const Location location =
                classifier->location_to_level_set(cell);
              cell->get_dof_indices(indices);
              for (unsigned int i = 0; i < indices.size(); ++i)
                if (finite_element.system_to_component_index(i).first >= dim &&
                    holds(location, phases[pressure_phase(i)]))
                  used[pressure_phase(i)]
                      [relevant_dofs.index_within_set(indices[i])] = true;
            }
        for (const auto &cell : dofs.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(indices);
              for (unsigned int i = 0; i < indices.size(); ++i)
                if (finite_element.system_to_component_index(i).first >= dim &&
                    !used[pressure_phase(i)]
                         [relevant_dofs.index_within_set(indices[i])] &&
                    constraints.can_store_line(indices[i]) &&
                    !constraints.is_constrained(indices[i]))
                  constraints.add_line(indices[i]);
            }
      }
    constraints.close();
  }

  template <int dim>
  void
  ExtendedPressureStokes<dim>::assemble(
    const LevelSetField<dim>            &alpha,
    const TrilinosWrappers::MPI::Vector &curvature,
    const TrilinosWrappers::MPI::Vector &,
    const double                         surface_time_step)
  {
    system_matrix = 0;
    system_rhs    = 0;
    schur_matrix  = 0;

    const auto classifier = alpha.classifier();
    make_constraints(classifier.get());

    // The terms: the bulk and ASGS terms per phase, the surface terms once
    // per cell, the traction on the free box faces.
    const StokesTerms<dim> terms(settings, surface_time_step);
    if (terms.needs_curvature() &&
        curvature.size() != alpha.dof_handler().n_dofs())
      throw std::runtime_error("viscous flow: the sharp-curvature surface-"
                               "tension form needs a curvature on the "
                               "level-set DoFs");
    using CellData = StokesCellData<dim>;
    typename CellData::Inputs inputs{alpha, phase_law, old_displacement};
    if (terms.needs_curvature())
      inputs.curvature = &curvature;
    terms.set_inputs(inputs);
    inputs.extended_pressure = true;

    CellData         data(finite_element, inputs);
    CellContribution contribution(finite_element.dofs_per_cell);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          contribution.reset();
          data.reinit_cut(cell);
          for (const Phase phase : phases)
            if (data.select_phase(phase))
              terms.assemble_bulk(data, contribution);
          terms.assemble_surface(data, contribution);
          add_cell_contribution(data,
                                cell,
                                constraints,
                                contribution,
                                system_matrix,
                                system_rhs,
                                schur_matrix);
        }
    if (ghost_penalty > 0)
      assemble_ghost_penalty(alpha, *classifier);
    compress_system(system_matrix, system_rhs, schur_matrix);
  }

  template <int dim>
  void
  ExtendedPressureStokes<dim>::assemble_ghost_penalty(
    const LevelSetField<dim>               &alpha,
    const NonMatching::MeshClassifier<dim> &classifier)
  {
    const GhostPenaltyAssembler<dim> penalty(ghost_penalty);
    FEInterfaceValues<dim> values = penalty_face_values(finite_element);
    const std::array<PhaseCoefficients, 2> laws = {
      {phase_law.coefficients({1, 0}), phase_law.coefficients({0, 1})}};
    FullMatrix<double> matrix, schur, matrix_p, schur_p;
    std::vector<unsigned int>            pressure_dofs;
    std::vector<types::global_dof_index> indices;
    for_each_penalty_face(dofs,
                          settings.band_level,
                          [&](const auto        &cell,
                              const unsigned int f,
                              const auto        &neighbor,
                              const bool         coarser) {
      const Location here  = classifier.location_to_level_set(cell);
      const Location there = classifier.location_to_level_set(neighbor);
      if (here != Location::intersected && there != Location::intersected)
        return;
      reinit_penalty_face(values, cell, f, neighbor, coarser);
      const unsigned int n = values.n_current_interface_dofs();
      const double       h = cell_size(cell);
      for (const Phase phase : phases)
        if (holds(here, phase) && holds(there, phase))
          {
            const PhaseCoefficients &law = laws[phase == Phase::solid ? 0 : 1];
            matrix.reinit(n, n);
            schur.reinit(n, n);
            penalty.assemble(values,
                             alpha.measure(),
                             pressure_component(phase),
                             law.a2 * h * h * h / law.a1,
                             matrix,
                             schur);
            // Add the rows of the phase's pressure only, the entries the
            // pattern holds: the face's other DoFs include the neighbour's
            // constrained velocities, whose diagonal the constraints would
            // add to a row another rank owns and this one has no entry in.
            component_interface_dofs(values,
                                     finite_element,
                                     pressure_component(phase),
                                     pressure_dofs,
                                     indices);
            matrix_p.reinit(indices.size(), indices.size());
            schur_p.reinit(indices.size(), indices.size());
            matrix_p.extract_submatrix_from(matrix,
                                            pressure_dofs,
                                            pressure_dofs);
            schur_p.extract_submatrix_from(schur,
                                           pressure_dofs,
                                           pressure_dofs);
            constraints.distribute_local_to_global(matrix_p,
                                                   indices,
                                                   system_matrix);
            constraints.distribute_local_to_global(schur_p,
                                                   indices,
                                                   schur_matrix);
          }
    });
  }

  template <int dim>
  unsigned int
  ExtendedPressureStokes<dim>::solve()
  {
    BlockVector owned_solution(owned_partitioning, dofs.get_communicator());
    const unsigned int iterations =
      solve_block_system(system_matrix,
                         schur_matrix.block(1, 1),
                         velocity_modes,
                         dim,
                         system_rhs,
                         owned_solution,
                         settings.tolerance,
                         settings.max_iterations,
                         settings.smoothed_aggregation);
    constraints.distribute(owned_solution);
    ghosted_solution = owned_solution;
    return iterations;
  }

  template <int dim>
  void
  ExtendedPressureStokes<dim>::remove_rigid_motion(
    const LevelSetField<dim> &alpha)
  {
    remove_free_rigid_motion(dofs, alpha, free_motions, ghosted_solution);
  }

  template <int dim>
  std::unique_ptr<VelocityPressureOperator<dim>>
  make_velocity_pressure_operator(
    const Triangulation<dim>                     &tria,
    const typename TwoPhaseStokes<dim>::Settings &settings,
    const PhaseLaw<dim>                          &law,
    const ViscousFlowParameters                  &parameters)
  {
    if (parameters.pressure_space ==
        ViscousFlowParameters::PressureSpace::extended)
      return std::make_unique<ExtendedPressureStokes<dim>>(
        tria, settings, law, parameters.ghost_penalty);
    if (parameters.pressure_space == ViscousFlowParameters::PressureSpace::solid)
      return std::make_unique<SolidElasticStokes<dim>>(
        tria, settings, law, parameters.ghost_penalty);
    return std::make_unique<TwoPhaseStokes<dim>>(tria, settings, law);
  }

  template class ExtendedPressureStokes<2>;
  template class ExtendedPressureStokes<3>;
  template std::unique_ptr<VelocityPressureOperator<2>>
  make_velocity_pressure_operator(const Triangulation<2> &,
                                  const TwoPhaseStokes<2>::Settings &,
                                  const PhaseLaw<2> &,
                                  const ViscousFlowParameters &);
  template std::unique_ptr<VelocityPressureOperator<3>>
  make_velocity_pressure_operator(const Triangulation<3> &,
                                  const TwoPhaseStokes<3>::Settings &,
                                  const PhaseLaw<3> &,
                                  const ViscousFlowParameters &);
} // namespace levelsinter
