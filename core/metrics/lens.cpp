#include "core/metrics/lens.hpp"

#include <algorithm>
#include <cmath>

namespace fp {
namespace {

// theta - sin(2 theta) / 2: the area of the circular segment of half-angle theta on a unit
// circle. For small theta the two terms cancel, so the Taylor series is used there.
double segment_shape(double theta) {
  if (theta < 0.1) {
    const double t2 = theta * theta;
    return theta * t2 *
           (2.0 / 3.0 - t2 * (2.0 / 15.0 - t2 * (4.0 / 315.0 - t2 * (2.0 / 2835.0 - t2 * (4.0 / 155925.0)))));
  }
  return theta - 0.5 * std::sin(2.0 * theta);
}

}  // namespace

double lens_volume(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) return ball_measure<3>(std::min(r1, r2));
  // Here d > |r1 - r2| >= 0, so the division is safe; every factor of the numerator scales with
  // d near d -> |r1 - r2|, so there is no cancellation for nearly concentric equal spheres.
  const double s = r1 + r2 - d;
  const double dr = r1 - r2;
  return kPi * s * s * (d * d - 3.0 * dr * dr + 2.0 * d * (r1 + r2)) / (12.0 * d);
}

double lens_area(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) return ball_measure<2>(std::min(r1, r2));
  // Sum of the two circular segments cut by the common chord. x_i: signed distance from centre
  // i to the chord (negative when the chord lies beyond the centre); h: half chord, from Heron's
  // formula written as a product so that it keeps full relative precision near tangency. The
  // half-angles come from atan2 rather than acos, which loses half the digits near tangency.
  const double x1 = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
  const double x2 = d - x1;
  const double h = std::sqrt(std::max(0.0, (r1 + r2 - d) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2))) /
                   (2.0 * d);
  return r1 * r1 * segment_shape(std::atan2(h, x1)) + r2 * r2 * segment_shape(std::atan2(h, x2));
}

}  // namespace fp
