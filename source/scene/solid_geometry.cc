#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/scene/parameter_entries.h>
#include <levelsinter/scene/solid_geometry.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace levelsinter
{
  std::vector<std::vector<double>>
  parse_shape_rows(const std::string              &text,
                   const std::vector<std::string> &names,
                   const std::string              &entry_name)
  {
    std::string expected;
    for (const auto &name : names)
      expected += (expected.empty() ? "" : ", ") + name;
    std::vector<std::vector<double>> rows;
    unsigned int                     index = 0;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        ++index;
        if (item.empty())
          continue;
        const auto where = "entry '" + entry_name + "', item " +
                           std::to_string(index) + ": ";
        const auto fields = Utilities::split_string_list(item, ',');
        if (fields.size() != names.size())
          throw std::runtime_error(where + "expected " +
                                   std::to_string(names.size()) +
                                   " values (" + expected + "), found " +
                                   std::to_string(fields.size()) + " in '" +
                                   item + "'");
        std::vector<double> row;
        for (const auto &f : fields)
          {
            std::istringstream in(f);
            double             v;
            if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v))
              throw std::runtime_error(where + "'" + f + "' is not a number");
            row.push_back(v);
          }
        rows.push_back(row);
      }
    return rows;
  }

  std::vector<std::string>
  superellipse_columns(const unsigned int dim, const bool with_exponent)
  {
    std::vector<std::string> names =
      dim == 2 ? std::vector<std::string>{"x", "y", "a", "b"} :
                 std::vector<std::string>{"x", "y", "z", "a", "b", "c"};
    if (with_exponent)
      names.push_back("p");
    if (dim == 2)
      names.push_back("angle");
    else
      names.insert(names.end(), {"angle_x", "angle_y", "angle_z"});
    return names;
  }

  std::vector<std::vector<double>>
  parse_superellipses(const std::string &text,
                      const unsigned int dim,
                      const bool         with_exponent,
                      const std::string &entry_name)
  {
    auto rows = parse_shape_rows(text,
                                 superellipse_columns(dim, with_exponent),
                                 entry_name);
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        auto &row = rows[i];
        if (!with_exponent)
          row.insert(row.begin() + 2 * dim, 2.);
        const auto where = "item " + std::to_string(i + 1) + ": ";
        for (unsigned int k = dim; k < 2 * dim; ++k)
          if (!(row[k] > 0))
            throw std::runtime_error("entry '" + entry_name + "', " + where +
                                     "the semi-axes must be positive");
        if (!(row[2 * dim] >= 2))
          throw std::runtime_error(
            "entry '" + entry_name + "', " + where + "the exponent p must be " +
            "at least 2 (below, the tips have unbounded curvature)");
      }
    return rows;
  }

  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &entry_name)
  {
    std::map<std::string, double> constants{{"pi", M_PI}};
    for (const auto &item : Utilities::split_string_list(text, ','))
      {
        if (item.empty())
          continue;
        const auto         pair = Utilities::split_string_list(item, '=');
        std::istringstream in(pair.size() == 2 ? pair[1] : "");
        double             v;
        if (pair.size() != 2 || pair[0].empty() || !(in >> v) ||
            !(in >> std::ws).eof() || !std::isfinite(v))
          throw std::runtime_error("entry '" + entry_name + "': '" + item +
                                   "' is not of the form name = number");
        constants[pair[0]] = v;
      }
    return constants;
  }

  template <int dim>
  ImplicitSurfaceDistance<dim>::ImplicitSurfaceDistance(
    std::function<double(const Point<dim> &)> phi,
    const double                              length_scale)
    : phi(std::move(phi))
    , length_scale(length_scale)
  {}

  template <int dim>
  Tensor<1, dim>
  ImplicitSurfaceDistance<dim>::gradient_of_phi(const Point<dim> &x) const
  {
    const double   h = 1e-6 * length_scale;
    Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Point<dim> plus = x, minus = x;
        plus[d] += h;
        minus[d] -= h;
        g[d] = (phi(plus) - phi(minus)) / (2 * h);
      }
    return g;
  }

  template <int dim>
  bool
  ImplicitSurfaceDistance<dim>::project_onto_surface(Point<dim> &x) const
  {
    const double tolerance = 1e-12 * length_scale;
    for (unsigned int k = 0; k < 50; ++k)
      {
        Tensor<1, dim> g = gradient_of_phi(x);
        if (g.norm() == 0)
          {
            // A critical point (the centre of a symmetric body): step off it.
            x[0] += 1e-3 * length_scale;
            g = gradient_of_phi(x);
            if (g.norm() == 0)
              return false;
          }
        const Tensor<1, dim> step = phi(x) / g.norm_square() * g;
        x -= step;
        if (step.norm() <= tolerance)
          return true;
      }
    return false;
  }

  template <int dim>
  double
  ImplicitSurfaceDistance<dim>::value(const Point<dim> &q,
                                      const unsigned int) const
  {
    const double phi_q = phi(q);
    if (phi_q == 0)
      return 0;
    const double sign = phi_q < 0 ? -1 : 1;
    Point<dim>   x    = q;
    if (!project_onto_surface(x))
      {
        const double g = gradient_of_phi(q).norm();
        return g > 0 ? phi_q / g : phi_q;
      }
    // Tangential steps: at the closest point, q - x is normal to the
    // surface. A step that does not bring the surface point closer is
    // halved; none left means x is the closest point to rounding.
    const double tolerance = 1e-12 * length_scale;
    for (unsigned int iteration = 0; iteration < 200; ++iteration)
      {
        const Tensor<1, dim> g = gradient_of_phi(x);
        const Tensor<1, dim> n = g / g.norm();
        const Tensor<1, dim> r = q - x;
        const Tensor<1, dim> t = r - (r * n) * n;
        if (t.norm() <= tolerance)
          break;
        bool closer = false;
        for (double factor = 1; factor > 1e-6 && !closer; factor /= 2)
          {
            Point<dim> y = x + factor * t;
            if (project_onto_surface(y) && q.distance(y) < q.distance(x))
              {
                x      = y;
                closer = true;
              }
          }
        if (!closer)
          break;
      }
    return sign * q.distance(x);
  }

  namespace
  {
    // A vector turned by a superellipse row's rotation (about x, then y,
    // then z in 3D) from the body frame to the world frame, or back.
    template <int dim>
    Tensor<1, dim>
    rotate(const std::vector<double> &row, Tensor<1, dim> v, const bool back)
    {
      // Rotate by +-angle in the plane (i, j).
      const auto turn = [&v, back](const unsigned int i,
                                   const unsigned int j,
                                   const double       degrees) {
        const double c = std::cos(degrees * M_PI / 180),
                     s = (back ? -1 : 1) * std::sin(degrees * M_PI / 180);
        const double vi = c * v[i] - s * v[j], vj = s * v[i] + c * v[j];
        v[i] = vi;
        v[j] = vj;
      };
      const unsigned int angles = 2 * dim + 1;
      if constexpr (dim == 2)
        turn(0, 1, row[angles]);
      else if (back)
        {
          turn(0, 1, row[angles + 2]); // z
          turn(2, 0, row[angles + 1]); // y
          turn(1, 2, row[angles]);     // x
        }
      else
        {
          turn(1, 2, row[angles]);
          turn(2, 0, row[angles + 1]);
          turn(0, 1, row[angles + 2]);
        }
      return v;
    }


    // Points of a superellipse row's surface in the world frame: the
    // parametrisation y_d = a_d sgn(w_d) |w_d|^(2/p), w on the unit circle
    // (sphere), at @p n angles per half turn.
    template <int dim>
    std::vector<Point<dim>>
    surface_points(const std::vector<double> &row, const unsigned int n)
    {
      const double            p = row[2 * dim];
      std::vector<Point<dim>> points;
      const auto              power = [p](const double w) {
        return (w < 0 ? -1 : 1) * std::pow(std::abs(w), 2 / p);
      };
      for (unsigned int i = 0; i < 2 * n; ++i)
        for (unsigned int j = 0; j <= (dim == 2 ? 0 : n); ++j)
          {
            const double   t = i * M_PI / n, s = j * M_PI / n;
            Tensor<1, dim> w;
            if constexpr (dim == 2)
              w = Tensor<1, dim>({std::cos(t), std::sin(t)});
            else
              w = Tensor<1, dim>({std::cos(t) * std::sin(s),
                                  std::sin(t) * std::sin(s),
                                  std::cos(s)});
            Tensor<1, dim> y;
            for (unsigned int d = 0; d < dim; ++d)
              y[d] = row[dim + d] * power(w[d]);
            Point<dim> x;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = row[d];
            points.push_back(x + rotate<dim>(row, y, false));
          }
      return points;
    }

  } // namespace

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_expression_function(const std::string                   &expression,
                           const unsigned int                   n_components,
                           const std::map<std::string, double> &constants,
                           const std::string                   &entry_name,
                           const bool                           time_dependent)
  {
    const std::string variables =
      FunctionParser<dim>::default_variable_names() +
      (time_dependent ? ",t" : "");
    auto f = std::make_unique<FunctionParser<dim>>(n_components);
    // deal.II prints muparser's diagnosis to std::cerr before it throws;
    // the error message below carries it instead.
    std::ostringstream silenced;
    auto *const        cerr_buffer = std::cerr.rdbuf(silenced.rdbuf());
    try
      {
        f->initialize(variables,
                      Utilities::split_string_list(expression, ';'),
                      constants,
                      time_dependent);
        // Evaluate once so that an unknown symbol is reported now.
        Vector<double> v(n_components);
        f->vector_value(Point<dim>(), v);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const std::exception &e)
      {
        std::cerr.rdbuf(cerr_buffer);
        // The parser's words, without deal.II's frame and stack trace.
        std::string said = e.what();
        const auto  from = said.find("The parser said:");
        said = said.substr(from == std::string::npos ? 0 : from + 16);
        said = said.substr(0, said.find("Stacktrace"));
        std::string words;
        for (const auto &w : Utilities::split_string_list(said, ' '))
          for (const auto &part : Utilities::split_string_list(w, '\n'))
            if (!part.empty())
              words += (words.empty() ? "" : " ") + part;
        throw std::runtime_error("entry '" + entry_name +
                                 "': the expression '" + expression +
                                 "' (of " + variables +
                                 " and the constants) cannot be evaluated: " +
                                 words);
      }
    return f;
  }

  template <int dim>
  void
  check_superellipses_in_domain(const std::vector<std::vector<double>> &rows,
                                const std::vector<double> &lower_corner,
                                const std::vector<double> &upper_corner,
                                const std::string         &entry_name)
  {
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double tol = 1e-6 * (upper_corner[d] - lower_corner[d]);
          const double c   = rows[i][d];
          double       lo = c, hi = c;
          for (const auto &x : surface_points<dim>(rows[i], 180))
            {
              lo = std::min(lo, x[d]);
              hi = std::max(hi, x[d]);
            }
          const bool out_below = lo < lower_corner[d] - tol &&
                                 std::abs(c - lower_corner[d]) > tol;
          const bool out_above = hi > upper_corner[d] + tol &&
                                 std::abs(c - upper_corner[d]) > tol;
          if (out_below || out_above)
            {
              std::ostringstream msg;
              msg << "entry '" << entry_name << "', item " << i + 1
                  << ": the shape spans [" << lo << ", " << hi
                  << "] along axis " << d << ", not inside the domain's ["
                  << lower_corner[d] << ", " << upper_corner[d]
                  << "]; a shape may only be cut by a face its centre lies "
                     "on (symmetry plane)";
              throw std::runtime_error(msg.str());
            }
        }
  }

  template <int dim>
  void
  check_implicit_function(const std::string                   &expression,
                          const std::map<std::string, double> &constants,
                          const std::vector<double>           &lower_corner,
                          const std::vector<double>           &upper_corner,
                          const std::string                   &entry_name)
  {
    const auto f =
      make_expression_function<dim>(expression, 1, constants, entry_name);
    const unsigned int n = dim == 2 ? 64 : 24;
    double             smallest = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < std::pow(n + 1, dim); ++k)
      {
        Point<dim>   x;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d, rest /= n + 1)
          x[d] = lower_corner[d] +
                 (upper_corner[d] - lower_corner[d]) * (rest % (n + 1)) / n;
        const double v = f->value(x);
        if (std::isnan(v))
          {
            std::ostringstream msg;
            msg << "the expression '" << expression << "' is not a number at ("
                << x << ")";
            fail_entry(entry_name, msg.str());
          }
        smallest = std::min(smallest, v);
      }
    if (!(smallest < 0))
      fail_entry(entry_name,
                 "the expression '" + expression +
                   "' is nowhere negative on a grid of " +
                   std::to_string(n + 1) + "^" + std::to_string(dim) +
                   " points over the domain: it describes no solid "
                   "(negative inside)");
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_superellipse_distance(const std::vector<double> &row)
  {
    if (row.size() != (dim == 2 ? 6u : 10u))
      throw std::invalid_argument("a superellipse row has the wrong length");
    const double p = row[2 * dim];
    double       a_min = row[dim], a_max = row[dim];
    for (unsigned int d = 1; d < dim; ++d)
      {
        a_min = std::min(a_min, row[dim + d]);
        a_max = std::max(a_max, row[dim + d]);
      }
    // The body frame: y = B (q - centre), B the rotation undone.
    Point<dim>     centre;
    Tensor<2, dim> B;
    for (unsigned int d = 0; d < dim; ++d)
      {
        centre[d] = row[d];
        Tensor<1, dim> e;
        e[d]                 = 1;
        const auto column    = rotate<dim>(row, e, true);
        for (unsigned int k = 0; k < dim; ++k)
          B[k][d] = column[k];
      }
    const auto phi = [row, p, a_min, centre, B](const Point<dim> &q) {
      const Tensor<1, dim> y = B * (q - centre);
      // N = (sum |y_d / a_d|^p)^(1/p), scaled by its largest term so that
      // large p does not overflow.
      double m = 0;
      for (unsigned int d = 0; d < dim; ++d)
        m = std::max(m, std::abs(y[d]) / row[dim + d]);
      if (m == 0)
        return -a_min;
      double sum = 0;
      for (unsigned int d = 0; d < dim; ++d)
        sum += std::pow(std::abs(y[d]) / row[dim + d] / m, p);
      return a_min * (m * std::pow(sum, 1 / p) - 1);
    };
    return std::make_unique<ImplicitSurfaceDistance<dim>>(phi, a_max);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_implicit_distance(const std::string                   &expression,
                         const std::map<std::string, double> &constants,
                         const double                         length_scale,
                         const std::string                   &entry_name)
  {
    const std::shared_ptr<FunctionParser<dim>> f =
      make_expression_function<dim>(expression, 1, constants, entry_name);
    return std::make_unique<ImplicitSurfaceDistance<dim>>(
      [f](const Point<dim> &x) { return f->value(x); }, length_scale);
  }

  template <int dim>
  SolidMinusHoles<dim>::SolidMinusHoles(
    std::vector<std::unique_ptr<Function<dim>>> parts,
    std::vector<std::unique_ptr<Function<dim>>> holes)
    : parts(std::move(parts))
    , holes(std::move(holes))
  {
    if (this->parts.empty())
      throw std::invalid_argument("a solid needs at least one part");
  }

  template <int dim>
  double
  SolidMinusHoles<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    double d = std::numeric_limits<double>::max();
    for (const auto &part : parts)
      d = std::min(d, part->value(p));
    for (const auto &hole : holes)
      d = std::max(d, -hole->value(p));
    return d;
  }

  template class ImplicitSurfaceDistance<2>;
  template class ImplicitSurfaceDistance<3>;
  template class SolidMinusHoles<2>;
  template class SolidMinusHoles<3>;
  template void
  check_superellipses_in_domain<2>(const std::vector<std::vector<double>> &,
                                   const std::vector<double> &,
                                   const std::vector<double> &,
                                   const std::string &);
  template void
  check_superellipses_in_domain<3>(const std::vector<std::vector<double>> &,
                                   const std::vector<double> &,
                                   const std::vector<double> &,
                                   const std::string &);
  template void
  check_implicit_function<2>(const std::string &,
                             const std::map<std::string, double> &,
                             const std::vector<double> &,
                             const std::vector<double> &,
                             const std::string &);
  template void
  check_implicit_function<3>(const std::string &,
                             const std::map<std::string, double> &,
                             const std::vector<double> &,
                             const std::vector<double> &,
                             const std::string &);
  template std::unique_ptr<FunctionParser<2>>
  make_expression_function<2>(const std::string &,
                              const unsigned int,
                              const std::map<std::string, double> &,
                              const std::string &,
                              const bool);
  template std::unique_ptr<FunctionParser<3>>
  make_expression_function<3>(const std::string &,
                              const unsigned int,
                              const std::map<std::string, double> &,
                              const std::string &,
                              const bool);
  template std::unique_ptr<Function<2>>
  make_superellipse_distance<2>(const std::vector<double> &);
  template std::unique_ptr<Function<3>>
  make_superellipse_distance<3>(const std::vector<double> &);
  template std::unique_ptr<Function<2>>
  make_implicit_distance<2>(const std::string &,
                            const std::map<std::string, double> &,
                            const double,
                            const std::string &);
  template std::unique_ptr<Function<3>>
  make_implicit_distance<3>(const std::string &,
                            const std::map<std::string, double> &,
                            const double,
                            const std::string &);
} // namespace levelsinter
