#pragma once

namespace levelsinter
{
  /**
   * Coefficients of the mixed velocity-pressure operator at one point, as
   * the paper writes them for Eq. 93-94 and 99:
   *   a1 eps(v):eps(w) - a2 p div w,   -q div v - c_p p q,
   * with a1 = 2 eta_eff, a2 the pressure weight and c_p the compressibility
   * (pressure-mass) coefficient. The right-hand sides that a phase may add
   * (the elastic history term of Eq. 93-94) belong to the same law.
   */
  struct PhaseCoefficients
  {
    double a1          = 0; // 2 x effective viscosity
    double a2          = 1; // weight of p in the momentum equation
    double compressibility = 0; // c_p
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
   * How the two phases respond, as a function of the phase fractions. The operator (TwoPhaseStokes) assembles
   * whatever law it is given; the viscous mechanism passes NewtonianPhases,
   * the elastic-solid/fluid problem of volume diffusion (Eq. 93-94: a1 =
   * 2(G dt H_s + eta H_f), a2 = (1 - 2G/3K) H_s + H_f, c_p = H_s/(K dt)) is
   * another implementation of this interface.
   */
  class PhaseLaw
  {
  public:
    virtual ~PhaseLaw() = default;

    virtual PhaseCoefficients
    coefficients(const PhaseFractions &fractions) const = 0;
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
  class NewtonianPhases : public PhaseLaw
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

  private:
    double eta_s;
    double eta_f;
    double c;
  };
} // namespace levelsinter
