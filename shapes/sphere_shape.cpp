#include "shapes/sphere_shape.hpp"

#include <fcl/geometry/shape/sphere.h>

#include <memory>
#include <sstream>

#include "shapes/round_surface.hpp"

namespace fp {

template <int D>
double SphereShape<D>::measure() const { return ball_measure<D>(r_); }

template <int D>
Vec<D> SphereShape<D>::support(const Vec<D>& u) const {
  const double n = u.norm();
  return n > 0 ? Vec<D>(u * (r_ / n)) : Vec<D>::Zero();
}

template <int D>
SurfaceMesh<D> SphereShape<D>::surface(int resolution) const { return capsule_surface<D>(0.0, r_, resolution); }

template <int D>
std::vector<FclPart<D>> SphereShape<D>::fcl_parts() const {
  FclPart<D> p;
  p.geometry = std::make_shared<fcl::Sphered>(r_);  // a disk is a sphere cut by z = 0
  return {p};
}

template <int D>
ShapePtr<D> SphereShape<D>::scaled(double s) const { return std::make_shared<SphereShape<D>>(r_ * s); }

template <int D>
std::string SphereShape<D>::definition_json() const {
  std::ostringstream os;
  os.precision(17);
  os << R"({"kind": "sphere", "radius": )" << r_ << "}";
  return os.str();
}

template class SphereShape<2>;
template class SphereShape<3>;

}  // namespace fp
