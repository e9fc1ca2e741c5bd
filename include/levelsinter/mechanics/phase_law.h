#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <levelsinter/mechanics/viscoelastic_state.h>
#include <levelsinter/scene/materials_parameters.h>
#include <levelsinter/scene/phase_law_parameters.h>
#include <levelsinter/scene/viscous_flow_parameters.h>

#include <memory>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * Coefficients of the mixed velocity-pressure operator at one point, as
   * the paper writes them for Eq. 93-94 and 99:
   *   a1 eps(v):eps(w) - a2 p div w,   -q div v - c_p p q,
   * with a1 = 2 eta_eff, a2 the pressure weight and c_p the compressibility
   * (pressure-mass) coefficient.
   */
  struct PhaseCoefficients
  {
    double a1              = 0; // 2 x effective viscosity
    double a2              = 1; // weight of p in the momentum equation
    double compressibility = 0; // c_p
  };

  /**
   * Right-hand sides a law with memory adds at one point (Eq. 93-94 for
   * the elastic solid): the momentum equation gets -stress : grad w, the
   * continuity equation div v + c_p p = dilatation_rate. On an
   * axisymmetric scene the stress has the hoop entry sigma_thth too, which
   * meets e_thth(w) = w_r / r.
   */
  template <int dim>
  struct HistoryTerms
  {
    SymmetricTensor<2, dim> stress;
    double                  hoop_stress     = 0;
    double                  dilatation_rate = 0;
  };

  /**
   * What a law with memory reads at one point, filled by the law itself
   * (PhaseLaw::material_states()): the strain of the previous step's
   * displacement (elastic solid) and the polymer stress tau^n = G (c^n - I)
   * of the conformation field (viscoelastic melts) with its hoop entry
   * tau_thth (0 on a plane scene; the elastic solid is refused on
   * axisymmetric scenes, so its strain has none).
   */
  template <int dim>
  struct MaterialState
  {
    SymmetricTensor<2, dim> old_strain;
    SymmetricTensor<2, dim> polymer_stress;
    double                  polymer_hoop_stress = 0;
  };

  /**
   * Where a law with memory finds its state on one cell: FEValues of the
   * operator's element and of the level set's, both reinit on the cell
   * with the same quadrature, and the displacement u^{n-1} the operator
   * keeps (TwoPhaseStokes::displacement(), ghosted).
   */
  template <int dim>
  struct MaterialInputs
  {
    const FEValues<dim>                      &values;
    const FEValues<dim>                      &level_set_values;
    const TrilinosWrappers::MPI::BlockVector &displacement;
  };

  /**
   * Where a point lies: the smoothed solid fraction H_s (Eq. 102, 1 in the
   * particles) and the fraction of bulk atmosphere, the same ramp shifted by
   * 2E into the fluid so that it vanishes across the transition zone.
   */
  struct PhaseFractions
  {
    double solid      = 0;
    double bulk_fluid = 0;
  };

  /**
   * How the two phases respond, as a function of the phase fractions. The
   * operator (TwoPhaseStokes) assembles whatever law it is given: the
   * viscous mechanism passes NewtonianPhases, the elastic-solid/fluid
   * problem of volume diffusion ElasticSolidFluid
   * (make_phase_law() chooses by name).
   */
  template <int dim>
  class PhaseLaw
  {
  public:
    virtual ~PhaseLaw() = default;

    virtual PhaseCoefficients
    coefficients(const PhaseFractions &fractions) const = 0;

    /** Whether the law has memory: then the operator asks it for its
     * state on every cell (material_states()) and for the history
     * right-hand sides at every point (history()). */
    virtual bool
    has_history() const
    {
      return false;
    }

    /** The law's state at the quadrature points of @p inputs: the entries
     * it reads in history(), in @p states[k] for point k (sized at least
     * to the number of points). */
    virtual void
    material_states(const MaterialInputs<dim> &,
                    std::vector<MaterialState<dim>> &) const
    {}

    /** The history right-hand sides for the state @p state at the point. */
    virtual HistoryTerms<dim>
    history(const PhaseFractions &, const MaterialState<dim> &) const
    {
      return {};
    }

    /** The step a rate-form law discretises (Eq. 92); call before each
     * assembly. Laws without memory ignore it. */
    virtual void
    set_time_step(const double)
    {}

    /** Whether the pressure of a solve stays the same when only the step
     * changes, so that a step taken again shorter from the same state may
     * keep it (VolumeDiffusion::shorten_step()). */
    virtual bool
    pressure_independent_of_step() const
    {
      return false;
    }
  };

  /**
   * Two Newtonian phases: viscosity eta_s in the particles, eta_f in the
   * atmosphere, mixed linearly with H_s. The bulk of the atmosphere is
   * compressible with bulk viscosity eta_f / c (div v = -c p / eta_f): a
   * closed pore filled with an incompressible fluid could never shrink.
   * Within the transition zone the mixture stays incompressible: a
   * compressibility weighted by H_f there would let the smeared solid
   * pressure drain solid volume (measured: 4 % area loss vs 2 % in the
   * Hopper case at R/h = 20). c = 0 makes both phases incompressible (the
   * static-bubble benchmark).
   */
  template <int dim>
  class NewtonianPhases : public PhaseLaw<dim>
  {
  public:
    NewtonianPhases(const double solid_viscosity,
                    const double fluid_viscosity,
                    const double fluid_compressibility)
      : eta_s(solid_viscosity)
      , eta_f(fluid_viscosity)
      , c(fluid_compressibility)
    {}

    PhaseCoefficients
    coefficients(const PhaseFractions &f) const override
    {
      PhaseCoefficients k;
      k.a1              = 2 * (eta_s * f.solid + eta_f * (1 - f.solid));
      k.a2              = 1;
      k.compressibility = c * f.bulk_fluid / eta_f;
      return k;
    }

    /** Stokes flow has no step in it. */
    bool
    pressure_independent_of_step() const override
    {
      return true;
    }

  private:
    double eta_s;
    double eta_f;
    double c;
  };

  /**
   * Linear elastic particles (shear modulus G, bulk modulus K) in a
   * Newtonian atmosphere (eta_f), paper Eq. 86-94. With p = -K div u and
   * u^n = u^{n-1} + dt v^n (Eq. 92) the solid's equilibrium
   * 2G div eps(u) - (1 - 2G/3K) grad p = 0 becomes, for (v^n, p^n),
   *   a1 = 2 (G dt H_s + eta_f H_f),  a2 = (1 - 2G/3K) H_s + H_f,
   *   c_p = H_s / (K dt)  (+ the atmosphere's c H_bulk / eta_f),
   * with the history -2G H_s eps(u^{n-1}) : eps(w) in the momentum and
   * div v + c_p p = -H_s div u^{n-1} / dt (the paper's coefficients,
   * checked). The atmosphere keeps the compressibility option of
   * NewtonianPhases (0: incompressible, as in the paper).
   */
  template <int dim>
  class ElasticSolidFluid : public PhaseLaw<dim>
  {
  public:
    ElasticSolidFluid(const double shear_modulus,
                      const double bulk_modulus,
                      const double fluid_viscosity,
                      const double fluid_compressibility)
      : G(shear_modulus)
      , K(bulk_modulus)
      , eta_f(fluid_viscosity)
      , c(fluid_compressibility)
    {}

    PhaseCoefficients
    coefficients(const PhaseFractions &f) const override;

    bool
    has_history() const override
    {
      return true;
    }

    /** The strain eps(u^{n-1}) of the operator's displacement. */
    void
    material_states(const MaterialInputs<dim>       &inputs,
                    std::vector<MaterialState<dim>> &states) const override;

    HistoryTerms<dim>
    history(const PhaseFractions     &f,
            const MaterialState<dim> &state) const override;

    void
    set_time_step(const double time_step) override
    {
      dt = time_step;
    }

    /** With Delta u = dt v the solid's equations above do not contain dt
     * (the ASGS tau ~ h^2 / a1 scales with 1 / dt too); only the
     * atmosphere's eta_f eps(v) does, a relative eta_f / (G dt) of the
     * solid's stress (measured: doc/numerics.md, "Volume diffusion"). */
    bool
    pressure_independent_of_step() const override
    {
      return true;
    }

  private:
    double G;
    double K;
    double eta_f;
    double c;
    double dt = 0;
  };

  /**
   * Viscoelastic particles (the viscoelastic seed, Eq. 4-7): solvent
   * viscosity eta_s plus the polymer stress tau = G (c - I) of a
   * conformation field, in a Newtonian atmosphere (eta_f, compressibility
   * as NewtonianPhases). The polymer stress enters implicitly through its
   * linearisation about the state at rest, lambda tau' + tau = 2 eta_p D,
   * taken backward in time over the step:
   *   tau^{n+1} = lambda / (lambda + dt) tau^n
   *               + 2 eta_p dt / (lambda + dt) D(v^{n+1}),
   * so the particles get the viscosity eta_s + eta_p dt / (lambda + dt)
   * and the explicit stress lambda / (lambda + dt) H_s tau^n. The full
   * nonlinear model then updates c with v^{n+1} (ConformationField). At
   * lambda -> 0 (eta_p = G lambda fixed) this is the Newtonian law with
   * eta_s + eta_p whatever dt; at lambda -> infinity the elastic rate form
   * (viscosity G dt, as ElasticSolidFluid). tau^n is read from
   * @p polymer, the melt's ViscoelasticState.
   */
  template <int dim>
  class ViscoelasticPhases : public PhaseLaw<dim>
  {
  public:
    ViscoelasticPhases(const double                    solvent_viscosity,
                       const double                    polymer_viscosity,
                       const double                    relaxation_time,
                       const double                    fluid_viscosity,
                       const double                    fluid_compressibility,
                       const ViscoelasticState<dim>   &polymer)
      : eta_s(solvent_viscosity)
      , eta_p(polymer_viscosity)
      , lambda(relaxation_time)
      , eta_f(fluid_viscosity)
      , c(fluid_compressibility)
      , polymer(polymer)
    {}

    PhaseCoefficients
    coefficients(const PhaseFractions &f) const override;

    bool
    has_history() const override
    {
      return true;
    }

    /** The polymer stress tau^n and its hoop entry. */
    void
    material_states(const MaterialInputs<dim>       &inputs,
                    std::vector<MaterialState<dim>> &states) const override;

    HistoryTerms<dim>
    history(const PhaseFractions     &f,
            const MaterialState<dim> &state) const override;

    void
    set_time_step(const double time_step) override
    {
      dt = time_step;
    }

  private:
    double eta_s;
    double eta_p;
    double lambda;
    double eta_f;
    double c;
    double dt = 0;
    const ViscoelasticState<dim> &polymer;
  };

  /**
   * The law a scene asks for ('Phase law/Law'), with the particles'
   * viscosity of 'Viscous flow' and the atmosphere of 'Materials'; a
   * viscoelastic law reads the polymer stress of @p polymer (required for
   * it, unused otherwise).
   */
  template <int dim>
  std::unique_ptr<PhaseLaw<dim>>
  make_phase_law(const PhaseLawParameters     &law,
                 const ViscousFlowParameters  &flow,
                 const MaterialsParameters    &materials,
                 const ViscoelasticState<dim> *polymer = nullptr);
} // namespace levelsinter
