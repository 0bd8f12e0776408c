#include "core/metrics/ball_box.hpp"

#include <algorithm>
#include <utility>
#include <array>
#include <cmath>


namespace fp {
namespace {

// Sorts the first n entries (a handful; std::sort here makes GCC 12 warn about bounds it cannot see).
template <std::size_t N>
void sort_first(std::array<double, N>& a, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && a[j - 1] > a[j]; --j) std::swap(a[j - 1], a[j]);
}

// int_0^x sqrt(r^2 - t^2) dt for |x| <= r.
double half_chord_integral(double r, double x) {
  const double u = std::clamp(x / r, -1.0, 1.0);
  return 0.5 * r * r * (u * std::sqrt(std::max(0.0, 1.0 - u * u)) + std::asin(u));
}

// Area of the disk (origin, r) inside [x0, x1] x [y0, y1], exact.
double disk_rect_area(double r, double x0, double x1, double y0, double y1) {
  x0 = std::max(x0, -r), x1 = std::min(x1, r);
  if (!(x1 > x0) || !(y1 > y0) || !(r > 0.0)) return 0.0;
  // Abscissae where the half-chord h(x) = sqrt(r^2 - x^2) equals |y0| or |y1|.
  std::array<double, 6> cuts{};
  int n = 0;
  cuts[n++] = x0;
  for (const double y : {y0, y1})
    if (std::abs(y) < r) {
      const double x = std::sqrt(r * r - y * y);
      for (const double s : {-x, x})
        if (s > x0 && s < x1) cuts[n++] = s;
    }
  cuts[n++] = x1;
  sort_first(cuts, n);
  double area = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b > a)) continue;
    const double m = 0.5 * (a + b), h = std::sqrt(std::max(0.0, r * r - m * m));
    const bool top_circle = h < y1, bottom_circle = -h > y0;
    const double top = top_circle ? h : y1, bottom = bottom_circle ? -h : y0;
    if (!(top > bottom)) continue;  // the chord misses [y0, y1] on this piece
    const double circle = half_chord_integral(r, b) - half_chord_integral(r, a);
    area += (top_circle ? circle : y1 * (b - a)) - (bottom_circle ? -circle : y0 * (b - a));
  }
  return area;
}

// 20-point Gauss-Legendre on [-1, 1] (nodes and weights of the positive half).
constexpr std::array<double, 10> kNodes{0.0765265211334973, 0.2277858511416451, 0.3737060887154195,
                                        0.5108670019508271, 0.6360536807265150, 0.7463319064601508,
                                        0.8391169718222188, 0.9122344282513259, 0.9639719272779138,
                                        0.9931285991850949};
constexpr std::array<double, 10> kWeights{0.1527533871307258, 0.1491729864726037, 0.1420961093183820,
                                          0.1316886384491766, 0.1181945319615184, 0.1019301198172404,
                                          0.0832767415767048, 0.0626720483341091, 0.0406014298003869,
                                          0.0176140071391521};

double ball_box_3d(double r, const Vec3& lo, const Vec3& hi) {
  const double z0 = std::max(lo.z(), -r), z1 = std::min(hi.z(), r);
  if (!(z1 > z0)) return 0.0;
  // Heights where the section's radius equals the distance to an edge line or a corner.
  std::array<double, 2 + 2 * 8> cuts{};
  int n = 0;
  cuts[n++] = z0;
  auto add = [&](double s2) {
    if (!(s2 < r * r)) return;
    const double z = std::sqrt(r * r - s2);
    for (const double t : {-z, z})
      if (t > z0 && t < z1) cuts[n++] = t;
  };
  for (const double x : {lo.x(), hi.x()}) add(x * x);
  for (const double y : {lo.y(), hi.y()}) add(y * y);
  for (const double x : {lo.x(), hi.x()})
    for (const double y : {lo.y(), hi.y()}) add(x * x + y * y);
  cuts[n++] = z1;
  sort_first(cuts, n);
  double v = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b > a)) continue;
    // z = a + (b - a) s(t), s = 3t^2 - 2t^3: the area's kinks at the ends, (z - a)^(1/2) or
    // (z - a)^(3/2), become smooth in t, where Gauss-Legendre converges fast.
    double s = 0.0;
    for (std::size_t q = 0; q < kNodes.size(); ++q)
      for (const double t : {0.5 - 0.5 * kNodes[q], 0.5 + 0.5 * kNodes[q]}) {
        const double z = a + (b - a) * t * t * (3 - 2 * t);
        const double rho = std::sqrt(std::max(0.0, r * r - z * z));
        s += kWeights[q] * 6 * t * (1 - t) * disk_rect_area(rho, lo.x(), hi.x(), lo.y(), hi.y());
      }
    v += 0.5 * (b - a) * s;
  }
  return v;
}

}  // namespace

template <int D>
double ball_box_measure(const Vec<D>& c, double r, const Vec<D>& lo, const Vec<D>& hi) {
  if (!(r > 0.0)) return 0.0;
  // In the ball's frame; count the face planes that cut it.
  const Vec<D> a = lo - c, b = hi - c;
  int cutting = 0, axis = 0;
  for (int k = 0; k < D; ++k) {
    if (a[k] >= r || b[k] <= -r || !(b[k] > a[k])) return 0.0;  // disjoint (or an empty box)
    if (a[k] > -r) ++cutting, axis = k;
    if (b[k] < r) ++cutting, axis = k;
  }
  if (cutting == 0) return ball_measure<D>(r);
  if (cutting == 1) return ball_inside_plane<D>(r, a[axis] > -r ? -a[axis] : b[axis]);  // a cap cut off
  if constexpr (D == 2) return disk_rect_area(r, a.x(), b.x(), a.y(), b.y());
  else return ball_box_3d(r, a, b);
}

template double ball_box_measure<2>(const Vec2&, double, const Vec2&, const Vec2&);
template double ball_box_measure<3>(const Vec3&, double, const Vec3&, const Vec3&);

}  // namespace fp
