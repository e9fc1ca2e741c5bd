#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/interface_measures.h>
#include <levelsinter/mechanisms/grain_boundary_diffusion.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // The sums kernel_sums() returns per grain boundary.
    constexpr unsigned int n_sums = 5;

    // An equilibrium neck r sin(psi/2) of fewer triple-line kernel
    // half-widths than this was measured not to settle: 1.15 (R/h = 8,
    // gamma_gb = gamma_s) and 1.66 (R/h = 32, gamma_gb / gamma_s = 1.9);
    // 2.3 settled (R/h = 16) (doc/validation.md, "Settling the pair: R/h =
    // 32, the axisymmetric pair, R/h = 8").
    constexpr double settled_neck_kernels = 2;

    // The grains of the power cells @p cells (the candidates @p near) that
    // own @p x: the least power's, and every other within a tie of it. A
    // node on a grain boundary (equal powers: mesh lines often lie on the
    // plane of equal grains) belongs to all of them, so that a symmetric
    // pair stays symmetric.
    template <int dim>
    std::vector<unsigned int>
    tied_owners(const PowerCells<dim>           &cells,
                const Point<dim>                &x,
                const std::vector<unsigned int> &near)
    {
      const unsigned int owner = cells.owner(x, near);
      const double       tie =
        cells.power(x, owner) + 1e-9 * std::pow(cells.radius(owner), 2);
      std::vector<unsigned int> tied;
      for (const unsigned int k : near)
        if (cells.power(x, k) <= tie)
          tied.push_back(k);
      return tied;
    }

    // The solution of matrix x = rhs with no component in the matrix's
    // null space (singular values below 1e-10 of the largest count as
    // zero), by the singular-value decomposition.
    dealii::Vector<double>
    minimum_norm_solution(LAPACKFullMatrix<double>     &matrix,
                          const dealii::Vector<double> &rhs)
    {
      const unsigned int n = rhs.size();
      matrix.compute_svd();
      const auto            &u     = matrix.get_svd_u();
      const auto            &vt    = matrix.get_svd_vt();
      const double           s_max = matrix.singular_value(0);
      dealii::Vector<double> x(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          const double s = matrix.singular_value(k);
          if (!(s > 1e-10 * s_max))
            break;
          double projection = 0;
          for (unsigned int r = 0; r < n; ++r)
            projection += u(r, k) * rhs(r);
          for (unsigned int r = 0; r < n; ++r)
            x(r) += projection / s * vt(k, r);
        }
      return x;
    }
  } // namespace

  template <int dim>
  GrainBoundaryDiffusion<dim>::GrainBoundaryDiffusion(
    const GrainBoundaryParameters          &parameters,
    const std::vector<std::vector<double>> &particles,
    const double                            seconds_per_time_unit,
    SurfaceDiffusion<dim>                  &surface_diffusion,
    TimerOutput                            &timer)
    : parameters(parameters)
    , mobility(parameters.coefficient * seconds_per_time_unit)
    , surface_diffusion(surface_diffusion)
    , timer(timer)
  {
    for (const auto &p : particles)
      {
        Point<dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = p[d];
        centre.push_back(c);
        radii.push_back(p[dim]);
      }
    trial_velocity.resize(centre.size());
    weight_shift.resize(centre.size(), 0.);
    if (parameters.triple_line && parameters.energy_ratio > 0)
      surface_diffusion.set_potential_source(
        [this](const LevelSetField<dim> &alpha, auto &mu) {
          triple_line_potential(alpha, mu);
        });
    if (!parameters.surface_factors.empty())
      surface_diffusion.set_mobility_source(
        [this](const LevelSetField<dim> &alpha, auto &factor) {
          surface_mobility_factors(alpha, factor);
        });
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::surface_mobility_factors(
    const LevelSetField<dim>      &alpha,
    TrilinosWrappers::MPI::Vector &factor) const
  {
    // Each node takes its grain's factor of C_s, a node on a grain boundary
    // the mean of its grains': the coefficient jumps within the cells about
    // the boundary's plane, and the weak form keeps the flux C_s grad_s
    // kappa continuous across it.
    const PowerCells<dim>     cells = grains();
    std::vector<unsigned int> near;
    for (const auto &cell : alpha.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cells.candidates(cell->center(), cell->diameter() / 2, near);
          for (const unsigned int v : cell->vertex_indices())
            if (const auto i = cell->vertex_dof_index(v, 0);
                alpha.locally_owned().is_element(i))
              {
                const auto tied = tied_owners(cells, cell->vertex(v), near);
                double     sum  = 0;
                for (const unsigned int k : tied)
                  sum += parameters.surface_factor(k);
                factor(i) = sum / tied.size();
              }
        }
    factor.compress(VectorOperation::insert);
  }

  template <int dim>
  PowerCells<dim>
  GrainBoundaryDiffusion<dim>::grains() const
  {
    std::vector<std::vector<double>> rows;
    for (unsigned int i = 0; i < centre.size(); ++i)
      {
        std::vector<double> row(centre[i].begin_raw(), centre[i].end_raw());
        row.push_back(std::sqrt(radii[i] * radii[i] + weight_shift[i]));
        rows.push_back(row);
      }
    return PowerCells<dim>(rows);
  }

  template <int dim>
  std::vector<double>
  GrainBoundaryDiffusion<dim>::kernel_sums(
    const LevelSetField<dim>        &alpha,
    const MixedCurvatureSolver<dim> *geometry,
    const bool                       kink,
    const bool                       explicit_curvature) const
  {
    // Per boundary, over the discrete interface: the deposition's volume
    // rate per unit speed, int I_h(w N) . n (W), int I_h(w kappa) (with
    // @p geometry's N and kappa), int I_h(w), with @p explicit_curvature
    // int I_h(w) (div N + mu), and with @p geometry int |grad_s I_h(w)|^2
    // (the implicit contact law's stiffness); one pass for all.
    const unsigned int  nb = boundaries.size();
    std::vector<double> sums(n_sums * nb, 0.);
    std::vector<types::global_dof_index> indices(alpha.fe().n_dofs_per_cell());
    std::vector<double>                  w(indices.size()), curvature;
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.surface_flags =
      update_values | update_JxW_values | update_normal_vectors |
      (geometry ? update_gradients : update_default) |
      (explicit_curvature ? update_quadrature_points : update_default);
    integrands.on_surface = [&](const auto &cell, const auto &values) {
      // Q1: the cell's dofs are its vertices, in order.
      cell->get_dof_indices(indices);
      bool cell_has_curvature = false;
      for (unsigned int b = 0; b < nb; ++b)
        {
          if (!kernel_weights(boundaries[b], cell, w, kink))
            continue;
          if (explicit_curvature && !cell_has_curvature)
            {
              // div N + mu at the points: the curvature of the state, as
              // the kappa row holds it before the implicit term (with the
              // hoop term N_r / r on a body of revolution).
              const auto &normals = geometry->nodal_normals();
              curvature.assign(values.n_quadrature_points, 0.);
              for (const unsigned int q : values.quadrature_point_indices())
                {
                  double radial = 0;
                  for (unsigned int v = 0; v < indices.size(); ++v)
                    {
                      curvature[q] +=
                        values.shape_value(v, q) * potential(indices[v]);
                      radial += values.shape_value(v, q) * normals[0](indices[v]);
                      for (unsigned int c = 0; c < dim; ++c)
                        curvature[q] +=
                          values.shape_grad(v, q)[c] * normals[c](indices[v]);
                    }
                  curvature[q] += radial * alpha.measure().inverse_radius(
                                             values.quadrature_point(q));
                }
              cell_has_curvature = true;
            }
          for (const unsigned int q : values.quadrature_point_indices())
            {
              double         weight = 0, weighted_kappa = 0;
              Tensor<1, dim> weighted_normal, weight_gradient;
              for (unsigned int v = 0; v < indices.size(); ++v)
                {
                  const double phi = values.shape_value(v, q) * w[v];
                  weight += phi;
                  if (geometry)
                    {
                      weighted_kappa += phi * geometry->curvature()(indices[v]);
                      for (unsigned int c = 0; c < dim; ++c)
                        weighted_normal[c] +=
                          phi * geometry->nodal_normals()[c](indices[v]);
                      weight_gradient += w[v] * values.shape_grad(v, q);
                    }
                }
              const double JxW = alpha.measure().JxW(values, q);
              const auto  &n   = values.normal_vector(q);
              sums[n_sums * b] += weighted_normal * n * JxW;
              sums[n_sums * b + 1] += weighted_kappa * JxW;
              sums[n_sums * b + 2] += weight * JxW;
              if (explicit_curvature)
                sums[n_sums * b + 3] += weight * curvature[q] * JxW;
              weight_gradient -= (weight_gradient * n) * n;
              sums[n_sums * b + 4] += weight_gradient.norm_square() * JxW;
            }
        }
    };
    interface_measures::integrate_regions(alpha, integrands);
    Utilities::MPI::sum(sums, alpha.dof_handler().get_communicator(), sums);
    return sums;
  }

  template <int dim>
  bool
  GrainBoundaryDiffusion<dim>::kernel_weights(
    const grain_geometry::GrainBoundary<dim>            &boundary,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<double>                                  &w,
    const bool                                            kink) const
  {
    const double width   = kink ? kink_width : deposition_width;
    const double plateau = kink ? kink_plateau : 0.;
    const double reach   = std::max({boundary.radius,
                                   boundary.end_distance[0],
                                   boundary.end_distance[1]}) +
                         plateau + 2 * std::max(width, plateau) +
                         cell->diameter();
    if (cell->center().distance(boundary.origin) > reach)
      return false;
    bool any = false;
    for (unsigned int v = 0; v < w.size(); ++v)
      {
        w[v] = grain_geometry::triple_line_weight(boundary,
                                                  cell->vertex(v),
                                                  width,
                                                  plateau);
        any  = any || w[v] > 0;
      }
    return any;
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::find_boundaries(const LevelSetField<dim> &alpha)
  {
    boundaries = grain_geometry::find_grain_boundaries(alpha, grains());
    h_min      = finest_cell_size(alpha.dof_handler().get_triangulation());
    deposition_width = parameters.deposition_width * h_min;
    kink_width       = parameters.kink_width * h_min;
    kink_plateau =
      surface_diffusion.geometry().band_filter().thickness();
    if (parameters.sharp_contact)
      move_to_sharp_triple_lines(alpha);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::move_to_sharp_triple_lines(
    const LevelSetField<dim> &alpha)
  {
    // The near circles are those of the grain measures: fitted beyond 1.5
    // l of the plane, clear of the kink's k cells and the deposition's
    // bump, to R / 4 further.
    const auto circles = grain_geometry::fit_surface_circles(
      alpha, grains(), boundaries, 1.5 * deposition_width);
    const bool body_3d = alpha.measure().template body_dimension<dim>() == 3;
    for (unsigned int b = 0; b < boundaries.size(); ++b)
      {
        auto  &boundary = boundaries[b];
        double end[2]   = {boundary.radius, boundary.radius};
        if (boundary.strip)
          std::copy_n(boundary.end_distance, 2, end);
        for (unsigned int e = 0; e < (boundary.strip ? 2 : 1); ++e)
          {
            double       sum = 0;
            unsigned int n   = 0;
            for (unsigned int side = 0; side < 2; ++side)
              if (const double crossing = grain_geometry::plane_crossing(
                    circles[b].near[side][e]);
                  std::isfinite(crossing))
                {
                  sum += crossing;
                  ++n;
                }
            if (n == 0)
              continue;
            // The level set fills the groove's corner by 0.2-0.3 cells
            // with a kink of 2 cells and 0.6 with 4 (doc/validation.md,
            // "Settling the pair: the sharp contact radius"): a difference
            // up to k / 2 cells is that filling and moved in full, from
            // there to k cells less and less (no jump in a). A larger one
            // is a neck still forming, whose surface the near circles do
            // not follow: the rays' end stays.
            const double offset = end[e] - sum / n;
            const double share =
              std::clamp(2 - 2 * std::abs(offset) / kink_width, 0., 1.);
            end[e] -= share * offset;
          }
        if (!boundary.strip)
          end[1] = end[0];
        grain_geometry::set_extent(boundary, end[0], end[1], body_3d);
      }
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::triple_line_potential(
    const LevelSetField<dim>      &alpha,
    TrilinosWrappers::MPI::Vector &mu)
  {
    TimerOutput::Scope scope(timer, "grain-boundary diffusion");
    find_boundaries(alpha);
    boundaries_current = true;
    // mu = S P_b w_b / int I_h(w_b): across each triple line the potential
    // integrates to S = pi - psi per unit length of the line (P_b its
    // length in the domain), the turning of the surface's tangent there at
    // equilibrium. The sharp form's w_b is a ridge on the boundary's plane
    // along the band, so that every level curve crossing the plane near
    // the line turns there, as the sharp surfaces do.
    const bool          kink = kink_width > 0;
    const auto          sums = kernel_sums(alpha, nullptr, kink);
    std::vector<double> scale(boundaries.size(), 0.);
    for (unsigned int b = 0; b < boundaries.size(); ++b)
      if (sums[n_sums * b + 2] > 0)
        scale[b] = parameters.triple_line_turning() *
                   boundaries[b].perimeter * boundaries[b].area_in_domain /
                   boundaries[b].area / sums[n_sums * b + 2];
    // Every cell holding a node sees the same kernels there
    // (kernel_weights' reach), so each writes the same sum.
    mu = 0;
    std::vector<double> w(alpha.fe().n_dofs_per_cell()), value(w.size());
    for (const auto &cell : alpha.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          std::fill(value.begin(), value.end(), 0.);
          for (unsigned int b = 0; b < boundaries.size(); ++b)
            if (scale[b] > 0 && kernel_weights(boundaries[b], cell, w, kink))
              for (unsigned int v = 0; v < w.size(); ++v)
                value[v] += scale[b] * w[v];
          for (unsigned int v = 0; v < w.size(); ++v)
            if (const auto i = cell->vertex_dof_index(v, 0);
                alpha.locally_owned().is_element(i))
              mu(i) = value[v];
        }
    mu.compress(VectorOperation::insert);
    potential.reinit(alpha.locally_owned(),
                     alpha.locally_relevant(),
                     alpha.dof_handler().get_communicator());
    potential = mu;
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::compute(const LevelSetField<dim> &alpha,
                                       const double              dt)
  {
    TimerOutput::Scope scope(timer, "grain-boundary diffusion");
    // The volumes balance_volumes() keeps: those of t = 0.
    if (parameters.conserve_volumes && initial_volume.empty())
      initial_volume = grain_geometry::grain_volumes(alpha, grains());
    if (!boundaries_current)
      find_boundaries(alpha);
    boundaries_current = false;
    check_representable();
    // With the sharp condition the explicit curvature is measured too (its
    // potential mu is that of this state: triple_line_potential() ran
    // before the surface-diffusion solve).
    const bool read_explicit =
      kink_width > 0 && potential.size() == alpha.dof_handler().n_dofs();
    const unsigned int nb   = boundaries.size();
    const auto         sums =
      kernel_sums(alpha, &surface_diffusion.geometry(), false, read_explicit);

    // A boundary whose triple line the kernel does not see on the
    // interface has no neck to deposit at: no contact.
    last_contacts.clear();
    std::vector<double> deposition_weight;
    for (unsigned int b = 0; b < nb; ++b)
      if (const double *sum = &sums[n_sums * b]; sum[0] > 0 && sum[2] > 0)
        {
          Contact contact;
          contact.boundary       = boundaries[b];
          contact.root_curvature = sum[1] / sum[2];
          if (read_explicit)
            contact.explicit_root_curvature = sum[3] / sum[2];
          if (parameters.implicit_contact)
            contact.damping =
              mobility *
              parameters.boundary_factor(boundaries[b].i, boundaries[b].j) *
              contact_stiffness(boundaries[b], sum, dt) * dt /
              boundaries[b].resistance;
          last_contacts.push_back(contact);
          deposition_weight.push_back(sum[0]);
        }
    solve_grain_velocities();

    // The volume rate the approach takes out of a boundary (its part in
    // the domain) goes back at its triple line.
    deposition_speed.clear();
    max_speed = 0;
    for (unsigned int k = 0; k < last_contacts.size(); ++k)
      {
        const auto &contact = last_contacts[k];
        deposition_speed.push_back(contact.approach_rate *
                                   contact.boundary.area_in_domain /
                                   deposition_weight[k]);
        max_speed = std::max({max_speed,
                              std::abs(contact.approach_rate),
                              std::abs(deposition_speed.back())});
      }
  }

  template <int dim>
  double
  GrainBoundaryDiffusion<dim>::equilibrium_neck(const unsigned int i,
                                                const unsigned int j) const
  {
    // Two grains of radius r end as truncated discs or spheres meeting in
    // a grain boundary of radius about r sin(psi/2), r the smaller radius.
    return std::min(radii[i], radii[j]) * parameters.sin_half_dihedral_angle();
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::check_representable() const
  {
    for (const auto &b : boundaries)
      {
        // The triple line's kernels (deposition, root curvature) have the
        // half-width l: a neck narrower than l is not resolved, and the
        // contact law then cycles between a neck that snaps open and one
        // that narrows (measured at gamma_gb / gamma_s = 1.9, R/h = 16:
        // doc/validation.md, "Settling the pair: the step's accuracy,
        // clear stops").
        const double neck = equilibrium_neck(b.i, b.j);
        if (neck < deposition_width)
          {
            std::ostringstream message;
            message << "grains " << b.i << " and " << b.j
                    << ": at Grain boundaries/Energy ratio = "
                    << parameters.energy_ratio
                    << " their equilibrium grain boundary has the radius r "
                       "sin(psi/2) = "
                    << neck << " (r = " << std::min(radii[b.i], radii[b.j])
                    << "), less than the triple line's kernel half-width "
                       "l = Deposition width x h_min = "
                    << deposition_width
                    << ", so the neck cannot be resolved: refine the mesh "
                       "(Mesh refinement/Maximum level), lower the Deposition "
                       "width or the Energy ratio";
            throw std::runtime_error(message.str());
          }
        // The power partition of rigid grains needs each grain's centre in
        // its own cell: a grain boundary at a centre means a grain being
        // swallowed, or two grains merged into one (gamma_gb -> 0, d ->
        // 0), which this split cannot represent.
        const double reach[2] = {(b.origin - centre[b.i]) * b.normal,
                                 (centre[b.j] - b.origin) * b.normal};
        for (unsigned int side = 0; side < 2; ++side)
          if (reach[side] < h_min)
            {
              std::ostringstream message;
              message << "grains " << b.i << " and " << b.j
                      << ": their grain boundary is " << reach[side]
                      << " from the centre of grain "
                      << (side == 0 ? b.i : b.j) << ", less than a finest cell "
                      << h_min << " (centre distance " << b.centre_distance
                      << "): the grain is being swallowed or the two have "
                         "merged into one, which rigid grains split by power "
                         "cells cannot represent (doc/numerics.md, \"Grain "
                         "boundaries and densification\")";
              throw std::runtime_error(message.str());
            }
      }
  }

  template <int dim>
  double
  GrainBoundaryDiffusion<dim>::contact_stiffness(
    const grain_geometry::GrainBoundary<dim> &boundary,
    const double                             *sum,
    const double                              dt) const
  {
    // An approach delta deposits the normal displacement eta = delta
    // (A_dom / W) w at the triple line (add_nodal_velocity()); on the
    // surface it changes the curvature by -Delta_s eta, whose kernel mean,
    // after one integration by parts, raises kappa_root by delta (A_dom /
    // W) int |grad_s w|^2 / int w, and lowers F = P sin(psi/2) - A
    // kappa_root by A times that. Surface diffusion spreads the bump
    // within the step over (C_s dt)^(1/4) (doc/numerics.md, "Settling:
    // the contact law's step"): a bump of width L > l has the curvature
    // (l / L)^3 of the kernel's.
    // With per-grain materials the spread is the mean of the two grains'
    // surfaces'.
    const double l = deposition_width;
    const double c_s =
      surface_diffusion.coefficient() *
      (parameters.surface_factor(boundary.i) +
       parameters.surface_factor(boundary.j)) /
      2;
    const double L = std::max(l, std::pow(c_s * dt, 0.25));
    return boundary.area * boundary.area_in_domain / sum[0] * sum[4] /
           sum[2] * std::pow(l / L, 3);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::solve_grain_velocities()
  {
    const unsigned int n = centre.size();
    std::fill(trial_velocity.begin(), trial_velocity.end(), Tensor<1, dim>());
    if (last_contacts.empty())
      return;
    // In units gamma_s = C_gb = 1: K_ij = G(a) / f_ij, F_ij = P sin(psi/2)
    // - A kappa_root, f_ij the boundary's factor of C_gb (per-grain
    // materials; 1 for one material); V scales with C_gb (the mobility).
    // The implicit law
    // reads F after the step's approach, F - S u dt: the approach's
    // resistance becomes G (1 + g), g = C_gb S dt / G (the contact's
    // damping), sliding keeps G.
    LAPACKFullMatrix<double> matrix(dim * n, dim * n);
    dealii::Vector<double>   rhs(dim * n);
    const double             sin_half = parameters.sin_half_dihedral_angle();
    const double             beta     = parameters.sliding_resistance;
    for (const auto &contact : last_contacts)
      {
        const auto    &b = contact.boundary;
        const auto    &m = b.normal;
        const double   K =
          b.resistance / parameters.boundary_factor(b.i, b.j);
        const double   F = b.perimeter * sin_half - b.area * contact.root_curvature;
        for (unsigned int p = 0; p < dim; ++p)
          {
            for (unsigned int q = 0; q < dim; ++q)
              {
                const double B =
                  K * ((1 + contact.damping) * m[p] * m[q] +
                       beta * ((p == q) - m[p] * m[q]));
                matrix(b.i * dim + p, b.i * dim + q) += B;
                matrix(b.j * dim + p, b.j * dim + q) += B;
                matrix(b.i * dim + p, b.j * dim + q) -= B;
                matrix(b.j * dim + p, b.i * dim + q) -= B;
              }
            rhs(b.i * dim + p) += F * m[p];
            rhs(b.j * dim + p) -= F * m[p];
          }
      }
    // The minimum-norm solution: no component in the null space (each
    // cluster's rigid translation, the grains without contact); a contact
    // whose G = pi a^4 / 8 is 1e-10 of the largest is one just forming.
    const dealii::Vector<double> x = minimum_norm_solution(matrix, rhs);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int p = 0; p < dim; ++p)
        trial_velocity[i][p] = mobility * x(i * dim + p);
    for (auto &contact : last_contacts)
      contact.approach_rate =
        (trial_velocity[contact.boundary.i] - trial_velocity[contact.boundary.j]) *
        contact.boundary.normal;
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::add_nodal_velocity(
    const LevelSetField<dim> &alpha,
    VelocityField<dim>       &velocity) const
  {
    TimerOutput::Scope        scope(timer, "grain-boundary diffusion");
    const PowerCells<dim>     cells   = grains();
    const auto               &normals = surface_diffusion.geometry().nodal_normals();
    std::vector<unsigned int> near;
    unsigned int              near_cell = numbers::invalid_unsigned_int;
    velocity.add_vertex_values(alpha.dof_handler(),
                               [&](const auto &cell, const unsigned int v) {
      if (cell->active_cell_index() != near_cell)
        {
          cells.candidates(cell->center(), cell->diameter() / 2, near);
          near_cell = cell->active_cell_index();
        }
      // A node on a grain boundary moves with the mean of its grains.
      const Point<dim> x    = cell->vertex(v);
      const auto       tied = tied_owners(cells, x, near);
      Tensor<1, dim>   value;
      for (const unsigned int k : tied)
        value += trial_velocity[k];
      value /= tied.size();
      const auto i = cell->vertex_dof_index(v, 0);
      for (unsigned int k = 0; k < last_contacts.size(); ++k)
        if (const double w =
              grain_geometry::triple_line_weight(last_contacts[k].boundary,
                                                 x,
                                                 deposition_width);
            w > 0)
          for (unsigned int c = 0; c < dim; ++c)
            value[c] += deposition_speed[k] * w * normals[c](i);
      return value;
    });
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::add_velocity(const LevelSetField<dim> &alpha,
                                            const double        t,
                                            const double        dt,
                                            VelocityField<dim> &velocity)
  {
    compute(alpha, dt);
    trial_dt       = dt;
    trial_start_time = t;
    add_nodal_velocity(alpha, velocity);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::add_probe_velocity(
    const LevelSetField<dim> &alpha,
    const double,
    VelocityField<dim> &velocity)
  {
    // The step is not known yet: the implicit law takes the last one's.
    compute(alpha, trial_dt);
    add_nodal_velocity(alpha, velocity);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::accept_step(const LevelSetField<dim> &alpha)
  {
    for (unsigned int i = 0; i < centre.size(); ++i)
      centre[i] += trial_dt * trial_velocity[i];
    if (parameters.conserve_volumes)
      balance_volumes(alpha);
    report_lost_contacts(alpha);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::report_lost_contacts(
    const LevelSetField<dim> &alpha)
  {
    std::map<std::pair<unsigned int, unsigned int>, double> current;
    for (const auto &contact : last_contacts)
      current[{contact.boundary.i, contact.boundary.j}] =
        contact.approach_rate;
    // The contacts are those of the state at the step's start, the same on
    // every rank; rank 0 says which were lost, and after the first step
    // whether the pairs can settle: check_representable() stops below one
    // kernel half-width, but up to settled_neck_kernels the runs measured
    // relaxation cycles or offsets of 5-34 %, and scenes run there for
    // their early stage (the 27-grain packing at level 2).
    if (Utilities::MPI::this_mpi_process(
          alpha.dof_handler().get_communicator()) == 0)
      {
        if (trial_start_time == 0)
          {
            double       narrowest = std::numeric_limits<double>::max();
            unsigned int narrow    = 0;
            for (const auto &contact : last_contacts)
              {
                const double neck =
                  equilibrium_neck(contact.boundary.i, contact.boundary.j) /
                  deposition_width;
                narrowest = std::min(narrowest, neck);
                narrow += (neck < settled_neck_kernels);
              }
            if (narrow > 0)
              std::cout << "warning: " << narrow << " of the "
                        << last_contacts.size()
                        << " grain boundaries have an equilibrium radius r "
                           "sin(psi/2) of fewer than "
                        << settled_neck_kernels
                        << " triple-line kernel half-widths (Deposition "
                           "width x h_min = "
                        << deposition_width << "; the narrowest " << narrowest
                        << "): pairs there were measured not to settle at "
                           "their equilibrium (doc/validation.md, \"Settling "
                           "the pair: R/h = 32, the axisymmetric pair, R/h = "
                           "8\"); refine the mesh for the end state"
                        << std::endl;
          }
        for (const auto &[pair, rate] : accepted_contacts)
          if (current.count(pair) == 0)
            std::cout << "note: t = " << trial_start_time
                      << ": the grain boundary of grains " << pair.first
                      << " and " << pair.second
                      << " is gone (its grains are more than 10 % beyond "
                         "touching, its plane no longer meets the solid, or "
                         "its triple line no longer meets the interface; last "
                         "approach rate "
                      << rate
                      << "): no contact law acts between the two grains any "
                         "more"
                      << std::endl;
      }
    accepted_contacts = std::move(current);
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::balance_volumes(const LevelSetField<dim> &alpha)
  {
    TimerOutput::Scope scope(timer, "grain-boundary diffusion");
    const unsigned int n = centre.size();
    // Newton on V_i(w) = V_i(0) V / V(0) (V the solid's volume, which the
    // volume correction holds), with the derivatives of the measured
    // volumes (raising w_i moves the plane of (i, j) towards j by dw_i /
    // (2 d_ij)). Each cluster's total is the solid's, not the weights':
    // the minimum-norm solution leaves it. Up to 5 iterations, to 1e-6 of
    // each grain's volume.
    for (unsigned int iteration = 0; iteration < 5; ++iteration)
      {
        FullMatrix<double> derivatives;
        const auto         volume =
          grain_geometry::grain_volumes(alpha, grains(), &derivatives);
        const double ratio =
          std::accumulate(volume.begin(), volume.end(), 0.) /
          std::accumulate(initial_volume.begin(), initial_volume.end(), 0.);
        dealii::Vector<double> residual(n);
        double                 largest = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            residual(i) = ratio * initial_volume[i] - volume[i];
            largest =
              std::max(largest, std::abs(residual(i)) / initial_volume[i]);
          }
        if (largest < 1e-6)
          return;
        LAPACKFullMatrix<double> jacobian(n, n);
        jacobian = derivatives;
        const dealii::Vector<double> dw =
          minimum_norm_solution(jacobian, residual);
        for (unsigned int i = 0; i < n; ++i)
          weight_shift[i] += dw(i);
      }
  }

  template <int dim>
  double
  GrainBoundaryDiffusion<dim>::time_step_limit(const LevelSetField<dim> &) const
  {
    // The explicit law's limit is that of its stability; the implicit law
    // is stable at any step and its limit is the shape's accuracy: the
    // pair's end state is off by 3-4 % at the CFL step, within 0.6 % at
    // accuracy_fraction (doc/validation.md, "Settling the pair: the step's
    // accuracy, clear stops").
    const double fraction =
      parameters.implicit_contact ? accuracy_fraction : 0.5;
    return max_speed > 0 ? fraction * h_min / max_speed :
                           std::numeric_limits<double>::infinity();
  }

  template <int dim>
  std::string
  GrainBoundaryDiffusion<dim>::save() const
  {
    std::ostringstream out;
    out << std::setprecision(17) << centre.size() << ' ' << max_speed << ' '
        << h_min;
    for (const auto &c : centre)
      for (unsigned int d = 0; d < dim; ++d)
        out << ' ' << c[d];
    out << ' ' << initial_volume.size();
    for (unsigned int i = 0; i < initial_volume.size(); ++i)
      out << ' ' << initial_volume[i] << ' ' << weight_shift[i];
    return out.str();
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::load(const std::string &state)
  {
    std::istringstream in(state);
    std::size_t        n = 0;
    in >> n >> max_speed >> h_min;
    if (n != centre.size())
      throw std::runtime_error(
        "the checkpoint holds " + std::to_string(n) + " grains, the scene " +
        std::to_string(centre.size()) +
        ": resume with the scene the checkpoint was written with");
    for (auto &c : centre)
      for (unsigned int d = 0; d < dim; ++d)
        in >> c[d];
    if (!in)
      throw std::runtime_error("the grains' state in the checkpoint is "
                               "incomplete");
    // Checkpoints written before `Conserve grain volumes` end here.
    if (std::size_t n_volumes = 0; in >> n_volumes)
      {
        if (n_volumes != 0 && n_volumes != n)
          n_volumes = 0, in.setstate(std::ios::failbit);
        initial_volume.resize(n_volumes);
        for (std::size_t i = 0; i < n_volumes; ++i)
          in >> initial_volume[i] >> weight_shift[i];
        if (!in)
          throw std::runtime_error("the grains' volumes in the checkpoint "
                                   "are incomplete");
      }
  }

  template <int dim>
  void
  GrainBoundaryDiffusion<dim>::add_output_fields(
    const LevelSetField<dim> &alpha,
    DataOut<dim>             &data_out) const
  {
    grain_geometry::cell_grains(alpha,
                                grains(),
                                grain_id,
                                &boundary_indicator);
    // Cell data: one value per active cell of the mesh data_out is on.
    data_out.add_data_vector(grain_id,
                             "grain_boundary_diffusion_grain_id",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(boundary_indicator,
                             "grain_boundary_diffusion_boundary",
                             DataOut<dim>::type_cell_data);
  }

  template class GrainBoundaryDiffusion<2>;
  template class GrainBoundaryDiffusion<3>;
} // namespace levelsinter
