#include <levelsinter/mechanics/conformation_model.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace levelsinter
{
  namespace
  {
    using Eigenpairs = std::array<std::pair<double, Tensor<1, 3>>, 3>;

    Eigenpairs
    eigenpairs(const SymmetricTensor<2, 3> &t)
    {
      // Jacobi: accurate eigenvectors also for nearly equal eigenvalues,
      // which c = I (the state at rest) always has.
      return eigenvectors(t, SymmetricTensorEigenvectorMethod::jacobi);
    }

    /** sum_i f(mu_i) r_i r_i^T */
    template <typename Function>
    SymmetricTensor<2, 3>
    spectral(const Eigenpairs &pairs, const Function &f)
    {
      SymmetricTensor<2, 3> result;
      for (const auto &[mu, r] : pairs)
        result += f(mu) * symmetrize(outer_product(r, r));
      return result;
    }

    double
    exponential(const double mu)
    {
      return std::exp(mu);
    }
  } // namespace

  SymmetricTensor<2, 3>
  tensor_exp(const SymmetricTensor<2, 3> &s)
  {
    return spectral(eigenpairs(s), exponential);
  }

  SymmetricTensor<2, 3>
  tensor_log(const SymmetricTensor<2, 3> &c)
  {
    return spectral(eigenpairs(c), [](const double lambda) {
      if (!(lambda > 0))
        throw std::runtime_error(
          "The conformation tensor has an eigenvalue " +
          std::to_string(lambda) +
          " <= 0: it is not positive definite, so it has no logarithm.");
      return std::log(lambda);
    });
  }

  template <int dim>
  Tensor<2, 3>
  embed_velocity_gradient(const Tensor<2, dim> &grad_u)
  {
    Tensor<2, 3> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        result[i][j] = grad_u[i][j];
    return result;
  }

  ConformationModel::ConformationModel(const Parameters &parameters)
    : parameters(parameters)
  {
    if (!(parameters.relaxation_time > 0) || !(parameters.modulus > 0))
      throw std::runtime_error(
        "A conformation model needs a positive modulus G and relaxation "
        "time lambda.");
    if (parameters.law == Law::giesekus &&
        (parameters.mobility < 0 || parameters.mobility > 0.5))
      throw std::runtime_error(
        "The Giesekus mobility alpha must lie in [0, 0.5] (0 is "
        "Oldroyd-B; above 0.5 the shear stress is not monotonic).");
    if (parameters.law == Law::xpp &&
        (!(parameters.stretch_relaxation_time > 0) || !(parameters.arms > 0)))
      throw std::runtime_error(
        "The XPP model needs a positive stretch relaxation time lambda_s "
        "and number of arms q.");
  }

  SymmetricTensor<2, 3>
  ConformationModel::relaxation(const SymmetricTensor<2, 3> &c) const
  {
    const SymmetricTensor<2, 3> identity = unit_symmetric_tensor<3>();
    const double                lambda   = parameters.relaxation_time;
    if (parameters.law == Law::giesekus)
      {
        const SymmetricTensor<2, 3> a = c - identity;
        return (a + parameters.mobility * symmetrize(Tensor<2, 3>(a) * a)) /
               lambda;
      }
    const double tr      = trace(c);
    const double stretch = std::sqrt(tr / 3.);
    const double nu      = 2. / parameters.arms;
    return 2. * std::exp(nu * (stretch - 1.)) /
             parameters.stretch_relaxation_time * (1. - 3. / tr) * c +
           (3. / tr * c - identity) / lambda;
  }

  SymmetricTensor<2, 3>
  ConformationModel::rate(const SymmetricTensor<2, 3> &c,
                          const Tensor<2, 3>          &grad_u) const
  {
    const Tensor<2, 3> lc = grad_u * Tensor<2, 3>(c);
    return symmetrize(lc + transpose(lc)) - relaxation(c);
  }

  SymmetricTensor<2, 3>
  ConformationModel::log_rate(const SymmetricTensor<2, 3> &s,
                              const Tensor<2, 3>          &grad_u) const
  {
    const Eigenpairs            pairs = eigenpairs(s);
    const SymmetricTensor<2, 3> c     = spectral(pairs, exponential);
    const SymmetricTensor<2, 3> c_inverse =
      spectral(pairs, [](const double mu) { return std::exp(-mu); });
    // g(c) is a function of c, so g(c) c^{-1} is symmetric.
    return log_deformation_rate(s, grad_u) -
           symmetrize(Tensor<2, 3>(relaxation(c)) * Tensor<2, 3>(c_inverse));
  }

  SymmetricTensor<2, 3>
  ConformationModel::log_deformation_rate(const SymmetricTensor<2, 3> &s,
                                          const Tensor<2, 3> &grad_u) const
  {
    const Eigenpairs pairs = eigenpairs(s);
    Tensor<2, 3>     rotation; // columns: eigenvectors of s (and c)
    std::array<double, 3> lambda;
    for (unsigned int i = 0; i < 3; ++i)
      {
        lambda[i] = std::exp(pairs[i].first);
        for (unsigned int k = 0; k < 3; ++k)
          rotation[k][i] = pairs[i].second[k];
      }
    // grad u = Omega + B + N c^{-1} in the principal frame of c: B the
    // stretching that commutes with c, Omega the spin of its axes.
    const Tensor<2, 3> m = transpose(rotation) * grad_u * rotation;
    Tensor<2, 3>       b, omega;
    for (unsigned int i = 0; i < 3; ++i)
      {
        b[i][i] = m[i][i];
        for (unsigned int j = i + 1; j < 3; ++j)
          // Equal eigenvalues: the axes are free to turn, and the pair's
          // shear only splits the eigenvalues, a stretching.
          if (std::abs(lambda[j] - lambda[i]) <=
              1e-12 * std::max(lambda[i], lambda[j]))
            b[i][j] = b[j][i] = 0.5 * (m[i][j] + m[j][i]);
          else
            {
              omega[i][j] = (lambda[j] * m[i][j] + lambda[i] * m[j][i]) /
                            (lambda[j] - lambda[i]);
              omega[j][i] = -omega[i][j];
            }
      }
    const Tensor<2, 3> spin = rotation * omega * transpose(rotation);
    const Tensor<2, 3> s_full(s);
    return symmetrize(spin * s_full - s_full * spin +
                      2. * rotation * b * transpose(rotation));
  }

  std::array<double, 3>
  ConformationModel::relaxation_of_eigenvalues(
    const std::array<double, 3> &c) const
  {
    SymmetricTensor<2, 3> diagonal;
    for (unsigned int i = 0; i < 3; ++i)
      diagonal[i][i] = c[i];
    const SymmetricTensor<2, 3> g = relaxation(diagonal);
    return {{g[0][0], g[1][1], g[2][2]}};
  }

  SymmetricTensor<2, 3>
  ConformationModel::relax_log(const SymmetricTensor<2, 3> &s,
                               const double                 dt) const
  {
    Eigenpairs            pairs = eigenpairs(s);
    std::array<double, 3> c;
    for (unsigned int i = 0; i < 3; ++i)
      c[i] = std::exp(pairs[i].first);
    if (parameters.law == Law::giesekus)
      {
        const double e = std::exp(-dt / parameters.relaxation_time);
        for (double &ci : c)
          {
            const double x = ci - 1;
            ci = 1 + x * e / (1 + parameters.mobility * x * (1 - e));
          }
      }
    else
      {
        // Backward Euler, c - c_old + dt g(c) = 0, by Newton's method with
        // a difference Jacobian (3 x 3); the step is halved while it would
        // leave the positive eigenvalues.
        const std::array<double, 3> old = c;
        for (unsigned int iteration = 0; iteration < 50; ++iteration)
          {
            const auto            g = relaxation_of_eigenvalues(c);
            Tensor<1, 3>          residual;
            Tensor<2, 3>          jacobian;
            for (unsigned int i = 0; i < 3; ++i)
              residual[i] = c[i] - old[i] + dt * g[i];
            for (unsigned int j = 0; j < 3; ++j)
              {
                std::array<double, 3> shifted = c;
                const double          d       = 1e-7 * std::max(1., c[j]);
                shifted[j] += d;
                const auto g_shifted = relaxation_of_eigenvalues(shifted);
                for (unsigned int i = 0; i < 3; ++i)
                  jacobian[i][j] =
                    (i == j) + dt * (g_shifted[i] - g[i]) / d;
              }
            const Tensor<1, 3> update = invert(jacobian) * residual;
            double             step   = 1;
            while (step > 1e-6 && (c[0] - step * update[0] <= 0 ||
                                   c[1] - step * update[1] <= 0 ||
                                   c[2] - step * update[2] <= 0))
              step /= 2;
            for (unsigned int i = 0; i < 3; ++i)
              c[i] -= step * update[i];
            if (update.norm() <= 1e-13 * (c[0] + c[1] + c[2]))
              break;
          }
      }
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      result += std::log(c[i]) *
                symmetrize(outer_product(pairs[i].second, pairs[i].second));
    return result;
  }

  SymmetricTensor<2, 3>
  ConformationModel::stress(const SymmetricTensor<2, 3> &c) const
  {
    return parameters.modulus * (c - unit_symmetric_tensor<3>());
  }

  double
  ConformationModel::polymer_viscosity() const
  {
    return parameters.modulus * parameters.relaxation_time;
  }

  template Tensor<2, 3>
  embed_velocity_gradient<2>(const Tensor<2, 2> &);
  template Tensor<2, 3>
  embed_velocity_gradient<3>(const Tensor<2, 3> &);
} // namespace levelsinter
