#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/refinement_parameters.h>

namespace levelsinter
{
  const char *const RefinementParameters::band_width_rule =
    "the band width must be smaller than Level set/Filter thickness (beyond "
    "E the filtered level set carries no distance) and at least "
    "(Adapt interval x CFL number + 1) x h, h the cell size at Maximum "
    "level, so that the interface cannot leave the refined band between "
    "two adaptations";

  void
  RefinementParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry("Minimum level",
                        "0",
                        Patterns::Integer(0, 20),
                        "Refinement level far from the interface (0 = the "
                        "coarse subdivision).");
      prm.declare_entry("Maximum level",
                        "4",
                        Patterns::Integer(0, 20),
                        "Refinement level inside the interface band. The "
                        "mesh this gives must fit in memory: the scene is "
                        "refused if the estimated band cells would not.");
      prm.declare_entry(
        "Band width",
        "0.05",
        Patterns::Double(0),
        std::string("Cells closer than this distance to the interface (same "
                    "length unit as the domain) are refined to the maximum "
                    "level; ") +
          band_width_rule + ".");
      prm.declare_entry("Adapt interval",
                        "5",
                        Patterns::Integer(1),
                        "Re-adapt the mesh every this many steps.");
      prm.declare_entry(
        "Curvature refinement levels",
        "0",
        Patterns::Integer(0, 10),
        "Extra levels above the maximum level where the interface is "
        "sharply curved (necks): a band cell is refined further while its "
        "size h and the curvature k = sqrt(k1^2 + k2^2) of the level set "
        "there (|kappa| in 2D) give (Cells per curvature radius) * k * h > 1. "
        "Extra level j is confined to the band width / 2^j. 0 = off.");
      prm.declare_entry(
        "Cells per curvature radius",
        "4",
        Patterns::Double(0.1),
        "With Curvature refinement levels > 0: how many cells a curvature "
        "radius 1/k must span before the refinement stops. A cell is "
        "coarsened again once its parent would span twice as many.");
    }
    prm.leave_subsection();
  }

  void
  RefinementParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    min_level        = prm.get_integer("Minimum level");
    max_level        = prm.get_integer("Maximum level");
    band_width       = prm.get_double("Band width");
    adapt_interval   = prm.get_integer("Adapt interval");
    curvature_levels = prm.get_integer("Curvature refinement levels");
    cells_per_curvature_radius = prm.get_double("Cells per curvature radius");
    prm.leave_subsection();
    if (max_level + curvature_levels > 20)
      fail_entry("Mesh refinement/Curvature refinement levels",
                 "Maximum level + Curvature refinement levels must not "
                 "exceed 20");
    if (max_level < min_level)
      fail_entry("Mesh refinement/Maximum level",
                 "must be at least the minimum level (" +
                   std::to_string(min_level) + ")");
  }
} // namespace levelsinter
