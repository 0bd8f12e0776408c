#include "core/sampling/standard_normal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fp {
namespace {

constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt2Pi = 0.39894228040143267794;
constexpr double kHalfLog2Pi = 0.91893853320467274178;

// AS 241 (PPND16). q = p - 1/2; tail = min(p, 1 - p), supplied by the caller at full precision.
double as241(double q, double tail) {
  if (std::fabs(q) <= 0.425) {
    const double r = 0.180625 - q * q;
    return q *
           (((((((2.5090809287301226727e+3 * r + 3.3430575583588128105e+4) * r +
                 6.7265770927008700853e+4) * r + 4.5921953931549871457e+4) * r +
               1.3731693765509461125e+4) * r + 1.9715909503065514427e+3) * r +
             1.3314166789178437745e+2) * r + 3.3871328727963666080e+0) /
           (((((((5.2264952788528545610e+3 * r + 2.8729085735721942674e+4) * r +
                 3.9307895800092710610e+4) * r + 2.1213794301586595867e+4) * r +
               5.3941960214247511077e+3) * r + 6.8718700749205790830e+2) * r +
             4.2313330701600911252e+1) * r + 1.0);
  }
  const double inf = std::numeric_limits<double>::infinity();
  if (!(tail > 0.0)) return q < 0.0 ? -inf : inf;
  double r = std::sqrt(-std::log(tail));
  double x;
  if (r <= 5.0) {
    r -= 1.6;
    x = (((((((7.74545014278341407640e-4 * r + 2.27238449892691845833e-2) * r +
              2.41780725177450611770e-1) * r + 1.27045825245236838258e+0) * r +
            3.64784832476320460504e+0) * r + 5.76949722146069140550e+0) * r +
          4.63033784615654529590e+0) * r + 1.42343711074968357734e+0) /
        (((((((1.05075007164441684324e-9 * r + 5.47593808499534494600e-4) * r +
              1.51986665636164571966e-2) * r + 1.48103976427480074590e-1) * r +
            6.89767334985100004550e-1) * r + 1.67638483018380384940e+0) * r +
          2.05319162663775882187e+0) * r + 1.0);
  } else {
    r -= 5.0;
    x = (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r +
              1.24266094738807843860e-3) * r + 2.65321895265761230930e-2) * r +
            2.96560571828504891230e-1) * r + 1.78482653991729133580e+0) * r +
          5.46378491116411436990e+0) * r + 6.65790464350110377720e+0) /
        (((((((2.04426310338993978564e-15 * r + 1.42151175831644588870e-7) * r +
              1.84631831751005468180e-5) * r + 7.86869131145613259100e-4) * r +
            1.48753612908506148525e-2) * r + 1.36929880922735805310e-1) * r +
          5.99832206555887937690e-1) * r + 1.0);
  }
  return q < 0.0 ? -x : x;
}

// Mills ratio (1 - Phi(x)) / phi(x) for x >= 5 by its continued fraction
// 1 / (x + 1 / (x + 2 / (x + 3 / (x + ...)))), evaluated from the bottom.
double mills_ratio(double x) {
  double t = x;
  for (int k = 60; k >= 1; --k) t = x + k / t;
  return 1.0 / t;
}

// Below this, Phi(x) is taken from its asymptotic form (erfc underflows near -37.5).
constexpr double kLogCdfAsymptotic = -30.0;

}  // namespace

double normal_pdf(double x) { return kInvSqrt2Pi * std::exp(-0.5 * x * x); }
double normal_cdf(double x) { return 0.5 * std::erfc(-x * kInvSqrt2); }
double normal_sf(double x) { return 0.5 * std::erfc(x * kInvSqrt2); }

double normal_log_cdf(double x) {
  if (x < kLogCdfAsymptotic) return -0.5 * x * x - kHalfLog2Pi + std::log(mills_ratio(-x));
  if (x > 0.0) return std::log1p(-normal_sf(x));
  return std::log(normal_cdf(x));
}

double normal_quantile(double p) {
  if (!(p > 0.0)) return -std::numeric_limits<double>::infinity();
  if (!(p < 1.0)) return std::numeric_limits<double>::infinity();
  return as241(p - 0.5, std::min(p, 1.0 - p));
}

double normal_quantile_centred(double h) {
  // 0.5 - |h| is exact for |h| in [1/4, 1/2] (Sterbenz), which covers the tail branch.
  return as241(h, 0.5 - std::fabs(h));
}

TruncatedStandardNormal::TruncatedStandardNormal(double a, double b) : a_(a), b_(b) {
  // Centred on 1/2 where the interval straddles 0 or stays close to it (there Phi - 1/2 keeps
  // relative precision while Phi and 1 - Phi do not); otherwise the tail holding the interval.
  const bool centre = (a < 0.0 && b > 0.0) || (a > -1.0 && b < 1.0);
  side_ = centre ? Side::Centre : (b <= 0.0 ? Side::Lower : Side::Upper);
  ca_ = coordinate(a);
  cb_ = coordinate(b);
  mass_ = side_ == Side::Upper ? ca_ - cb_ : cb_ - ca_;
}

double TruncatedStandardNormal::coordinate(double z) const {
  switch (side_) {
    case Side::Lower: return normal_cdf(z);
    case Side::Upper: return normal_sf(z);
    case Side::Centre: break;
  }
  return 0.5 * std::erf(z * kInvSqrt2);
}

double TruncatedStandardNormal::log_mass() const {
  if (side_ == Side::Centre) return std::log(mass_);
  // Tail side: log(P(near end) - P(far end)) from the log-CDFs, which never underflow.
  const double near_end = side_ == Side::Lower ? normal_log_cdf(b_) : normal_log_cdf(-a_);
  const double far_end = side_ == Side::Lower ? normal_log_cdf(a_) : normal_log_cdf(-b_);
  return near_end + std::log(-std::expm1(far_end - near_end));
}

double TruncatedStandardNormal::quantile(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  // (1 - u) ca + u cb rather than ca + u (cb - ca): exact at both ends even when cb is far
  // below the rounding error of ca (a far upper tail).
  const double c = (1.0 - u) * ca_ + u * cb_;
  double z;
  switch (side_) {
    case Side::Lower: z = normal_quantile(c); break;
    case Side::Upper: z = -normal_quantile(c); break;
    default: z = normal_quantile_centred(c); break;
  }
  return std::clamp(z, a_, b_);
}

double TruncatedStandardNormal::cdf(double z) const {
  if (!(z > a_)) return 0.0;
  if (!(z < b_)) return 1.0;
  const double c = coordinate(z);
  const double f = side_ == Side::Upper ? (ca_ - c) / mass_ : (c - ca_) / mass_;
  return std::clamp(f, 0.0, 1.0);
}

double TruncatedStandardNormal::mean() const {
  // phi(a) - phi(b) without cancellation: factor out the larger density, d = (b^2 - a^2) / 2.
  const double d = 0.5 * (b_ - a_) * (b_ + a_);
  const double diff = std::fabs(a_) <= std::fabs(b_) ? normal_pdf(a_) * -std::expm1(-d)
                                                    : normal_pdf(b_) * std::expm1(d);
  return std::clamp(diff / mass_, a_, b_);
}

}  // namespace fp
