#include <levelsinter/mechanics/cut_cell_rules.h>

#include <cmath>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    // The Lagrange polynomials of the 1D points @p nodes at @p t.
    void
    lagrange_values(const std::vector<Point<1>> &nodes,
                    const double                 t,
                    std::vector<double>         &values)
    {
      values.assign(nodes.size(), 1.);
      for (unsigned int j = 0; j < nodes.size(); ++j)
        for (unsigned int m = 0; m < nodes.size(); ++m)
          if (m != j)
            values[j] *= (t - nodes[m][0]) / (nodes[j][0] - nodes[m][0]);
    }
  } // namespace

  template <int dim>
  CutCellRules<dim>::CutCellRules(
    const DoFHandler<dim>               &dofs,
    const TrilinosWrappers::MPI::Vector &level_set,
    const unsigned int                   n_points)
    : gauss_1d(n_points)
    , gauss(n_points)
    , q_collection_1d(gauss_1d)
    , generator(q_collection_1d, dofs, level_set)
    , tensor_index(gauss.size())
  {
    // QGauss<dim> is the tensor product of QGauss<1>: find each point's
    // 1D factors rather than rely on the order of the product.
    for (unsigned int q = 0; q < gauss.size(); ++q)
      for (unsigned int d = 0; d < dim; ++d)
        {
          unsigned int nearest = 0;
          for (unsigned int j = 1; j < n_points; ++j)
            if (std::abs(gauss_1d.point(j)[0] - gauss.point(q)[d]) <
                std::abs(gauss_1d.point(nearest)[0] - gauss.point(q)[d]))
              nearest = j;
          tensor_index[q][d] = nearest;
        }
  }

  template <int dim>
  void
  CutCellRules<dim>::fit(const Quadrature<dim> &part,
                         std::vector<double>   &weights) const
  {
    weights.clear();
    if (part.size() == 0)
      return;
    weights.assign(gauss.size(), 0.);
    std::array<std::vector<double>, dim> factor;
    for (unsigned int k = 0; k < part.size(); ++k)
      {
        for (unsigned int d = 0; d < dim; ++d)
          lagrange_values(gauss_1d.get_points(), part.point(k)[d], factor[d]);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            double l = part.weight(k);
            for (unsigned int d = 0; d < dim; ++d)
              l *= factor[d][tensor_index[q][d]];
            weights[q] += l;
          }
      }
  }

  template <int dim>
  void
  CutCellRules<dim>::generate(
    const typename Triangulation<dim>::active_cell_iterator &cell)
  {
    // The cell's edges along the axes; the rules hold for axis-parallel
    // cells only (the box meshes'), whose Jacobian is diag(extent).
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const Point<dim>       origin     = cell->vertex(0);
    Tensor<1, dim>         extent     = cell->vertex(n_vertices - 1) - origin;
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(cell->vertex(v)[d] - origin[d] -
                     ((v >> d) & 1) * extent[d]) > 1e-10 * extent.norm())
          throw std::logic_error(
            "the cut-cell rules need cells with edges along the axes");

    generator.generate(cell);
    fit(generator.get_inside_quadrature(), inside_weights);
    fit(generator.get_outside_quadrature(), outside_weights);

    const auto &surface = generator.get_surface_quadrature();
    double      volume  = 1;
    for (unsigned int d = 0; d < dim; ++d)
      volume *= extent[d];
    surface_points.resize(surface.size());
    for (unsigned int k = 0; k < surface.size(); ++k)
      {
        const Point<dim>     &y = surface.point(k);
        const Tensor<1, dim> &n = surface.normal_vector(k);
        SurfacePoint         &p = surface_points[k];
        // dS = det J |J^-T n| w (NonMatching::ImmersedSurfaceQuadrature).
        Tensor<1, dim> scaled;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p.point[d] = origin[d] + extent[d] * y[d];
            scaled[d]  = n[d] / extent[d];
          }
        p.dS     = surface.weight(k) * volume * scaled.norm();
        p.normal = scaled / scaled.norm();
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            // Q1 shape function of vertex v: prod_d (y_d or 1 - y_d).
            std::array<double, dim> f, df;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const bool upper = (v >> d) & 1;
                f[d]             = upper ? y[d] : 1 - y[d];
                df[d]            = (upper ? 1. : -1.) / extent[d];
              }
            p.value[v] = 1;
            for (unsigned int d = 0; d < dim; ++d)
              {
                p.value[v] *= f[d];
                p.gradient[v][d] = df[d];
                for (unsigned int e = 0; e < dim; ++e)
                  if (e != d)
                    p.gradient[v][d] *= f[e];
              }
          }
      }
  }

  template class CutCellRules<2>;
  template class CutCellRules<3>;
} // namespace levelsinter
