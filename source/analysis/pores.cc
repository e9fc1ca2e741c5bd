#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <levelsinter/analysis/pores.h>
#include <levelsinter/level_set/interface_measures.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

namespace levelsinter
{
  template <int dim>
  double
  Pore<dim>::sphericity() const
  {
    unsigned int planes = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const bool low  = box_faces & (1u << (2 * d)),
                   high = box_faces & (1u << (2 * d + 1));
        if (low && high)
          return std::numeric_limits<double>::quiet_NaN();
        planes += low || high;
      }
    if (open)
      return std::numeric_limits<double>::quiet_NaN();
    if (area <= 0)
      return 0;
    return (dim == 3 ? 36 * M_PI * volume * volume / (area * area * area) :
                       4 * M_PI * volume / (area * area)) /
           (1u << planes);
  }

  template <int dim>
  double
  Pore<dim>::equivalent_radius() const
  {
    return dim == 3 ? std::cbrt(3 * volume / (4 * M_PI)) :
                      std::sqrt(volume / M_PI);
  }

  namespace
  {
    class DisjointSets
    {
    public:
      explicit DisjointSets(const unsigned int n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0u);
      }

      unsigned int
      find(unsigned int k)
      {
        while (parent[k] != k)
          k = parent[k] = parent[parent[k]];
        return k;
      }

      void
      unite(const unsigned int a, const unsigned int b)
      {
        const unsigned int ra = find(a), rb = find(b);
        if (ra != rb)
          parent[std::max(ra, rb)] = std::min(ra, rb);
      }

    private:
      std::vector<unsigned int> parent;
    };

    // Per component, summed over the cells of one rank, then the ranks.
    template <int dim>
    struct Sums
    {
      double             volume = 0, area = 0, volume_in_window = 0;
      Tensor<1, dim>     first_moment;
      bool               open      = false;
      unsigned int       box_faces = 0; // bit b: box face b
      static constexpr unsigned int size = 6 + dim;

      void
      pack(std::vector<double> &out, const double label) const
      {
        out.insert(out.end(),
                   {label,
                    volume,
                    area,
                    volume_in_window,
                    double(open),
                    double(box_faces)});
        for (unsigned int d = 0; d < dim; ++d)
          out.push_back(first_moment[d]);
      }

      void
      add(const double *in)
      {
        volume += in[1];
        area += in[2];
        volume_in_window += in[3];
        open   = open || in[4] > 0;
        box_faces |= static_cast<unsigned int>(in[5]);
        for (unsigned int d = 0; d < dim; ++d)
          first_moment[d] += in[6 + d];
      }
    };
  } // namespace

  template <int dim>
  std::vector<Pore<dim>>
  find_pores(const LevelSetField<dim>              &level_set,
             const std::vector<types::boundary_id> &symmetry_boundaries,
             const BoundingBox<dim>                &window,
             std::vector<int>                      *vertex_pores)
  {
    const auto        &dofs     = level_set.dof_handler();
    const IndexSet    &relevant = level_set.locally_relevant();
    const MPI_Comm     comm     = dofs.get_communicator();
    const unsigned int n        = relevant.n_elements();
    std::vector<double> value(n);
    for (unsigned int k = 0; k < n; ++k)
      value[k] = level_set.alpha()(relevant.nth_index_in_set(k));

    // 1. Components on this rank's cells (Q1: one DoF per vertex, in the
    //    cell's lexicographic vertex order).
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    DisjointSets           sets(n);
    std::vector<types::global_dof_index>                   indices(n_vertices);
    std::array<unsigned int, n_vertices>                   local;
    auto read_cell = [&](const auto &cell) {
      cell->get_dof_indices(indices);
      for (unsigned int v = 0; v < n_vertices; ++v)
        local[v] = relevant.index_within_set(indices[v]);
    };
    auto positive = [&](const unsigned int v) { return value[local[v]] > 0; };
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          read_cell(cell);
          for (unsigned int v = 0; v < n_vertices; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              if (!(v & (1u << d)) && positive(v) && positive(v | (1u << d)))
                sets.unite(local[v], local[v | (1u << d)]);
          // The faces' ambiguous diagonals (asymptotic decider).
          for (unsigned int d1 = 0; d1 < dim; ++d1)
            for (unsigned int d2 = d1 + 1; d2 < dim; ++d2)
              for (unsigned int base = 0; base < n_vertices; ++base)
                if (!(base & ((1u << d1) | (1u << d2))))
                  {
                    const unsigned int v[4] = {base,
                                               base | (1u << d1),
                                               base | (1u << d2),
                                               base | (1u << d1) | (1u << d2)};
                    const double f0 = value[local[v[0]]],
                                 f1 = value[local[v[1]]],
                                 f2 = value[local[v[2]]],
                                 f3 = value[local[v[3]]];
                    if (f0 > 0 && f3 > 0 && f1 <= 0 && f2 <= 0 &&
                        f0 * f3 > f1 * f2)
                      sets.unite(local[v[0]], local[v[3]]);
                    if (f1 > 0 && f2 > 0 && f0 <= 0 && f3 <= 0 &&
                        f1 * f2 > f0 * f3)
                      sets.unite(local[v[1]], local[v[2]]);
                  }
        }

    // 2. Global labels: the smallest global vertex index of the component,
    //    spread through the ghost vertices until no rank changes a label.
    constexpr double    none = std::numeric_limits<double>::max();
    std::vector<double> label(n, none); // per local root
    for (unsigned int k = 0; k < n; ++k)
      if (value[k] > 0)
        label[sets.find(k)] =
          std::min(label[sets.find(k)], double(relevant.nth_index_in_set(k)));
    LinearAlgebra::distributed::Vector<double> exchanged;
    for (;;)
      {
        exchanged.reinit(level_set.locally_owned(), relevant, comm);
        for (unsigned int k = 0; k < n; ++k)
          exchanged(relevant.nth_index_in_set(k)) =
            value[k] > 0 ? label[sets.find(k)] : none;
        exchanged.compress(VectorOperation::min);
        exchanged.update_ghost_values();
        int changed = 0;
        for (unsigned int k = 0; k < n; ++k)
          if (value[k] > 0)
            if (const double l = exchanged(relevant.nth_index_in_set(k));
                l < label[sets.find(k)])
              {
                label[sets.find(k)] = l;
                changed             = 1;
              }
        if (Utilities::MPI::max(changed, comm) == 0)
          break;
      }

    // 3. Volume, centroid and area per component; open components.
    std::map<double, Sums<dim>> sums;
    const auto                 &fe = level_set.fe();
    // Call after read_cell(). A cell without a positive vertex has no
    // atmosphere (alpha_h <= 0 throughout): none.
    auto owner = [&](const Point<dim> &unit) {
      unsigned int best   = 0;
      double       weight = -1;
      for (unsigned int v = 0; v < n_vertices; ++v)
        if (positive(v))
          if (const double w = value[local[v]] * fe.shape_value(v, unit);
              w > weight)
            {
              weight = w;
              best   = v;
            }
      return weight < 0 ? none : label[sets.find(local[best])];
    };
    interface_measures::RegionIntegrands<dim> integrands;
    integrands.atmosphere_flags = update_JxW_values | update_quadrature_points;
    integrands.surface_flags    = update_JxW_values;
    integrands.on_atmosphere    = [&](const auto &cell, const auto &values) {
      const bool in_window = window.point_inside(cell->center());
      read_cell(cell);
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const double l = owner(values.get_quadrature().point(q));
          if (l == none)
            continue;
          auto &s = sums[l];
          const double JxW = level_set.measure().JxW(values, q);
          s.volume += JxW;
          s.first_moment += JxW * values.quadrature_point(q);
          if (in_window)
            s.volume_in_window += JxW;
        }
    };
    integrands.on_surface = [&](const auto &cell, const auto &values) {
      read_cell(cell);
      for (const unsigned int q : values.quadrature_point_indices())
        if (const double l = owner(values.get_quadrature().point(q));
            l != none)
          sums[l].area += level_set.measure().JxW(values, q);
    };
    interface_measures::integrate_regions(level_set, integrands);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const bool symmetry =
                std::find(symmetry_boundaries.begin(),
                          symmetry_boundaries.end(),
                          cell->face(f)->boundary_id()) !=
                symmetry_boundaries.end();
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  const unsigned int k = relevant.index_within_set(
                    cell->face(f)->vertex_dof_index(v, 0));
                  if (value[k] > 0)
                    {
                      auto &s = sums[label[sets.find(k)]];
                      s.box_faces |= 1u << cell->face(f)->boundary_id();
                      s.open   = s.open || !symmetry;
                    }
                }
            }

    // 4. Gather the components of all ranks (few numbers per pore).
    std::vector<double> packed;
    for (const auto &[l, s] : sums)
      s.pack(packed, l);
    std::map<double, Sums<dim>> total;
    for (const auto &part : Utilities::MPI::all_gather(comm, packed))
      for (std::size_t i = 0; i < part.size(); i += Sums<dim>::size)
        total[part[i]].add(&part[i]);
    std::vector<Pore<dim>> pores;
    std::vector<double>    labels;
    for (const auto &[l, s] : total)
      if (s.volume > 0)
        {
          labels.push_back(l);
          Pore<dim> pore;
          pore.volume           = s.volume;
          pore.area             = s.area;
          pore.volume_in_window = s.volume_in_window;
          pore.centroid         = Point<dim>(s.first_moment / s.volume);
          pore.open             = s.open;
          pore.box_faces        = s.box_faces;
          pores.push_back(pore);
        }
    // An order independent of the partition: centroids compared after
    // rounding to 1e-9 of the window's size, far below the cell size (the
    // sums differ in the last digits).
    const double scale = window.get_boundary_points().first.distance(
                           window.get_boundary_points().second) *
                         1e-9;
    auto key = [scale](const Pore<dim> &p) {
      std::array<long long, dim> k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = std::llround(p.centroid[d] / scale);
      return k;
    };
    std::vector<unsigned int> order(pores.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
      return key(pores[a]) < key(pores[b]);
    });
    std::vector<Pore<dim>> sorted;
    std::map<double, int>  index_of_label;
    for (const unsigned int i : order)
      {
        index_of_label[labels[i]] = sorted.size();
        sorted.push_back(pores[i]);
      }
    if (vertex_pores)
      {
        vertex_pores->assign(n, -1);
        for (unsigned int k = 0; k < n; ++k)
          if (value[k] > 0)
            if (const auto found = index_of_label.find(label[sets.find(k)]);
                found != index_of_label.end())
              (*vertex_pores)[k] = found->second;
      }
    return sorted;
  }

  template <int dim>
  std::vector<unsigned int>
  PoreTracker<dim>::update(const std::vector<Pore<dim>> &pores,
                           std::vector<Event>           &events)
  {
    // Candidate matches (distance, old, new), nearest first.
    std::vector<std::tuple<double, unsigned int, unsigned int>> candidates;
    for (unsigned int o = 0; o < previous.size(); ++o)
      for (unsigned int p = 0; p < pores.size(); ++p)
        if (!pores[p].open)
          {
            const double d =
              previous[o].pore.centroid.distance(pores[p].centroid);
            if (d < std::max(previous[o].pore.equivalent_radius(),
                             pores[p].equivalent_radius()))
              candidates.emplace_back(d, o, p);
          }
    std::sort(candidates.begin(), candidates.end());
    std::vector<unsigned int> ids(pores.size(), 0);
    std::vector<bool>         matched(previous.size(), false);
    for (const auto &[distance, o, p] : candidates)
      if (!matched[o] && ids[p] == 0)
        {
          matched[o] = true;
          ids[p]     = previous[o].id;
        }
    for (unsigned int o = 0; o < previous.size(); ++o)
      if (!matched[o])
        events.push_back(
          {"vanished", previous[o].id, previous[o].pore.volume});
    std::vector<Tracked> now;
    for (unsigned int p = 0; p < pores.size(); ++p)
      if (!pores[p].open)
        {
          if (ids[p] == 0)
            {
              ids[p] = next_id++;
              events.push_back({"closed", ids[p], pores[p].volume});
            }
          now.push_back({ids[p], pores[p]});
        }
    previous = now;
    return ids;
  }

  template struct Pore<2>;
  template struct Pore<3>;
  template std::vector<Pore<2>>
  find_pores(const LevelSetField<2> &,
             const std::vector<types::boundary_id> &,
             const BoundingBox<2> &,
             std::vector<int> *);
  template std::vector<Pore<3>>
  find_pores(const LevelSetField<3> &,
             const std::vector<types::boundary_id> &,
             const BoundingBox<3> &,
             std::vector<int> *);
  template class PoreTracker<2>;
  template class PoreTracker<3>;
} // namespace levelsinter
