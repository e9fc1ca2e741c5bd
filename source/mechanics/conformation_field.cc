#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/same_cell.h>
#include <levelsinter/mechanics/conformation_field.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    /**
     * What both assemblies of the transport read on a cell: shape values,
     * the velocity (and its gradient) with the SUPG parameter at the
     * quadrature points, and on boundary faces the inflow weight
     * -min(0, v . n) at the face points.
     */
    template <int dim>
    struct TransportScratch
    {
      TransportScratch(const FiniteElement<dim> &fe,
                       const VelocityField<dim> &velocity)
        : velocity(velocity)
        , quadrature(2)
        , face_quadrature(2)
        , values(fe,
                 quadrature,
                 update_values | update_gradients | update_JxW_values |
                   update_quadrature_points)
        , velocity_values(velocity.fe(),
                          quadrature,
                          update_values | update_gradients)
        , face_values(fe,
                      face_quadrature,
                      update_values | update_normal_vectors |
                        update_JxW_values)
        , velocity_face_values(velocity.fe(), face_quadrature, update_values)
        , v(quadrature.size())
        , grad_v(quadrature.size())
        , tau(quadrature.size())
        , v_face(face_quadrature.size())
        , inflow(face_quadrature.size())
      {}

      template <typename CellIterator>
      void
      reinit(const CellIterator &cell, const double dt)
      {
        velocity_cell = same_cell(cell, velocity.dof_handler());
        values.reinit(cell);
        velocity_values.reinit(velocity_cell);
        velocity_values[FEValuesExtractors::Vector(0)].get_function_values(
          velocity.values(), v);
        velocity_values[FEValuesExtractors::Vector(0)]
          .get_function_gradients(velocity.values(), grad_v);
        const double h = cell_size(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          tau[q] =
            1. / std::sqrt(4. / (dt * dt) + 4. * v[q].norm_square() / (h * h));
      }

      template <typename CellIterator>
      void
      reinit_face(const CellIterator &cell, const unsigned int f)
      {
        face_values.reinit(cell, f);
        velocity_face_values.reinit(velocity_cell, f);
        velocity_face_values[FEValuesExtractors::Vector(0)]
          .get_function_values(velocity.values(), v_face);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          inflow[q] = -std::min(0., v_face[q] * face_values.normal_vector(q));
      }

      const VelocityField<dim>                       &velocity;
      const QGauss<dim>                               quadrature;
      const QGauss<dim - 1>                           face_quadrature;
      FEValues<dim>                                   values, velocity_values;
      FEFaceValues<dim>                               face_values,
        velocity_face_values;
      typename DoFHandler<dim>::active_cell_iterator velocity_cell;
      std::vector<Tensor<1, dim>>                     v;
      std::vector<Tensor<2, dim>>                     grad_v;
      std::vector<double>                             tau;
      std::vector<Tensor<1, dim>>                     v_face;
      std::vector<double>                             inflow;
    };
  } // namespace

  template <int dim>
  ConformationField<dim>::ConformationField(const DoFHandler<dim>   &dofs,
                                            const ConformationModel &model,
                                            const SceneMeasure      &measure)
    : model(model)
    , dofs(dofs)
    , measure(measure)
    , fe(1)
    , comm(dofs.get_communicator())
  {}

  template <int dim>
  std::vector<std::pair<unsigned int, unsigned int>>
  ConformationField<dim>::components()
  {
    if (dim == 2)
      return {{0, 0}, {1, 1}, {2, 2}, {0, 1}};
    return {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  }

  template <int dim>
  SymmetricTensor<2, 3>
  ConformationField<dim>::conformation(const std::vector<double> &s)
  {
    SymmetricTensor<2, 3> log_c;
    const auto            list = components();
    for (unsigned int k = 0; k < list.size(); ++k)
      log_c[list[k].first][list[k].second] = s[k];
    return tensor_exp(log_c);
  }

  template <int dim>
  void
  ConformationField<dim>::setup()
  {
    if (dofs.get_fe().n_components() != 1 || dofs.get_fe().degree != 1)
      throw std::logic_error("ConformationField needs a scalar Q1 DoFHandler");
    owned    = dofs.locally_owned_dofs();
    relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    DynamicSparsityPattern pattern(relevant);
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, owned, comm, relevant);
    matrix.reinit(owned, owned, pattern, comm);

    state.resize(components().size());
    for (Vector &v : state)
      v.reinit(owned, relevant, comm);
    advanced = state;
  }

  template <int dim>
  void
  ConformationField<dim>::set(
    const std::function<SymmetricTensor<2, 3>(const Point<dim> &)> &c)
  {
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(), dofs, points);
    const auto          list = components();
    std::vector<Vector> values(list.size(), Vector(owned, comm));
    for (const auto &[index, point] : points)
      if (owned.is_element(index))
        {
          const SymmetricTensor<2, 3> log_c = tensor_log(c(point));
          for (unsigned int k = 0; k < list.size(); ++k)
            values[k][index] = log_c[list[k].first][list[k].second];
        }
    for (unsigned int k = 0; k < list.size(); ++k)
      {
        values[k].compress(VectorOperation::insert);
        constraints.distribute(values[k]);
        state[k] = values[k];
      }
  }

  template <int dim>
  void
  ConformationField<dim>::commit()
  {
    state = advanced;
  }

  template <int dim>
  void
  ConformationField<dim>::fade(
    const std::function<double(types::global_dof_index)> &weight)
  {
    for (Vector &component : state)
      {
        Vector values(owned, comm);
        for (const auto i : owned)
          values[i] = weight(i) * component[i];
        values.compress(VectorOperation::insert);
        constraints.distribute(values);
        component = values;
      }
  }

  template <int dim>
  void
  ConformationField<dim>::stress_values(
    const FEValues<dim>                  &values,
    std::vector<SymmetricTensor<2, dim>> &stress,
    std::vector<double>                  &hoop_stress) const
  {
    const auto          list = components();
    const unsigned int  n_q  = values.n_quadrature_points;
    std::vector<double> s_q(n_q);
    std::vector<SymmetricTensor<2, 3>> log_c(n_q);
    for (unsigned int k = 0; k < list.size(); ++k)
      {
        values.get_function_values(state[k], s_q);
        for (unsigned int q = 0; q < n_q; ++q)
          log_c[q][list[k].first][list[k].second] = s_q[q];
      }
    stress.resize(n_q);
    hoop_stress.resize(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const SymmetricTensor<2, 3> tau = model.stress(tensor_exp(log_c[q]));
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            stress[q][i][j] = tau[i][j];
        hoop_stress[q] = tau[2][2];
      }
  }

  template <int dim>
  void
  ConformationField<dim>::assemble_matrix(const VelocityField<dim> &velocity,
                                          const double              dt)
  {
    matrix = 0;
    TransportScratch<dim>                scratch(fe, velocity);
    const FEValues<dim>                 &values = scratch.values;
    const FEFaceValues<dim>             &face   = scratch.face_values;
    const unsigned int                   n      = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<double>                  test(n), advective(n);

    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.reinit(cell, dt);
          cell_matrix = 0;
          for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
            {
              for (unsigned int i = 0; i < n; ++i)
                {
                  advective[i] = scratch.v[q] * values.shape_grad(i, q);
                  test[i] =
                    values.shape_value(i, q) + scratch.tau[q] * advective[i];
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) +=
                    test[i] *
                    (values.shape_value(j, q) / dt + 0.5 * advective[j]) *
                    values.JxW(q);
            }
          // Inflow (v.n < 0): c = I, i.e. s = 0, weakly (upwind term).
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                scratch.reinit_face(cell, f);
                for (const unsigned int q : face.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      cell_matrix(i, j) += 0.5 * scratch.inflow[q] *
                                           face.shape_value(i, q) *
                                           face.shape_value(j, q) *
                                           face.JxW(q);
              }
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_matrix, indices, matrix);
        }
    matrix.compress(VectorOperation::add);
    preconditioner.initialize(matrix);
  }

  template <int dim>
  std::vector<typename ConformationField<dim>::Vector>
  ConformationField<dim>::assemble_rhs(const VelocityField<dim>  &velocity,
                                       const double               dt,
                                       const std::vector<Vector> &old,
                                       const std::vector<Vector> &stage,
                                       const bool                 average,
                                       const Vector *stretch_weight) const
  {
    const auto             list = components();
    const unsigned int                   m = list.size();
    TransportScratch<dim>                scratch(fe, velocity);
    const FEValues<dim>                 &values = scratch.values;
    const FEFaceValues<dim>             &face   = scratch.face_values;
    const unsigned int                   n      = fe.n_dofs_per_cell();
    const unsigned int                   n_q    = values.n_quadrature_points;
    std::vector<dealii::Vector<double>>  cell_rhs(m, dealii::Vector<double>(n));
    std::vector<types::global_dof_index> indices(n);
    std::vector<std::vector<double>>     s_old(m, std::vector<double>(n_q)),
      s_stage(m, std::vector<double>(n_q)),
      s_face(m, std::vector<double>(face.n_quadrature_points));
    std::vector<std::vector<Tensor<1, dim>>> grad_s_old(
      m, std::vector<Tensor<1, dim>>(n_q));
    std::vector<double> weight(n_q, 1.);

    std::vector<Vector> rhs(m);
    for (Vector &r : rhs)
      r.reinit(owned, comm);

    const auto log_tensor = [&](const std::vector<std::vector<double>> &s,
                                const unsigned int                      q) {
      SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < m; ++k)
        t[list[k].first][list[k].second] = s[k][q];
      return t;
    };

    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scratch.reinit(cell, dt);
          for (unsigned int k = 0; k < m; ++k)
            {
              values.get_function_values(old[k], s_old[k]);
              values.get_function_gradients(old[k], grad_s_old[k]);
              values.get_function_values(stage[k], s_stage[k]);
              cell_rhs[k] = 0;
            }
          if (stretch_weight)
            values.get_function_values(*stretch_weight, weight);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Tensor<1, dim> &v = scratch.v[q];
              Tensor<2, 3> l = embed_velocity_gradient<dim>(scratch.grad_v[q]);
              l[2][2] +=
                v[0] * measure.inverse_radius(values.quadrature_point(q));
              SymmetricTensor<2, 3> source =
                model.log_deformation_rate(log_tensor(s_stage, q), l);
              if (average)
                source = 0.5 * (source + model.log_deformation_rate(
                                           log_tensor(s_old, q), l));
              source *= weight[q];
              for (unsigned int k = 0; k < m; ++k)
                {
                  const double old_part =
                    s_old[k][q] / dt - 0.5 * (v * grad_s_old[k][q]) +
                    source[list[k].first][list[k].second];
                  for (unsigned int i = 0; i < n; ++i)
                    cell_rhs[k](i) +=
                      (values.shape_value(i, q) +
                       scratch.tau[q] * (v * values.shape_grad(i, q))) *
                      old_part * values.JxW(q);
                }
            }
          // The old half of the inflow term, -(1/2) inflow s^n (s = 0 in).
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                scratch.reinit_face(cell, f);
                for (unsigned int k = 0; k < m; ++k)
                  face.get_function_values(old[k], s_face[k]);
                for (const unsigned int q : face.quadrature_point_indices())
                  for (unsigned int k = 0; k < m; ++k)
                    for (unsigned int i = 0; i < n; ++i)
                      cell_rhs[k](i) -= 0.5 * scratch.inflow[q] *
                                        s_face[k][q] * face.shape_value(i, q) *
                                        face.JxW(q);
              }
          cell->get_dof_indices(indices);
          for (unsigned int k = 0; k < m; ++k)
            constraints.distribute_local_to_global(cell_rhs[k],
                                                   indices,
                                                   rhs[k]);
        }
    for (Vector &r : rhs)
      r.compress(VectorOperation::add);
    return rhs;
  }

  template <int dim>
  std::vector<typename ConformationField<dim>::Vector>
  ConformationField<dim>::relaxed(const std::vector<Vector> &s,
                                  const double               dt) const
  {
    const auto          list = components();
    std::vector<Vector> values(list.size(), Vector(owned, comm));
    for (const auto i : owned)
      {
        SymmetricTensor<2, 3> log_c;
        for (unsigned int k = 0; k < list.size(); ++k)
          log_c[list[k].first][list[k].second] = s[k](i);
        log_c = model.relax_log(log_c, dt);
        for (unsigned int k = 0; k < list.size(); ++k)
          values[k][i] = log_c[list[k].first][list[k].second];
      }
    std::vector<Vector> result(list.size());
    for (unsigned int k = 0; k < list.size(); ++k)
      {
        values[k].compress(VectorOperation::insert);
        constraints.distribute(values[k]);
        result[k].reinit(owned, relevant, comm);
        result[k] = values[k];
      }
    return result;
  }

  template <int dim>
  unsigned int
  ConformationField<dim>::solve(std::vector<Vector> &rhs,
                                std::vector<Vector> &result)
  {
    unsigned int iterations = 0;
    result.resize(rhs.size());
    for (unsigned int k = 0; k < rhs.size(); ++k)
      {
        Vector solution(owned, comm);
        solution = state[k]; // the old step as the initial guess
        const double norm = rhs[k].l2_norm();
        if (norm > 0)
          {
            SolverControl control(1000, 1e-12 * norm);
            TrilinosWrappers::SolverGMRES solver(control);
            try
              {
                solver.solve(matrix, solution, rhs[k], preconditioner);
              }
            catch (const SolverControl::NoConvergence &e)
              {
                std::ostringstream message;
                message << "GMRES of the conformation transport did not "
                           "converge in "
                        << e.last_step << " iterations (residual "
                        << std::scientific << std::setprecision(2)
                        << e.last_residual << "); lower the time step";
                throw std::runtime_error(message.str());
              }
            iterations = std::max(iterations, control.last_step());
          }
        else
          solution = 0;
        if (!std::isfinite(solution.l2_norm()))
          throw std::runtime_error(
            "the conformation tensor became non-finite; lower the time "
            "step");
        constraints.distribute(solution);
        result[k].reinit(owned, relevant, comm);
        result[k] = solution;
      }
    return iterations;
  }

  template <int dim>
  unsigned int
  ConformationField<dim>::advance(const VelocityField<dim> &velocity,
                                  const double              dt,
                                  const Vector             *stretch_weight)
  {
    assemble_matrix(velocity, dt);
    // Strang splitting: half a step of relaxation at the nodes, the
    // transport with the deformation terms, the other half. The transport
    // is Heun: a predictor with the old source, then the average of the
    // old and the predicted source (the operator is the same).
    const std::vector<Vector> start = relaxed(state, dt / 2);
    std::vector<Vector> rhs =
      assemble_rhs(velocity, dt, start, start, false, stretch_weight);
    std::vector<Vector> predicted;
    unsigned int        iterations = solve(rhs, predicted);
    rhs = assemble_rhs(velocity, dt, start, predicted, true, stretch_weight);
    std::vector<Vector> transported;
    iterations = std::max(iterations, solve(rhs, transported));
    advanced   = relaxed(transported, dt / 2);
    return iterations;
  }

  template <int dim>
  void
  ConformationField<dim>::add_state(StateTransfer<dim> &transfer)
  {
    std::vector<Vector *> vectors;
    for (Vector &v : state)
      vectors.push_back(&v);
    transfer.add(dofs, vectors);
  }

  template class ConformationField<2>;
  template class ConformationField<3>;
} // namespace levelsinter
