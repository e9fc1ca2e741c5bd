#pragma once

#include <levelsinter/scene/level_set_parameters.h>

namespace levelsinter
{
  /**
   * The filter that turns a signed distance d into the level set alpha,
   * cut off at thickness E (paper Sect. 4.4.2):
   *  - sine (Eq. 65): alpha = (2E/pi) sin(pi d / 2E) for |d| <= E, else
   *    +-2E/pi. (Eq. 65 prints the middle case as -E <= alpha <= 0; it holds
   *    for -E <= d <= E.)
   *  - tanh (Eq. 69): alpha = E tanh(d / E).
   * Both keep the sign convention alpha < 0 in the solid.
   */
  class LevelSetFilter
  {
  public:
    // The choice of `Level set/Filter`.
    using Type = LevelSetParameters::Filter;

    LevelSetFilter(const Type type, const double thickness);

    /** alpha(d). */
    double
    filter(const double distance) const;

    /**
     * The distance a value of alpha stands for, the inverse of filter();
     * saturated values return +-E (sine) or a value >= 3E (tanh).
     */
    double
    distance(const double alpha) const;

    /**
     * The norm |grad alpha| that reinitialisation aims at, as a function of
     * alpha itself: Eq. 67 for the sine filter, 1 - (alpha/E)^2 for tanh.
     */
    double
    gradient_norm_target(const double alpha) const;

    /** |alpha| far from the interface: 2E/pi (sine) or E (tanh). */
    double
    saturation() const;

    double
    thickness() const
    {
      return E;
    }

  private:
    Type   type;
    double E;
  };
} // namespace levelsinter
