#include <levelsinter/scene/geometry_parameters.h>
#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/particles.h>

namespace levelsinter
{
  void
  GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry(
        "Shape",
        "particles",
        Patterns::Selection("particles|slotted disk|perturbed particle"),
        "What the solid is at t = 0: the union of the particles, "
        "Zalesak's slotted disk (2D only; for the transport benchmark), or "
        "the first particle with its radius modulated by one mode "
        "(r = R(1 + delta cos n theta) in 2D, R(1 + delta P_n(cos theta)) "
        "in 3D; the Mullins test of surface diffusion).");
      prm.declare_entry("Perturbation amplitude",
                        "0.05",
                        Patterns::Double(-0.5, 0.5),
                        "delta of the perturbed particle, relative to R "
                        "(either sign; no unit).");
      prm.declare_entry("Perturbation mode",
                        "2",
                        Patterns::Integer(0),
                        "n of the perturbed particle.");
      prm.declare_entry(
        "Particles",
        "",
        Patterns::Anything(),
        "Inline particles 'x, y[, z], r' separated by ';', e.g. "
        "'0.3, 0.5, 0.2; 0.7, 0.5, 0.2' (same length unit as the domain). "
        "May be combined with a particle file. Two particles must not have "
        "the same centre, and each radius must span at least 2 cells of "
        "the band (Mesh refinement/Maximum level).");
      prm.declare_entry(
        "Particle file",
        "",
        Patterns::Anything(),
        "CSV file of particles (same length unit as the domain): a header "
        "line naming the columns x, y, r (2D) or x, y, z, r (3D) in any "
        "order (case and spaces ignored), then one particle per line. "
        "Relative paths are relative to the scene file. Blank lines and "
        "lines starting with '#' are ignored.");
      prm.declare_entry("Slotted disk centre",
                        "0.5, 0.75",
                        Patterns::Anything(),
                        "Centre of Zalesak's disk (same length unit as the "
                        "domain).");
      prm.declare_entry("Slotted disk radius",
                        "0.15",
                        Patterns::Double(0),
                        "Radius of Zalesak's disk (same length unit as the "
                        "domain).");
      prm.declare_entry("Slot width",
                        "0.05",
                        Patterns::Double(0),
                        "Width of the slot, centred on the disk's vertical "
                        "axis (same length unit as the domain).");
      prm.declare_entry("Slot depth",
                        "0.25",
                        Patterns::Double(0),
                        "Depth of the slot, measured from the bottom of the "
                        "disk upward (same length unit as the domain).");
    }
    prm.leave_subsection();
  }

  void
  GeometryParameters::parse(ParameterHandler       &prm,
                            const unsigned int      d,
                            const std::string      &scene_directory,
                            const DomainParameters &domain)
  {
    prm.enter_subsection("Geometry");
    shape = read_selection<Shape>(
      prm,
      "Geometry",
      "Shape",
      {{"particles", Shape::particles},
       {"slotted disk", Shape::slotted_disk},
       {"perturbed particle", Shape::perturbed_particle}});
    particles =
      parse_inline_particles(prm.get("Particles"), d, "Geometry/Particles");
    particle_file = prm.get("Particle file");
    if (!particle_file.empty())
      {
        if (particle_file.front() != '/' && !scene_directory.empty())
          particle_file = scene_directory + "/" + particle_file;
        const auto from_file = read_particle_file(particle_file, d);
        particles.insert(particles.end(), from_file.begin(), from_file.end());
      }
    if (shape == Shape::slotted_disk)
      slotted_disk_centre =
        read_coordinates(prm, "Geometry", "Slotted disk centre", 2);
    slotted_disk_radius    = prm.get_double("Slotted disk radius");
    slot_width             = prm.get_double("Slot width");
    slot_depth             = prm.get_double("Slot depth");
    perturbation_amplitude = prm.get_double("Perturbation amplitude");
    perturbation_mode      = prm.get_integer("Perturbation mode");
    prm.leave_subsection();

    if (shape == Shape::perturbed_particle && particles.size() != 1)
      fail_entry("Geometry/Particles",
                 "Shape = perturbed particle needs exactly one particle");
    if (shape == Shape::slotted_disk)
      {
        if (d != 2)
          fail_entry("Geometry/Shape", "'slotted disk' exists in 2D only");
        if (slot_width >= 2 * slotted_disk_radius ||
            slot_depth >= 2 * slotted_disk_radius)
          fail_entry("Geometry/Slot width",
                     "slot width and depth must be smaller than the disk "
                     "diameter");
        check_particles_in_domain({{slotted_disk_centre[0],
                                    slotted_disk_centre[1],
                                    slotted_disk_radius}},
                                  domain.lower_corner,
                                  domain.upper_corner);
        return;
      }
    if (particles.empty())
      fail_entry("Geometry/Particles",
                 "the scene has no particle: give 'Particles' or 'Particle "
                 "file'");
    check_distinct_centres(particles);
    check_particles_in_domain(particles,
                              domain.lower_corner,
                              domain.upper_corner);
  }
} // namespace levelsinter
