#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** The `Velocity` subsection: a prescribed velocity field
   * (PrescribedVelocity mechanism). */
  struct PrescribedVelocityParameters
  {
    enum class Type
    {
      none,
      constant,
      rotation,
      expression
    };

    static void
    declare(ParameterHandler &prm);

    /** Read and check; throws std::runtime_error naming the entry. Vectors
     * are read only where the type uses them, so that the 2D defaults do
     * not get in the way of a 3D scene; an expression is parsed and
     * evaluated once here, so that the run never starts with a bad one. */
    void
    parse(ParameterHandler &prm, const unsigned int dimension);

    Type                type = Type::none;
    std::vector<double> constant;
    std::vector<double> rotation_centre;
    std::vector<double> rotation_axis;
    double              angular_velocity = 0;
    std::string         expression;
    // Expression constants by name (pi always defined).
    std::map<std::string, double> constants;
  };
} // namespace levelsinter
