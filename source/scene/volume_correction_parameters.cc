#include <levelsinter/scene/volume_correction_parameters.h>

namespace levelsinter
{
  void
  VolumeCorrectionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume correction");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Add to the velocity of the other mechanisms the "
                      "uniform normal speed v^c of Eq. 113-116 that gives "
                      "back, over each step, the solid volume gained or "
                      "lost since t = 0 (by the scheme, the transport and "
                      "the remeshing alike).");
    prm.leave_subsection();
  }

  void
  VolumeCorrectionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume correction");
    enabled = prm.get_bool("Enabled");
    prm.leave_subsection();
  }
} // namespace levelsinter
