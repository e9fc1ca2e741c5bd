#include <deal.II/base/mpi.h>

#include <levelsinter/level_set/cell_size.h>
#include <levelsinter/level_set/ghosted_vector.h>

#include <levelsinter/level_set/point_value.h>
#include <levelsinter/level_set/smoothed_heaviside.h>
#include <levelsinter/mechanics/viscoelastic_state.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace levelsinter
{
  ConformationModel::Parameters
  conformation_parameters(const PhaseLawParameters &law)
  {
    ConformationModel::Parameters p;
    p.law = law.law == PhaseLawParameters::Law::xpp ?
              ConformationModel::Law::xpp :
              ConformationModel::Law::giesekus;
    p.relaxation_time         = law.relaxation_time;
    p.modulus                 = law.polymer_viscosity / law.relaxation_time;
    p.mobility                = law.giesekus_mobility;
    p.stretch_relaxation_time = law.xpp_stretch_relaxation_time;
    p.arms                    = law.xpp_arms;
    return p;
  }

  template <int dim>
  ViscoelasticState<dim>::ViscoelasticState(
    const PhaseLawParameters &law,
    const LevelSetFilter     &filter,
    const double              interface_half_width,
    const unsigned int        band_level)
    : model(conformation_parameters(law))
    , filter(filter)
    , interface_half_width(interface_half_width)
    , band_level(band_level)
  {}

  template <int dim>
  void
  ViscoelasticState<dim>::setup(const LevelSetField<dim> &alpha)
  {
    // On the level set's DoFs, which outlive the mesh changes.
    if (!field)
      field = std::make_unique<ConformationField<dim>>(alpha.dof_handler(),
                                                       model,
                                                       alpha.measure());
    field->setup();
    pending = false;
    const auto  &tria  = alpha.dof_handler().get_triangulation();
    const double h_min = finest_cell_size(tria);
    const int finer = int(tria.n_global_levels()) - 1 - int(band_level);
    h_band          = h_min * (1u << std::max(0, finer));
  }

  template <int dim>
  void
  ViscoelasticState<dim>::advance(const LevelSetField<dim> &alpha,
                                  const VelocityField<dim> &velocity,
                                  const double              dt)
  {
    const TrilinosWrappers::MPI::Vector weight = stretch_weight(alpha);
    iterations = field->advance(velocity, dt, &weight);
    pending    = true;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  ViscoelasticState<dim>::stretch_weight(const LevelSetField<dim> &alpha) const
  {
    // The atmosphere carries c only so that it can be transported; its
    // fast flow would stretch c with nothing to resist it, and the
    // transition zone weighs that c with H_s > 0 (doc/numerics.md,
    // "Viscoelastic melts"). So the stretch is full where alpha <= 0 and
    // fades to none at 2E: H_s(alpha - E).
    const SmoothedHeaviside heaviside(interface_half_width * h_band);
    TrilinosWrappers::MPI::Vector owned(
      alpha.locally_owned(), alpha.dof_handler().get_communicator());
    for (const auto i : alpha.locally_owned())
      owned(i) = heaviside.solid_fraction(alpha.alpha()(i) -
                                          heaviside.half_width());
    return ghosted_from_owned(owned,
                              alpha.constraints(),
                              alpha.locally_relevant());
  }

  template <int dim>
  void
  ViscoelasticState<dim>::accept(const LevelSetField<dim> &alpha)
  {
    if (!pending)
      return;
    field->commit();
    const double saturation = 0.999 * filter.saturation();
    field->fade([&](const types::global_dof_index i) {
      return alpha.alpha()(i) < saturation ? 1. : 0.;
    });
    pending = false;

    const MPI_Comm comm = alpha.dof_handler().get_communicator();
    std::array<TrilinosWrappers::MPI::Vector, 4> owned;
    for (auto &v : owned)
      v.reinit(alpha.locally_owned(), comm);
    const auto         &s = field->log_conformation();
    std::vector<double> values(s.size());
    double              largest = 0;
    for (const auto i : alpha.locally_owned())
      {
        for (unsigned int k = 0; k < s.size(); ++k)
          values[k] = s[k](i);
        const SymmetricTensor<2, 3> c =
          ConformationField<dim>::conformation(values);
        owned[0](i) = trace(c);
        largest     = std::max(largest, double(owned[0](i)));
        const std::array<double, 3> lambda = eigenvalues(c);
        for (unsigned int d = 0; d < 3; ++d)
          owned[d + 1](i) = std::sqrt(lambda[d]);
      }
    for (unsigned int k = 0; k < owned.size(); ++k)
      (k == 0 ? trace_c : stretches[k - 1]) =
        ghosted_from_owned(owned[k],
                           alpha.constraints(),
                           alpha.locally_relevant());
    max_trace_c = Utilities::MPI::max(largest, comm);
  }

  template <int dim>
  void
  ViscoelasticState<dim>::add_state(StateTransfer<dim> &transfer)
  {
    field->add_state(transfer);
  }

  template <int dim>
  void
  ViscoelasticState<dim>::stress_values(
    const FEValues<dim>                  &level_set_values,
    std::vector<SymmetricTensor<2, dim>> &stress,
    std::vector<double>                  &hoop_stress) const
  {
    if (!field)
      throw std::logic_error(
        "ViscoelasticState: the polymer stress is read after setup()");
    field->stress_values(level_set_values, stress, hoop_stress);
  }

  template <int dim>
  std::vector<std::string>
  ViscoelasticState<dim>::metric_names() const
  {
    return {"viscoelastic_iterations", "viscoelastic_max_trace_c"};
  }

  template <int dim>
  std::vector<double>
  ViscoelasticState<dim>::metric_values() const
  {
    return {double(iterations), max_trace_c};
  }

  template <int dim>
  std::vector<std::string>
  ViscoelasticState<dim>::point_metric_names() const
  {
    return {"viscoelastic_trace_c"};
  }

  template <int dim>
  std::vector<double>
  ViscoelasticState<dim>::point_metric_values(const LevelSetField<dim> &alpha,
                                              const Point<dim> &point) const
  {
    if (trace_c.size() != alpha.dof_handler().n_dofs())
      return {3.};
    return {value_at_point<double>(
      alpha.dof_handler(),
      point,
      "tr c",
      [&](const auto &cell, const Point<dim> &unit) {
        FEValues<dim> values(alpha.dof_handler().get_fe(),
                             Quadrature<dim>(unit),
                             update_values);
        values.reinit(cell);
        std::vector<double> v(1);
        values.get_function_values(trace_c, v);
        return v[0];
      })};
  }

  template <int dim>
  void
  ViscoelasticState<dim>::add_output_fields(const LevelSetField<dim> &alpha,
                                            DataOut<dim> &data_out) const
  {
    if (trace_c.size() != alpha.dof_handler().n_dofs())
      return;
    data_out.add_data_vector(alpha.dof_handler(),
                             trace_c,
                             "viscoelastic_trace_c");
    for (unsigned int d = 0; d < 3; ++d)
      data_out.add_data_vector(alpha.dof_handler(),
                               stretches[d],
                               "viscoelastic_stretch_" +
                                 std::to_string(d + 1));
  }

  template class ViscoelasticState<2>;
  template class ViscoelasticState<3>;
} // namespace levelsinter
