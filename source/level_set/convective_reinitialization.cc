#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <levelsinter/level_set/box_mapping.h>
#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/convective_reinitialization.h>
#include <levelsinter/level_set/same_cell.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  ConvectiveReinitialization<dim>::ConvectiveReinitialization(
    const LevelSetFilter &filter,
    const Settings       &settings,
    TimerOutput          &timer)
    : filter(filter)
    , settings(settings)
    , timer(timer)
  {}

  template <int dim>
  void
  ConvectiveReinitialization<dim>::setup_system(
    const LevelSetField<dim> &level_set)
  {
    h_min = finest_cell_size(level_set.dof_handler().get_triangulation());
  }

  template <int dim>
  double
  ConvectiveReinitialization<dim>::reinitialisation_share(
    const double dt,
    const double interface_speed) const
  {
    // lambda = strength h_min / dt moves alpha by strength h_min per step,
    // so a smaller step reinitialises more per unit time: at two grains'
    // volume-diffusion neck (R/h = 12.8) half the step moved the neck by
    // 6.9 % at 5 ms, half the step with half the strength by 0.6 %
    // (doc/validation.md). Scaled by v dt / h_min the reinitialisation
    // speed is strength v, a fixed multiple of the interface's own, for any
    // step and mesh; where the CFL number sets the step (v dt = CFL h_min)
    // this is the per-step form times CFL. The cap keeps a step's
    // reinitialisation at most the per-step form's, whose stability was
    // measured (a speed spike does not drive the ramp harder).
    if (!settings.per_interface_motion)
      return 1.;
    return std::min(1., interface_speed * dt / h_min);
  }

  template <int dim>
  void
  ConvectiveReinitialization<dim>::assemble(
    const LevelSetField<dim>      &level_set,
    const VelocityField<dim>      &velocity,
    const double                   dt,
    const double                   share,
    TrilinosWrappers::MPI::Vector &rhs)
  {
    TimerOutput::Scope scope(timer, "level set: assembly");
    // The matrix and its ILU live for one advance() (released at its end):
    // kept between steps, they sat beside the elastic problem's, whose
    // solve sets the coupled packings' peak memory.
    matrix.reinit(level_set.sparsity_pattern());
    rhs = 0;

    // lambda = h / dt with the finest h everywhere: the reinitialisation
    // then moves alpha by at most h_min per step in every cell, and the
    // coarse cells outside the band (where the filter should be saturated)
    // see a Courant number h_min / h_K < 1 instead of being driven hard.
    //
    // Optionally h is the band's cell size inside the solid (alpha < 0).
    // With k curvature levels h_min is 2^k below it, and at a growing
    // two-grain neck strength h_min / dt fell far behind the front: the
    // level set inside the neck stayed nearly flat (|alpha| < 0.005 where
    // the filtered distance is 0.028) until the neck split (k = 6). In the
    // atmosphere the finest h stays: there the first necks sit in a wedge
    // thinner than a cell, which a reinitialisation at the band's h on
    // both sides opened and separated. Scenes choose it (`auto`: surface
    // diffusion without viscous flow): on Hopper's viscous neck (2 levels)
    // it raised the final neck error from 0.265 to 0.290
    // (doc/validation.md, "Steps that grow with t").
    const double h_solid = std::max(h_min, settings.solid_cell_size);

    const QGauss<dim> quadrature(2);
    FEValues<dim> fe_values(box_mapping<dim>(),
                            level_set.fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
    FEValues<dim> velocity_values(box_mapping<dim>(),
                                  velocity.fe(),
                                  quadrature,
                                  update_values);
    const FEValuesExtractors::Vector velocities(0);
    const QGauss<dim - 1>            face_quadrature(2);
    FEFaceValues<dim> face_values(box_mapping<dim>(),
                                  level_set.fe(),
                                  face_quadrature,
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    FEFaceValues<dim> velocity_face_values(box_mapping<dim>(),
                                           velocity.fe(),
                                           face_quadrature,
                                           update_values);
    std::vector<Tensor<1, dim>> v_face(face_quadrature.size());
    std::vector<double>         alpha_face(face_quadrature.size());

    const unsigned int n_q           = quadrature.size();
    const unsigned int dofs_per_cell = level_set.fe().dofs_per_cell;
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    dealii::Vector<double> cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> indices(dofs_per_cell);
    std::vector<double>                  alpha(n_q);
    std::vector<Tensor<1, dim>>          grad_alpha(n_q);
    std::vector<Tensor<1, dim>>          v(n_q);
    std::vector<double>                  test(dofs_per_cell);
    std::vector<double>                  advective(dofs_per_cell);
    const double                         theta = settings.theta;

    for (const auto &cell : level_set.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto velocity_cell = same_cell(cell, velocity.dof_handler());
          fe_values.reinit(cell);
          velocity_values.reinit(velocity_cell);
          fe_values.get_function_values(level_set.alpha(), alpha);
          fe_values.get_function_gradients(level_set.alpha(), grad_alpha);
          velocity_values[velocities].get_function_values(velocity.values(), v);

          const double h = cell_size(cell);
          cell_matrix    = 0;
          cell_rhs       = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double a    = alpha[q];
              const double h_r  = a < 0 ? h_solid : h_min;
              const double lambda =
                settings.reinitialization_strength * h_r / dt;
              const double norm = grad_alpha[q].norm();
              const double eps  = h * norm;
              const double sign =
                (a == 0) ? 0. : a / std::sqrt(a * a + eps * eps);
              // Reinitialise where it is needed: at full strength where
              // ||grad alpha| - g(alpha)| >= delta, proportionally less
              // below. A profile that is already right (rigid motion) is
              // then left alone instead of being rebuilt every step from a
              // ramp that carries the transport's dispersion errors, which
              // dragged a rotating interface by ~1.5 degrees per turn.
              const double deviation =
                std::abs(norm - filter.gradient_norm_target(a));
              const double delta = settings.reinitialization_tolerance;
              const double need =
                share * (delta > 0 ? std::min(1., deviation / delta) : 1.);
              Tensor<1, dim> w = v[q];
              if (norm > 1e-12 * filter.saturation() / h)
                w += need * lambda * sign / norm * grad_alpha[q];
              const double source =
                need * lambda * sign * filter.gradient_norm_target(a);
              const double tau =
                1. / std::sqrt(4. / (dt * dt) + 4. * w.norm_square() / (h * h));
              const double old_residual_part =
                a / dt - (1 - theta) * (w * grad_alpha[q]) + source;
              const double JxW = fe_values.JxW(q);
              // Consistent diffusion nu div(grad alpha - w(alpha) g(alpha) n),
              // n from the previous step. It damps the Q1 checkerboard mode
              // that SUPG leaves alone where the streamlines run diagonal to
              // the cells, and on an exact filtered distance (Eq. 67) it
              // vanishes near alpha = 0, so unlike a plain Laplacian it does
              // not move a curved interface by nu kappa |grad alpha|.
              // w = 1 - (alpha/s)^4 fades the target out towards saturation,
              // where |grad alpha| = g(alpha) has no stable solution (g -> 0
              // but the direction n of a nearly flat alpha is noise).
              const double nu =
                need * settings.reinitialization_diffusion * (h_r / dt) * h;
              const double ratio2 = (a / filter.saturation()) *
                                    (a / filter.saturation());
              Tensor<1, dim> target_gradient;
              if (norm > 1e-12 * filter.saturation() / h)
                target_gradient = (1 - ratio2 * ratio2) *
                                  filter.gradient_norm_target(a) / norm *
                                  grad_alpha[q];
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  advective[i] = w * fe_values.shape_grad(i, q);
                  test[i]      = fe_values.shape_value(i, q) + tau * advective[i];
                }
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) +=
                      (test[i] *
                      (fe_values.shape_value(j, q) / dt + theta * advective[j]) +
                      nu * fe_values.shape_grad(i,q)*fe_values.shape_grad(j,q))*
                      JxW;
                  cell_rhs(i) += (test[i] * old_residual_part +
                                  nu * target_gradient *
                                    fe_values.shape_grad(i, q)) *
                                 JxW;
                }
            }

          // Inflow boundary (w.n < 0): alpha = +saturation (atmosphere)
          // imposed weakly by the upwind term int (w.n)^- (alpha - s) phi.
          // Without it the Galerkin problem leaves inflow values free and
          // they drift. Symmetry planes have w.n = 0 and get nothing.
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                face_values.reinit(cell, f);
                velocity_face_values.reinit(velocity_cell, f);
                velocity_face_values[velocities].get_function_values(
                  velocity.values(), v_face);
                face_values.get_function_values(level_set.alpha(), alpha_face);
                for (const unsigned int q :
                     face_values.quadrature_point_indices())
                  {
                    const double inflow =
                      -std::min(0., v_face[q] * face_values.normal_vector(q));
                    if (inflow == 0)
                      continue;
                    const double JxW = face_values.JxW(q);
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        const double phi_i = face_values.shape_value(i, q);
                        for (unsigned int j = 0; j < dofs_per_cell; ++j)
                          cell_matrix(i, j) += theta * inflow * phi_i *
                                               face_values.shape_value(j, q) *
                                               JxW;
                        cell_rhs(i) += inflow *
                                       (filter.saturation() -
                                        (1 - theta) * alpha_face[q]) *
                                       phi_i * JxW;
                      }
                  }
              }

          cell->get_dof_indices(indices);
          level_set.constraints().distribute_local_to_global(
            cell_matrix, cell_rhs, indices, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim>
  unsigned int
  ConvectiveReinitialization<dim>::advance(LevelSetField<dim>       &level_set,
                                           const VelocityField<dim> &velocity,
                                           const double              dt,
                                           const double              share)
  {
    TrilinosWrappers::MPI::Vector rhs(level_set.locally_owned(),
                                      level_set.dof_handler().get_communicator());
    assemble(level_set, velocity, dt, share, rhs);

    TimerOutput::Scope scope(timer, "level set: solve");
    TrilinosWrappers::MPI::Vector solution(rhs);
    solution = level_set.alpha(); // previous step as the initial guess
    preconditioner.initialize(matrix);
    SolverControl control(settings.max_iterations,
                          settings.solver_tolerance * rhs.l2_norm());
    TrilinosWrappers::SolverGMRES solver(control);
    try
      {
        solver.solve(matrix, solution, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "GMRES of the level-set transport did not converge in "
                << e.last_step << " iterations (residual " << std::scientific
                << std::setprecision(2) << e.last_residual
                << "); raise Level set/Maximum solver iterations or lower "
                   "the CFL number";
        throw std::runtime_error(message.str());
      }
    if (!std::isfinite(solution.l2_norm()))
      throw std::runtime_error(
        "the level set became non-finite in the transport step; reduce the "
        "CFL number or the time step");

    // The filtered function is bounded by its saturation value; the
    // transport may overshoot it by a rounding-sized amount far from the
    // interface, which would leave the filter's range (g undefined there).
    const double s = filter.saturation();
    for (const auto i : level_set.locally_owned())
      solution[i] = std::clamp(double(solution[i]), -s, s);
    level_set.set_from_owned(solution);
    preconditioner.clear();
    matrix.clear();
    return control.last_step();
  }

  template class ConvectiveReinitialization<2>;
  template class ConvectiveReinitialization<3>;
} // namespace levelsinter
