#include <deal.II/base/utilities.h>

#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/prescribed_velocity_parameters.h>
#include <levelsinter/scene/solid_geometry.h>

#include <cmath>

namespace levelsinter
{
  void
  PrescribedVelocityParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Velocity");
    {
      prm.declare_entry("Type",
                        "none",
                        Patterns::Selection(
                          "none|constant|rotation|expression"),
                        "Prescribed velocity that transports the level set.");
      prm.declare_entry("Constant",
                        "0, 0",
                        Patterns::Anything(),
                        "Velocity vector for Type = constant (length unit "
                        "of the domain per scene time unit).");
      prm.declare_entry("Rotation centre",
                        "0.5, 0.5",
                        Patterns::Anything(),
                        "A point on the rotation axis (Type = rotation; "
                        "same length unit as the domain).");
      prm.declare_entry("Rotation axis",
                        "0, 0, 1",
                        Patterns::Anything(),
                        "Rotation axis in 3D (normalised internally); "
                        "ignored in 2D.");
      prm.declare_entry("Angular velocity",
                        "6.283185307179586",
                        Patterns::Double(),
                        "Angular velocity in radians per scene time unit, "
                        "counter-clockwise about the axis.");
      prm.declare_entry("Expression",
                        "0; 0",
                        Patterns::Anything(),
                        "Velocity components separated by ';' as functions "
                        "of x, y[, z] and t (deal.II FunctionParser syntax; "
                        "length unit of the domain per scene time unit).");
      prm.declare_entry("Expression constants",
                        "",
                        Patterns::Anything(),
                        "Constants for the expression, e.g. 'U=1, T=2'.");
    }
    prm.leave_subsection();
  }

  void
  PrescribedVelocityParameters::parse(ParameterHandler  &prm,
                                      const unsigned int d)
  {
    prm.enter_subsection("Velocity");
    type = read_selection<Type>(prm,
                                "Velocity",
                                "Type",
                                {{"none", Type::none},
                                 {"constant", Type::constant},
                                 {"rotation", Type::rotation},
                                 {"expression", Type::expression}});
    if (type == Type::constant)
      constant = read_coordinates(prm, "Velocity", "Constant", d);
    if (type == Type::rotation)
      {
        rotation_centre =
          read_coordinates(prm, "Velocity", "Rotation centre", d);
        rotation_axis = read_coordinates(prm, "Velocity", "Rotation axis", 3);
      }
    angular_velocity     = prm.get_double("Angular velocity");
    expression           = prm.get("Expression");
    constants = parse_constants(prm.get("Expression constants"),
                                "Velocity/Expression constants");
    prm.leave_subsection();
    if (type == Type::expression)
      {
        if (Utilities::split_string_list(expression, ';').size() != d)
          fail_entry("Velocity/Expression",
                     "needs " + std::to_string(d) +
                       " components separated by ';'");
        if (d == 2)
          make_expression_function<2>(
            expression, d, constants, "Velocity/Expression", true);
        else
          make_expression_function<3>(
            expression, d, constants, "Velocity/Expression", true);
      }
    if (type == Type::rotation && d == 3 &&
        std::hypot(rotation_axis[0], rotation_axis[1], rotation_axis[2]) == 0)
      fail_entry("Velocity/Rotation axis", "must not be the zero vector");
  }
} // namespace levelsinter
