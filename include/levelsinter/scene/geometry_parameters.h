#pragma once

#include <deal.II/base/parameter_handler.h>

#include <levelsinter/scene/domain_parameters.h>

#include <map>
#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /** The `Geometry` subsection: the solid at t = 0. */
  struct GeometryParameters
  {
    enum class Shape
    {
      particles,
      slotted_disk,
      // The first particle, radius modulated by one mode (Mullins test of
      // surface diffusion).
      perturbed_particle,
      // Hopper's exact coalescence shape with the neck of the two equal
      // circles of `Particles` (2D).
      hopper
    };

    static void
    declare(ParameterHandler &prm);

    /**
     * Read the entries and the particle file (relative to
     * @p scene_directory), check the particles against each other and
     * against @p domain; throws std::runtime_error naming the entry.
     */
    void
    parse(ParameterHandler       &prm,
          const unsigned int      dimension,
          const std::string      &scene_directory,
          const DomainParameters &domain);

    /**
     * Whether the particles are the bodies whose necks and centres the
     * metrics follow (Shape = particles or hopper).
     */
    bool
    particles_are_bodies() const;

    Shape shape = Shape::particles;
    // A 2D scene that stands for a body of revolution about x = 0 (x = r,
    // y = z; SceneMeasure).
    bool axisymmetric = false;
    // Inline particles and the particle file are merged: x, y[, z], r.
    std::vector<std::vector<double>> particles;
    std::string                      particle_file;
    // Where each particle was given, for errors: "entry
    // 'Geometry/Particles', item 2" or "particle file 'F', line 14".
    std::vector<std::string> particle_origins;
    // The solid of Shape = particles is the union of the particles, the
    // superellipses and the implicit function's solid, minus the pores and
    // elliptic pores.
    // Inline pores and the pore file, merged: x, y[, z], r.
    std::vector<std::vector<double>> pores;
    std::string                      pore_file;
    // Ellipses (p = 2) and superellipses: rows of parse_superellipses().
    std::vector<std::vector<double>> superellipses;
    std::vector<std::vector<double>> elliptic_pores;
    // f(x, y[, z]) < 0 inside; empty: none.
    std::string                      implicit_function;
    std::map<std::string, double>    implicit_constants;
    std::vector<double>              slotted_disk_centre;
    double                           slotted_disk_radius    = 0;
    double                           slot_width             = 0;
    double                           slot_depth             = 0;
    double                           perturbation_amplitude = 0;
    unsigned int                     perturbation_mode      = 2;
  };
} // namespace levelsinter
