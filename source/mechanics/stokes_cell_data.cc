#include <deal.II/base/quadrature_lib.h>

#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/level_set/smoothed_heaviside.h>
#include <levelsinter/mechanics/stokes_cell_data.h>

#include <algorithm>
#include <cmath>

namespace levelsinter
{
  namespace
  {
    template <int dim>
    std::vector<unsigned int>
    components_of(const FESystem<dim> &fe)
    {
      std::vector<unsigned int> component(fe.dofs_per_cell);
      for (unsigned int i = 0; i < component.size(); ++i)
        component[i] = fe.system_to_component_index(i).first;
      return component;
    }

    const UpdateFlags cell_flags = update_values | update_gradients |
                                       update_JxW_values |
                                       update_quadrature_points;
    const UpdateFlags level_set_flags = update_values | update_gradients;
  } // namespace

  // Three Gauss points per direction: the smoothed coefficients and the
  // Dirac vary across a cell of the transition zone, and for the balanced
  // force the products grad H_h . w and H_h div w (degree 2 per direction)
  // are integrated exactly, so that f = grad(gamma kappa H_h) holds to
  // round-off. Where the phases are uniform 2 points per direction
  // integrate the Q1 products exactly (8/27 of the cost in 3D).
  template <int dim>
  StokesCellData<dim>::StokesCellData(const FESystem<dim> &fe,
                                      const Inputs        &inputs)
    : component(components_of(fe))
    , n_dofs(component.size())
    , inputs(inputs)
    , measure(inputs.alpha.measure())
    , transition_values(box_mapping<dim>(), fe, QGauss<dim>(3), cell_flags)
    , uniform_values(box_mapping<dim>(), fe, QGauss<dim>(2), cell_flags)
    , transition_level_set_values(box_mapping<dim>(),
                                  inputs.alpha.fe(),
                                  QGauss<dim>(3),
                                  level_set_flags)
    , uniform_level_set_values(box_mapping<dim>(),
                               inputs.alpha.fe(),
                               QGauss<dim>(2),
                               level_set_flags)
    , face_values(box_mapping<dim>(),
                  fe,
                  QGauss<dim - 1>(2),
                  update_values | update_normal_vectors | update_JxW_values |
                    update_quadrature_points)
    , fe_collection(fe)
    , mapping_collection(box_mapping<dim>())
    , uncut_quadrature(QGauss<dim>(2))
    // 3 points per direction for the extended pressure's volume parts, 2
    // for the sharp surface alone (both below).
    , cut_quadrature(QGauss<1>(inputs.extended_pressure ? 3 : 2))
    , vertex_alpha(inputs.alpha.fe().dofs_per_cell)
    , vertex_kappa(inputs.alpha.fe().dofs_per_cell)
  {
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        (is_pressure(i) ? pressure_dofs : velocity_dofs).push_back(i);
        vertex_of.push_back(fe.system_to_component_index(i).second);
      }
    if (inputs.extended_pressure)
      for (const unsigned int i : pressure_dofs)
        phase_pressure_dofs[component[i] - dim].push_back(i);
    if (!inputs.extended_pressure && inputs.surface != SurfaceMeasure::sharp)
      return;
    classifier = inputs.alpha.classifier();
    NonMatching::RegionUpdateFlags flags;
    flags.surface = update_values | update_gradients | update_JxW_values |
                    update_normal_vectors | update_quadrature_points;
    if (inputs.extended_pressure)
      {
        // 3 points per direction as below; the fitted weights sit on the
        // transition rule's points.
        if (!measure.is_axisymmetric())
          {
            cut_rules = std::make_unique<CutCellRules<dim>>(
              inputs.alpha.dof_handler(), inputs.alpha.alpha(), 3);
            return;
          }
        // Uncut cells: 2 Gauss points per direction, exact for the Q1
        // products as in reinit(). Cut cells: the generated rules on
        // {alpha_h < 0} and {alpha_h > 0} from 3 points per direction, so
        // that the two parts add up to the cell's integral of the
        // velocity terms to round-off and the pressure terms see a
        // well-resolved part.
        flags.inside  = cell_flags;
        flags.outside = cell_flags;
      }
    // The sharp surface alone: 2 points per direction (cut_quadrature), as
    // Q1 test-function gradients vary linearly in a cell and the geometric
    // error of the Q1 zero level set (O(h^2)) dominates the quadrature
    // error.
    cut_values =
      std::make_unique<NonMatching::FEValues<dim>>(mapping_collection,
                                                   fe_collection,
                                                   uncut_quadrature,
                                                   cut_quadrature,
                                                   flags,
                                                   *classifier,
                                                   inputs.alpha.dof_handler(),
                                                   inputs.alpha.alpha());
  }

  template <int dim>
  void
  StokesCellData<dim>::reinit(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    const LevelSetField<dim> &alpha = inputs.alpha;
    h = cell_size(cell);
    // E follows the cell where it is refined beyond the band, so that the
    // 3-point rule integrates the jump instead of sampling it, and stays
    // the band's on coarser cells, where the filtered level set is no
    // distance (doc/numerics.md, "Mesh refinement: curvature refinement
    // near necks").
    const int    coarser = std::max(0, int(inputs.band_level) - cell->level());
    const double E = inputs.interface_half_width_cells * h / (1u << coarser);

    // The phases are constant where alpha < -E (solid) or alpha > 3E
    // (atmosphere beyond its compressible layer, Eq. 102 shifted by 2E); Q1
    // alpha takes its extremes at the vertices. A void atmosphere takes the
    // 2-point rule from alpha > E on, where only its compressible layer's
    // weight varies: a filtered level set saturates at +-2 E_f / pi (sine
    // filter), inside that layer in the packings (0.036 against 3E = 0.042
    // in packing_154_coupled_3d.prm), so that otherwise 84-87 % of a
    // packing mesh's cells took the 3-point rule (doc/performance.md,
    // "Session 22": 37 % with it, the metrics of the 8-sphere guard within
    // 5e-4). The nodal H_h of the balanced force is not bounded this way
    // under hanging nodes, so that form keeps the 3-point rule.
    const auto ls_cell = same_cell(cell, alpha.dof_handler());
    ls_cell->get_dof_values(alpha.alpha(), vertex_alpha);
    const auto [lowest, highest] =
      std::minmax_element(vertex_alpha.begin(), vertex_alpha.end());
    const double atmosphere = inputs.void_atmosphere ? E : 3 * E;
    const bool   uniform    = inputs.solid_fraction == nullptr &&
                         (*highest < -E || *lowest > atmosphere);
    FEValues<dim> &values = uniform ? uniform_values : transition_values;
    FEValues<dim> &level_set_values =
      uniform ? uniform_level_set_values : transition_level_set_values;
    values.reinit(cell);
    level_set_values.reinit(ls_cell);
    reinit_shapes(values);
    gather_phases(values, level_set_values, E);

    surface.clear();
    if (inputs.surface == SurfaceMeasure::smeared)
      gather_smeared_surface(E);
    else if (inputs.surface == SurfaceMeasure::sharp)
      gather_sharp_surface(cell);
    free_faces.clear();
    if (inputs.free_faces)
      gather_free_faces(cell);
  }

  template <int dim>
  void
  StokesCellData<dim>::reinit_shapes(const FEValues<dim> &values)
  {
    n_q = values.n_quadrature_points;
    // Grown, never shrunk: the rule alternates between 2 and 3 points per
    // direction from cell to cell.
    if (JxW.size() < n_q)
      {
        JxW.resize(n_q);
        inverse_radius.resize(n_q);
        law.resize(n_q);
        tau.resize(n_q);
        history.resize(n_q);
        balanced_force.resize(n_q);
        value.resize(n_q, std::vector<double>(n_dofs));
        gradient.resize(n_q, std::vector<Tensor<1, dim>>(n_dofs));
        states.resize(n_q);
      }
    for (unsigned int k = 0; k < n_q; ++k)
      {
        JxW[k]            = measure.JxW(values, k);
        inverse_radius[k] = measure.inverse_radius(values.quadrature_point(k));
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            value[k][i]    = values.shape_value_component(i, k, component[i]);
            gradient[k][i] = values.shape_grad_component(i, k, component[i]);
          }
        history[k]        = HistoryTerms<dim>();
        balanced_force[k] = Tensor<1, dim>();
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::gather_phases(const FEValues<dim> &values,
                                     const FEValues<dim> &level_set_values,
                                     const double         E)
  {
    const LevelSetField<dim> &alpha     = inputs.alpha;
    const PhaseLaw<dim>      &phase_law = inputs.law;
    const SmoothedHeaviside   heaviside(E);
    alpha_q.resize(n_q);
    grad_alpha_q.resize(n_q);
    level_set_values.get_function_values(alpha.alpha(), alpha_q);
    level_set_values.get_function_gradients(alpha.alpha(), grad_alpha_q);
    const bool balanced = inputs.solid_fraction != nullptr;
    if (balanced)
      {
        kappa_q.resize(n_q);
        grad_heaviside_q.resize(n_q);
        level_set_values.get_function_values(*inputs.curvature, kappa_q);
        level_set_values.get_function_gradients(*inputs.solid_fraction,
                                                grad_heaviside_q);
      }
    const bool memory = phase_law.has_history();
    if (memory)
      phase_law.material_states(
        {values, level_set_values, inputs.displacement}, states);

    // The Schur approximation weighs the pressure mass with the cell-mean
    // viscosity (Grinevich & Olshanskii 2009), which keeps the outer
    // iterations independent of the contrast (doc/numerics.md, "Stokes
    // preconditioner").
    a1_cell = 0;
    for (unsigned int k = 0; k < n_q; ++k)
      {
        const PhaseFractions fractions{
          heaviside.solid_fraction(alpha_q[k]),
          1 - heaviside.solid_fraction(alpha_q[k] - 2 * E)};
        law[k] = phase_law.coefficients(fractions);
        if (memory)
          history[k] = phase_law.history(fractions, states[k]);
        a1_cell += law[k].a1 / n_q;
        tau[k] = inputs.stabilisation_constant * law[k].a2 * h * h / law[k].a1;
        if (balanced)
          balanced_force[k] =
            inputs.surface_tension * kappa_q[k] * grad_heaviside_q[k];
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::gather_smeared_surface(const double E)
  {
    // dS -> delta(alpha) |grad alpha| dV: by the co-area formula the smeared
    // integral is the average of the sharp one over the level sets
    // |alpha| < E.
    const SmoothedHeaviside heaviside(E);
    for (unsigned int k = 0; k < n_q; ++k)
      {
        const double norm   = grad_alpha_q[k].norm();
        const double weight = heaviside.dirac(alpha_q[k]) * norm * JxW[k];
        if (weight > 0)
          {
            SurfacePoint point{grad_alpha_q[k] / norm, weight, {}, {}};
            point.grad_w.resize(n_dofs);
            point.hoop.resize(n_dofs);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                point.grad_w[i] = velocity_gradient(k, i);
                point.hoop[i]   = hoop(k, i);
              }
            surface.push_back(std::move(point));
          }
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::gather_sharp_surface(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    cut_values->reinit(cell);
    if (const auto &cut = cut_values->get_surface_fe_values())
      {
        if (inputs.curvature)
          same_cell(cell, inputs.alpha.dof_handler())
            ->get_dof_values(*inputs.curvature, vertex_kappa);
        add_surface_points(*cut);
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::add_surface_points(
    const NonMatching::FEImmersedSurfaceValues<dim> &cut)
  {
    const FEValuesExtractors::Vector velocity(0);
    for (const unsigned int k : cut.quadrature_point_indices())
      {
        SurfacePoint point{cut.normal_vector(k), measure.JxW(cut, k), {}, {}};
        const double inverse_radius =
          measure.inverse_radius(cut.quadrature_point(k));
        point.grad_w.resize(n_dofs);
        point.hoop.resize(n_dofs);
        point.normal_w.resize(n_dofs);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const Tensor<1, dim> w = cut[velocity].value(i, k);
            point.grad_w[i]        = cut[velocity].gradient(i, k);
            point.hoop[i]          = w[0] * inverse_radius;
            point.normal_w[i]      = w * point.normal;
          }
        // kappa_h is Q1 on the level set's element, the velocity's base
        // element: its shape functions are the first component's.
        if (inputs.curvature)
          for (unsigned int j = 0; j < vertex_kappa.size(); ++j)
            point.curvature +=
              vertex_kappa[j] *
              cut.shape_value_component(
                fe_collection[0].component_to_system_index(0, j), k, 0);
        surface.push_back(std::move(point));
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::add_surface_points(
    const std::vector<typename CutCellRules<dim>::SurfacePoint> &points)
  {
    for (const auto &p : points)
      {
        SurfacePoint point{p.normal, p.dS, {}, {}};
        point.grad_w.assign(n_dofs, Tensor<2, dim>());
        point.hoop.assign(n_dofs, 0.);
        point.normal_w.assign(n_dofs, 0.);
        for (unsigned int i = 0; i < n_dofs; ++i)
          if (!is_pressure(i))
            {
              point.grad_w[i][component[i]] = p.gradient[vertex_of[i]];
              point.normal_w[i] = p.value[vertex_of[i]] * p.normal[component[i]];
            }
        if (inputs.curvature)
          for (unsigned int j = 0; j < vertex_kappa.size(); ++j)
            point.curvature += vertex_kappa[j] * p.value[j];
        surface.push_back(std::move(point));
      }
  }

  template <int dim>
  void
  StokesCellData<dim>::reinit_cut(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    h = cell_size(cell);
    surface.clear();
    cut_cell     = cell;
    cut_location = classifier->location_to_level_set(cell);
    if (!cut_rules)
      gather_sharp_surface(cell);
    else if (cut_location == NonMatching::LocationToLevelSet::intersected)
      {
        cut_rules->generate(cell);
        if (inputs.curvature)
          same_cell(cell, inputs.alpha.dof_handler())
            ->get_dof_values(*inputs.curvature, vertex_kappa);
        add_surface_points(cut_rules->surface());
      }
    free_faces.clear();
    if (inputs.free_faces)
      gather_free_faces(cell);
  }

  template <int dim>
  const FEValues<dim> *
  StokesCellData<dim>::reinit_part(const Phase phase)
  {
    using Location    = NonMatching::LocationToLevelSet;
    const bool inside = phase == Phase::solid;
    if (!cut_rules)
      {
        const auto &region = inside ? cut_values->get_inside_fe_values() :
                                      cut_values->get_outside_fe_values();
        if (!region)
          return nullptr;
        reinit_shapes(*region);
        return &*region;
      }
    if (cut_location != Location::intersected)
      {
        if ((cut_location == Location::inside) != inside)
          return nullptr;
        uniform_values.reinit(cut_cell);
        reinit_shapes(uniform_values);
        return &uniform_values;
      }
    if (!cut_rules->has_part(inside))
      return nullptr;
    transition_values.reinit(cut_cell);
    reinit_shapes(transition_values);
    // The fitted weights on the unit cell, times det J.
    const auto &weights = cut_rules->weights(inside);
    const auto &gauss   = cut_rules->cell_quadrature();
    for (unsigned int k = 0; k < n_q; ++k)
      JxW[k] *= weights[k] / gauss.weight(k);
    return &transition_values;
  }

  template <int dim>
  bool
  StokesCellData<dim>::select_phase(const Phase phase)
  {
    const FEValues<dim> *region = reinit_part(phase);
    if (!region)
      return false;
    pressure_dofs = phase_pressure_dofs[phase == Phase::solid ? 0 : 1];

    // Each phase is pure on its side of the sharp interface: no smoothing
    // width, and the atmosphere is compressible up to the interface, since
    // the solid's own pressure keeps the solid incompressible (the
    // transition zone of NewtonianPhases is not needed).
    const PhaseFractions fractions =
      phase == Phase::solid ? PhaseFractions{1, 0} : PhaseFractions{0, 1};
    const PhaseCoefficients coefficients = inputs.law.coefficients(fractions);
    // Laws that read their state from the level set's element
    // (viscoelastic melts) are refused with the extended pressure
    // (SceneParameters), so the level-set values are not read.
    const bool memory = inputs.law.has_history();
    if (memory)
      inputs.law.material_states(
        {*region, uniform_level_set_values, inputs.displacement}, states);
    a1_cell = coefficients.a1;
    for (unsigned int k = 0; k < n_q; ++k)
      {
        law[k] = coefficients;
        if (memory)
          history[k] = inputs.law.history(fractions, states[k]);
        tau[k] = inputs.stabilisation_constant * coefficients.a2 * h * h /
                 coefficients.a1;
      }
    return true;
  }

  template <int dim>
  void
  StokesCellData<dim>::gather_free_faces(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    const FEValuesExtractors::Vector velocity(0);
    const auto &symmetry = inputs.symmetry_boundaries;
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() &&
          std::find(symmetry.begin(), symmetry.end(), face->boundary_id()) ==
            symmetry.end())
        {
          face_values.reinit(cell, face);
          Face free_face;
          free_face.boundary_id = face->boundary_id();
          for (const unsigned int k : face_values.quadrature_point_indices())
            {
              FacePoint point{face_values.normal_vector(k),
                              measure.JxW(face_values, k),
                              {}};
              point.w.resize(n_dofs);
              for (unsigned int i = 0; i < n_dofs; ++i)
                point.w[i] = face_values[velocity].value(i, k);
              free_face.points.push_back(std::move(point));
            }
          free_faces.push_back(std::move(free_face));
        }
  }

  template class StokesCellData<2>;
  template class StokesCellData<3>;
} // namespace levelsinter
