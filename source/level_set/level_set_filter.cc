#include <levelsinter/level_set/level_set_filter.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace levelsinter
{
  LevelSetFilter::LevelSetFilter(const Type type, const double thickness)
    : type(type)
    , E(thickness)
  {
    if (!(thickness > 0))
      throw std::invalid_argument("the filter thickness must be positive");
  }

  double
  LevelSetFilter::saturation() const
  {
    return type == Type::sine ? 2 * E / M_PI : E;
  }

  double
  LevelSetFilter::filter(const double d) const
  {
    if (type == Type::tanh)
      return E * std::tanh(d / E);
    const double s = saturation();
    return s * std::sin(std::clamp(d, -E, E) / s);
  }

  double
  LevelSetFilter::distance(const double alpha) const
  {
    const double ratio = std::clamp(alpha / saturation(), -1.0, 1.0);
    if (type == Type::tanh)
      {
        // atanh(0.995) = 3.0: beyond that alpha carries no distance.
        return E * std::atanh(std::clamp(ratio, -0.995, 0.995));
      }
    return saturation() * std::asin(ratio);
  }

  double
  LevelSetFilter::gradient_norm_target(const double alpha) const
  {
    const double ratio = alpha / saturation();
    if (type == Type::tanh)
      return std::max(0.0, 1 - ratio * ratio);
    return std::sqrt(std::max(0.0, 1 - ratio * ratio));
  }
} // namespace levelsinter
