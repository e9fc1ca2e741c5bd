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
  void
  ElasticSolidFluid<dim>::material_states(
    const MaterialInputs<dim>       &inputs,
    std::vector<MaterialState<dim>> &states) const
  {
    std::vector<SymmetricTensor<2, dim>> strain(
      inputs.values.n_quadrature_points);
    inputs.values[FEValuesExtractors::Vector(0)]
      .get_function_symmetric_gradients(inputs.displacement, strain);
    for (unsigned int k = 0; k < strain.size(); ++k)
      states[k].old_strain = strain[k];
  }

  template <int dim>
  HistoryTerms<dim>
  ElasticSolidFluid<dim>::history(const PhaseFractions     &f,
                                  const MaterialState<dim> &state) const
  {
    HistoryTerms<dim> terms;
    terms.stress          = 2 * G * f.solid * state.old_strain;
    terms.dilatation_rate = -f.solid * trace(state.old_strain) / dt;
    return terms;
  }

  template <int dim>
  PhaseCoefficients
  ViscoelasticPhases<dim>::coefficients(const PhaseFractions &f) const
  {
    // dt = 0 (a velocity at a fixed time): the polymer stress is all
    // explicit, the instantaneous response.
    PhaseCoefficients k;
    k.a1 = 2 * ((eta_s + eta_p * dt / (lambda + dt)) * f.solid +
                eta_f * (1 - f.solid));
    k.a2 = 1;
    k.compressibility = c * f.bulk_fluid / eta_f;
    return k;
  }

  template <int dim>
  void
  ViscoelasticPhases<dim>::material_states(
    const MaterialInputs<dim>       &inputs,
    std::vector<MaterialState<dim>> &states) const
  {
    std::vector<SymmetricTensor<2, dim>> stress;
    std::vector<double>                  hoop_stress;
    polymer.stress_values(inputs.level_set_values, stress, hoop_stress);
    for (unsigned int k = 0; k < stress.size(); ++k)
      {
        states[k].polymer_stress      = stress[k];
        states[k].polymer_hoop_stress = hoop_stress[k];
      }
  }

  template <int dim>
  HistoryTerms<dim>
  ViscoelasticPhases<dim>::history(const PhaseFractions     &f,
                                   const MaterialState<dim> &state) const
  {
    HistoryTerms<dim> terms;
    const double memory = lambda / (lambda + dt) * f.solid;
    terms.stress        = memory * state.polymer_stress;
    terms.hoop_stress   = memory * state.polymer_hoop_stress;
    return terms;
  }

  template <int dim>
  std::unique_ptr<PhaseLaw<dim>>
  make_phase_law(const PhaseLawParameters     &law,
                 const ViscousFlowParameters  &flow,
                 const MaterialsParameters    &materials,
                 const ViscoelasticState<dim> *polymer)
  {
    if (law.law == PhaseLawParameters::Law::elastic_solid)
      return std::make_unique<ElasticSolidFluid<dim>>(law.shear_modulus,
                                                      law.bulk_modulus,
                                                      materials.fluid_viscosity,
                                                      materials.fluid_compressibility);
    if (law.is_viscoelastic())
      {
        if (polymer == nullptr)
          throw std::logic_error(
            "make_phase_law: a viscoelastic law needs the melt's "
            "ViscoelasticState");
        return std::make_unique<ViscoelasticPhases<dim>>(
          flow.solid_viscosity,
          law.polymer_viscosity,
          law.relaxation_time,
          materials.fluid_viscosity,
          materials.fluid_compressibility,
          *polymer);
      }
    return std::make_unique<NewtonianPhases<dim>>(flow.solid_viscosity,
                                                  materials.fluid_viscosity,
                                                  materials.fluid_compressibility);
  }

  template class ElasticSolidFluid<2>;
  template class ElasticSolidFluid<3>;
  template class ViscoelasticPhases<2>;
  template class ViscoelasticPhases<3>;
  template std::unique_ptr<PhaseLaw<2>>
  make_phase_law(const PhaseLawParameters &,
                 const ViscousFlowParameters &,
                 const MaterialsParameters &,
                 const ViscoelasticState<2> *);
  template std::unique_ptr<PhaseLaw<3>>
  make_phase_law(const PhaseLawParameters &,
                 const ViscousFlowParameters &,
                 const MaterialsParameters &,
                 const ViscoelasticState<3> *);
} // namespace levelsinter
