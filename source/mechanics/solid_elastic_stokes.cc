#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/mechanics/cut_assembly.h>
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

    // Active FE indices of SolidElasticStokes::fe_collection.
    constexpr unsigned int with_solid = 0, void_cell = 1;

    // The largest edge of the box the triangulation fills.
    template <int dim>
    double
    box_size(const Triangulation<dim> &tria)
    {
      const auto   box  = GridTools::compute_bounding_box(tria);
      double       size = 0;
      for (unsigned int d = 0; d < dim; ++d)
        size = std::max(size, box.side_length(d));
      return size;
    }

    // Velocity block 0, pressure block 1, numbered component-wise.
    template <int dim>
    std::array<types::global_dof_index, 2>
    number_by_blocks(DoFHandler<dim> &dofs)
    {
      std::vector<unsigned int> block_of_component(dim + 1, 0);
      block_of_component[dim] = 1;
      DoFRenumbering::component_wise(dofs, block_of_component);
      const auto per_block =
        DoFTools::count_dofs_per_fe_block(dofs, block_of_component);
      return {{per_block[0], per_block[1]}};
    }

    std::vector<IndexSet>
    split(const IndexSet                              &set,
          const std::array<types::global_dof_index, 2> n)
    {
      return {set.get_view(0, n[0]), set.get_view(n[0], n[0] + n[1])};
    }
  } // namespace

  template <int dim>
  SolidElasticStokes<dim>::SolidElasticStokes(const Triangulation<dim> &tria,
                                              const Settings &settings,
                                              const PhaseLaw<dim> &phase_law,
                                              const double ghost_penalty)
    : settings(settings)
    , free_motions(dim, settings.symmetry_boundaries)
    , phase_law(phase_law)
    , ghost_penalty(ghost_penalty)
    , finite_element(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1)
    // FE_Nothing in the element's base structure: base by base, FE_Q and
    // a non-dominating FE_Nothing have no requirements on a shared face,
    // so a face between a cell with solid and a void one is free (the
    // solid's boundary), also across hanging nodes from a coarser void
    // cell.
    , fe_collection(finite_element,
                    FESystem<dim>(FE_Nothing<dim>(), dim, FE_Nothing<dim>(), 1))
    , drag_per_a1(1e-6 / (box_size(tria) * box_size(tria)))
    , dofs(tria)
    , solid_dofs(tria)
  {
    // ViscousFlowParameters refuses the direct solver with this space;
    // the volume-diffusion mechanics sets the sharp tensorial form itself.
    if (settings.form != TwoPhaseStokes<dim>::SurfaceTensionForm::sharp ||
        settings.direct_solver)
      throw std::logic_error("the solid-only elastic problem needs the sharp "
                             "tensorial surface tension and the iterative "
                             "solver");
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::setup_dofs()
  {
    dofs.distribute_dofs(finite_element);
    const auto     n        = number_by_blocks(dofs);
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, hanging_node_constraints);
    hanging_node_constraints.close();
    const MPI_Comm comm = dofs.get_communicator();
    ghosted_solution.reinit(split(dofs.locally_owned_dofs(), n),
                            split(relevant, n),
                            comm);
    old_displacement.reinit(split(dofs.locally_owned_dofs(), n),
                            split(relevant, n),
                            comm);
    // The mesh changed: the solid's cells and DoFs follow in assemble().
    solid_dofs_current = false;
  }

  template <int dim>
  bool
  SolidElasticStokes<dim>::update_solid_cells(
    const NonMatching::MeshClassifier<dim> &classifier)
  {
    bool changed = !solid_dofs_current;
    for (const auto &cell : solid_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int index =
            classifier.location_to_level_set(cell) == Location::outside ?
              void_cell :
              with_solid;
          if (cell->active_fe_index() != index)
            {
              cell->set_active_fe_index(index);
              changed = true;
            }
        }
    return Utilities::MPI::max(int(changed), solid_dofs.get_communicator()) >
           0;
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::setup_solid_system()
  {
    solid_dofs.distribute_dofs(fe_collection);
    const auto     n        = number_by_blocks(solid_dofs);
    const IndexSet owned    = solid_dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(solid_dofs);
    owned_partitioning      = split(owned, n);
    relevant_partitioning   = split(relevant, n);

    // Hanging nodes and symmetry planes; no pins for the free rigid motions
    // (the box corners they sit at are void in general): the drag holds
    // them.
    FreeRigidMotions no_pins(dim, {});
    no_pins.translations.clear();
    no_pins.rotations.clear();
    make_velocity_constraints(solid_dofs,
                              relevant,
                              settings.symmetry_boundaries,
                              no_pins,
                              constraints);
    constraints.close();
    velocity_modes = rigid_body_modes(solid_dofs, owned_partitioning[0]);

    // The old matrices go first: the new pattern and matrix do not have to
    // fit in memory beside them.
    system_matrix.clear();
    schur_matrix.clear();

    // Cells couple everything (eps:eps all velocity components, div, ASGS);
    // the ghost-penalty faces couple each component with itself across
    // them, on the DoFs no constraint removes (assemble_ghost_penalty()).
    // The cells' pattern holds the pairs within each owned cell, so a face
    // between two owned cells adds only the pairs of a DoF of one cell and
    // one of the other that the two do not share (in 3D 4 x 4 per
    // component on a regular face, against 16 x 16 through
    // add_entries_local_to_global(), which was two thirds of this set-up:
    // doc/performance.md, "Session 25").
    const unsigned int n_c  = dim + 1;
    const MPI_Comm     comm = solid_dofs.get_communicator();
    std::vector<types::global_dof_index> cell_dofs(
      finite_element.dofs_per_cell),
      neighbor_dofs(finite_element.dofs_per_cell), own, other;
    // The DoFs of component @p c in @p dofs that @p not_in lacks and no
    // constraint removes, sorted.
    const auto only_in = [&](const std::vector<types::global_dof_index> &dofs,
                             const std::vector<types::global_dof_index> &not_in,
                             const unsigned int                          c,
                             std::vector<types::global_dof_index> &result) {
      result.clear();
      for (unsigned int i = 0; i < dofs.size(); ++i)
        if (finite_element.system_to_component_index(i).first == c &&
            std::find(not_in.begin(), not_in.end(), dofs[i]) == not_in.end() &&
            !constraints.is_constrained(dofs[i]))
          result.push_back(dofs[i]);
      std::sort(result.begin(), result.end());
    };
    {
      BlockDynamicSparsityPattern dsp(relevant_partitioning);
      DoFTools::make_sparsity_pattern(solid_dofs,
                                      dsp,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));
      for_each_penalty_face(solid_dofs,
                            settings.band_level,
                            [&](const auto &cell,
                                const unsigned int,
                                const auto &neighbor,
                                const bool) {
        if (cell->active_fe_index() != with_solid ||
            neighbor->active_fe_index() != with_solid)
          return;
        cell->get_dof_indices(cell_dofs);
        neighbor->get_dof_indices(neighbor_dofs);
        for (unsigned int c = 0; c < n_c; ++c)
          if (neighbor->is_locally_owned())
            {
              only_in(cell_dofs, neighbor_dofs, c, own);
              only_in(neighbor_dofs, cell_dofs, c, other);
              for (const auto i : own)
                dsp.add_entries(i, other.begin(), other.end(), true);
              for (const auto j : other)
                dsp.add_entries(j, own.begin(), own.end(), true);
            }
          else
            {
              // A ghost neighbour's own pairs are in its owner's pattern,
              // not in the rows of this rank's that the assembly writes to
              // and sends on: every pair of the two cells goes in here.
              only_in(cell_dofs, {}, c, own);
              only_in(neighbor_dofs, {}, c, other);
              own.insert(own.end(), other.begin(), other.end());
              constraints.add_entries_local_to_global(own, dsp, false);
            }
      });
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      system_matrix.reinit(owned_partitioning, dsp, comm);
    }
    make_schur_layout(system_matrix,
                      owned_partitioning,
                      relevant_partitioning,
                      constraints,
                      schur_matrix);
    system_rhs.reinit(owned_partitioning, comm);
    solid_solution.reinit(owned_partitioning, relevant_partitioning, comm);
    solid_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
    solid_dofs_current = true;
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::copy_on_solid_cells(
    const DoFHandler<dim>           &from_dofs,
    const BlockVector               &from,
    const DoFHandler<dim>           &to_dofs,
    const AffineConstraints<double> &to_constraints,
    BlockVector                     &to) const
  {
    // The same Q1/Q1 element on both sides of a cell with solid: the local
    // DoFs correspond one to one. Every owned DoF of @p to on a cell with
    // solid lies on a locally owned or ghost cell, whose DoFs @p from holds.
    std::vector<IndexSet> owned_blocks;
    for (unsigned int b = 0; b < to.n_blocks(); ++b)
      owned_blocks.push_back(to.block(b).locally_owned_elements());
    BlockVector    owned(owned_blocks, to_dofs.get_communicator());
    const IndexSet mine = owned.locally_owned_elements();
    Vector<double> values(finite_element.dofs_per_cell);
    std::vector<types::global_dof_index> indices(finite_element.dofs_per_cell);
    for (const auto &cell : solid_dofs.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == with_solid)
        {
          same_cell(cell, from_dofs)->get_dof_values(from, values);
          same_cell(cell, to_dofs)->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            if (mine.is_element(indices[i]))
              owned(indices[i]) = values[i];
        }
    owned.compress(VectorOperation::insert);
    to_constraints.distribute(owned);
    to = owned;
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::fit_to(const LevelSetField<dim> &alpha)
  {
    classifier = alpha.classifier();
    if (update_solid_cells(*classifier))
      setup_solid_system();
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::assemble(const LevelSetField<dim> &alpha,
                                    const TrilinosWrappers::MPI::Vector &,
                                    const TrilinosWrappers::MPI::Vector &,
                                    const double surface_time_step)
  {
    Assert(classifier && solid_dofs_current,
           ExcMessage("assemble() needs fit_to() on the same level set"));
    // u^{n-1} on the solid's DoFs, for the history terms.
    copy_on_solid_cells(
      dofs, old_displacement, solid_dofs, constraints, solid_displacement);

    system_matrix = 0;
    system_rhs    = 0;
    schur_matrix  = 0;
    const StokesTerms<dim> terms(settings, surface_time_step);
    const DragAssembler<dim> drag(drag_per_a1);
    using CellData = StokesCellData<dim>;
    typename CellData::Inputs inputs{alpha, phase_law, solid_displacement};
    terms.set_inputs(inputs);
    // The solid's part of each cell with the pure solid's law: the extended
    // pressure's gathering, of which this space uses the solid phase (its
    // element's one pressure, component dim, is the solid's).
    inputs.extended_pressure = true;

    CellData         data(finite_element, inputs);
    CellContribution contribution(finite_element.dofs_per_cell);
    for (const auto &cell : solid_dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == with_solid)
        {
          contribution.reset();
          data.reinit_cut(cell);
          if (data.select_phase(Phase::solid))
            {
              terms.assemble_bulk(data, contribution);
              drag.assemble(data, contribution);
            }
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
      assemble_ghost_penalty(alpha);
    compress_system(system_matrix, system_rhs, schur_matrix);
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::assemble_ghost_penalty(
    const LevelSetField<dim> &alpha)
  {
    const GhostPenaltyAssembler<dim> penalty(ghost_penalty);
    FEInterfaceValues<dim> values = penalty_face_values(finite_element);
    const PhaseCoefficients law = phase_law.coefficients({1, 0});
    FullMatrix<double>      matrix, schur, unit, part;
    std::vector<unsigned int>            local, kept;
    std::vector<types::global_dof_index> global, kept_global;
    for_each_penalty_face(solid_dofs,
                          settings.band_level,
                          [&](const auto        &cell,
                              const unsigned int f,
                              const auto        &neighbor,
                              const bool         coarser) {
      if (cell->active_fe_index() != with_solid ||
          neighbor->active_fe_index() != with_solid ||
          (classifier->location_to_level_set(cell) !=
             Location::intersected &&
           classifier->location_to_level_set(neighbor) !=
             Location::intersected))
        return;
      reinit_penalty_face(values, cell, f, neighbor, coarser);
      const unsigned int n = values.n_current_interface_dofs();
      const double       h = cell_size(cell);
      // Each component's penalty is its weight times one matrix, the
      // products of the jumps of the vertices' Q1 shape functions: every
      // component lists the face's vertices in the same order among the
      // interface DoFs. So the face is integrated once, for component 0
      // at weight 1 (GhostPenaltyAssembler adds -g w [.][.] to `matrix`,
      // the -C of a pressure, and +g w [.][.] to `schur`).
      matrix.reinit(n, n);
      schur.reinit(n, n);
      penalty.assemble(values, alpha.measure(), 0, 1., matrix, schur);
      component_interface_dofs(values, finite_element, 0, local, global);
      unit.reinit(local.size(), local.size());
      unit.extract_submatrix_from(schur, local, local);
      for (unsigned int c = 0; c <= dim; ++c)
        {
          // The velocity's penalty goes into A, the pressure's into -C
          // and the Schur approximation.
          const bool   pressure = c == dim;
          const double weight =
            pressure ? law.a2 * h * h * h / law.a1 : law.a1 * h;
          component_interface_dofs(values, finite_element, c, local, global);
          AssertDimension(local.size(), unit.m());
          // The component's DoFs that no constraint removes, the entries
          // the pattern holds (a constrained DoF of a ghost neighbour
          // would add its diagonal to a row this rank has no entry in).
          kept.clear();
          kept_global.clear();
          for (unsigned int k = 0; k < global.size(); ++k)
            if (!constraints.is_constrained(global[k]))
              {
                kept.push_back(k);
                kept_global.push_back(global[k]);
              }
          part.reinit(kept.size(), kept.size());
          part.extract_submatrix_from(unit, kept, kept);
          part *= pressure ? -weight : weight;
          constraints.distribute_local_to_global(part,
                                                 kept_global,
                                                 system_matrix);
          if (pressure)
            {
              part *= -1.;
              constraints.distribute_local_to_global(part,
                                                     kept_global,
                                                     schur_matrix);
            }
        }
    });
  }

  template <int dim>
  unsigned int
  SolidElasticStokes<dim>::solve()
  {
    BlockVector owned_solution(owned_partitioning,
                               solid_dofs.get_communicator());
    // A Chebyshev smoother of degree 1: the two-phase spaces' degree 2 is
    // for their viscosity contrast, which the solid alone does not have.
    // On the 27 spheres like the 154 (1 rank, 3 solves): FGMRES 30/30/21
    // against 27/27/19 iterations, 21.7 s against 30.9 s, the metrics
    // within 4.0e-4 (doc/performance.md, "Session 25").
    const unsigned int iterations =
      solve_block_system(system_matrix,
                         schur_matrix.block(1, 1),
                         velocity_modes,
                         dim,
                         system_rhs,
                         owned_solution,
                         settings.tolerance,
                         settings.max_iterations,
                         settings.smoothed_aggregation,
                         1);
    constraints.distribute(owned_solution);
    solid_solution = owned_solution;
    copy_on_solid_cells(solid_dofs,
                        solid_solution,
                        dofs,
                        hanging_node_constraints,
                        ghosted_solution);
    return iterations;
  }

  template <int dim>
  void
  SolidElasticStokes<dim>::remove_rigid_motion(const LevelSetField<dim> &alpha)
  {
    remove_free_rigid_motion(dofs, alpha, free_motions, ghosted_solution);
  }

  template class SolidElasticStokes<2>;
  template class SolidElasticStokes<3>;
} // namespace levelsinter
