#include <deal.II/base/utilities.h>

#include <levelsinter/scene/domain_parameters.h>
#include <levelsinter/scene/parameter_entries.h>

#include <algorithm>

namespace levelsinter
{
  void
  DomainParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Domain");
    {
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::Anything(),
                        "Lower corner of the box domain, one coordinate per "
                        "dimension, comma-separated (the scene's length "
                        "unit: m with material data, else any unit used "
                        "consistently by every length of the scene).");
      prm.declare_entry("Upper corner",
                        "1, 1",
                        Patterns::Anything(),
                        "Upper corner of the box domain (same length unit).");
      prm.declare_entry("Subdivisions",
                        "1, 1",
                        Patterns::List(Patterns::Integer(1), 2, 3, ","),
                        "Number of coarse cells along each axis (level 0 of "
                        "the mesh). Choose them so that coarse cells are "
                        "about cubes.");
      prm.declare_entry(
        "Symmetry planes",
        "",
        Patterns::MultipleSelection("x-|x+|y-|y+|z-|z+"),
        "Box faces the scene is mirrored across, e.g. 'y-' or 'x-, y-': "
        "zero normal velocity there (the rigid motion the planes leave free "
        "is removed from the velocity, no drift of the particles as a "
        "whole), and the refinement reads the interface as continued "
        "across them (no false kink where a particle meets the face).");
    }
    prm.leave_subsection();
  }

  void
  DomainParameters::parse(ParameterHandler &prm, const unsigned int dimension)
  {
    const unsigned int d = dimension;
    prm.enter_subsection("Domain");
    lower_corner = read_coordinates(prm, "Domain", "Lower corner", d);
    upper_corner = read_coordinates(prm, "Domain", "Upper corner", d);
    {
      const auto values = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Subdivisions"), ','));
      if (values.size() != d)
        fail_entry("Domain/Subdivisions",
                   "needs " + std::to_string(d) + " integers, got '" +
                     prm.get("Subdivisions") + "'");
      subdivisions.assign(values.begin(), values.end());
    }
    for (unsigned int i = 0; i < d; ++i)
      if (!(lower_corner[i] < upper_corner[i]))
        fail_entry("Domain/Upper corner",
                   "each coordinate must be larger than the lower corner's");
    const std::vector<std::string> faces = {"x-", "x+", "y-", "y+", "z-", "z+"};
    symmetry_planes.clear();
    for (const auto &name :
         Utilities::split_string_list(prm.get("Symmetry planes"), ','))
      {
        const auto id =
          std::find(faces.begin(), faces.end(), name) - faces.begin();
        if (id >= 2 * int(d))
          fail_entry("Domain/Symmetry planes",
                     "'" + name + "' is not a face of a " + std::to_string(d) +
                       "D box");
        symmetry_planes.push_back(id);
      }
    prm.leave_subsection();
  }

  double
  DomainParameters::coarse_cell_size() const
  {
    double h = 0;
    for (unsigned int i = 0; i < subdivisions.size(); ++i)
      h = std::max(h, (upper_corner[i] - lower_corner[i]) / subdivisions[i]);
    return h;
  }
} // namespace levelsinter
