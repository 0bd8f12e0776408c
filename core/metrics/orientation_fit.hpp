#pragma once
// The test of a template's orientations against its law (core/sampling/orientation_law.hpp), the
// orientation counterpart of radii_fit.hpp: no density lever may bias the orientations without
// the verdict saying so. The body x axis a = R e_x of each rotation R is read as the law draws it:
//   fixed     the largest angle between a rotation and the law's (p = 1 within kOrientationSlack, else 0);
//   otherwise one-sample Kolmogorov-Smirnov tests (core/sampling/ks_test.hpp) of
//     3D  polar    a.n (watson: |a.n|) against the law's tabulated CDF (isotropic: uniform on [-1, 1], n = z)
//         azimuth  the angle of a around n, against uniform
//         spin     the angle of R e_y around a (from a reference perpendicular to a), against uniform
//     2D  angle    psi, the angle from n to a, against the law's CDF (isotropic: uniform)
// Beside the tests, the sample's nematic order about n (3D <P2(a.n)>, 2D <cos 2 psi>) and the
// law's, with the sampling noise of a sample of that size.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/sampling/orientation_law.hpp"

namespace fp {

/// The angle (radians) by which a rotation may differ from a fixed law's and still be it: files
/// carry quaternions in decimals, whose rounding this absorbs.
inline constexpr double kOrientationSlack = 1e-9;
/// Default level of the orientation tests, shared by them (Bonferroni), beside the size tests'.
inline constexpr double kOrientationAlpha = 1e-3;

struct OrientationFit {
  struct Test {
    std::string name;  ///< "polar", "azimuth", "spin", "angle" or "fixed"
    double statistic = std::numeric_limits<double>::quiet_NaN();  ///< K-S D_n; fixed: the largest angle (radians)
    double p = std::numeric_limits<double>::quiet_NaN();
  };
  std::string law;          ///< OrientationLaw::describe()
  std::uint64_t n = 0;      ///< rotations tested (0: not computed)
  std::vector<Test> tests;  ///< empty when not computed
  double order = std::numeric_limits<double>::quiet_NaN();      ///< the sample's nematic order about the law's axis
  double law_order = std::numeric_limits<double>::quiet_NaN();  ///< the law's
  double order_noise = std::numeric_limits<double>::quiet_NaN();  ///< sd of a sample's order under the law (n rotations)

  bool computed() const { return n > 0; }
  /// Every test's p >= level (or not computed).
  bool passes(double level) const;
  /// "polar K-S D = 0.02, p = 0.5; azimuth ...; order S 0.012 (law 0, noise 0.016)".
  std::string describe() const;
};

/// The test of `rotations` (any order) against `law`; none gives the default (not computed).
template <int D>
OrientationFit orientation_fit(const std::vector<Eigen::Matrix<double, D, D>>& rotations, const OrientationLaw<D>& law);

}  // namespace fp
