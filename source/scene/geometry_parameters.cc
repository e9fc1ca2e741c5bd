#include <levelsinter/scene/geometry_parameters.h>
#include <levelsinter/scene/hopper.h>
#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/particles.h>
#include <levelsinter/scene/solid_geometry.h>

#include <sstream>

namespace levelsinter
{
  namespace
  {
    // Shape = hopper: two equal overlapping circles in 2D, and Hopper's
    // shape of them inside the domain.
    void
    check_hopper_pair(const std::vector<std::vector<double>> &particles,
                      const unsigned int                      d,
                      const bool                              axisymmetric,
                      const DomainParameters                 &domain)
    {
      if (d != 2 || axisymmetric)
        fail_entry("Geometry/Shape",
                   "'hopper' is the plane shape of two cylinders: it needs "
                   "'Dimension = 2' without 'Axisymmetric'");
      if (particles.size() != 2 || particles[0][2] != particles[1][2])
        fail_entry("Geometry/Particles",
                   "Shape = hopper needs exactly two particles of the same "
                   "radius");
      const HopperPair pair(particles);
      if (!pair.overlapping())
        fail_entry("Geometry/Particles",
                   "Shape = hopper: the two circles must overlap (centre "
                   "distance between 0 and 2 r): their overlap gives the "
                   "neck");
      const Point<2>     &centre = pair.centre;
      const Tensor<1, 2> &e      = pair.direction;
      // The shape is symmetric about its line of centres and its neck
      // line: if they lie along the axes, it may cross a face through its
      // centre (a symmetry plane).
      const bool  aligned = std::abs(e[0] * e[1]) < 1e-12;
      const auto &lo = domain.lower_corner, &hi = domain.upper_corner;
      for (const Point<2> &q : Hopper(pair.R).boundary(pair.m(), 720))
        {
          const Point<2> x(centre[0] + e[0] * q[0] - e[1] * q[1],
                           centre[1] + e[1] * q[0] + e[0] * q[1]);
          for (unsigned int k = 0; k < 2; ++k)
            {
              const double tol     = 1e-12 * (hi[k] - lo[k]);
              const auto   on_face = [&](const double face) {
                return aligned && std::abs(centre[k] - face) <= tol;
              };
              if ((x[k] < lo[k] - tol && !on_face(lo[k])) ||
                  (x[k] > hi[k] + tol && !on_face(hi[k])))
                {
                  std::ostringstream point;
                  point << x[0] << ", " << x[1];
                  fail_entry("Geometry/Particles",
                             "Shape = hopper: Hopper's shape of these "
                             "circles reaches (" +
                               point.str() +
                               ") outside the domain (the shape is longer "
                               "than the two circles)");
                }
            }
        }
    }
  } // namespace

  bool
  GeometryParameters::particles_are_bodies() const
  {
    return shape == Shape::particles || shape == Shape::hopper;
  }

  void
  GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry(
        "Shape",
        "particles",
        Patterns::Selection("particles|slotted disk|perturbed particle|"
                            "hopper"),
        "What the solid is at t = 0: the union of the particles, "
        "Zalesak's slotted disk (2D only; for the transport benchmark), "
        "Hopper's exact shape of two coalescing cylinders (2D only: the "
        "two equal circles of 'Particles' give the radius R, the centre, "
        "the line of centres and the neck half-width, that of their "
        "overlap; viscous sintering from an exact start), or "
        "the first particle with its radius modulated by one mode "
        "(r = R(1 + delta cos n theta) in 2D, R(1 + delta P_n(cos theta)) "
        "in 3D and on an axisymmetric scene, theta from the z axis or the "
        "axis of revolution; the Mullins test of surface diffusion).");
      prm.declare_entry(
        "Axisymmetric",
        "false",
        Patterns::Bool(),
        "2D only: the scene is a body of revolution about the line x = 0 "
        "(x is the distance r from the axis, y the axial coordinate z), so "
        "that two spheres on the axis cost a 2D run. 'Domain/Lower corner' "
        "must have x = 0; the axis then acts as a symmetry plane (v_r = 0 "
        "there; listing 'x-' in 'Domain/Symmetry planes' is allowed and "
        "changes nothing). Particles are centred on the axis or do not "
        "reach it (rings). Volumes, areas and every integral the metrics "
        "report are those of the 3D body. Viscous flow (Newtonian, every "
        "surface tension form), surface diffusion and a prescribed "
        "velocity are available; volume diffusion is not yet.");
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
        "Relative paths are relative to the scene file (what a scene "
        "reads is found beside it; Output/Directory, what a run writes, "
        "is relative to the working directory). Blank lines and "
        "lines starting with '#' are ignored.");
      prm.declare_entry(
        "Pores",
        "",
        Patterns::Anything(),
        "Balls cut out of the solid (holes inside or between particles), "
        "'x, y[, z], r' separated by ';' as for 'Particles'. May be combined "
        "with a pore file.");
      prm.declare_entry("Pore file",
                        "",
                        Patterns::Anything(),
                        "CSV file of pores, in the form of the particle "
                        "file.");
      prm.declare_entry(
        "Ellipses",
        "",
        Patterns::Anything(),
        "Ellipses (ellipsoids in 3D) added to the solid, separated by ';': "
        "'x, y, a, b, angle' in 2D (centre, semi-axes along the body's x "
        "and y, and the angle in degrees from the x axis to the body's x "
        "axis, counterclockwise); 'x, y, z, a, b, c, angle_x, angle_y, "
        "angle_z' in 3D (the body turned about x, then y, then z, in "
        "degrees).");
      prm.declare_entry(
        "Superellipses",
        "",
        Patterns::Anything(),
        "Superellipses |x'/a|^p + |y'/b|^p = 1 (superellipsoids in 3D, "
        "+ |z'/c|^p) added to the solid, as 'Ellipses' with the exponent p "
        "(at least 2) after the semi-axes: 'x, y, a, b, p, angle' in 2D, "
        "'x, y, z, a, b, c, p, angle_x, angle_y, angle_z' in 3D.");
      prm.declare_entry("Elliptic pores",
                        "",
                        Patterns::Anything(),
                        "Ellipses (ellipsoids) cut out of the solid, in the "
                        "form of 'Ellipses'.");
      prm.declare_entry(
        "Implicit function",
        "",
        Patterns::Anything(),
        "A solid added to the others: the region where this function of "
        "x, y[, z] is negative (muparser syntax, e.g. "
        "'x^4 + y^4 - 0.2^4'). Its zero set is the surface; the level set "
        "is built from the distance to it.");
      prm.declare_entry("Implicit function constants",
                        "",
                        Patterns::Anything(),
                        "Constants of the implicit function, 'name = value' "
                        "separated by ','; pi is defined.");
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
       {"perturbed particle", Shape::perturbed_particle},
       {"hopper", Shape::hopper}});
    particles =
      parse_inline_particles(prm.get("Particles"), d, "Geometry/Particles");
    particle_origins.clear();
    for (unsigned int i = 0; i < particles.size(); ++i)
      particle_origins.push_back("entry 'Geometry/Particles', item " +
                                 std::to_string(i + 1));
    particle_file = prm.get("Particle file");
    if (!particle_file.empty())
      {
        if (particle_file.front() != '/' && !scene_directory.empty())
          particle_file = scene_directory + "/" + particle_file;
        std::vector<unsigned int> lines;
        const auto                from_file =
          read_particle_file(particle_file, d, "particle", &lines);
        particles.insert(particles.end(), from_file.begin(), from_file.end());
        for (const unsigned int line : lines)
          particle_origins.push_back("particle file '" + particle_file +
                                     "', line " + std::to_string(line));
      }
    pores = parse_inline_particles(prm.get("Pores"),
                                   d,
                                   "Geometry/Pores",
                                   "pore");
    pore_file = prm.get("Pore file");
    if (!pore_file.empty())
      {
        if (pore_file.front() != '/' && !scene_directory.empty())
          pore_file = scene_directory + "/" + pore_file;
        const auto from_file = read_particle_file(pore_file, d, "pore");
        pores.insert(pores.end(), from_file.begin(), from_file.end());
      }
    // Each list is checked against the domain as read, so that an error
    // names the entry and the item.
    const auto read_shapes = [&](const std::string &entry,
                                 const bool         with_exponent) {
      const auto rows = parse_superellipses(prm.get(entry),
                                            d,
                                            with_exponent,
                                            "Geometry/" + entry);
      (d == 2 ? check_superellipses_in_domain<2> :
                check_superellipses_in_domain<3>)(rows,
                                                  domain.lower_corner,
                                                  domain.upper_corner,
                                                  "Geometry/" + entry);
      return rows;
    };
    superellipses      = read_shapes("Ellipses", false);
    const auto super   = read_shapes("Superellipses", true);
    superellipses.insert(superellipses.end(), super.begin(), super.end());
    elliptic_pores     = read_shapes("Elliptic pores", false);
    implicit_function  = prm.get("Implicit function");
    implicit_constants = parse_constants(
      prm.get("Implicit function constants"),
      "Geometry/Implicit function constants");
    if (shape == Shape::slotted_disk)
      slotted_disk_centre =
        read_coordinates(prm, "Geometry", "Slotted disk centre", 2);
    slotted_disk_radius    = prm.get_double("Slotted disk radius");
    slot_width             = prm.get_double("Slot width");
    slot_depth             = prm.get_double("Slot depth");
    perturbation_amplitude = prm.get_double("Perturbation amplitude");
    perturbation_mode      = prm.get_integer("Perturbation mode");
    axisymmetric           = prm.get_bool("Axisymmetric");
    prm.leave_subsection();

    if (axisymmetric)
      {
        if (d != 2)
          fail_entry("Geometry/Axisymmetric",
                     "needs 'Dimension = 2': the scene's x and y are the "
                     "radius r and the axial coordinate z of a body of "
                     "revolution");
        if (domain.lower_corner[0] != 0)
          {
            std::ostringstream x;
            x << domain.lower_corner[0];
            fail_entry("Geometry/Axisymmetric",
                       "the axis is the domain's lower x face: 'Domain/Lower "
                       "corner' must have x = 0 (x is the distance r from "
                       "the axis), not " +
                         x.str());
          }
        // A disk across the axis but off it turns into a body with an edge
        // on the axis, which the level set cannot carry.
        for (const auto *list : {&particles, &pores})
          for (unsigned int i = 0; i < list->size(); ++i)
            {
              const auto &ball = (*list)[i];
              if (ball[0] != 0 && ball[0] < ball[2])
                fail_entry(list == &particles ? "Geometry/Particles" :
                                                "Geometry/Pores",
                           std::string(list == &particles ? "particle " :
                                                            "pore ") +
                             std::to_string(i + 1) +
                             " reaches across the axis x = 0 without being "
                             "centred on it: with 'Axisymmetric = true' a "
                             "ball is centred on the axis (x = 0, a "
                             "sphere) or lies off it (x >= r, a ring)");
            }
      }

    const bool general_solid = !pores.empty() || !superellipses.empty() ||
                               !elliptic_pores.empty() ||
                               !implicit_function.empty();
    if (shape != Shape::particles && general_solid)
      fail_entry("Geometry/Shape",
                 "pores, ellipses, superellipses and implicit functions "
                 "describe the solid of Shape = particles only");
    if (shape == Shape::perturbed_particle && particles.size() != 1)
      fail_entry("Geometry/Particles",
                 "Shape = perturbed particle needs exactly one particle");
    if (shape == Shape::hopper)
      {
        // The circles only give the pair: the solid is Hopper's shape.
        check_hopper_pair(particles, d, axisymmetric, domain);
        return;
      }
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
    if (particles.empty() && superellipses.empty() &&
        implicit_function.empty())
      fail_entry("Geometry/Particles",
                 "the scene has no solid: give 'Particles', 'Particle file', "
                 "'Ellipses', 'Superellipses' or 'Implicit function'");
    const auto &lo = domain.lower_corner, &hi = domain.upper_corner;
    check_particles_in_domain(particles, lo, hi);
    check_particles_in_domain(pores, lo, hi, "pore");
    if (!implicit_function.empty())
      (d == 2 ? check_implicit_function<2> : check_implicit_function<3>)(
        implicit_function,
        implicit_constants,
        lo,
        hi,
        "Geometry/Implicit function");
  }
} // namespace levelsinter
