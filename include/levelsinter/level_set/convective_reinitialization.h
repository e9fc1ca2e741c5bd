#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>
#include <levelsinter/level_set/velocity_field.h>

namespace levelsinter
{
  /**
   * One time step of the filtered level set's transport with convective
   * reinitialisation (paper Eq. 68):
   *
   *   d alpha/dt + (v + lambda v_r) . grad alpha = lambda sgn(alpha) g(alpha),
   *
   * lambda = h / dt (times a strength and the step's share of it, 1 or
   * v dt / h_min; h the finest cell size, or in the solid optionally the
   * band's), v_r = sgn(alpha) grad alpha /
   * |grad alpha| and g the filter's gradient-norm target (Eq. 67). As in
   * the paper, v_r and the right-hand side are taken from the previous step
   * (linearisation), the sign is smoothed as
   * alpha / sqrt(alpha^2 + (h_K |grad alpha|)^2)
   * (Eq. 57 with eps = h_K, scaled so that it does not depend on the
   * gradient's size), and the equation is stabilised by SUPG (Eq. 72) with
   * the transient tau = ((2/dt)^2 + (2|w|/h_K)^2)^(-1/2), which reduces to
   * Eq. 73 (h_K / 2|w|) when the step is large. The transport term is
   * discretised with the theta method (0.5: Crank-Nicolson) where the paper
   * used explicit Euler: the reinitialisation velocity has a Courant number
   * of one by construction (lambda dt = h), which explicit Euler sits on the
   * edge of. An isotropic diffusion proportional to the reinitialisation
   * speed (zero on the interface) damps the checkerboard mode that SUPG
   * leaves undamped where streamlines run diagonal to the cells (see
   * doc/numerics.md). On the inflow part of the boundary alpha is set weakly to the
   * atmosphere's saturated value.
   */
  template <int dim>
  class ConvectiveReinitialization
  {
  public:
    struct Settings
    {
      double       theta            = 0.5;
      double       solver_tolerance = 1e-10;
      unsigned int max_iterations   = 1000;
      // lambda dt / h_min; the paper's choice is 1.
      double reinitialization_strength = 0.25;
      // c in the consistent diffusion nu = c (h_min / dt) h.
      double reinitialization_diffusion = 0.05;
      // delta: full reinitialisation where ||grad alpha| - g| >= delta.
      double reinitialization_tolerance = 0.25;
      // If positive, lambda's h in the solid: the cell size at the band's
      // level (`Maximum level`). 0: the finest cell everywhere.
      double solid_cell_size = 0;
      // false: the strength and the diffusion act per step. true: per time
      // the fastest interface point takes to cross the finest cell
      // (reinitialisation_share()).
      bool per_interface_motion = false;
    };

    ConvectiveReinitialization(const LevelSetFilter &filter,
                               const Settings       &settings,
                               TimerOutput          &timer);

    /** Take the finest cell size of the current mesh; after each remesh. */
    void
    setup_system(const LevelSetField<dim> &level_set);

    /**
     * The share of the full strength and diffusion that a step of dt
     * applies: 1 per step; per interface motion min(1, v dt / h_min), with
     * v the largest speed near the interface, so that the reinitialisation
     * per unit time does not depend on the step (doc/numerics.md).
     */
    double
    reinitialisation_share(const double dt, const double interface_speed) const;

    /**
     * Advance alpha by dt with the given velocity (evaluated by the caller
     * at the time the theta scheme needs). Returns the GMRES iterations;
     * throws if the solver fails. @p share scales the reinitialisation's
     * strength and diffusion (reinitialisation_share()); 0 makes the step
     * pure transport (a small correction after a step that has already
     * been reinitialised: the reinitialisation moves the interface by a
     * fixed amount per call, so a second one per step costs accuracy).
     */
    unsigned int
    advance(LevelSetField<dim>       &level_set,
            const VelocityField<dim> &velocity,
            const double              dt,
            const double              share);

  private:
    void
    assemble(const LevelSetField<dim>       &level_set,
             const VelocityField<dim>       &velocity,
             const double                    dt,
             const double                    share,
             TrilinosWrappers::MPI::Vector &rhs);

    const LevelSetFilter             filter;
    const Settings                   settings;
    TimerOutput                     &timer;
    TrilinosWrappers::SparseMatrix   matrix;
    TrilinosWrappers::PreconditionILU preconditioner;
    double                            h_min = 0;
  };
} // namespace levelsinter
