#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <levelsinter/geometry/boundary_flux.h>
#include <levelsinter/geometry/geometry_band.h>
#include <levelsinter/geometry/nodal_normals.h>
#include <levelsinter/geometry/normal_gradient_extension.h>
#include <levelsinter/geometry/recovered_gradient.h>
#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/ghosted_vector.h>
#include <levelsinter/level_set/same_cell.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // c in the reaction c |N| / h_K of the extension equation: xi and the
    // reach r (the same equation with data 1) decay alike, exp(-c s / h)
    // over a path s, so xi / r is free of it, while r ~ 0 marks the nodes
    // no source reaches. 0.1: r ~ 0.6-0.75 on the interface with lambda =
    // 3 h, and a matrix far from singular where no source is upstream.
    constexpr double reaction = 0.1;

    // Nodes with r below this fraction of the decay over the offset itself
    // count as not reached.
    constexpr double reached_fraction = 0.5;

    // Least interface support int_Gamma w_i ds of a boundary-flux source
    // node, in h_min^(dim - 1) (compute_flux_sources()): about half a
    // cell's width of interface in the cells at the node.
    constexpr double flux_support_fraction = 0.5;

    // c of the limited extrapolation: at each source the carried
    // correction keeps |d eta| <= c |g|. For a harmonic mode n read at
    // depth |d| below radius r, |d eta / g| = (n - 1) |d| / r, so c = 2
    // passes modes up to n = 3 unclipped on the packings' spheres (lambda
    // = 3 cells at R/h ~ 7, r ~ R - 3 h) and any mode once R/h >~ 20,
    // while a one-cell ridge, whose eta is a difference of differences of
    // the discrete gradient, is cut to twice its own value. Measured on 8
    // spheres like the 154 (doc/validation.md, "Packings: the limited
    // extrapolation"): c = 4 let the ridge grow again (18.7 um/s at t =
    // 0.014 s), c = 1 and 2 kept the step at its cap to t = 0.015 s.
    constexpr double extrapolation_limit = 2;
  } // namespace

  template <int dim>
  NormalGradientExtension<dim>::NormalGradientExtension(
    const LevelSetFilter &filter,
    const Settings       &settings,
    TimerOutput          &timer)
    : filter(filter)
    , settings(settings)
    , timer(timer)
  {}

  template <int dim>
  void
  NormalGradientExtension<dim>::setup(const LevelSetField<dim> &level_set)
  {
    xi.reinit(level_set.locally_owned(),
              level_set.locally_relevant(),
              level_set.dof_handler().get_communicator());
  }

  template <int dim>
  void
  NormalGradientExtension<dim>::compute_sources(
    const LevelSetField<dim> &level_set,
    const DoFHandler<dim>    &field_dofs,
    const unsigned int        component,
    const Vector             &field,
    Vector                   &is_source,
    Vector                   &values,
    std::array<Vector, dim>  &gradient)
  {
    const auto    &dofs  = level_set.dof_handler();
    const MPI_Comm comm  = dofs.get_communicator();
    const auto    &owned = level_set.locally_owned();
    // Per node: how many cells around it reach closer to the interface
    // than lambda, the sum of grad p over the cells and their number.
    Vector                  excluded, count;
    std::array<Vector, dim> gradient_sum;
    excluded.reinit(owned, level_set.locally_relevant(), comm, true);
    count.reinit(owned, level_set.locally_relevant(), comm, true);
    for (auto &sum : gradient_sum)
      sum.reinit(owned, level_set.locally_relevant(), comm, true);

    // grad p evaluated at the vertices, cell by cell: the average over the
    // cells at a node is a centred difference on a uniform patch (O(h^2)).
    // Or recovered over the solid part of the cells (Settings).
    if (settings.recovered_gradient)
      add_solid_gradient_projection<dim>(
        level_set, field_dofs, component, field, count, gradient_sum);
    const Quadrature<dim> vertices(level_set.fe().get_unit_support_points());
    FEValues<dim> field_values(box_mapping<dim>(),
                               field_dofs.get_fe(),
                               vertices,
                               update_gradients);
    const FEValuesExtractors::Scalar pressure(component);
    std::vector<Tensor<1, dim>>      gradients(vertices.size());
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    // The smeared jump is (lambda - 1) h_min deep (the interface lies in the
    // finest cells), and the vertex gradient of a cell K reads its edges,
    // up to h_K closer to the interface: clean if d < -((lambda - 1) h_min +
    // h_K), lambda h on a uniform mesh. Counting all of lambda in h_K left
    // no source next to coarser cells inside the band.
    const double h_min = finest_cell_size(dofs.get_triangulation());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          if (!settings.recovered_gradient)
            {
              field_values.reinit(same_cell(cell, field_dofs));
              field_values[pressure].get_function_gradients(field, gradients);
            }
          const double lambda = (settings.interior_offset - 1) * h_min +
                                cell_size(cell);
          // Q1: local DoF v sits at vertex v, the v-th support point.
          for (unsigned int v = 0; v < indices.size(); ++v)
            {
              const auto i = indices[v];
              if (filter.distance(level_set.alpha()(i)) >= -lambda)
                excluded(i) += 1;
              if (settings.recovered_gradient)
                continue;
              count(i) += 1;
              for (unsigned int c = 0; c < dim; ++c)
                gradient_sum[c](i) += gradients[v][c];
            }
        }
    excluded.compress(VectorOperation::add);
    count.compress(VectorOperation::add);
    for (auto &sum : gradient_sum)
      sum.compress(VectorOperation::add);

    is_source = 0;
    values    = 0;
    for (auto &component : gradient)
      component.reinit(owned, comm);
    for (const auto i : owned)
      if (excluded(i) == 0 && count(i) > 0 &&
          !level_set.constraints().is_constrained(i))
        {
          // Element writes only set (a += would switch the Trilinos vector
          // to add mode, which is collective).
          double g = 0;
          for (unsigned int c = 0; c < dim; ++c)
            {
              gradient[c](i) = gradient_sum[c](i) / count(i);
              g += gradient_sum[c](i) / count(i) * normals[c](i);
            }
          is_source(i) = 1;
          values(i)    = g;
        }
    is_source.compress(VectorOperation::insert);
    values.compress(VectorOperation::insert);
    for (auto &component : gradient)
      component.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  NormalGradientExtension<dim>::compute_flux_sources(
    const LevelSetField<dim> &level_set,
    const DoFHandler<dim>    &field_dofs,
    const unsigned int        component,
    const Vector             &field,
    Vector                   &is_source,
    Vector                   &values) const
  {
    const auto    &dofs  = level_set.dof_handler();
    const MPI_Comm comm  = dofs.get_communicator();
    const auto    &owned = level_set.locally_owned();
    InterfaceMoments<dim> moments;
    Vector                flux;
    std::vector<Vector *> accumulated = {&moments.mass,
                                         &moments.normal_position,
                                         &flux};
    for (unsigned int d = 0; d < dim; ++d)
      {
        accumulated.push_back(&moments.normal[d]);
        accumulated.push_back(&moments.position[d]);
      }
    for (Vector *vector : accumulated)
      vector->reinit(owned, level_set.locally_relevant(), comm, true);
    add_boundary_flux<dim>(
      level_set, field_dofs, component, field, moments, flux);
    for (Vector *vector : accumulated)
      vector->compress(VectorOperation::add);

    // The test function of node i is w_i = sum of phi_j over the nodes j
    // of the cells at i (each once): 1 on those cells, 0 one ring further,
    // so int_Gamma w_i ds is about the interface length (area) across
    // those cells, also where the interface only grazes phi_i's own
    // support (whose quotient would amplify the error of grad p_h), and
    // every vertex of a cut cell gets a value. The sums over j are the
    // products with the level set's pattern filled with ones.
    TrilinosWrappers::SparseMatrix patch(level_set.sparsity_pattern());
    for (const auto row : owned)
      for (auto entry = patch.begin(row); entry != patch.end(row); ++entry)
        entry->value() = 1;
    // The sum over node i's patch of the owned entries of @p per_node.
    const auto patch_sum = [&](const Vector &per_node) {
      Vector owned_part(owned, comm), sum(owned, comm);
      for (const auto i : owned)
        owned_part(i) = per_node(i);
      owned_part.compress(VectorOperation::insert);
      patch.vmult(sum, owned_part);
      return sum;
    };
    const Vector patch_mass            = patch_sum(moments.mass);
    const Vector patch_flux            = patch_sum(flux);
    const Vector patch_normal_position = patch_sum(moments.normal_position);
    std::array<Vector, dim> patch_normal, patch_position;
    for (unsigned int d = 0; d < dim; ++d)
      {
        patch_normal[d]   = patch_sum(moments.normal[d]);
        patch_position[d] = patch_sum(moments.position[d]);
      }

    // A node whose cells the interface only clips at a corner takes the
    // carried values of its neighbours instead. So does a node outside the
    // solid whose patch holds interface that bends towards it, the solid
    // concave there. The quotient averages xi over the interface in the
    // patch, and on the concave side that interface wraps around the node:
    // the patch of a node in a neck's gap holds the flanks on both sides
    // and the foot of the neck below it, while an inner node's patch there
    // holds the foot alone. At the foot xi changes sign within a cell or
    // two (the foot fills, the flanks feed it), so the outer node took the
    // flanks' sign and the cut cells at the foot, interpolating it with the
    // inner node's, moved the foot inwards: the two grains' neck stalled,
    // at R/h = 25.6 from t = 0.002 s while the gap was narrower than the
    // patch, and at R/h = 51.2 from t = 0.0004 s with a meniscus of about
    // 3 cells that the former test of one sheet (|mean n| >= 0.9) let
    // through (doc/validation.md, "Volume diffusion: the neck's sources",
    // "... the neck at three meshes"). Carried along N from the solid's
    // side, these nodes take the foot's value. Where the solid is convex
    // the outer nodes stay sources: there the inner nodes' patches are the
    // ones wrapped around, and hold more solid, where the discrete p is
    // not harmonic (with the solid's nodes alone the cylinder's mode 2 was
    // 7 % slow at R/h = 32). Which side the interface bends to: with c its
    // centroid in the patch, int_Gamma n . (x - c) w_i ds is
    // int |x - c|^2 w_i ds / R > 0 on a circle of radius R around the
    // solid and the negative of it around a hole; two sheets facing each
    // other across a gap count as concave, as does the gap of a concave
    // corner. In an axisymmetric scene this is the meridian curve's bend.
    // The same holds for a node inside the solid within a quarter of a
    // finest cell of a concave interface. When a neck's foot reaches a
    // node, the quotient of that node read xi > 0 (+61, R/h = 12.8) where
    // the nodes a cell deeper and along the flanks read -80 to -530, and
    // the neck stood still while its foot sat on the node (doc/validation.md,
    // "Volume diffusion: the neck from a fillet"). Such a node takes the
    // mean of the source values around it (below).
    const double h_min = finest_cell_size(dofs.get_triangulation());
    const double least_support =
      flux_support_fraction * std::pow(h_min, dim - 1);
    is_source = 0;
    values    = 0;
    std::vector<types::global_dof_index> at_concave_foot;
    for (const auto i : owned)
      if (patch_mass(i) >= least_support &&
          !level_set.constraints().is_constrained(i))
        {
          double bend = patch_normal_position(i);
          for (unsigned int d = 0; d < dim; ++d)
            bend -= patch_position[d](i) / patch_mass(i) * patch_normal[d](i);
          const double distance = filter.distance(level_set.alpha()(i));
          if (bend < 0 && distance >= -0.25 * h_min)
            {
              if (distance < 0)
                at_concave_foot.push_back(i);
              continue;
            }
          is_source(i) = 1;
          values(i)    = patch_flux(i) / patch_mass(i);
        }
    is_source.compress(VectorOperation::insert);
    values.compress(VectorOperation::insert);

    // The inner node at a concave foot cannot take a carried value: along
    // -N its upstream is the outer node above it, which is no source
    // either, and each of the two carries fixes the other side at 0. Both
    // were left unreached with xi = 0: holes in the velocity along a
    // concave arc, between neighbours reading -100 to -1150 (the fillet's
    // arc at t = 0: 20 / 20 / 32 such interface cells at R/h = 12.8 /
    // 25.6 / 51.2, doc/validation.md, "Volume diffusion: the fillet's
    // foot"). It takes the mean of the source values in its patch
    // instead, weighted with their interface support (the quotients of
    // its neighbours along the interface and a cell deeper), and the outer
    // node is carried from it.
    Vector support(owned, comm), weighted(owned, comm);
    for (const auto i : owned)
      {
        support(i)  = is_source(i) * patch_mass(i);
        weighted(i) = support(i) * values(i);
      }
    support.compress(VectorOperation::insert);
    weighted.compress(VectorOperation::insert);
    const Vector around       = patch_sum(support);
    const Vector around_value = patch_sum(weighted);
    for (const auto i : at_concave_foot)
      if (around(i) > 0)
        {
          is_source(i) = 1;
          values(i)    = around_value(i) / around(i);
        }
    is_source.compress(VectorOperation::insert);
    values.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  NormalGradientExtension<dim>::compute_slopes(
    const LevelSetField<dim>      &level_set,
    const std::array<Vector, dim> &gradient,
    Vector                        &is_source,
    Vector                        &values,
    Vector                        &slopes) const
  {
    const auto    &dofs     = level_set.dof_handler();
    const MPI_Comm comm     = dofs.get_communicator();
    const auto    &owned    = level_set.locally_owned();
    const auto    &relevant = level_set.locally_relevant();
    Vector         source(owned, relevant, comm);
    source = is_source;
    std::array<Vector, dim> G;
    for (unsigned int c = 0; c < dim; ++c)
      {
        G[c].reinit(owned, relevant, comm);
        G[c] = gradient[c];
      }
    Vector sum, count;
    sum.reinit(owned, relevant, comm, true);
    count.reinit(owned, relevant, comm, true);

    // eta = N . (grad grad p) N: along the normal of a distance function N
    // does not turn ((N . grad) N = 0), so d(grad p . N)/dn needs no
    // derivative of N, which is poor where the filter nears saturation.
    // grad grad p is the gradient of the nodal gradients, at the vertex,
    // on the cells whose vertices all carry clean gradients.
    const Quadrature<dim> vertices(level_set.fe().get_unit_support_points());
    FEValues<dim> fe_values(box_mapping<dim>(),
                            level_set.fe(),
                            vertices,
                            update_gradients);
    std::array<std::vector<Tensor<1, dim>>, dim> hessian_rows;
    for (auto &row : hessian_rows)
      row.resize(vertices.size());
    std::vector<types::global_dof_index> indices(level_set.fe().dofs_per_cell);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          if (std::any_of(indices.begin(), indices.end(), [&](const auto i) {
                return source(i) == 0;
              }))
            continue;
          fe_values.reinit(cell);
          for (unsigned int c = 0; c < dim; ++c)
            fe_values.get_function_gradients(G[c], hessian_rows[c]);
          for (unsigned int v = 0; v < indices.size(); ++v)
            {
              const auto     i = indices[v];
              Tensor<1, dim> N;
              for (unsigned int c = 0; c < dim; ++c)
                N[c] = normals[c](i);
              for (unsigned int c = 0; c < dim; ++c)
                sum(i) += N[c] * (hessian_rows[c][v] * N);
              count(i) += 1;
            }
        }
    sum.compress(VectorOperation::add);
    count.compress(VectorOperation::add);
    // A source node without such a cell (on a step of the staircase
    // d = -lambda) would feed g without its slope along the characteristics
    // that pass it (measured: a 16 % error where the interface runs along a
    // grid line); it takes its value from the sources behind it instead.
    slopes = 0;
    for (const auto i : owned)
      if (is_source(i) > 0 && count(i) > 0)
        {
          const double d   = filter.distance(level_set.alpha()(i));
          double       eta = sum(i) / count(i);
          if (settings.limited_extrapolation &&
              std::abs(d * eta) > extrapolation_limit * std::abs(values(i)))
            eta = std::copysign(extrapolation_limit * std::abs(values(i)) /
                                  std::abs(d),
                                eta);
          slopes(i) = eta;
          values(i) = values(i) - d * eta;
        }
      else if (is_source(i) > 0)
        {
          is_source(i) = 0;
          values(i)    = 0;
        }
    for (auto *v : {&is_source, &values, &slopes})
      v->compress(VectorOperation::insert);
  }

  template <int dim>
  void
  NormalGradientExtension<dim>::assemble(const LevelSetField<dim> &level_set,
                                         const Vector             &fixed)
  {
    const auto    &dofs = level_set.dof_handler();
    const MPI_Comm comm = dofs.get_communicator();
    // The matrix and its ILU live for one carry() (released at its end),
    // not beside the elastic problem's matrices and AMG at the next solve.
    matrix.reinit(level_set.sparsity_pattern());
    // Per node: the band cells and all cells at it. Nodes that no band cell
    // touches keep xi = 0 (identity rows).
    Vector touched, cells;
    touched.reinit(level_set.locally_owned(),
                   level_set.locally_relevant(),
                   comm,
                   true);
    cells.reinit(level_set.locally_owned(),
                 level_set.locally_relevant(),
                 comm,
                 true);

    const QGauss<dim>  quadrature(2);
    FEValues<dim> fe_values(box_mapping<dim>(),
                            level_set.fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    const unsigned int n  = level_set.fe().dofs_per_cell;
    const unsigned int nq = quadrature.size();
    FullMatrix<double> cell_matrix(n, n);
    std::vector<types::global_dof_index> indices(n);
    std::array<std::vector<double>, dim> normal_values;
    for (auto &values : normal_values)
      values.resize(nq);
    std::vector<double> advective(n), test(n);

    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          cells(cell->vertex_dof_index(v, 0)) += 1;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && in_geometry_band(filter, level_set, cell))
        {
          fe_values.reinit(cell);
          for (unsigned int c = 0; c < dim; ++c)
            fe_values.get_function_values(normals[c], normal_values[c]);
          const double h = cell_size(cell);
          cell_matrix    = 0;
          for (unsigned int q = 0; q < nq; ++q)
            {
              Tensor<1, dim> N;
              for (unsigned int c = 0; c < dim; ++c)
                N[c] = normal_values[c][q];
              const double speed = N.norm();
              if (speed == 0)
                continue;
              const double sigma = reaction * speed / h;
              // SUPG (Eq. 72) with tau = h / 2|N| (Eq. 73) for the steady
              // advection, bounded by 1/sigma where the reaction dominates.
              const double tau =
                1. / std::sqrt(4. * speed * speed / (h * h) + sigma * sigma);
              for (unsigned int i = 0; i < n; ++i)
                {
                  advective[i] = N * fe_values.shape_grad(i, q);
                  test[i]      = fe_values.shape_value(i, q) + tau * advective[i];
                }
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) +=
                    test[i] *
                    (advective[j] + sigma * fe_values.shape_value(j, q)) * JxW;
            }
          cell->get_dof_indices(indices);
          level_set.constraints().distribute_local_to_global(cell_matrix,
                                                             indices,
                                                             matrix);
          for (const auto i : indices)
            touched(i) += 1;
        }
    matrix.compress(VectorOperation::add);
    touched.compress(VectorOperation::add);
    cells.compress(VectorOperation::add);

    // Fixed (source) nodes: xi = its value (Eq. 110); untouched nodes:
    // xi = 0. The
    // band's edge in the solid is an inflow boundary of N . grad u = 0 (N
    // points out of the solid): without data there u is only fixed up to
    // the weak reaction's decay along each characteristic, and the
    // system is nearly singular. On a uniform mesh that edge is all
    // sources; where coarser cells border it, it need not be, and GMRES
    // stalled (measured: residual 7.2 from 3.0e3 after 1000 iterations,
    // the exact solution 200 times the data). Such edge nodes get xi = 0
    // and reach 0: nothing enters from deeper than the band.
    std::vector<types::global_dof_index> identity_rows;
    for (const auto i : level_set.locally_owned())
      {
        const bool inflow_edge =
          touched(i) > 0 && touched(i) < cells(i) &&
          filter.distance(level_set.alpha()(i)) < 0 &&
          !level_set.constraints().is_constrained(i);
        if (fixed(i) > 0 || touched(i) == 0 || inflow_edge)
          identity_rows.push_back(i);
      }
    matrix.clear_rows(identity_rows, 1.);
  }

  template <int dim>
  std::string
  NormalGradientExtension<dim>::worst_row(const LevelSetField<dim> &level_set,
                                          const Vector             &rhs,
                                          const Vector &solution) const
  {
    const auto    &owned = level_set.locally_owned();
    const MPI_Comm comm  = level_set.dof_handler().get_communicator();
    Vector         residual(owned, comm);
    matrix.vmult(residual, solution);
    residual.sadd(-1., 1., rhs);
    // The owned node with the largest residual, then the largest over the
    // ranks.
    std::pair<double, Point<dim>> worst(-1., Point<dim>());
    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto i = cell->vertex_dof_index(v, 0);
            if (owned.is_element(i) && std::abs(residual(i)) > worst.first)
              worst = {std::abs(residual(i)), cell->vertex(v)};
          }
    for (const auto &other : Utilities::MPI::all_gather(comm, worst))
      if (other.first > worst.first)
        worst = other;
    std::ostringstream message;
    message << "the largest residual is at x = (" << worst.second
            << "). Measured on the two grains by volume diffusion (xi as the "
               "boundary flux): the band's nodal normals there had turned "
               "within a cell, after xi and then the level set grew a "
               "sawtooth from one node to the next along a stretch where the "
               "interface ran along a grid line; a smaller step did not "
               "help, nor did more iterations (doc/validation.md, \"Volume "
               "diffusion: the fillet's foot\")";
    return message.str();
  }

  template <int dim>
  unsigned int
  NormalGradientExtension<dim>::carry(const LevelSetField<dim> &level_set,
                                      const Vector             &fixed,
                                      const std::vector<const Vector *> &data,
                                      std::vector<Vector> &solutions)
  {
    {
      TimerOutput::Scope scope(timer, "normal gradient: assembly");
      assemble(level_set, fixed);
    }
    TimerOutput::Scope scope(timer, "normal gradient: solve");
    const auto    &owned = level_set.locally_owned();
    const MPI_Comm comm  = level_set.dof_handler().get_communicator();
    preconditioner.initialize(matrix);
    unsigned int iterations = 0;
    solutions.clear();
    for (const Vector *rhs : data)
      {
        solutions.emplace_back(owned, comm);
        SolverControl control(settings.max_iterations,
                              settings.solver_tolerance * rhs->l2_norm());
        TrilinosWrappers::SolverGMRES gmres(control);
        if (rhs->l2_norm() > 0)
          try
            {
              gmres.solve(matrix, solutions.back(), *rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &e)
            {
              std::ostringstream message;
              message << "GMRES of the normal pressure gradient extension "
                         "(Eq. 110-111) did not converge in "
                      << e.last_step << " iterations (residual "
                      << std::scientific << std::setprecision(2)
                      << e.last_residual << "); "
                      << worst_row(level_set, *rhs, solutions.back());
              throw std::runtime_error(message.str());
            }
        iterations += control.last_step();
        level_set.constraints().distribute(solutions.back());
      }
    preconditioner.clear();
    matrix.clear();
    return iterations;
  }

  template <int dim>
  unsigned int
  NormalGradientExtension<dim>::carry_both_ways(
    const LevelSetField<dim> &level_set,
    const Vector             &is_source,
    const Vector             &values,
    Vector                   &owned_xi,
    Vector                   &reach)
  {
    const auto    &owned = level_set.locally_owned();
    const MPI_Comm comm  = level_set.dof_handler().get_communicator();
    // The sources lie within a cell of the interface: the floor of the
    // reach as for an offset of one cell.
    const double reach_floor = reached_fraction * std::exp(-reaction);
    Vector       fixed(owned, comm);
    std::vector<Vector> solutions;
    unsigned int        iterations = 0;
    for (const double side : {1., -1.})
      {
        // The nodes on the other side are upstream of the sources: fixed
        // at 0, so that each solve is an inflow problem from the interface
        // (and its matrix regular without the reaction).
        for (const auto i : owned)
          fixed(i) = is_source(i) > 0 ||
                         side * filter.distance(level_set.alpha()(i)) < 0 ?
                       1. :
                       0.;
        fixed.compress(VectorOperation::insert);
        if (side < 0)
          for (auto &component : normals)
            component *= -1.;
        iterations += carry(level_set, fixed, {&values, &is_source}, solutions);
        if (side < 0)
          for (auto &component : normals)
            component *= -1.;
        for (const auto i : owned)
          {
            const double d = filter.distance(level_set.alpha()(i));
            if (is_source(i) > 0)
              {
                owned_xi(i) = values(i);
                reach(i)    = 1;
              }
            else if (side > 0 ? d >= 0 : d < 0)
              {
                reach(i)    = solutions[1](i);
                owned_xi(i) = solutions[1](i) < reach_floor ?
                                0. :
                                solutions[0](i) / solutions[1](i);
              }
          }
      }
    owned_xi.compress(VectorOperation::insert);
    reach.compress(VectorOperation::insert);
    return iterations;
  }

  template <int dim>
  unsigned int
  NormalGradientExtension<dim>::solve(const LevelSetField<dim> &level_set,
                                      const DoFHandler<dim>    &field_dofs,
                                      const unsigned int        component,
                                      const Vector             &field)
  {
    const auto    &dofs  = level_set.dof_handler();
    const MPI_Comm comm  = dofs.get_communicator();
    const auto    &owned = level_set.locally_owned();
    Vector is_source(owned, comm), values(owned, comm), slopes(owned, comm);
    {
      TimerOutput::Scope scope(timer, "normal gradient: assembly");
      normals = levelsinter::nodal_normals(level_set,
                                           filter,
                                           settings.normals_from_distance,
                                           settings.symmetry_boundaries);
      if (settings.boundary_flux)
        compute_flux_sources(
          level_set, field_dofs, component, field, is_source, values);
      else
        {
          std::array<Vector, dim> gradient;
          compute_sources(
            level_set, field_dofs, component, field, is_source, values,
            gradient);
          if (settings.linear_extrapolation)
            compute_slopes(level_set, gradient, is_source, values, slopes);
        }
      if (is_source.l1_norm() == 0)
        throw std::runtime_error(
          settings.boundary_flux ?
            "volume diffusion: no level-set node has enough interface "
            "support to read the pressure's boundary flux; is there an "
            "interface in the mesh?" :
            "volume diffusion: no level-set node lies deeper than lambda = " +
              std::to_string(settings.interior_offset) +
              " cells in the solid, so the pressure gradient cannot be read "
              "anywhere; refine the mesh, lower 'Volume diffusion/Interior "
              "offset' or raise 'Level set/Filter thickness' (lambda must "
              "stay below 0.8 E, where the level set still has a slope)");
    }

    Vector       owned_xi(owned, comm), owned_reach(owned, comm);
    unsigned int iterations = 0;
    double       reach_floor;
    if (settings.boundary_flux)
      {
        iterations  = carry_both_ways(
          level_set, is_source, values, owned_xi, owned_reach);
        reach_floor = reached_fraction * std::exp(-reaction);
      }
    else
      {
        // The carried g (or g - d eta), eta, and the reach r for the data 1.
        std::vector<Vector> solutions;
        iterations = carry(level_set,
                           is_source,
                           {&values, &slopes, &is_source},
                           solutions);
        // Division by r undoes the reaction's decay. Where r is small no
        // source is upstream: both are what SUPG leaks from the side, with
        // weights of both signs, and their ratio is not bounded by the
        // sources (measured 1.9 times their range in a bar thinner than
        // 2 lambda), so xi = 0.
        reach_floor =
          reached_fraction * std::exp(-reaction * settings.interior_offset);
        for (const auto i : owned)
          owned_xi(i) =
            solutions[2](i) < reach_floor ?
              0. :
              (solutions[0](i) +
               filter.distance(level_set.alpha()(i)) * solutions[1](i)) /
                solutions[2](i);
        owned_reach = solutions[2];
      }
    xi = ghosted_from_owned(owned_xi,
                            level_set.constraints(),
                            level_set.locally_relevant());

    Vector reach(owned, level_set.locally_relevant(), comm);
    reach = owned_reach;
    unsigned int cells = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double lowest = filter.saturation(), highest = -lowest,
                 least_reach = 1;
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto i = cell->vertex_dof_index(v, 0);
              lowest       = std::min(lowest, double(level_set.alpha()(i)));
              highest      = std::max(highest, double(level_set.alpha()(i)));
              least_reach  = std::min(least_reach, double(reach(i)));
            }
          if (lowest <= 0 && highest > 0 && least_reach < reach_floor)
            ++cells;
        }
    unsourced_cells = Utilities::MPI::sum(cells, comm);
    return iterations;
  }

  template <int dim>
  Tensor<1, dim>
  NormalGradientExtension<dim>::velocity(const types::global_dof_index i,
                                         const double coefficient) const
  {
    Tensor<1, dim> v;
    for (unsigned int c = 0; c < dim; ++c)
      v[c] = -coefficient * xi(i) * normals[c](i);
    return v;
  }

  template class NormalGradientExtension<2>;
  template class NormalGradientExtension<3>;
} // namespace levelsinter
