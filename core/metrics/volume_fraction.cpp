#include "core/metrics/volume_fraction.hpp"

#include <cmath>
#include <stdexcept>

#include "core/metrics/compensated_sum.hpp"
#include "core/metrics/lens.hpp"

namespace fp {

template <int D>
double vf_reference_sphere(const Packing<D>& packing, const Vec<D>& center, double r_ref) {
  if (!(r_ref > 0.0) || !std::isfinite(r_ref))
    throw std::invalid_argument("vf_reference_sphere: r_ref must be positive and finite");
  CompensatedSum covered;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const double d = (packing.centers[i] - center).norm();
    const double r = packing.radii[i];
    if (d < r + r_ref) covered.add(ball_intersection_measure<D>(r, r_ref, d));
  }
  return covered.value() / ball_measure<D>(r_ref);
}

template <int D>
std::vector<std::pair<double, double>> vf_reference_curve(const Packing<D>& packing, const Vec<D>& center,
                                                          double r_from, double r_to, int count) {
  if (count < 1) throw std::invalid_argument("vf_reference_curve: count must be >= 1");
  if (!(r_from > 0.0) || !(r_to >= r_from) || !std::isfinite(r_to))
    throw std::invalid_argument("vf_reference_curve: need 0 < r_from <= r_to, finite");
  std::vector<std::pair<double, double>> curve;
  curve.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const double r = k == 0 ? r_from : k == count - 1 ? r_to : r_from + (r_to - r_from) * k / (count - 1);
    curve.emplace_back(r, vf_reference_sphere(packing, center, r));
  }
  return curve;
}

template <int D>
double vf_container(const Packing<D>& packing, double container_measure) {
  if (!(container_measure > 0.0) || !std::isfinite(container_measure))
    throw std::invalid_argument("vf_container: container_measure must be positive and finite");
  CompensatedSum solid;
  for (const double r : packing.radii) solid.add(ball_measure<D>(r));
  return solid.value() / container_measure;
}

template double vf_reference_sphere<2>(const Packing<2>&, const Vec<2>&, double);
template double vf_reference_sphere<3>(const Packing<3>&, const Vec<3>&, double);
template std::vector<std::pair<double, double>> vf_reference_curve<2>(const Packing<2>&, const Vec<2>&, double,
                                                                      double, int);
template std::vector<std::pair<double, double>> vf_reference_curve<3>(const Packing<3>&, const Vec<3>&, double,
                                                                      double, int);
template double vf_container<2>(const Packing<2>&, double);
template double vf_container<3>(const Packing<3>&, double);

}  // namespace fp
