#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <levelsinter/level_set/level_set_field.h>
#include <levelsinter/level_set/level_set_filter.h>

#include <array>
#include <string>
#include <vector>

namespace levelsinter
{
  using namespace dealii;

  /**
   * The normal pressure gradient xi on the interface (paper Eq. 110-111),
   * Q1 on the level set's DoFs:
   *
   *   xi = grad p . N      at the nodes deeper than lambda in the solid,
   *   N . grad xi = 0      elsewhere in the band (SUPG, Eq. 72-73),
   *
   * N the nodal unit normals of Eq. 84 (nodal_normals(), from the distance):
   * continuous, so the extension follows well-defined characteristics, and
   * the same N that carries the velocity v = -C_v xi N of Eq. 112. The
   * pressure is discontinuous across the interface (Laplace's jump, smeared
   * over a few cells by the continuous approximation and the ASGS
   * stabilisation), so its gradient is only read where every cell around a
   * node lies clear of that smear: d < -((lambda - 1) h_min + h_K) for
   * every cell K at the node, lambda = `interior offset` (lambda h on a
   * uniform mesh; the derivation is in doc/numerics.md, "Volume
   * diffusion"). The values are
   * carried outwards along N across the interface and to the band's outer
   * edge. Carried as they are (Eq. 111), the interface sees grad p . N
   * taken lambda deeper, a first-order error -lambda d(xi)/dn; with
   * linear extrapolation the normal derivative eta of the source values
   * is carried too and xi = (g - d eta) + d eta along each characteristic
   * (Aslam 2004), second order (doc/numerics.md).
   *
   * Where the solid is thinner than about 2 lambda (a young neck), no
   * characteristic from the interface reaches a source node. A reaction
   * term keeps the system regular there, a second solve with data 1 (the
   * reach) tells those nodes apart and divides the reaction's decay out
   * elsewhere; xi = 0 where nothing is reached (no volume-diffusion speed
   * where it cannot be measured), and unsourced_interface_cells() counts
   * the interface cells concerned so that the caller can warn.
   */
  template <int dim>
  class NormalGradientExtension
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    struct Settings
    {
      // lambda in cell sizes: a node is a source if d < -((lambda - 1)
      // h_min + h_K) for every cell K at it. 6: `Volume diffusion/Interior
      // offset`'s default; the xi tests set their own (3).
      double       interior_offset = 6;
      // Carry g - d eta and eta = d g / dn along N and add them up as
      // xi = (g - d eta) + d eta at each node (linear extrapolation, second
      // order), or g alone (the paper's constant extension, first order).
      bool         linear_extrapolation = true;
      // With linear_extrapolation: bound the carried correction at each
      // source, |d eta| <= c |g| (c in normal_gradient_extension.cc), so
      // that the extrapolation cannot feed a grid-scale ridge of xi
      // (doc/numerics.md, "Volume diffusion: the normal pressure
      // gradient", limited extrapolation).
      bool         limited_extrapolation = false;
      // grad p at a node: the average of the cells' gradients at the vertex
      // (false), or recovered by a lumped L2 projection over the solid part
      // of the cells (add_solid_gradient_projection()), which reads no
      // atmosphere and allows interior_offset = 0 (every solid node a
      // source).
      bool         recovered_gradient = false;
      // xi read on the interface itself as the pressure's boundary flux
      // (add_boundary_flux(), Green's formula for a harmonic p) at the
      // solid's nodes with interface support, carried along N outwards and
      // along -N inwards; interior_offset, linear_extrapolation and
      // recovered_gradient are then not read.
      bool         boundary_flux = false;
      // Normals from the distance filter^-1(alpha) (second order in h).
      bool         normals_from_distance = true;
      double       solver_tolerance      = 1e-10;
      unsigned int max_iterations        = 1000;
      // Box faces across which the level set continues as its mirror image.
      std::vector<types::boundary_id> symmetry_boundaries;
    };

    NormalGradientExtension(const LevelSetFilter &filter,
                            const Settings       &settings,
                            TimerOutput          &timer);

    /** Size xi for the level set's DoFs; after each remesh. */
    void
    setup(const LevelSetField<dim> &level_set);

    /**
     * Compute xi for the pressure given as component @p component of the
     * finite-element field @p field (ghosted) on @p field_dofs, a
     * DoFHandler on the level set's triangulation (e.g. component dim of
     * the Q1^dim x Q1 Stokes system). Returns the GMRES iterations; throws
     * std::runtime_error if the solver fails or no node lies deeper than
     * lambda in the solid.
     */
    unsigned int
    solve(const LevelSetField<dim> &level_set,
          const DoFHandler<dim>    &field_dofs,
          const unsigned int        component,
          const Vector             &field);

    /** xi (ghosted) on the level set's DoFs. */
    const Vector &
    normal_gradient() const
    {
      return xi;
    }

    /** The nodal unit normals N used (Eq. 84), one ghosted vector per axis. */
    const std::array<Vector, dim> &
    nodal_normals() const
    {
      return normals;
    }

    /**
     * The volume-diffusion velocity -C_v xi_i N_i (Eq. 112) at the level-set
     * DoF @p i (locally relevant), for the coefficient C_v of
     * VolumeDiffusionParameters.
     */
    Tensor<1, dim>
    velocity(const types::global_dof_index i, const double coefficient) const;

    /**
     * Interface cells (alpha changes sign) with a vertex that no
     * characteristic from a source node reaches (all ranks): where the
     * solid is too thin for the offset lambda, xi is set to 0.
     */
    unsigned int
    unsourced_interface_cells() const
    {
      return unsourced_cells;
    }

  private:
    // Marks the source nodes, their nodal grad p in @p gradient and
    // g = grad p . N in @p values; the other nodes get 0.
    void
    compute_sources(const LevelSetField<dim> &level_set,
                    const DoFHandler<dim>    &field_dofs,
                    const unsigned int        component,
                    const Vector             &field,
                    Vector                   &is_source,
                    Vector                   &values,
                    std::array<Vector, dim>  &gradient);

    // At the source nodes, the normal derivative eta = dg/dn from the cells
    // whose vertices are all sources, and g - d eta in @p values, d the
    // distance; source nodes without such a cell stop being sources.
    void
    compute_slopes(const LevelSetField<dim>      &level_set,
                   const std::array<Vector, dim> &gradient,
                   Vector                        &is_source,
                   Vector                        &values,
                   Vector                        &slopes) const;

    // boundary_flux: the source nodes are those whose shape function has
    // enough interface support; g = xi_i there (add_boundary_flux()).
    void
    compute_flux_sources(const LevelSetField<dim> &level_set,
                         const DoFHandler<dim>    &field_dofs,
                         const unsigned int        component,
                         const Vector             &field,
                         Vector                   &is_source,
                         Vector                   &values) const;

    // Rows of the nodes with @p fixed > 0 keep the data (Dirichlet).
    void
    assemble(const LevelSetField<dim> &level_set, const Vector &fixed);

    // After a failed solve of the assembled matrix for @p rhs: where the
    // residual of @p solution is largest (all ranks) and what that meant
    // where it was measured, for the error message.
    std::string
    worst_row(const LevelSetField<dim> &level_set,
              const Vector             &rhs,
              const Vector             &solution) const;

    // Assemble with the current normals and carry each of @p data along
    // them; returns the GMRES iterations.
    unsigned int
    carry(const LevelSetField<dim>           &level_set,
          const Vector                       &fixed,
          const std::vector<const Vector *>  &data,
          std::vector<Vector>                &solutions);

    // boundary_flux: carry the interface values outwards along N to the
    // nodes with d >= 0 and inwards along -N to those with d < 0; xi and
    // the reach of each node from the side it lies on.
    unsigned int
    carry_both_ways(const LevelSetField<dim> &level_set,
                    const Vector             &is_source,
                    const Vector             &values,
                    Vector                   &owned_xi,
                    Vector                   &reach);

    const LevelSetFilter              filter;
    const Settings                    settings;
    TimerOutput                      &timer;
    TrilinosWrappers::SparseMatrix    matrix;
    TrilinosWrappers::PreconditionILU preconditioner;
    std::array<Vector, dim>           normals;
    Vector                            xi;
    unsigned int                      unsourced_cells = 0;
  };
} // namespace levelsinter
