#include <levelsinter/mechanics/stokes_terms.h>

namespace levelsinter
{
  template <int dim>
  StokesTerms<dim>::StokesTerms(const Settings &settings,
                                const double    surface_time_step)
    : settings(settings)
    , implicit_dt(settings.surface_tension != 0 ? surface_time_step : 0.)
    , load([&]() {
      using Form = typename TwoPhaseStokes<dim>::SurfaceTensionForm;
      if (settings.surface_tension == 0)
        return Load::none;
      if (settings.form == Form::csf_curvature)
        return Load::balanced_force;
      if (settings.form == Form::sharp_curvature)
        return Load::curvature;
      return Load::tensorial;
    }())
  {
    const double gamma = settings.surface_tension;
    bulk.push_back(std::make_unique<BulkAssembler<dim>>());
    bulk.push_back(std::make_unique<StabilisationAssembler<dim>>());
    if (load == Load::balanced_force)
      bulk.push_back(std::make_unique<BalancedForceAssembler<dim>>());
    else if (load == Load::curvature)
      surface.push_back(
        std::make_unique<CurvatureSurfaceTensionAssembler<dim>>(gamma));
    else if (load == Load::tensorial)
      surface.push_back(
        std::make_unique<TensorialSurfaceTensionAssembler<dim>>(gamma));
    if (implicit_dt > 0)
      surface.push_back(
        std::make_unique<LaplaceBeltramiAssembler<dim>>(gamma, implicit_dt));
    if (settings.external_pressure != 0)
      faces.push_back(
        std::make_unique<TractionAssembler<dim>>(settings.external_pressure));
  }

  template <int dim>
  void
  StokesTerms<dim>::set_inputs(
    typename StokesCellData<dim>::Inputs &inputs) const
  {
    using CellData = StokesCellData<dim>;
    using Form     = typename TwoPhaseStokes<dim>::SurfaceTensionForm;
    inputs.surface_tension = settings.surface_tension;
    // The surface loads and the Laplace-Beltrami term read the surface.
    if (load == Load::tensorial || load == Load::curvature || implicit_dt > 0)
      inputs.surface = settings.form == Form::sharp ||
                           settings.form == Form::sharp_curvature ?
                         CellData::SurfaceMeasure::sharp :
                         CellData::SurfaceMeasure::smeared;
    inputs.interface_half_width_cells = settings.interface_half_width_cells;
    inputs.band_level                 = settings.band_level;
    inputs.stabilisation_constant     = settings.stabilisation_constant;
    inputs.void_atmosphere            = settings.void_atmosphere;
    inputs.free_faces                 = !faces.empty();
    inputs.symmetry_boundaries        = settings.symmetry_boundaries;
  }

  template <int dim>
  void
  StokesTerms<dim>::assemble_bulk(const StokesCellData<dim> &data,
                                  CellContribution          &cell) const
  {
    for (const auto &assembler : bulk)
      assembler->assemble(data, cell);
  }

  template <int dim>
  void
  StokesTerms<dim>::assemble_surface(const StokesCellData<dim> &data,
                                     CellContribution          &cell) const
  {
    for (const auto &assembler : surface)
      assembler->assemble(data, cell);
    for (const auto &face : data.free_faces)
      for (const auto &assembler : faces)
        assembler->assemble(data, face, cell);
  }

  template class StokesTerms<2>;
  template class StokesTerms<3>;
} // namespace levelsinter
