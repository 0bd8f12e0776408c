#pragma once
// The standard normal distribution, written out so that every compiler draws the same numbers:
// CDF and tails from std::erfc / std::erf (never 1 - CDF, which loses the far tail), the
// quantile by Wichura's AS 241 (Applied Statistics 37(3), 1988; relative accuracy ~1e-16 for
// tail probabilities down to 1e-300), and the normal restricted to an interval [a, b], which
// the truncated normal and lognormal radius distributions sample by inverse CDF.
namespace fp {

double normal_pdf(double x);
/// Phi(x) = P(Z <= x); accurate (relatively) in the lower tail.
double normal_cdf(double x);
/// 1 - Phi(x) = P(Z > x); accurate (relatively) in the upper tail.
double normal_sf(double x);
/// log Phi(x), finite for every finite x (asymptotic continued fraction where Phi underflows).
double normal_log_cdf(double x);
/// x with Phi(x) = p, for p in (0, 1); -inf for p <= 0, +inf for p >= 1.
double normal_quantile(double p);
/// x with Phi(x) - 1/2 = h, for h in (-1/2, 1/2): keeps full precision when Phi(x) is near 1/2.
double normal_quantile_centred(double h);

/// Z ~ N(0, 1) conditioned on a <= Z <= b (a < b, both finite). Every probability is taken on
/// the side of the interval where it is small (lower tail, upper tail, or centred on 1/2), so
/// the CDF and the inverse CDF keep their relative accuracy far in either tail.
class TruncatedStandardNormal {
 public:
  TruncatedStandardNormal(double a, double b);

  double lower() const { return a_; }
  double upper() const { return b_; }
  /// P(a <= Z <= b) of the untruncated normal; 0 if it underflows (see log_mass).
  double mass() const { return mass_; }
  /// log P(a <= Z <= b), finite even where mass() underflows.
  double log_mass() const;
  /// Inverse CDF: u in [0, 1] to z in [a, b] (non-decreasing in u up to rounding).
  double quantile(double u) const;
  double cdf(double z) const;
  /// E[Z | a <= Z <= b]; needs mass() > 0.
  double mean() const;

 private:
  enum class Side { Lower, Centre, Upper };
  /// Phi(z), Phi(z) - 1/2 or 1 - Phi(z), depending on side_.
  double coordinate(double z) const;

  double a_, b_;
  Side side_;
  double ca_, cb_;  // coordinate(a), coordinate(b)
  double mass_;
};

}  // namespace fp
