#pragma once
// Value types shared by every folder: fixed-size Eigen vectors and axis-aligned boxes.
#include <Eigen/Core>
#include <limits>

namespace fp {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

/// Axis-aligned bounding box; empty when lo > hi.
template <int D>
struct Aabb {
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> hi = Vec<D>::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec<D>& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool contains(const Vec<D>& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  Vec<D> size() const { return hi - lo; }
  Vec<D> center() const { return 0.5 * (lo + hi); }
};

/// pi, spelled once.
inline constexpr double kPi = 3.14159265358979323846;

/// Volume (D=3) or area (D=2) of a ball of radius r.
template <int D>
constexpr double ball_measure(double r) {
  if constexpr (D == 2) return kPi * r * r;
  else return 4.0 / 3.0 * kPi * r * r * r;
}

}  // namespace fp
