#pragma once

#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/geometry/grain_boundaries.h>
#include <levelsinter/mechanisms/mechanism.h>
#include <levelsinter/mechanisms/surface_diffusion.h>
#include <levelsinter/scene/grain_boundary_parameters.h>

#include <limits>
#include <map>
#include <vector>

namespace levelsinter
{
  /**
   * Grain-boundary diffusion between rigid grains (doc/numerics.md, "Grain
   * boundaries and densification"): each particle is a grain, the solid in
   * the power cell of its moving centre. Each step finds the grain
   * boundaries, reads the neck-root curvature of the surface-diffusion
   * solve, solves the force balance of all grains together for their
   * velocities (the contact law N = G gamma_s u / C_gb - gamma_s (P
   * sin(psi/2) - A kappa_root) of Bouvard and McMeeking), and adds to the
   * interface velocity each grain's rigid velocity in its cell and the
   * deposition, at the triple lines, of the matter the approach takes out
   * of the grain boundaries. Built after SurfaceDiffusion, whose solve of
   * the same step it reads.
   */
  template <int dim>
  class GrainBoundaryDiffusion : public Mechanism<dim>
  {
  public:
    GrainBoundaryDiffusion(const GrainBoundaryParameters          &parameters,
                           const std::vector<std::vector<double>> &particles,
                           const double                 seconds_per_time_unit,
                           SurfaceDiffusion<dim>       &surface_diffusion,
                           TimerOutput                 &timer);

    std::string
    name() const override
    {
      return "grain-boundary diffusion";
    }

    /** Nothing lives on the mesh: the grains' state is their centres. */
    void
    setup(const LevelSetField<dim> &) override
    {}

    void
    add_velocity(const LevelSetField<dim> &alpha,
                 const double              t,
                 const double              dt,
                 VelocityField<dim>       &velocity) override;

    void
    add_probe_velocity(const LevelSetField<dim> &alpha,
                       const double              t,
                       VelocityField<dim>       &velocity) override;

    /**
     * The centres move by the trial's velocities times its dt; with
     * `Conserve grain volumes` the weights are then corrected
     * (balance_volumes()).
     */
    void
    accept_step(const LevelSetField<dim> &alpha) override;

    /**
     * No grain boundary closes, and no deposition moves the surface, by
     * more than half a finest cell in a step (the last velocities); with
     * the implicit contact law, which is stable at any step, by more than
     * accuracy_fraction of a cell (doc/numerics.md, "Settling: the step's
     * accuracy").
     */
    double
    time_step_limit(const LevelSetField<dim> &alpha) const override;

    /** The centres, weights and volumes at t = 0 of the grains. */
    std::string
    save() const override;

    void
    load(const std::string &state) override;

    /** grain_boundary_diffusion_grain_id and _boundary (cell fields). */
    void
    add_output_fields(const LevelSetField<dim> &alpha,
                      DataOut<dim>             &data_out) const override;

    /** A grain boundary of the last velocity computation and its flux. */
    struct Contact
    {
      grain_geometry::GrainBoundary<dim> boundary;
      // The kernel's mean of the surface's curvature about the triple line.
      double root_curvature = 0;
      // With the sharp condition, the same mean of the explicit curvature
      // div N + mu, free of the kappa row's dt term (doc/numerics.md, "The
      // root curvature's bias"); a measurement, the law reads
      // root_curvature. NaN without the condition.
      double explicit_root_curvature = std::numeric_limits<double>::quiet_NaN();
      // u = (V_i - V_j) . n, positive when the grains approach.
      double approach_rate = 0;
      // With the implicit contact law, g = C_gb S dt / G: the law is (1 +
      // g) G u = C_gb F (doc/numerics.md, "Settling: the implicit contact
      // law"); 0 for the explicit law.
      double damping = 0;
    };

    const std::vector<Contact> &
    contacts() const
    {
      return last_contacts;
    }

    /** The grains at the accepted centres, with their weights r_i. */
    PowerCells<dim>
    grains() const;

    /** The accepted centres (the scene's particle centres at t = 0). */
    const std::vector<Point<dim>> &
    centres() const
    {
      return centre;
    }

    /** l: the half-width of the triple-line kernel (last computation). */
    double
    kernel_width() const
    {
      return deposition_width;
    }

  private:
    // The grain boundaries at the accepted centres on @p alpha.
    void
    find_boundaries(const LevelSetField<dim> &alpha);

    // With `Sharp contact radius`: each boundary's a (each end's in 2D)
    // moved from the rays' end to where the near circles of its grains'
    // surfaces meet its plane, by as much of the difference as is a
    // corner's filling (doc/numerics.md, "Settling: the sharp contact
    // radius").
    void
    move_to_sharp_triple_lines(const LevelSetField<dim> &alpha);

    // The triple-line condition's chemical potential mu on the level set's
    // DoFs (SurfaceDiffusion::set_potential_source), from the grain
    // boundaries it finds, which compute() of the same state then uses.
    void
    triple_line_potential(const LevelSetField<dim>      &alpha,
                          TrilinosWrappers::MPI::Vector &mu);

    // Per-grain materials: each node's factor of C_s (locally owned
    // entries of @p factor, on the level set's DoFs), for
    // SurfaceDiffusion::set_mobility_source.
    void
    surface_mobility_factors(const LevelSetField<dim>      &alpha,
                             TrilinosWrappers::MPI::Vector &factor) const;

    // The kernel w of @p boundary at the vertices of @p cell into @p w;
    // false if it is zero at all of them. With @p kink the sharp
    // condition's kernel (narrow across the plane, flat along it over the
    // band), else the deposition's.
    bool
    kernel_weights(const grain_geometry::GrainBoundary<dim>            &boundary,
                   const typename DoFHandler<dim>::active_cell_iterator &cell,
                   std::vector<double> &w,
                   const bool           kink = false) const;

    // Per boundary: int over the interface of I_h(w N) . n, I_h(w kappa)
    // (N and kappa of @p geometry; zero without), I_h(w) and, with
    // @p explicit_curvature (and @p geometry), I_h(w) (div N + mu) (the
    // explicit curvature: N's divergence at the interface plus the
    // triple-line potential of the last triple_line_potential(); else
    // zero), w the kernel of kernel_weights(..., @p kink).
    std::vector<double>
    kernel_sums(const LevelSetField<dim>        &alpha,
                const MixedCurvatureSolver<dim> *geometry,
                const bool                       kink               = false,
                const bool                       explicit_curvature = false) const;

    // Grain boundaries, root curvatures and the trial velocities of a step
    // @p dt from the level set and the accepted centres.
    void
    compute(const LevelSetField<dim> &alpha, const double dt);

    // The radius r sin(psi/2) of the grain boundary of grains @p i and
    // @p j at their equilibrium, r the smaller grain's radius.
    double
    equilibrium_neck(const unsigned int i, const unsigned int j) const;

    // Stops the run, with what the model cannot represent, where a grain
    // boundary's equilibrium neck is narrower than the triple-line kernel
    // or a grain boundary has reached a grain's centre.
    void
    check_representable() const;

    // Reports the contacts the accepted trial lost (and warns of new ones
    // whose equilibrium neck is barely resolved), and keeps the trial's.
    void
    report_lost_contacts(const LevelSetField<dim> &alpha);

    // S = dF/d(delta): how much the approach delta = u dt of a step,
    // deposited at the triple line, lowers the driving force F of
    // @p boundary, from its kernel_sums() @p sum.
    double
    contact_stiffness(const grain_geometry::GrainBoundary<dim> &boundary,
                      const double                             *sum,
                      const double                              dt) const;

    // V_i from the balance of all grains (the contact laws of contacts),
    // the minimum-norm solution (SVD) so that each cluster's rigid
    // translation is zero.
    void
    solve_grain_velocities();

    void
    balance_volumes(const LevelSetField<dim> &alpha);

    // The rigid velocities and the deposition at the nodes, added to
    // @p velocity.
    void
    add_nodal_velocity(const LevelSetField<dim> &alpha,
                       VelocityField<dim>       &velocity) const;

    const GrainBoundaryParameters parameters;
    // C_gb in the scene's time unit.
    const double                  mobility;
    const SurfaceDiffusion<dim>  &surface_diffusion;
    TimerOutput                  &timer;
    std::vector<double>           radii;
    // The power cells' weights are r_i^2 + weight_shift[i].
    std::vector<double>           weight_shift;
    std::vector<double>           initial_volume;
    std::vector<Point<dim>>       centre;
    std::vector<Tensor<1, dim>>   trial_velocity;
    double                        trial_dt = 0;
    std::vector<Contact>          last_contacts;
    // The contacts (i, j) of the last accepted step and their approach
    // rates: a grain boundary that is no longer found is reported.
    std::map<std::pair<unsigned int, unsigned int>, double> accepted_contacts;
    // The start of the trial step, for that report.
    double trial_start_time = 0;
    std::vector<grain_geometry::GrainBoundary<dim>> boundaries;
    // Whether boundaries are those of the state compute() sees (found by
    // triple_line_potential() before the surface-diffusion solve).
    bool boundaries_current = false;
    // The triple-line potential mu of the last triple_line_potential()
    // (ghosted, on the level set's DoFs).
    TrilinosWrappers::MPI::Vector potential;
    // Per contact: the deposition speed per unit kernel weight, Q / W.
    std::vector<double>           deposition_speed;
    double                        deposition_width = 0;
    // The sharp condition's kernel: half-width across the plane (0: the
    // regularised condition) and its plateau along it (the band's E).
    double kink_width   = 0;
    double kink_plateau = 0;
    // The largest approach rate and deposition speed of the last compute().
    double max_speed = 0;
    double h_min     = 0;
    // The implicit law's step limit: the fraction of a finest cell a
    // contact's approach or deposition moves the surface in a step.
    static constexpr double accuracy_fraction = 0.03;
    mutable dealii::Vector<float> grain_id, boundary_indicator;
  };
} // namespace levelsinter
