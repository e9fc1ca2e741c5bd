#include <levelsinter/mechanics/phase_law.h>

#include <stdexcept>

namespace levelsinter
{
  template <int dim>
  PhaseCoefficients
  ElasticSolidFluid<dim>::coefficients(const PhaseFractions &f) const
  {
    if (!(dt > 0))
      throw std::runtime_error(
        "elastic-solid phase law: the rate form needs a time step > 0");
    PhaseCoefficients k;
    const double      fluid = 1 - f.solid;
    k.a1                    = 2 * (G * dt * f.solid + eta_f * fluid);
    k.a2 = (1 - 2 * G / (3 * K)) * f.solid + fluid;
    k.compressibility = f.solid / (K * dt) + c * f.bulk_fluid / eta_f;
    return k;
  }

  template <int dim>
  HistoryTerms<dim>
  ElasticSolidFluid<dim>::history(
    const PhaseFractions          &f,
    const SymmetricTensor<2, dim> &old_strain) const
  {
    HistoryTerms<dim> terms;
    terms.stress          = 2 * G * f.solid * old_strain;
    terms.dilatation_rate = -f.solid * trace(old_strain) / dt;
    return terms;
  }

  template <int dim>
  std::unique_ptr<PhaseLaw<dim>>
  make_phase_law(const PhaseLawParameters    &law,
                 const ViscousFlowParameters &flow)
  {
    if (law.law == PhaseLawParameters::Law::elastic_solid)
      return std::make_unique<ElasticSolidFluid<dim>>(law.shear_modulus,
                                                      law.bulk_modulus,
                                                      flow.fluid_viscosity,
                                                      flow.fluid_compressibility);
    return std::make_unique<NewtonianPhases<dim>>(flow.solid_viscosity,
                                                  flow.fluid_viscosity,
                                                  flow.fluid_compressibility);
  }

  template class ElasticSolidFluid<2>;
  template class ElasticSolidFluid<3>;
  template std::unique_ptr<PhaseLaw<2>>
  make_phase_law(const PhaseLawParameters &, const ViscousFlowParameters &);
  template std::unique_ptr<PhaseLaw<3>>
  make_phase_law(const PhaseLawParameters &, const ViscousFlowParameters &);
} // namespace levelsinter
