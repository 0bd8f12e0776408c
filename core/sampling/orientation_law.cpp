#include "core/sampling/orientation_law.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fp {
namespace {

/// Grid cells of the tabulated CDF: at |kappa| = kMaxConcentration the 3D watson density falls by
/// e over 1 / (2 kappa) = 5e-4, 33 cells.
constexpr int kCells = 1 << 16;

/// A unit vector perpendicular to the unit vector u (deterministic: from the world axis least
/// aligned with u).
Vec3 perpendicular(const Vec3& u) {
  const Vec3 a = u.cwiseAbs();
  const Vec3 ref = a.x() <= a.y() && a.x() <= a.z() ? Vec3::UnitX() : a.y() <= a.z() ? Vec3::UnitY() : Vec3::UnitZ();
  return (ref - ref.dot(u) * u).normalized();
}

}  // namespace

AxisAngleLaw::AxisAngleLaw(OrientationKind kind, int dimension, double kappa)
    : kind_(kind), dimension_(dimension), kappa_(kappa) {
  if (kind != OrientationKind::Watson && kind != OrientationKind::Fisher)
    throw std::invalid_argument("AxisAngleLaw: the law must be watson or fisher");
  if (!(std::abs(kappa) <= kMaxConcentration)) throw std::invalid_argument("AxisAngleLaw: |kappa| must be <= 1000");
  if (dimension == 3) {
    lo_ = kind == OrientationKind::Watson ? 0.0 : -1.0;  // watson: |a.n|, the law being axial
    hi_ = 1.0;
  } else {
    lo_ = -kPi;
    hi_ = kPi;
  }
  if (kappa == 0.0) {  // uniform: no table (every isotropic template has one of these)
    order_sd_ = dimension == 3 ? std::sqrt(0.2) : std::sqrt(0.5);  // Var P2(t), t ~ U[-1, 1]; Var cos 2 psi
    return;
  }
  // Simpson per cell for the CDF at the nodes and for the order moment.
  const double h = (hi_ - lo_) / kCells;
  auto order_of = [&](double u) { return dimension_ == 3 ? 1.5 * u * u - 0.5 : std::cos(2 * u); };
  cum_.assign(kCells + 1, 0.0);
  slope_.assign(kCells + 1, 0.0);
  double total = 0.0, moment = 0.0, moment2 = 0.0, f0 = density(lo_);
  slope_[0] = f0;
  for (int k = 0; k < kCells; ++k) {
    const double x0 = lo_ + k * h, xm = x0 + 0.5 * h, x1 = lo_ + (k + 1) * h;
    const double fm = density(xm), f1 = density(x1);
    total += h / 6 * (f0 + 4 * fm + f1);
    const double g0 = order_of(x0), gm = order_of(xm), g1 = order_of(x1);
    moment += h / 6 * (f0 * g0 + 4 * fm * gm + f1 * g1);
    moment2 += h / 6 * (f0 * g0 * g0 + 4 * fm * gm * gm + f1 * g1 * g1);
    cum_[static_cast<std::size_t>(k) + 1] = total;
    slope_[static_cast<std::size_t>(k) + 1] = f1;
    f0 = f1;
  }
  for (double& c : cum_) c /= total;
  for (double& f : slope_) f *= h / total;  // dF/dw per cell, w the position in the cell in [0, 1]
  cum_.back() = 1.0;
  order_ = moment / total;
  order_sd_ = std::sqrt(std::max(0.0, moment2 / total - order_ * order_));
}

double AxisAngleLaw::density(double u) const {
  // Shifted so that the largest value is 1 (no overflow at |kappa| = 1000).
  const double k = kappa_;
  if (dimension_ == 3) {
    if (kind_ == OrientationKind::Watson) return std::exp(k >= 0 ? k * (u * u - 1) : k * u * u);
    return std::exp(k >= 0 ? k * (u - 1) : k * (u + 1));
  }
  const double c = kind_ == OrientationKind::Watson ? std::cos(2 * u) : std::cos(u);
  return std::exp(k >= 0 ? k * (c - 1) : k * (c + 1));
}

double AxisAngleLaw::in_cell(std::size_t k, double w) const {
  // Cubic Hermite on the cell's CDF values and densities: error ~ h^4 F'''' (1e-9 at |kappa| = 1000).
  const double w2 = w * w, w3 = w2 * w;
  const double v = (2 * w3 - 3 * w2 + 1) * cum_[k] + (w3 - 2 * w2 + w) * slope_[k] + (-2 * w3 + 3 * w2) * cum_[k + 1] +
                   (w3 - w2) * slope_[k + 1];
  return std::clamp(v, cum_[k], cum_[k + 1]);
}

double AxisAngleLaw::cdf(double x) const {
  if (!(x > lo_)) return 0.0;
  if (!(x < hi_)) return 1.0;
  if (cum_.empty()) return (x - lo_) / (hi_ - lo_);
  const double s = (x - lo_) / (hi_ - lo_) * kCells;
  const auto k = std::min(static_cast<std::size_t>(s), static_cast<std::size_t>(kCells) - 1);
  return in_cell(k, s - static_cast<double>(k));
}

double AxisAngleLaw::quantile(double p) const {
  p = std::clamp(p, 0.0, 1.0);
  if (cum_.empty()) return lo_ + p * (hi_ - lo_);
  // The last node with cum <= p, then the cell's CDF inverted by bisection (monotone: clamped).
  const auto it = std::upper_bound(cum_.begin(), cum_.end(), p);
  auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cum_.begin() - 1));
  k = std::min(k, static_cast<std::size_t>(kCells) - 1);
  double a = 0.0, b = 1.0;
  for (int it2 = 0; it2 < 52; ++it2) {
    const double m = 0.5 * (a + b);
    (in_cell(k, m) < p ? a : b) = m;
  }
  return lo_ + (static_cast<double>(k) + 0.5 * (a + b)) * (hi_ - lo_) / kCells;
}

template <int D>
Eigen::Matrix<double, D, D> isotropic_rotation(Rng& rng) {
  if constexpr (D == 2) {
    return rotation_about<2>(Vec2::Zero(), 2 * kPi * rng.uniform01());
  } else {
    // Shoemake (1992): a uniform unit quaternion from three uniforms.
    const double u1 = rng.uniform01(), u2 = rng.uniform01(), u3 = rng.uniform01();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    return Eigen::Quaterniond(b * std::cos(2 * kPi * u3), a * std::sin(2 * kPi * u2), a * std::cos(2 * kPi * u2),
                              b * std::sin(2 * kPi * u3))
        .normalized()
        .toRotationMatrix();
  }
}

template <int D>
Eigen::Matrix<double, D, D> rotation_about(const Vec<D>& u, double angle) {
  if constexpr (D == 2) {
    (void)u;
    Eigen::Matrix2d r;
    r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return r;
  } else {
    return Eigen::AngleAxisd(angle, u).toRotationMatrix();
  }
}

template <int D>
OrientationLaw<D> OrientationLaw<D>::isotropic() {
  OrientationLaw law;
  law.axis_ = D == 3 ? Vec<D>::UnitZ() : Vec<D>::UnitX();  // where its test measures angles from
  law.angle_ = std::make_shared<AxisAngleLaw>(OrientationKind::Fisher, D, 0.0);
  return law;
}

template <int D>
OrientationLaw<D> OrientationLaw<D>::fixed(const Rotation& r) {
  OrientationLaw law;
  law.kind_ = OrientationKind::Fixed;
  law.fixed_ = r;
  return law;
}

template <int D>
OrientationLaw<D> OrientationLaw<D>::about_axis(OrientationKind kind, const Vec<D>& n, double kappa) {
  if (!(n.norm() > 0) || !n.allFinite()) throw std::invalid_argument("orientation law: the axis must be a non-zero vector");
  OrientationLaw law;
  law.kind_ = kind;
  law.axis_ = n.normalized();
  law.kappa_ = kappa;
  law.angle_ = std::make_shared<AxisAngleLaw>(kind, D, kappa);
  return law;
}

template <int D>
double OrientationLaw<D>::concentration_for_order(OrientationKind kind, double order) {
  auto order_at = [&](double kappa) { return AxisAngleLaw(kind, D, kappa).order(); };
  // watson: S rises from its girdle limit (3D -1/2, 2D -1) to 1; fisher's order is even in kappa.
  double lo = kind == OrientationKind::Watson ? -kMaxConcentration : 0.0, hi = kMaxConcentration;
  const double s_lo = order_at(lo), s_hi = order_at(hi);
  if (!(order >= s_lo && order <= s_hi)) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "the nematic order %.6g is beyond what the law reaches with |kappa| <= %g (%.6g to %.6g)",
                  order, kMaxConcentration, s_lo, s_hi);
    throw std::invalid_argument(buf);
  }
  for (int it = 0; it < 60 && hi - lo > 1e-9 * std::max(1.0, std::abs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (order_at(mid) < order ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

template <int D>
typename OrientationLaw<D>::Rotation OrientationLaw<D>::draw(Rng& rng) const {
  switch (kind_) {
    case OrientationKind::Isotropic: return isotropic_rotation<D>(rng);
    case OrientationKind::Fixed: return fixed_;
    default: break;
  }
  if constexpr (D == 2) {
    const double psi = angle_->quantile(rng.uniform01());
    return rotation_about<2>(Vec2::Zero(), std::atan2(axis_.y(), axis_.x()) + psi);
  } else {
    double t = angle_->quantile(rng.uniform01());
    if (kind_ == OrientationKind::Watson && rng.uniform01() < 0.5) t = -t;  // axial: a and -a alike
    const double azimuth = 2 * kPi * rng.uniform01(), spin = 2 * kPi * rng.uniform01();
    const Vec3 e1 = perpendicular(axis_), e2 = axis_.cross(e1);
    const double s = std::sqrt(std::max(0.0, 1 - t * t));
    const Vec3 a = (t * axis_ + s * (std::cos(azimuth) * e1 + std::sin(azimuth) * e2)).normalized();
    const Vec3 b1 = perpendicular(a), b2 = a.cross(b1);
    const Vec3 y = std::cos(spin) * b1 + std::sin(spin) * b2;
    Rotation r;
    r.col(0) = a;
    r.col(1) = y;
    r.col(2) = a.cross(y);
    return r;
  }
}

template <int D>
std::string OrientationLaw<D>::describe() const {
  char buf[200];
  switch (kind_) {
    case OrientationKind::Isotropic: return "isotropic";
    case OrientationKind::Fixed:
      if constexpr (D == 2) {
        std::snprintf(buf, sizeof buf, "fixed %.6g degrees", std::atan2(fixed_(1, 0), fixed_(0, 0)) * 180 / kPi);
      } else {
        Eigen::Quaterniond q(fixed_);
        if (q.w() < 0) q.coeffs() *= -1;
        std::snprintf(buf, sizeof buf, "fixed [%.6g, %.6g, %.6g, %.6g]", q.w(), q.x(), q.y(), q.z());
      }
      return buf;
    default: break;
  }
  std::string axis = "[";
  for (int a = 0; a < D; ++a) {
    std::snprintf(buf, sizeof buf, "%s%.6g", a ? ", " : "", axis_[a]);
    axis += buf;
  }
  std::snprintf(buf, sizeof buf, "%s about %s], kappa %.6g (order S %.4g)", kind_ == OrientationKind::Watson ? "watson" : "fisher",
                axis.c_str(), kappa_, angle_->order());
  return buf;
}

template <int D>
OrientationLaw<D> OrientationSpec::law() const {
  switch (kind) {
    case Kind::Isotropic: return OrientationLaw<D>::isotropic();
    case Kind::Fixed:
      if constexpr (D == 2) {
        return OrientationLaw<D>::fixed(rotation_about<2>(Vec2::Zero(), fixed.at(0) * kPi / 180.0));
      } else {
        return OrientationLaw<D>::fixed(
            Eigen::Quaterniond(fixed.at(0), fixed.at(1), fixed.at(2), fixed.at(3)).normalized().toRotationMatrix());
      }
    default: return OrientationLaw<D>::about_axis(kind, Eigen::Map<const Vec<D>>(axis.data()), kappa);
  }
}

template OrientationLaw<2> OrientationSpec::law<2>() const;
template OrientationLaw<3> OrientationSpec::law<3>() const;
template class OrientationLaw<2>;
template class OrientationLaw<3>;
template Eigen::Matrix<double, 2, 2> isotropic_rotation<2>(Rng&);
template Eigen::Matrix<double, 3, 3> isotropic_rotation<3>(Rng&);
template Eigen::Matrix<double, 2, 2> rotation_about<2>(const Vec<2>&, double);
template Eigen::Matrix<double, 3, 3> rotation_about<3>(const Vec<3>&, double);

}  // namespace fp
