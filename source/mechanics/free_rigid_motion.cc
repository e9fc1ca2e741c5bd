#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/mechanics/free_rigid_motion.h>

#include <algorithm>
#include <limits>

namespace levelsinter
{
  FreeRigidMotions::FreeRigidMotions(
    const unsigned int                      dim,
    const std::vector<types::boundary_id> &symmetry_planes)
  {
    std::vector<bool> plane_normal_to(dim, false);
    for (const types::boundary_id id : symmetry_planes)
      plane_normal_to[id / 2] = true;
    for (unsigned int k = 0; k < dim; ++k)
      if (!plane_normal_to[k])
        translations.push_back(k);
    if (dim == 2 && symmetry_planes.empty())
      rotations.push_back(2);
    if (dim == 3)
      for (unsigned int k = 0; k < dim; ++k)
        {
          bool all_normal_to_k = true;
          for (unsigned int d = 0; d < dim; ++d)
            if (d != k && plane_normal_to[d])
              all_normal_to_k = false;
          if (all_normal_to_k)
            rotations.push_back(k);
        }
  }

  template <int dim>
  Tensor<1, dim>
  FreeRigidMotions::mode(const unsigned int m,
                         const Point<dim>  &x,
                         const Point<dim>  &centre) const
  {
    Tensor<1, dim> v;
    if (m < translations.size())
      {
        v[translations[m]] = 1;
        return v;
      }
    // e_k x (x - centre); in 2D e_z x r = (-r_y, r_x).
    const unsigned int   k = rotations[m - translations.size()];
    const Tensor<1, dim> r = x - centre;
    if constexpr (dim == 2)
      {
        v[0] = -r[1];
        v[1] = r[0];
      }
    else
      {
        Tensor<1, dim> axis;
        axis[k] = 1;
        v       = cross_product_3d(axis, r);
      }
    return v;
  }

  template <int dim>
  void
  remove_free_rigid_motion(const DoFHandler<dim>              &dofs,
                           const LevelSetField<dim>           &level_set,
                           const FreeRigidMotions             &motions,
                           TrilinosWrappers::MPI::BlockVector &solution)
  {
    const unsigned int n = motions.size();
    if (n == 0)
      return;
    const MPI_Comm comm = dofs.get_communicator();

    // Two Gauss points per direction, a point counting as solid if
    // alpha_h < 0 there: the projection only has to remove the drift, and
    // an O(h) error in the solid's weight changes the gauge by as much.
    const QGauss<dim> quadrature(2);
    FEValues<dim>     stokes_values(dofs.get_fe(),
                                quadrature,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    FEValues<dim> alpha_values(level_set.fe(), quadrature, update_values);
    std::vector<double>         alpha_q(quadrature.size());
    std::vector<Vector<double>> v_q(quadrature.size(),
                                    Vector<double>(dofs.get_fe().n_components()));

    // Rotations about the centre of the box. A rotation about e_k is free
    // only with the translations normal to e_k, so the span of the free
    // motions, and the projection, do not depend on the centre; the box
    // centre keeps the Gram matrix well conditioned.
    const Point<dim> centre =
      GridTools::compute_bounding_box(dofs.get_triangulation()).center();

    // Gram matrix G_mn = (phi_m, phi_n) and b_m = (phi_m, v) over the
    // solid; the rigid part is sum_m c_m phi_m with G c = b.
    std::vector<double>         gram(n * n, 0.), rhs(n, 0.);
    std::vector<Tensor<1, dim>> phi(n);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto alpha_cell = same_cell(cell, level_set.dof_handler());
          alpha_values.reinit(alpha_cell);
          alpha_values.get_function_values(level_set.alpha(), alpha_q);
          stokes_values.reinit(cell);
          stokes_values.get_function_values(solution, v_q);
          for (const unsigned int q : stokes_values.quadrature_point_indices())
            if (alpha_q[q] < 0)
              {
                const double w = level_set.measure().JxW(stokes_values, q);
                for (unsigned int m = 0; m < n; ++m)
                  phi[m] = motions.mode<dim>(m,
                                             stokes_values.quadrature_point(q),
                                             centre);
                for (unsigned int m = 0; m < n; ++m)
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      rhs[m] += w * phi[m][d] * v_q[q][d];
                    for (unsigned int l = 0; l < n; ++l)
                      gram[m * n + l] += w * (phi[m] * phi[l]);
                  }
              }
        }
    Utilities::MPI::sum(gram, comm, gram);
    Utilities::MPI::sum(rhs, comm, rhs);
    if (gram[0] == 0) // no solid
      return;
    FullMatrix<double> G(n, n);
    Vector<double>     b(n), c(n);
    for (unsigned int m = 0; m < n; ++m)
      {
        b[m] = rhs[m];
        for (unsigned int l = 0; l < n; ++l)
          G(m, l) = gram[m * n + l];
      }
    G.gauss_jordan();
    G.vmult(c, b);

    // The modes are linear in x, so their nodal interpolant is exact and
    // consistent with the hanging-node constraints.
    std::vector<IndexSet> owned_blocks;
    for (unsigned int b = 0; b < solution.n_blocks(); ++b)
      owned_blocks.push_back(solution.block(b).locally_owned_elements());
    TrilinosWrappers::MPI::BlockVector owned(owned_blocks, comm);
    owned                 = solution;
    const IndexSet &mine  = owned.locally_owned_elements();
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            Tensor<1, dim> rigid;
            for (unsigned int m = 0; m < n; ++m)
              rigid += c[m] * motions.mode<dim>(m, cell->vertex(v), centre);
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto i = cell->vertex_dof_index(v, d);
                if (mine.is_element(i))
                  owned(i) = solution(i) - rigid[d];
              }
          }
    owned.compress(VectorOperation::insert);
    solution = owned;
  }

  template <int dim>
  void
  make_velocity_constraints(const DoFHandler<dim>                 &dofs,
                            const IndexSet                        &relevant_dofs,
                            const std::vector<types::boundary_id> &symmetry,
                            const FreeRigidMotions                &motions,
                            AffineConstraints<double>             &constraints)
  {
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    const unsigned int n_components = dofs.get_fe().n_components();
    for (const types::boundary_id id : symmetry)
      {
        ComponentMask normal(n_components, false);
        normal.set(id / 2, true);
        VectorTools::interpolate_boundary_values(
          dofs,
          id,
          Functions::ZeroFunction<dim>(n_components),
          constraints,
          normal);
      }

    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &vertex : dofs.get_triangulation().get_vertices())
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], vertex[d]);
          upper[d] = std::max(upper[d], vertex[d]);
        }
    Point<dim> b = lower, c = lower;
    b[0]         = upper[0];
    c[1]         = upper[1];
    std::vector<std::pair<Point<dim>, unsigned int>> pins;
    for (const unsigned int k : motions.translations)
      pins.emplace_back(lower, k);
    for (const unsigned int k : motions.rotations)
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

  template Tensor<1, 2>
  FreeRigidMotions::mode<2>(const unsigned int,
                            const Point<2> &,
                            const Point<2> &) const;
  template Tensor<1, 3>
  FreeRigidMotions::mode<3>(const unsigned int,
                            const Point<3> &,
                            const Point<3> &) const;
  template void
  remove_free_rigid_motion(const DoFHandler<2> &,
                           const LevelSetField<2> &,
                           const FreeRigidMotions &,
                           TrilinosWrappers::MPI::BlockVector &);
  template void
  remove_free_rigid_motion(const DoFHandler<3> &,
                           const LevelSetField<3> &,
                           const FreeRigidMotions &,
                           TrilinosWrappers::MPI::BlockVector &);
  template void
  make_velocity_constraints(const DoFHandler<2> &,
                            const IndexSet &,
                            const std::vector<types::boundary_id> &,
                            const FreeRigidMotions &,
                            AffineConstraints<double> &);
  template void
  make_velocity_constraints(const DoFHandler<3> &,
                            const IndexSet &,
                            const std::vector<types::boundary_id> &,
                            const FreeRigidMotions &,
                            AffineConstraints<double> &);
} // namespace levelsinter
