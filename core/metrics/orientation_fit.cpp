#include "core/metrics/orientation_fit.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/sampling/ks_test.hpp"

namespace fp {
namespace {

/// A unit vector perpendicular to the unit vector u, a deterministic function of u (any works: a
/// uniform angle measured from it stays uniform).
Vec3 reference_perpendicular(const Vec3& u) {
  const Vec3 ref = std::abs(u.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  return (ref - ref.dot(u) * u).normalized();
}

OrientationFit::Test ks_test(const char* name, std::vector<double> x, const std::function<double(double)>& cdf) {
  OrientationFit::Test t;
  t.name = name;
  const std::size_t n = x.size();
  t.statistic = ks_statistic(std::move(x), cdf);
  t.p = ks_pvalue(t.statistic, n);
  return t;
}

double uniform_angle_cdf(double phi) { return std::clamp((phi + kPi) / (2 * kPi), 0.0, 1.0); }

}  // namespace

bool OrientationFit::passes(double level) const {
  for (const Test& t : tests)
    if (t.p < level) return false;
  return true;
}

std::string OrientationFit::describe() const {
  if (!computed()) return "not computed";
  std::string s;
  char buf[160];
  for (const Test& t : tests) {
    if (t.name == "fixed") std::snprintf(buf, sizeof buf, "fixed: largest deviation %.3g rad, p = %g", t.statistic, t.p);
    else std::snprintf(buf, sizeof buf, "%s K-S D = %.4g, p = %.3g", t.name.c_str(), t.statistic, t.p);
    s += (s.empty() ? "" : "; ") + std::string(buf);
  }
  if (std::isfinite(order)) {
    std::snprintf(buf, sizeof buf, "; order S %.4f (law %.4f, noise %.4f)", order, law_order, order_noise);
    s += buf;
  }
  return s;
}

template <int D>
OrientationFit orientation_fit(const std::vector<Eigen::Matrix<double, D, D>>& rotations, const OrientationLaw<D>& law) {
  OrientationFit fit;
  if (rotations.empty()) return fit;
  fit.law = law.describe();
  fit.n = rotations.size();
  const std::size_t n = rotations.size();
  if (law.kind() == OrientationKind::Fixed) {
    double worst = 0.0;
    for (const auto& R : rotations) {
      const Eigen::Matrix<double, D, D> E = law.fixed_rotation().transpose() * R;
      double angle;
      if constexpr (D == 2) angle = std::abs(std::atan2(E(1, 0), E(0, 0)));
      else angle = Eigen::AngleAxisd(E).angle();
      worst = std::max(worst, std::isfinite(angle) ? angle : std::numeric_limits<double>::infinity());
    }
    fit.tests.push_back({"fixed", worst, worst <= kOrientationSlack ? 1.0 : 0.0});
    return fit;
  }
  const AxisAngleLaw& angle = *law.angle_law();
  const Vec<D> axis = law.axis();
  auto cdf = [&angle](double u) { return angle.cdf(u); };
  double order_sum = 0.0;
  if constexpr (D == 2) {
    const double base = std::atan2(axis.y(), axis.x());
    std::vector<double> psi(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double phi = std::atan2(rotations[i](1, 0), rotations[i](0, 0));
      psi[i] = std::remainder(phi - base, 2 * kPi);  // in [-pi, pi]
      order_sum += std::cos(2 * psi[i]);
    }
    fit.tests.push_back(ks_test("angle", std::move(psi), cdf));
  } else {
    const Vec3 e1 = reference_perpendicular(axis), e2 = axis.cross(e1);
    const bool axial = law.kind() == OrientationKind::Watson;
    std::vector<double> polar(n), azimuth(n), spin(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 a = rotations[i].col(0).normalized(), y = rotations[i].col(1);
      const double t = std::clamp(a.dot(axis), -1.0, 1.0);
      polar[i] = axial ? std::abs(t) : t;
      azimuth[i] = std::atan2(a.dot(e2), a.dot(e1));
      const Vec3 b1 = reference_perpendicular(a), b2 = a.cross(b1);
      spin[i] = std::atan2(y.dot(b2), y.dot(b1));
      order_sum += 1.5 * t * t - 0.5;
    }
    fit.tests.push_back(ks_test("polar", std::move(polar), cdf));
    fit.tests.push_back(ks_test("azimuth", std::move(azimuth), uniform_angle_cdf));
    fit.tests.push_back(ks_test("spin", std::move(spin), uniform_angle_cdf));
  }
  fit.order = order_sum / static_cast<double>(n);
  fit.law_order = angle.order();
  fit.order_noise = angle.order_sd() / std::sqrt(static_cast<double>(n));
  return fit;
}

template OrientationFit orientation_fit<2>(const std::vector<Eigen::Matrix<double, 2, 2>>&, const OrientationLaw<2>&);
template OrientationFit orientation_fit<3>(const std::vector<Eigen::Matrix<double, 3, 3>>&, const OrientationLaw<3>&);

}  // namespace fp
