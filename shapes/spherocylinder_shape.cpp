#include "shapes/spherocylinder_shape.hpp"

#include <fcl/geometry/shape/capsule.h>

#include <algorithm>
#include <memory>
#include <sstream>

#include "shapes/round_surface.hpp"

namespace fp {

template <int D>
double SpherocylinderShape<D>::measure() const {
  if constexpr (D == 2) return 4 * a_ * r_ + kPi * r_ * r_;
  else return 2 * a_ * kPi * r_ * r_ + ball_measure<3>(r_);
}

template <int D>
Vec<D> SpherocylinderShape<D>::support(const Vec<D>& u) const {
  const double n = u.norm();
  Vec<D> p = n > 0 ? Vec<D>(u * (r_ / n)) : Vec<D>::Zero();
  p[0] += u[0] >= 0 ? a_ : -a_;
  return p;
}

template <int D>
bool SpherocylinderShape<D>::contains(const Vec<D>& x) const {
  Vec<D> d = x;
  d[0] -= std::clamp(x[0], -a_, a_);  // x minus its closest point on the segment
  return d.squaredNorm() <= r_ * r_;
}

template <int D>
SurfaceMesh<D> SpherocylinderShape<D>::surface(int resolution) const { return capsule_surface<D>(a_, r_, resolution); }

template <int D>
std::vector<FclPart<D>> SpherocylinderShape<D>::fcl_parts() const {
  FclPart<D> p;
  p.geometry = std::make_shared<fcl::Capsuled>(r_, 2 * a_);  // FCL's capsule lies along its z axis
  p.rotation << 0, 0, 1,  //
      0, 1, 0,            //
      -1, 0, 0;           // z -> x (a rotation about y)
  return {p};
}

template <int D>
ShapePtr<D> SpherocylinderShape<D>::scaled(double s) const {
  return std::make_shared<SpherocylinderShape<D>>(a_ * s, r_ * s);
}

template <int D>
std::string SpherocylinderShape<D>::definition_json() const {
  std::ostringstream os;
  os.precision(17);
  os << R"({"kind": "spherocylinder", "segment_half_length": )" << a_ << R"(, "radius": )" << r_
     << R"(, "axis": "body x"})";
  return os.str();
}

template class SpherocylinderShape<2>;
template class SpherocylinderShape<3>;

}  // namespace fp
