// Constitutive checks of the conformation models (viscoelastic seed,
// Eq. 5-7) in homogeneous flows against closed forms, in the direct and the
// log-conformation form:
//   conformation_models CASE FORM
// CASE: shear-oldroyd, extension-oldroyd, shear-giesekus, relax-giesekus,
// linear-xpp, forms-giesekus, forms-xpp, relax-step; FORM: direct | log
// (ignored by forms-* and relax-step). Prints the errors, exits 1 above the
// limit. Units: lambda = 1, G = 1 (so eta_p = 1).

#include <levelsinter/mechanics/conformation_model.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace levelsinter;

namespace
{
  using Rate = std::function<SymmetricTensor<2, 3>(
    const SymmetricTensor<2, 3> &, double)>;

  // Classical RK4; with 1000 steps per relaxation time its error (~dt^4)
  // is far below every limit used here.
  SymmetricTensor<2, 3>
  integrate(SymmetricTensor<2, 3> y,
            const Rate           &rate,
            const double          t0,
            const double          t1,
            const double          dt = 1e-3)
  {
    const unsigned int n = std::ceil((t1 - t0) / dt - 1e-9);
    const double       h = (t1 - t0) / n;
    double             t = t0;
    for (unsigned int i = 0; i < n; ++i, t += h)
      {
        const auto k1 = rate(y, t);
        const auto k2 = rate(y + 0.5 * h * k1, t + 0.5 * h);
        const auto k3 = rate(y + 0.5 * h * k2, t + 0.5 * h);
        const auto k4 = rate(y + h * k3, t + h);
        y += h / 6. * (k1 + 2. * k2 + 2. * k3 + k4);
      }
    return y;
  }

  // c(t) from c(t0) in the flow grad_u, in the chosen form.
  SymmetricTensor<2, 3>
  evolve(const ConformationModel     &model,
         const SymmetricTensor<2, 3> &c0,
         const Tensor<2, 3>          &grad_u,
         const double                 t,
         const bool                   log_form)
  {
    if (!log_form)
      return integrate(
        c0,
        [&](const SymmetricTensor<2, 3> &c, double) {
          return model.rate(c, grad_u);
        },
        0,
        t);
    return tensor_exp(integrate(
      tensor_log(c0),
      [&](const SymmetricTensor<2, 3> &s, double) {
        return model.log_rate(s, grad_u);
      },
      0,
      t));
  }

  Tensor<2, 3>
  shear(const double rate)
  {
    Tensor<2, 3> l; // u_x = rate y
    l[0][1] = rate;
    return l;
  }

  Tensor<2, 3>
  uniaxial(const double rate)
  {
    Tensor<2, 3> l;
    l[0][0] = rate;
    l[1][1] = l[2][2] = -0.5 * rate;
    return l;
  }

  ConformationModel
  giesekus(const double alpha)
  {
    ConformationModel::Parameters p;
    p.mobility = alpha;
    return ConformationModel(p);
  }

  ConformationModel
  xpp()
  {
    ConformationModel::Parameters p;
    p.law                     = ConformationModel::Law::xpp;
    p.stretch_relaxation_time = 0.5; // lambda / lambda_s = 2, q = 2 (seed)
    p.arms                    = 2;
    return ConformationModel(p);
  }

  const SymmetricTensor<2, 3> identity = unit_symmetric_tensor<3>();

  int
  report(const std::string &what, const double error, const double limit)
  {
    std::cout << what << ": error " << error << " (limit " << limit << ")"
              << std::endl;
    return error <= limit ? 0 : 1;
  }

  // Start-up of simple shear, Oldroyd-B (alpha = 0), Wi = lambda gamma' =
  // 0.5: c_xy = Wi (1 - e^-t), c_xx = 1 + 2 Wi^2 (1 - e^-t (1 + t)),
  // c_yy = c_zz = 1.
  int
  shear_oldroyd(const bool log_form)
  {
    const double wi    = 0.5;
    double       error = 0;
    for (const double t : {0.25, 1., 4.})
      {
        const auto c =
          evolve(giesekus(0), identity, shear(wi), t, log_form);
        error = std::max(
          {error,
           std::abs(c[0][1] - wi * (1 - std::exp(-t))),
           std::abs(c[0][0] - 1 - 2 * wi * wi * (1 - std::exp(-t) * (1 + t))),
           std::abs(c[1][1] - 1),
           std::abs(c[2][2] - 1)});
      }
    return report("Oldroyd-B start-up shear, Wi 0.5", error, 1e-9);
  }

  // Start-up of uniaxial extension, Oldroyd-B, Wi = lambda eps' = 0.4 (the
  // steady state exists below 0.5): c_xx = a + (1 - a) e^{-(1 - 2 Wi) t},
  // a = 1 / (1 - 2 Wi); c_yy = b + (1 - b) e^{-(1 + Wi) t}, b = 1/(1 + Wi).
  int
  extension_oldroyd(const bool log_form)
  {
    const double wi = 0.4, a = 1 / (1 - 2 * wi), b = 1 / (1 + wi);
    double       error = 0;
    for (const double t : {0.5, 2., 8.})
      {
        const auto c =
          evolve(giesekus(0), identity, uniaxial(wi), t, log_form);
        error = std::max(
          {error,
           std::abs(c[0][0] - a - (1 - a) * std::exp(-(1 - 2 * wi) * t)) / a,
           std::abs(c[1][1] - b - (1 - b) * std::exp(-(1 + wi) * t)),
           std::abs(c[2][2] - c[1][1]),
           std::abs(c[0][1])});
      }
    return report("Oldroyd-B start-up extension, Wi 0.4", error, 1e-9);
  }

  // Steady simple shear, Giesekus alpha = 0.3, Wi = 0.1, 1, 10 (Bird,
  // Armstrong & Hassager 1987): with chi^2 = (sqrt(1 + 16 a (1 - a) Wi^2)
  // - 1) / (8 a (1 - a) Wi^2) and f = (1 - chi) / (1 + (1 - 2a) chi),
  //   eta / eta_p = (1 - f)^2 / (1 + (1 - 2a) f),
  //   Psi_1 / (2 eta_p lambda) = f (1 - a f) / (Wi^2 a (1 - f)),
  //   Psi_2 / (eta_p lambda) = -f / Wi^2.
  // The start-up is run to t = 40 lambda (steady to round-off).
  int
  shear_giesekus(const bool log_form)
  {
    const double alpha = 0.3;
    double       error = 0;
    for (const double wi : {0.1, 1., 10.})
      {
        const double k   = 8 * alpha * (1 - alpha) * wi * wi;
        const double chi = std::sqrt((std::sqrt(1 + 2 * k) - 1) / k);
        const double f   = (1 - chi) / (1 + (1 - 2 * alpha) * chi);
        const double eta = (1 - f) * (1 - f) / (1 + (1 - 2 * alpha) * f);
        const double psi1 =
          2 * f * (1 - alpha * f) / (wi * wi * alpha * (1 - f));
        const double psi2 = -f / (wi * wi);
        const auto   c =
          evolve(giesekus(alpha), identity, shear(wi), 40, log_form);
        const double e_eta  = std::abs(c[0][1] / wi - eta) / eta;
        const double e_psi1 = std::abs((c[0][0] - c[1][1]) / (wi * wi) -
                                       psi1) / psi1;
        const double e_psi2 =
          std::abs((c[1][1] - c[2][2]) / (wi * wi) - psi2) / std::abs(psi2);
        std::cout << "  Wi " << wi << ": eta/eta_p " << c[0][1] / wi
                  << " (exact " << eta << "), Psi1 "
                  << (c[0][0] - c[1][1]) / (wi * wi) << " (exact " << psi1
                  << "), Psi2 " << (c[1][1] - c[2][2]) / (wi * wi)
                  << " (exact " << psi2 << ")" << std::endl;
        error = std::max({error, e_eta, e_psi1, e_psi2});
      }
    return report("Giesekus steady shear, alpha 0.3 (relative)", error, 1e-8);
  }

  // Relaxation after cessation, Giesekus alpha = 0.3, from the stretched
  // state c = diag(3, 1, 1): x = c_xx - 1 obeys x' = -x - alpha x^2, so
  // x = x0 e^-t / (1 + alpha x0 (1 - e^-t)).
  int
  relax_giesekus(const bool log_form)
  {
    const double          alpha = 0.3, x0 = 2;
    SymmetricTensor<2, 3> c0    = identity;
    c0[0][0] += x0;
    double error = 0;
    for (const double t : {0.1, 1., 5.})
      {
        const auto c =
          evolve(giesekus(alpha), c0, Tensor<2, 3>(), t, log_form);
        const double e = std::exp(-t);
        error =
          std::max({error,
                    std::abs(c[0][0] - 1 - x0 * e / (1 + alpha * x0 * (1 - e))),
                    std::abs(c[1][1] - 1),
                    std::abs(c[2][2] - 1)});
      }
    return report("Giesekus relaxation after cessation", error, 1e-9);
  }

  // The linear limit of XPP: at Wi = 1e-3 the start-up shear stress is
  // eta_p gamma' (1 - e^-t) up to O(Wi^2) (relative); c stays near I.
  int
  linear_xpp(const bool log_form)
  {
    const double wi    = 1e-3;
    double       error = 0;
    for (const double t : {0.5, 2., 8.})
      {
        const auto c = evolve(xpp(), identity, shear(wi), t, log_form);
        error =
          std::max(error, std::abs(c[0][1] / (wi * (1 - std::exp(-t))) - 1));
      }
    return report("XPP linear limit (relative shear stress)", error, 1e-5);
  }

  // The relaxation step alone (ConformationModel::relax_log), from a
  // sheared state c1 (Giesekus alpha = 0.3 start-up at Wi 5 to t = 1):
  // Giesekus in one step of 3 lambda against the closed form through the
  // eigenvalues (x -> x e / (1 + alpha x (1 - e))), XPP in 300 backward
  // Euler steps of 0.01 against RK4 of the log form (first order: measured
  // 0.0226 relative to |c - I|, limit 0.03), and one XPP step of 100 lambda
  // must stay positive and damp c - I at least as backward Euler damps
  // x' = -x / lambda, by 1 / (1 + dt / lambda) (measured 0.0494 from 5.4).
  int
  relax_step()
  {
    const auto c1 = evolve(giesekus(0.3), identity, shear(5.), 1., false);
    const SymmetricTensor<2, 3> s1 = tensor_log(c1);
    double                      error_giesekus = 0;
    {
      const double e      = std::exp(-3.);
      const auto   pairs  = eigenvectors(c1);
      SymmetricTensor<2, 3> exact;
      for (const auto &[c, r] : pairs)
        exact += (1 + (c - 1) * e / (1 + 0.3 * (c - 1) * (1 - e))) *
                 symmetrize(outer_product(r, r));
      error_giesekus =
        (tensor_exp(giesekus(0.3).relax_log(s1, 3.)) - exact).norm();
    }
    SymmetricTensor<2, 3> s = s1;
    for (unsigned int n = 0; n < 300; ++n)
      s = xpp().relax_log(s, 0.01);
    const auto reference = evolve(xpp(), c1, Tensor<2, 3>(), 3., true);
    const double error_xpp =
      (tensor_exp(s) - reference).norm() / (reference - identity).norm();
    const double error_large =
      (tensor_exp(xpp().relax_log(s1, 100.)) - identity).norm() /
      ((c1 - identity).norm() / 101.);
    std::cout << "Giesekus one step of 3 lambda: " << error_giesekus
              << "; XPP 300 steps of 0.01 (relative to c - I): " << error_xpp
              << "; XPP one step of 100: |c - I| / (|c1 - I| / 101) "
              << error_large << std::endl;
    return report("relaxation step (each error over its limit 1e-12, 0.03, "
                  "1: the largest)",
                  std::max({error_giesekus / 1e-12, error_xpp / 0.03,
                            error_large}),
                  1.);
  }

  // Direct and log form on the same start-up, well into the nonlinear
  // range: shear at Wi = 5 and extension at Wi = 2 (Giesekus alpha = 0.1
  // and XPP); they must agree to the integration error.
  int
  forms(const ConformationModel &model, const std::string &name)
  {
    double error = 0;
    for (const auto &[flow, t] :
         std::vector<std::pair<Tensor<2, 3>, double>>{{shear(5.), 3.},
                                                      {uniaxial(2.), 1.}})
      {
        const auto d = evolve(model, identity, flow, t, false);
        const auto l = evolve(model, identity, flow, t, true);
        error        = std::max(error, (d - l).norm() / d.norm());
      }
    return report(name + ": direct against log form (relative)", error, 1e-8);
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::cerr << "usage: conformation_models CASE [direct|log]\n";
      return 2;
    }
  const std::string which    = argv[1];
  const bool        log_form = argc > 2 && std::string(argv[2]) == "log";
  if (which == "shear-oldroyd")
    return shear_oldroyd(log_form);
  if (which == "extension-oldroyd")
    return extension_oldroyd(log_form);
  if (which == "shear-giesekus")
    return shear_giesekus(log_form);
  if (which == "relax-giesekus")
    return relax_giesekus(log_form);
  if (which == "linear-xpp")
    return linear_xpp(log_form);
  if (which == "relax-step")
    return relax_step();
  if (which == "forms-giesekus")
    return forms(giesekus(0.1), "Giesekus alpha 0.1");
  if (which == "forms-xpp")
    return forms(xpp(), "XPP q 2, lambda/lambda_s 2");
  std::cerr << "unknown case '" << which << "'\n";
  return 2;
}
