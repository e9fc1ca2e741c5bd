#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The polymeric part of a viscoelastic melt in conformation form (the
   * viscoelastic seed, Eq. 4-7): the extra stress tau = G (c - I), and the
   * conformation tensor c obeys
   *   upper-convected derivative of c = -g(c),
   * i.e. in a homogeneous flow with velocity gradient L (L_ij = du_i/dx_j)
   *   dc/dt = L c + c L^T - g(c),
   * with g(c) = (c - I + alpha (c - I)^2) / lambda for Giesekus (Eq. 6;
   * alpha = 0 is Oldroyd-B) and for the extended Pom-Pom model (Eq. 7)
   *   g(c) = 2 exp(nu (sqrt(tr c / 3) - 1)) / lambda_s (1 - 3 / tr c) c
   *          + (3 c / tr c - I) / lambda,   nu = 2 / q.
   * (The seed prints the exponent as exp[nu sqrt(tr c/3) - 1]; the XPP
   * model of Verbeeten et al. has exp(nu (Lambda - 1)) with the stretch
   * Lambda = sqrt(tr c / 3), so that the stretch relaxes at 1/lambda_s
   * when Lambda = 1; that form is used.)
   *
   * c is always 3 x 3: a planar flow still stretches c_zz through the trace
   * in XPP, and an axisymmetric one has c_thetatheta. A 2D velocity
   * gradient is embedded with zero third row and column.
   *
   * Both the direct form (c) and the log-conformation form (s = log c,
   * Fattal & Kupferman, J. Non-Newtonian Fluid Mech. 123 (2004) 281) are
   * offered; the log form keeps c positive definite at high Deborah
   * numbers. g(c) is a function of c alone, so it commutes with c and the
   * log form's relaxation term is -g(c) c^{-1}.
   */
  class ConformationModel
  {
  public:
    enum class Law
    {
      giesekus,
      xpp
    };

    struct Parameters
    {
      Law    law                     = Law::giesekus;
      double modulus                 = 1; // G
      double relaxation_time         = 1; // lambda (XPP: the backbone's)
      double mobility                = 0; // Giesekus alpha
      double stretch_relaxation_time = 1; // XPP lambda_s
      double arms                    = 2; // XPP q
    };

    explicit ConformationModel(const Parameters &parameters);

    /** The relaxation term g(c). */
    SymmetricTensor<2, 3>
    relaxation(const SymmetricTensor<2, 3> &c) const;

    /** dc/dt in a homogeneous flow with velocity gradient @p grad_u. */
    SymmetricTensor<2, 3>
    rate(const SymmetricTensor<2, 3> &c, const Tensor<2, 3> &grad_u) const;

    /** ds/dt for s = log c in the same flow (Fattal-Kupferman). */
    SymmetricTensor<2, 3>
    log_rate(const SymmetricTensor<2, 3> &s, const Tensor<2, 3> &grad_u) const;

    /** The deformation part of log_rate(), without the relaxation:
     * Omega s - s Omega + 2 B. */
    SymmetricTensor<2, 3>
    log_deformation_rate(const SymmetricTensor<2, 3> &s,
                         const Tensor<2, 3>          &grad_u) const;

    /**
     * s = log c after relaxing alone (dc/dt = -g(c)) for @p dt. g(c) is a
     * function of c, so the axes stay and each eigenvalue relaxes:
     * Giesekus exactly, x = c_i - 1 -> x e / (1 + alpha x (1 - e)),
     * e = exp(-dt / lambda); XPP (eigenvalues coupled through tr c) by a
     * backward Euler step solved with Newton's method. Both are stable for
     * any dt, which the stiff relaxation of a nearly Newtonian melt
     * (lambda << dt) needs.
     */
    SymmetricTensor<2, 3>
    relax_log(const SymmetricTensor<2, 3> &s, const double dt) const;

    /** tau = G (c - I). */
    SymmetricTensor<2, 3>
    stress(const SymmetricTensor<2, 3> &c) const;

    /** The zero-shear polymer viscosity eta_p = G lambda. */
    double
    polymer_viscosity() const;

  private:
    /** g(c) in the principal frame: the relaxation rate of each
     * eigenvalue @p c of c. */
    std::array<double, 3>
    relaxation_of_eigenvalues(const std::array<double, 3> &c) const;

    Parameters parameters;
  };

  /** exp and log of a symmetric tensor through its eigen-decomposition
   * (log requires positive eigenvalues). */
  SymmetricTensor<2, 3>
  tensor_exp(const SymmetricTensor<2, 3> &s);

  SymmetricTensor<2, 3>
  tensor_log(const SymmetricTensor<2, 3> &c);

  /** A dim x dim velocity gradient embedded in 3 x 3 (zero third row and
   * column in 2D). */
  template <int dim>
  Tensor<2, 3>
  embed_velocity_gradient(const Tensor<2, dim> &grad_u);
} // namespace levelsinter
