#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/volume_correction_parameters.h>

namespace levelsinter
{
  void
  VolumeCorrectionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume correction");
    prm.declare_entry(
      "Enabled",
      "auto",
      Patterns::Selection("auto|true|false"),
      "Add to the velocity of the other mechanisms the uniform normal speed "
      "v^c of Eq. 113-116 that gives back, over each step, the solid volume "
      "gained or lost since t = 0 (by the scheme, the transport and the "
      "remeshing alike). auto: on with viscous flow under a tensorial "
      "surface-tension form (sharp, csf), which loses solid area at first "
      "order in h through the pressure stabilisation (a resting bubble 1e-3 "
      "of its area per step at R/h = 8, doc/validation.md), off otherwise.");
    prm.leave_subsection();
  }

  void
  VolumeCorrectionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Volume correction");
    choice = read_selection<Choice>(prm,
                                    "Volume correction",
                                    "Enabled",
                                    {{"auto", Choice::automatic},
                                     {"true", Choice::on},
                                     {"false", Choice::off}});
    prm.leave_subsection();
  }
} // namespace levelsinter
