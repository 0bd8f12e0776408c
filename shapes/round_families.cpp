#include "shapes/round_families.hpp"

#include <cmath>
#include <memory>

#include "shapes/shape_parameters.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {

template <int D>
double equivalent_radius(double measure) {
  return std::pow(measure / ball_measure<D>(1.0), 1.0 / D);
}

template <int D>
ShapePrototype<D> sphere_prototype(const ShapeParameters& p) {
  (void)p;  // takes no parameter (the registry refuses any)
  return {std::make_shared<SphereShape<D>>(1.0),
          {{"circumscribed_radius", 1.0}, {"radius", 1.0}, {"diameter", 2.0}, {"equivalent_radius", 1.0}}};
}

template <int D>
ShapePrototype<D> spherocylinder_prototype(const ShapeParameters& p) {
  const ParameterReader r(p);
  const double k = width_over_length(r, "total length", "width", /*rod_only=*/true);
  auto shape = std::make_shared<SpherocylinderShape<D>>(1.0 - k, k);
  return {shape,
          {{"circumscribed_radius", 1.0},
           {"radius", k},
           {"length", 2.0},
           {"width", 2 * k},
           {"cylinder_length", 2 * (1 - k)},
           {"equivalent_radius", equivalent_radius<D>(shape->measure())}}};
}

template double equivalent_radius<2>(double);
template double equivalent_radius<3>(double);
template ShapePrototype<2> sphere_prototype<2>(const ShapeParameters&);
template ShapePrototype<3> sphere_prototype<3>(const ShapeParameters&);
template ShapePrototype<2> spherocylinder_prototype<2>(const ShapeParameters&);
template ShapePrototype<3> spherocylinder_prototype<3>(const ShapeParameters&);

}  // namespace fp
