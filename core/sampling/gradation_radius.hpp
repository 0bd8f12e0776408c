#pragma once
// A geotechnical grading (sieve) curve as a radius distribution.
//
// Input: points (d_j, P_j): sieve diameter d_j (strictly increasing, > 0) and the percent
// passing P_j (non-decreasing, P_0 = 0 at the smallest sieve, P_last = 100 at the largest).
// Model:
//  * Between two sieves the percent passing is linear in log(d), as grading curves are plotted:
//    P(d) = P_i + (P_{i+1} - P_i) ln(d / d_i) / ln(d_{i+1} / d_i). No particle is smaller than
//    d_0 or larger than d_last.
//  * Basis::Count: P is the percent passing by number of particles, so within a bin the count
//    density is uniform in ln d.
//  * Basis::Mass: P is the percent passing by mass. Particle mass is proportional to d^3
//    (dimension 3, spheres) or to d^2 (dimension 2, disks of unit thickness), so within bin i
//    the count density in s = ln d is proportional to (w_i / L_i) exp(-k s), k = 3 or 2,
//    with w_i = (P_{i+1} - P_i) / 100 and L_i = ln(d_{i+1} / d_i).
//    The dimension is ignored by Basis::Count.
// The radius is r = d / 2; cdf() is always the CDF of r BY COUNT (what a packing's radii are
// compared with); passing_fraction() is the input curve in its own basis.
// Sampling is exact, two draws per radius: uniform01() picks the bin by its count probability,
// uniform01() then inverts the bin's count CDF in ln d in closed form.
#include <utility>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

class GradationRadius final : public RadiusDistribution {
 public:
  enum class Basis { Mass, Count };

  /// Throws std::invalid_argument for fewer than 2 points, non-increasing or non-positive
  /// diameters, percentages outside [0, 100] or decreasing, a first point other than 0 % or a
  /// last point other than 100 %, or a dimension other than 2 or 3.
  GradationRadius(std::vector<std::pair<double, double>> diameter_percent_passing, Basis basis,
                  int dimension);

  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return r_min_; }
  double r_max() const override { return r_max_; }
  double mean() const override { return mean_; }
  std::string describe() const override;

  /// The input curve as a fraction in [0, 1], in the input basis, at sieve diameter d.
  double passing_fraction(double diameter) const;
  Basis basis() const { return basis_; }
  int dimension() const { return dimension_; }
  const std::vector<std::pair<double, double>>& points() const { return points_; }

 private:
  /// Fraction of the count of bin i below diameter d (d in the bin).
  double bin_count_cdf(std::size_t i, double d) const;

  std::vector<std::pair<double, double>> points_;
  Basis basis_;
  int dimension_;
  double k_;                           // count density ~ exp(-k ln d) within a bin: 0, 2 or 3
  std::vector<double> log_width_;      // L_i = ln(d_{i+1} / d_i)
  std::vector<double> count_prob_;     // probability by count of bin i
  std::vector<double> count_cumulative_;  // P(D <= d_{i+1}) by count; 1 exactly from the last drawable bin
  double r_min_ = 0.0, r_max_ = 0.0, mean_ = 0.0;
};

}  // namespace fp
