#include <deal.II/base/utilities.h>

#include <levelsinter/scene/analysis_parameters.h>
#include <levelsinter/scene/parameter_entries.h>

#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // The pattern has checked the numbers; the count depends on the
    // dimension.
    std::vector<double>
    corner(ParameterHandler  &prm,
           const std::string &entry,
           const unsigned int dimension)
    {
      const std::vector<double> values = Utilities::string_to_double(
        Utilities::split_string_list(prm.get(entry), ','));
      if (!values.empty() && values.size() != dimension)
        fail_entry("Analysis/" + entry,
             "needs " + std::to_string(dimension) +
               " comma-separated numbers (one per coordinate) or nothing");
      return values;
    }
  } // namespace

  void
  AnalysisParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Analysis");
    {
      prm.declare_entry(
        "Packing analysis",
        "auto",
        Patterns::Selection("auto|true|false"),
        "Every metrics interval: pores (open and closed porosity, closed "
        "pores, pores.csv, pore_events.csv), relative density in the control "
        "volume, the neck of every overlapping pair (necks.csv), the "
        "coordination number and the shrinkage. auto: on for a scene of "
        "two or more particles.");
      prm.declare_entry("Control volume lower corner",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "Lower corner of the box where relative density and "
                        "porosity are measured (comma-separated, one number "
                        "per coordinate). Empty: the bounding box of the "
                        "particle centres, or the domain if the centres "
                        "span no volume.");
      prm.declare_entry("Control volume upper corner",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "Upper corner of the control volume (see the lower "
                        "corner); both or neither.");
    }
    prm.leave_subsection();
  }

  void
  AnalysisParameters::parse(ParameterHandler  &prm,
                            const unsigned int dimension)
  {
    prm.enter_subsection("Analysis");
    packing_analysis = read_selection<Mode>(prm,
                                            "Analysis",
                                            "Packing analysis",
                                            {{"auto", Mode::automatic},
                                             {"true", Mode::on},
                                             {"false", Mode::off}});
    control_lower_corner = corner(prm, "Control volume lower corner", dimension);
    control_upper_corner = corner(prm, "Control volume upper corner", dimension);
    prm.leave_subsection();
    if (control_lower_corner.empty() != control_upper_corner.empty())
      fail_entry("Analysis/Control volume upper corner",
           "give both corners of the control volume or neither");
    for (unsigned int d = 0; d < control_lower_corner.size(); ++d)
      if (control_lower_corner[d] >= control_upper_corner[d])
        fail_entry("Analysis/Control volume upper corner",
             "must exceed the lower corner in every coordinate");
  }

  bool
  AnalysisParameters::enabled(const GeometryParameters::Shape shape,
                              const unsigned int              n_particles) const
  {
    if (packing_analysis == Mode::automatic)
      return shape == GeometryParameters::Shape::particles && n_particles >= 2;
    return packing_analysis == Mode::on;
  }
} // namespace levelsinter
