#pragma once
// The orientation law of a particle template: how the rotation (body frame -> world frame) of
// each particle is drawn, and the distribution functions that test it (core/metrics/
// orientation_fit.hpp). The law acts on the body x axis `a` (a capsule's or cylinder's axis, an
// ellipsoid's first semi-axis, a polyhedron's x as its vertices were written):
//  * isotropic: uniform rotations (Haar measure; 3D: Shoemake 1992, 2D: a uniform angle);
//  * fixed: one rotation for every particle;
//  * about an axis n, with a concentration kappa (3D: a's angle to n drawn from the law, the
//    azimuth of a around n and the spin of the body about a uniform; 2D: the angle psi from n):
//      watson  3D p(a) ~ exp(kappa (a.n)^2)       axial (a and -a alike); kappa < 0: a girdle around n
//              2D p(psi) ~ exp(kappa cos 2 psi)    axial von Mises
//      fisher  3D p(a) ~ exp(kappa a.n)           von Mises-Fisher (polar: a points along n)
//              2D p(psi) ~ exp(kappa cos psi)      von Mises
//    Instead of kappa, the nematic order S the law is to have: 3D <P2(a.n)> = (3 <(a.n)^2> - 1) / 2,
//    2D <cos 2 psi>; the law's kappa is then solved for (bisection on the tabulated moments).
// The law's scalar variable u (3D: a.n folded to [0, 1] for watson, a.n in [-1, 1] for fisher; 2D:
// psi in [-pi, pi]) has its CDF tabulated on a fine grid (Simpson per cell, cubic Hermite within a
// cell), which sampling inverts: exact to ~1e-9 in probability for |kappa| <= kMaxConcentration.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/vec.hpp"
#include "core/sampling/rng.hpp"

namespace fp {

/// The largest |kappa| a law takes (3D watson at 1000: S = 0.9985).
inline constexpr double kMaxConcentration = 1000.0;

enum class OrientationKind { Isotropic, Fixed, Watson, Fisher };

/// The distribution of the law's scalar variable u on [lo, hi], tabulated.
class AxisAngleLaw {
 public:
  /// `kind` Watson or Fisher, in dimension D (2 or 3), with concentration kappa.
  AxisAngleLaw(OrientationKind kind, int dimension, double kappa);
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  /// P(u <= x), continuous, 0 below lo and 1 above hi.
  double cdf(double x) const;
  /// The u of probability p in [0, 1] (the inverse of cdf).
  double quantile(double p) const;
  /// E[g(u)] for the law's nematic order: 3D <P2(a.n)>, 2D <cos 2 psi>.
  double order() const { return order_; }
  /// The standard deviation of that variable (P2(a.n), cos 2 psi) under the law: a sample of n
  /// has its mean within about 3 order_sd() / sqrt(n) of order().
  double order_sd() const { return order_sd_; }

 private:
  double density(double u) const;  ///< unnormalised
  double in_cell(std::size_t k, double w) const;  ///< the CDF at position w in [0, 1] of cell k
  OrientationKind kind_;
  int dimension_;
  double kappa_, lo_, hi_, order_ = 0.0, order_sd_ = 0.0;
  std::vector<double> cum_;    ///< normalised CDF at the grid nodes lo + k (hi - lo) / cells
  std::vector<double> slope_;  ///< its derivative there, per cell width
};

/// The law of a template's orientations.
template <int D>
class OrientationLaw {
 public:
  using Rotation = Eigen::Matrix<double, D, D>;

  static OrientationLaw isotropic();
  static OrientationLaw fixed(const Rotation& r);
  /// Watson or Fisher about the unit axis n (any length: normalised) with concentration kappa.
  static OrientationLaw about_axis(OrientationKind kind, const Vec<D>& n, double kappa);
  /// The kappa giving nematic order S (see above); throws std::invalid_argument when no |kappa|
  /// <= kMaxConcentration reaches it.
  static double concentration_for_order(OrientationKind kind, double order);

  OrientationKind kind() const { return kind_; }
  /// Draws a rotation (deterministic in rng: isotropic uses 3 uniforms in 3D, 1 in 2D).
  Rotation draw(Rng& rng) const;
  const Rotation& fixed_rotation() const { return fixed_; }
  /// The law's axis n: watson's and fisher's; isotropic: z (3D) or x (2D), the axis its test
  /// measures angles from (an isotropic law is fisher with kappa 0 about any axis).
  const Vec<D>& axis() const { return axis_; }
  double concentration() const { return kappa_; }
  /// The tabulated law of the angle variable (watson, fisher; isotropic: fisher with kappa 0),
  /// or null (fixed).
  const AxisAngleLaw* angle_law() const { return angle_.get(); }
  /// Whether a rotation about the body axis keeps a sample of the law a sample of it: the spin
  /// is uniform and independent of the axis (isotropic, watson and fisher in 3D).
  bool free_spin() const { return D == 3 && kind_ != OrientationKind::Fixed; }
  /// "isotropic", "fixed [w, x, y, z]", "watson about [0, 0, 1], kappa 5 (S 0.64)".
  std::string describe() const;

 private:
  OrientationKind kind_ = OrientationKind::Isotropic;
  Rotation fixed_ = Rotation::Identity();
  Vec<D> axis_ = Vec<D>::UnitX();
  double kappa_ = 0.0;
  std::shared_ptr<const AxisAngleLaw> angle_;
};

/// A law as a scene writes it (plain data; OrientationLaw is what draws and tests).
struct OrientationSpec {
  using Kind = OrientationKind;
  Kind kind = Kind::Isotropic;  ///< uniform random rotations (Haar), one fixed rotation, or a law about an axis
  std::vector<double> fixed;    ///< Fixed: 2D [angle in degrees]; 3D [w, x, y, z] unit quaternion
  std::vector<double> axis;     ///< Watson, Fisher: the law's axis (D components, unit)
  double kappa = 0.0;           ///< Watson, Fisher: the concentration (as written, or solved from the order S written)

  /// The law this describes, in dimension D.
  template <int D>
  OrientationLaw<D> law() const;
};

/// A uniform random rotation (Haar measure; 2D: a uniform angle).
template <int D>
Eigen::Matrix<double, D, D> isotropic_rotation(Rng& rng);

/// The rotation by `angle` about the unit axis u (3D), or by `angle` (2D, u ignored).
template <int D>
Eigen::Matrix<double, D, D> rotation_about(const Vec<D>& u, double angle);

}  // namespace fp
