#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/non_matching/fe_values.h>
#include <deal.II/non_matching/mesh_classifier.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/level_set/smoothed_heaviside.h>
#include <levelsinter/mechanics/block_schur_preconditioner.h>
#include <levelsinter/mechanics/free_rigid_motion.h>
#include <levelsinter/mechanics/rigid_body_modes.h>
#include <levelsinter/mechanics/stokes_assemblers.h>
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

        Table<2, DoFTools::Coupling> coupling(dim + 1, dim + 1);
        for (unsigned int c = 0; c < dim + 1; ++c)
          for (unsigned int d = 0; d < dim + 1; ++d)
            coupling[c][d] =
              (c == dim && d == dim) ? DoFTools::always : DoFTools::none;
        BlockDynamicSparsityPattern schur_dsp(relevant_partitioning);
        DoFTools::make_sparsity_pattern(
          dofs, coupling, schur_dsp, constraints, false);
        SparsityTools::distribute_sparsity_pattern(schur_dsp,
                                                   owned_dofs,
                                                   comm,
                                                   relevant_dofs);
        schur_matrix.reinit(owned_partitioning, schur_dsp, comm);
      }
    system_rhs.reinit(owned_partitioning, comm);
    ghosted_solution.reinit(owned_partitioning, relevant_partitioning, comm);
    old_displacement.reinit(owned_partitioning, relevant_partitioning, comm);
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::make_constraints()
  {
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    // Symmetry plane = box face with zero normal velocity; the faces are
    // axis-aligned (colorized ids 2k, 2k+1 have normal e_k), so this is a
    // homogeneous Dirichlet condition on one component.
    for (const types::boundary_id id : settings.symmetry_boundaries)
      {
        ComponentMask normal(dim + 1, false);
        normal.set(id / 2, true);
        VectorTools::interpolate_boundary_values(
          dofs, id, Functions::ZeroFunction<dim>(dim + 1), constraints, normal);
      }
    pin_rigid_body_modes();
    constraints.close();
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::pin_rigid_body_modes()
  {
    // Pin what survives the symmetry planes at box corners: with the lower
    // corner a, b = a + L_x e_x and c = a + L_y e_y, v_k(a) = 0 removes the
    // translation along e_k, v_y(b) = 0 the rotation about z, v_z(b) = 0
    // the one about y and v_z(c) = 0 the one about x. The capillary load is
    // self-equilibrated (see the class documentation), so the pins carry no
    // reaction: they only select one member of the family of solutions
    // (remove_rigid_motion() then selects the physical one).
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    const auto &tria = dofs.get_triangulation();
    for (const auto &vertex : tria.get_vertices())
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], vertex[d]);
          upper[d] = std::max(upper[d], vertex[d]);
        }
    Point<dim> b = lower, c = lower;
    b[0]         = upper[0];
    c[1]         = upper[1];
    std::vector<std::pair<Point<dim>, unsigned int>> pins;
    for (const unsigned int k : free_motions.translations)
      pins.emplace_back(lower, k);
    for (const unsigned int k : free_motions.rotations)
      if (k == 2)
        pins.emplace_back(b, 1);
      else if (k == 1)
        pins.emplace_back(b, 2);
      else
        pins.emplace_back(c, 2);
    const double tolerance = 1e-10 * lower.distance(upper);
    for (const auto &cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          for (const auto &[point, component] : pins)
            if (cell->vertex(v).distance(point) < tolerance)
              {
                const auto index = cell->vertex_dof_index(v, component);
                if (constraints.can_store_line(index) &&
                    !constraints.is_constrained(index))
                  constraints.add_line(index);
              }
  }

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

    const double gamma = settings.surface_tension;
    const bool              curvature_form =
      settings.form == SurfaceTensionForm::csf_curvature && gamma != 0;
    const bool sharp = settings.form == SurfaceTensionForm::sharp && gamma != 0;
    const double implicit_dt = gamma != 0 ? surface_time_step : 0.;
    if (curvature_form &&
        (curvature.size() != alpha.dof_handler().n_dofs() ||
         interface_level_set.size() != alpha.dof_handler().n_dofs()))
      throw std::runtime_error(
        "viscous flow: the csf-curvature surface-tension form needs a "
        "curvature and an interface level set on the level-set DoFs");

    // H_h of the balanced force: H_s at the level-set nodes, with the
    // hanging-node constraints applied so that H_h lies in the (continuous)
    // pressure space. A node has no cell size of its own: E is taken at the
    // finest cells (the form is meant for the bubble's uniform meshes).
    // Read from the interface level set: alpha is no distance everywhere
    // in the transition zone (redistanced_level_set()).
    TrilinosWrappers::MPI::Vector solid_fraction;
    if (curvature_form)
      {
        const SmoothedHeaviside heaviside(
          settings.interface_half_width_cells *
          GridTools::minimal_cell_diameter(dofs.get_triangulation()) /
          std::sqrt(double(dim)));
        const MPI_Comm                comm = dofs.get_communicator();
        TrilinosWrappers::MPI::Vector owned(alpha.locally_owned(), comm);
        for (const auto i : alpha.locally_owned())
          owned(i) = heaviside.solid_fraction(interface_level_set(i));
        owned.compress(VectorOperation::insert);
        alpha.constraints().distribute(owned);
        solid_fraction.reinit(alpha.locally_owned(),
                              alpha.locally_relevant(),
                              comm);
        solid_fraction = owned;
      }

    // Three Gauss points per direction: the smoothed coefficients and the
    // Dirac vary across a cell of the band; for the balanced force the
    // products grad H_h . w and H_h div w (degree 2 per direction) are
    // integrated exactly, so the discrete integration by parts that makes
    // f = grad(gamma kappa H_h) holds to round-off.
    // Cells the transition zone does not reach have constant coefficients
    // and no surface terms: there 2 points per direction integrate the Q1
    // products exactly, at 8/27 of the cost in 3D.
    const QGauss<dim>     quadrature(3);
    const QGauss<dim>     uniform_quadrature(2);
    const QGauss<dim - 1> face_quadrature(2);
    const UpdateFlags     flags = update_values | update_gradients |
                              update_JxW_values | update_quadrature_points;
    const SceneMeasure   &measure = alpha.measure();
    FEValues<dim> transition_values(finite_element, quadrature, flags);
    FEValues<dim> uniform_values(finite_element, uniform_quadrature, flags);
    FEValues<dim> transition_level_set_values(alpha.fe(),
                                              quadrature,
                                              update_values |
                                                update_gradients);
    FEValues<dim> uniform_level_set_values(alpha.fe(),
                                           uniform_quadrature,
                                           update_values | update_gradients);
    Vector<double> vertex_alpha(alpha.fe().dofs_per_cell);
    FEFaceValues<dim> face_values(finite_element,
                                  face_quadrature,
                                  update_values | update_normal_vectors |
                                    update_JxW_values |
                                    update_quadrature_points);

    std::unique_ptr<NonMatching::MeshClassifier<dim>> classifier;
    std::unique_ptr<NonMatching::FEValues<dim>>       cut_values;
    const hp::FECollection<dim>                       fe_collection(
      finite_element);
    if (sharp)
      {
        classifier = std::make_unique<NonMatching::MeshClassifier<dim>>(
          alpha.dof_handler(), alpha.alpha());
        classifier->reclassify();
        NonMatching::RegionUpdateFlags flags;
        flags.surface = update_values | update_gradients |
                        update_JxW_values | update_normal_vectors |
                        update_quadrature_points;
        // 2 points per direction: Q1 test-function gradients vary
        // linearly in a cell, and the geometric error of the Q1 zero level
        // set (O(h^2)) dominates the quadrature error.
        cut_values = std::make_unique<NonMatching::FEValues<dim>>(
          fe_collection,
          QGauss<1>(2),
          flags,
          *classifier,
          alpha.dof_handler(),
          alpha.alpha());
      }

    const FEValuesExtractors::Vector velocity(0);
    const unsigned int               n = finite_element.dofs_per_cell;
    std::vector<unsigned int>        component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = finite_element.system_to_component_index(i).first;
    StokesCellData<dim>                  data(component);
    CellContribution                     cell_contribution(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<double>                  alpha_q(quadrature.size());
    std::vector<Tensor<1, dim>>          grad_alpha_q(quadrature.size());
    std::vector<double>                  kappa_q(quadrature.size());
    std::vector<Tensor<1, dim>>          grad_heaviside_q(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> old_strain_q(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> polymer_stress_q(quadrature.size());
    std::vector<double>                  polymer_hoop_q(quadrature.size());
    const bool history        = phase_law.has_history();
    const bool polymer_stress = phase_law.has_polymer_stress();
    if (polymer_stress &&
        (conformation == nullptr ||
         &conformation->dof_handler() != &alpha.dof_handler()))
      throw std::logic_error(
        "TwoPhaseStokes: a law with polymer stress needs a conformation "
        "field on the level set's DoFs (set_conformation())");

    // The terms of the operator, chosen once for this assembly.
    std::vector<std::unique_ptr<StokesAssembler<dim>>> assemblers;
    assemblers.push_back(std::make_unique<BulkAssembler<dim>>());
    assemblers.push_back(std::make_unique<StabilisationAssembler<dim>>());
    if (curvature_form)
      assemblers.push_back(std::make_unique<BalancedForceAssembler<dim>>());
    else if (gamma != 0)
      assemblers.push_back(
        std::make_unique<TensorialSurfaceTensionAssembler<dim>>(gamma));
    if (implicit_dt > 0)
      assemblers.push_back(
        std::make_unique<LaplaceBeltramiAssembler<dim>>(gamma, implicit_dt));
    if (settings.external_pressure != 0)
      assemblers.push_back(
        std::make_unique<TractionAssembler<dim>>(settings.external_pressure));
    // The surface measure is needed by the tensorial load and the
    // Laplace-Beltrami term.
    const bool surface_measure = (gamma != 0 && !curvature_form) ||
                                 implicit_dt > 0;

    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double h = cell->diameter() / std::sqrt(double(dim));
          // The smoothing follows the cell where it is refined beyond the
          // band: a jump narrower than the cell would be sampled, not
          // integrated, by the 3-point Gauss rule (measured with E tied to
          // h_min under curvature refinement: the area drift grew 2.8-fold,
          // doc/validation.md). It does not widen on cells coarser than the
          // band: the filtered level set carries the distance only a few
          // band cells out (the sine filter saturates at 2 E_f / pi), so a
          // wider ramp there would mix the phases far from the interface.
          const int    coarser = std::max(0, int(settings.band_level) -
                                                cell->level());
          const double E =
            settings.interface_half_width_cells * h / (1u << coarser);
          const SmoothedHeaviside heaviside(E);

          // The phases are constant where alpha < -E (solid) or alpha > 3E
          // (atmosphere beyond its compressible layer, Eq. 102 shifted by
          // 2E); Q1 alpha takes its extremes at the vertices. The nodal
          // H_h of the balanced force is not bounded this way under
          // hanging nodes, so that form keeps the 3-point rule.
          const auto ls_cell = same_cell(cell, alpha.dof_handler());
          ls_cell->get_dof_values(alpha.alpha(), vertex_alpha);
          const auto [lowest, highest] =
            std::minmax_element(vertex_alpha.begin(), vertex_alpha.end());
          const bool uniform =
            !curvature_form && (*highest < -E || *lowest > 3 * E);
          FEValues<dim> &values = uniform ? uniform_values : transition_values;
          FEValues<dim> &level_set_values =
            uniform ? uniform_level_set_values : transition_level_set_values;
          const unsigned int n_q = values.get_quadrature().size();
          values.reinit(cell);
          level_set_values.reinit(ls_cell);
          data.reinit(values, measure);
          data.h = h;
          alpha_q.resize(n_q);
          grad_alpha_q.resize(n_q);
          level_set_values.get_function_values(alpha.alpha(), alpha_q);
          level_set_values.get_function_gradients(alpha.alpha(),
                                                  grad_alpha_q);
          if (curvature_form)
            {
              level_set_values.get_function_values(curvature, kappa_q);
              level_set_values.get_function_gradients(solid_fraction,
                                                      grad_heaviside_q);
            }
          if (history)
            {
              old_strain_q.resize(n_q);
              values[velocity].get_function_symmetric_gradients(
                old_displacement, old_strain_q);
            }
          if (polymer_stress)
            conformation->stress_values(level_set_values,
                                        polymer_stress_q,
                                        polymer_hoop_q);
          // The Schur approximation weighs the pressure mass with the
          // cell-mean viscosity (Grinevich & Olshanskii 2009): with the
          // pointwise 1/eta of the smeared interface the outer iterations
          // grew with the contrast (doc/numerics.md).
          data.a1_cell = 0;
          for (const unsigned int k : values.quadrature_point_indices())
            {
              const PhaseFractions fractions{
                heaviside.solid_fraction(alpha_q[k]),
                1 - heaviside.solid_fraction(alpha_q[k] - 2 * E)};
              data.law[k] = phase_law.coefficients(fractions);
              if (history || polymer_stress)
                {
                  MaterialState<dim> state;
                  if (history)
                    state.old_strain = old_strain_q[k];
                  if (polymer_stress)
                    {
                      state.polymer_stress      = polymer_stress_q[k];
                      state.polymer_hoop_stress = polymer_hoop_q[k];
                    }
                  data.history[k] = phase_law.history(fractions, state);
                }
              data.a1_cell += data.law[k].a1 / n_q;
              data.tau[k] = settings.stabilisation_constant * data.law[k].a2 *
                            h * h / data.law[k].a1;
              if (curvature_form)
                data.balanced_force[k] =
                  gamma * kappa_q[k] * grad_heaviside_q[k];
            }

          if (surface_measure && !sharp)
            for (const unsigned int k : values.quadrature_point_indices())
              {
                // dS -> delta(alpha) |grad alpha| dV: the co-area formula
                // makes the smeared integral the average of the sharp one
                // over the level sets |alpha| < E.
                const double norm = grad_alpha_q[k].norm();
                const double weight =
                  heaviside.dirac(alpha_q[k]) * norm * data.JxW[k];
                if (weight > 0)
                  {
                    typename StokesCellData<dim>::SurfacePoint point{
                      grad_alpha_q[k] / norm, weight, {}, {}};
                    point.grad_w.resize(n);
                    point.hoop.resize(n);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        point.grad_w[i] = data.velocity_gradient(k, i);
                        point.hoop[i]   = data.hoop(k, i);
                      }
                    data.surface.push_back(std::move(point));
                  }
              }
          if (surface_measure && sharp)
            {
              cut_values->reinit(cell);
              if (const auto &surface = cut_values->get_surface_fe_values())
                for (const unsigned int k :
                     surface->quadrature_point_indices())
                  {
                    typename StokesCellData<dim>::SurfacePoint point{
                      surface->normal_vector(k),
                      measure.JxW(*surface, k),
                      {},
                      {}};
                    const double inverse_radius =
                      measure.inverse_radius(surface->quadrature_point(k));
                    point.grad_w.resize(n);
                    point.hoop.resize(n);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        point.grad_w[i] = (*surface)[velocity].gradient(i, k);
                        point.hoop[i] =
                          (*surface)[velocity].value(i, k)[0] * inverse_radius;
                      }
                    data.surface.push_back(std::move(point));
                  }
            }

          // Free faces: those not on a symmetry plane.
          if (settings.external_pressure != 0)
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() &&
                  std::find(settings.symmetry_boundaries.begin(),
                            settings.symmetry_boundaries.end(),
                            face->boundary_id()) ==
                    settings.symmetry_boundaries.end())
                {
                  face_values.reinit(cell, face);
                  for (const unsigned int k :
                       face_values.quadrature_point_indices())
                    {
                      typename StokesCellData<dim>::FacePoint point{
                        face_values.normal_vector(k),
                        measure.JxW(face_values, k),
                        {}};
                      point.w.resize(n);
                      for (unsigned int i = 0; i < n; ++i)
                        point.w[i] = face_values[velocity].value(i, k);
                      data.free_faces.push_back(std::move(point));
                    }
                }

          cell_contribution.reset();
          for (const auto &assembler : assemblers)
            assembler->assemble(data, cell_contribution);
          symmetrise(data, cell_contribution);
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_contribution.matrix,
                                                 cell_contribution.rhs,
                                                 indices,
                                                 matrix,
                                                 rhs);
          if (!settings.direct_solver)
            constraints.distribute_local_to_global(cell_contribution.schur,
                                                   indices,
                                                   schur_matrix);
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
      {
        const BlockSchurPreconditioner preconditioner(
          system_matrix, schur_matrix.block(1, 1), velocity_modes, dim);
        SolverControl control(settings.max_iterations,
                              settings.tolerance * system_rhs.l2_norm());
        SolverFGMRES<BlockVector> solver(
          control, SolverFGMRES<BlockVector>::AdditionalData(100));
        constraints.set_zero(owned_solution);
        try
          {
            if (system_rhs.l2_norm() > 0)
              solver.solve(system_matrix,
                           owned_solution,
                           system_rhs,
                           preconditioner);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            // A diagnosis instead of deal.II's stack trace.
            std::ostringstream message;
            message << "velocity-pressure solve: FGMRES did not reach the relative "
                    << "residual " << settings.tolerance << " in "
                    << e.last_step << " iterations (residual "
                    << e.last_residual / system_rhs.l2_norm()
                    << "); raise 'Viscous flow/Maximum solver iterations' "
                    << "or use 'Linear solver = direct' for a small 2D scene";
            throw std::runtime_error(message.str());
          }
        iterations = control.last_step();
      }
    constraints.distribute(owned_solution);
    ghosted_solution = owned_solution;
    return iterations;
  }

  template <int dim>
  void
  TwoPhaseStokes<dim>::advance_displacement(const double dt)
  {
    // u^n = u^{n-1} + dt v^n (Eq. 92) on the velocity block; the pressure
    // block of the vector is unused.
    // Both operands without ghosts: Trilinos adds vectors of one layout.
    BlockVector owned(owned_partitioning, dofs.get_communicator());
    BlockVector velocity(owned_partitioning, dofs.get_communicator());
    owned    = old_displacement;
    velocity = ghosted_solution;
    owned.block(0).add(dt, velocity.block(0));
    old_displacement = owned;
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
