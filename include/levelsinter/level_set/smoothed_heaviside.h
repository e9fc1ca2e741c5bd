#pragma once

#include <cmath>

namespace levelsinter
{
  /**
   * Phase indicator and regularised Dirac built from the level set over a
   * transition half-width E (paper Eq. 102-104). alpha < 0 is the solid, so
   * solid_fraction() is H_s and dirac() = dH_f/dalpha. Near the interface the
   * filtered level set is a distance to second order, so E is a length.
   */
  class SmoothedHeaviside
  {
  public:
    explicit SmoothedHeaviside(const double half_width)
      : E(half_width)
    {}

    /** H_s(alpha), Eq. 102. */
    double
    solid_fraction(const double alpha) const
    {
      if (alpha < -E)
        return 1.;
      if (alpha > E)
        return 0.;
      return (E - alpha - E / M_PI * std::sin(M_PI * alpha / E)) / (2 * E);
    }

    /** delta(alpha) = dH_f/dalpha, Eq. 104; integrates to 1 over alpha. */
    double
    dirac(const double alpha) const
    {
      if (std::abs(alpha) > E)
        return 0.;
      return (1 + std::cos(M_PI * alpha / E)) / (2 * E);
    }

    double
    half_width() const
    {
      return E;
    }

  private:
    double E;
  };
} // namespace levelsinter
