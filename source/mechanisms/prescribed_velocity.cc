#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <levelsinter/mechanisms/prescribed_velocity.h>
#include <levelsinter/scene/solid_geometry.h>

#include <map>
#include <stdexcept>

namespace levelsinter
{
  namespace
  {
    template <int dim>
    class RigidRotation : public Function<dim>
    {
    public:
      RigidRotation(const Point<dim>     &centre,
                    const Tensor<1, 3>   &axis,
                    const double          omega)
        : Function<dim>(dim)
        , centre(centre)
        , omega_vector(omega * axis / axis.norm())
      {}

      void
      vector_value(const Point<dim> &p, Vector<double> &v) const override
      {
        Tensor<1, 3> r;
        for (unsigned int d = 0; d < dim; ++d)
          r[d] = p[d] - centre[d];
        const Tensor<1, 3> u = cross_product_3d(omega_vector, r);
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = u[d];
      }

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        Vector<double> v(dim);
        vector_value(p, v);
        return v[component];
      }

    private:
      Point<dim>   centre;
      Tensor<1, 3> omega_vector;
    };

    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &x)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    }
  } // namespace

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const SceneParameters::Velocity &parameters)
  {
    Assert(parameters.type != PrescribedVelocityParameters::Type::none,
           ExcMessage("a scene without a velocity builds no PrescribedVelocity"));
    if (parameters.type == PrescribedVelocityParameters::Type::constant)
      {
        std::vector<double> v(parameters.constant.begin(),
                              parameters.constant.begin() + dim);
        return std::make_unique<Functions::ConstantFunction<dim>>(v);
      }
    if (parameters.type == PrescribedVelocityParameters::Type::rotation)
      {
        Tensor<1, 3> axis;
        for (unsigned int d = 0; d < 3; ++d)
          axis[d] = parameters.rotation_axis[d];
        // In 2D the axis is z, whatever the parameter says.
        if (dim == 2)
          axis = Tensor<1, 3>({0, 0, 1});
        return std::make_unique<RigidRotation<dim>>(
          to_point<dim>(parameters.rotation_centre),
          axis,
          parameters.angular_velocity);
      }

    // Expression: components separated by ';', variables x,y[,z],t
    // (checked when the scene was read).
    return make_expression_function<dim>(parameters.expression,
                                         dim,
                                         parameters.constants,
                                         "Velocity/Expression",
                                         /*time_dependent=*/true);
  }

  template <int dim>
  PrescribedVelocity<dim>::PrescribedVelocity(
    const SceneParameters::Velocity &parameters,
    const double                     theta)
    : function(make_prescribed_velocity<dim>(parameters))
    , theta(theta)
  {}

  template <int dim>
  void
  PrescribedVelocity<dim>::add_velocity(const LevelSetField<dim> &,
                                        const double        t,
                                        const double        dt,
                                        VelocityField<dim> &velocity)
  {
    function->set_time(t + theta * dt);
    velocity.add(*function);
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::add_probe_velocity(const LevelSetField<dim> &,
                                              const double        t,
                                              VelocityField<dim> &velocity)
  {
    function->set_time(t);
    velocity.add(*function);
  }

  template class PrescribedVelocity<2>;
  template class PrescribedVelocity<3>;

  template std::unique_ptr<Function<2>>
  make_prescribed_velocity<2>(const SceneParameters::Velocity &);
  template std::unique_ptr<Function<3>>
  make_prescribed_velocity<3>(const SceneParameters::Velocity &);
} // namespace levelsinter
