#include "shapes/ball_union.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fp {

namespace {

constexpr double kTwoPi = 2 * kPi;

/// Disks that add nothing to the union: inside another one (of two equal disks, the later one).
std::vector<char> hidden_disks(std::span<const Ball<2>> disks) {
  const std::size_t n = disks.size();
  std::vector<char> hidden(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double ri = disks[i].radius;
    if (!(ri > 0)) { hidden[i] = 1; continue; }
    for (std::size_t j = 0; j < n && !hidden[i]; ++j) {
      const double rj = disks[j].radius;
      if (j == i || !(rj > 0)) continue;
      const double d = (disks[i].center - disks[j].center).norm();
      if (d + ri < rj || (d + ri == rj && (ri < rj || j < i))) hidden[i] = 1;
    }
  }
  return hidden;
}

/// Gauss–Kronrod 7/15 nodes and weights (QUADPACK qk15).
constexpr std::array<double, 8> kXgk = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                        0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kWgk = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kWg = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <class F>
double gauss_kronrod(const F& f, double a, double b, double tol, int depth) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double kronrod = kWgk[7] * fc, gauss = kWg[3] * fc;
  for (int k = 0; k < 7; ++k) {
    const double s = f(c - h * kXgk[k]) + f(c + h * kXgk[k]);
    kronrod += kWgk[k] * s;
    if (k % 2 == 1) gauss += kWg[k / 2] * s;
  }
  kronrod *= h;
  gauss *= h;
  if (std::abs(kronrod - gauss) <= tol || depth >= 40) return kronrod;
  return gauss_kronrod(f, a, c, 0.5 * tol, depth + 1) + gauss_kronrod(f, c, b, 0.5 * tol, depth + 1);
}

/// Per ball, the index of one ball of its group of overlapping balls. Groups are apart: their
/// outlines (2D) and slices (3D) never meet, so the union's measure is the sum of theirs.
template <int D>
std::vector<std::size_t> overlap_groups(std::span<const Ball<D>> balls) {
  std::vector<std::size_t> parent(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) parent[i] = i;
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      if ((balls[j].center - balls[i].center).norm() < balls[i].radius + balls[j].radius) parent[root(j)] = root(i);
  for (std::size_t i = 0; i < balls.size(); ++i) parent[i] = root(i);
  return parent;
}

/// The measure of a union of balls, group by group, each moved to one of its own centres and
/// scaled by a power of two to a largest radius of about 1 (both exact), measured by
/// `connected`, and scaled back. Taken as given, a group of small balls far from the origin
/// lost its digits: two disks of radius 1e-6 at distance 1 had an area of pure rounding (even
/// negative); the quadrature of a group of radius 1e-80 had a tolerance that underflowed to 0
/// and never converged (2^40 evaluations: cluster templates hung the scene's reading).
template <int D, class Measure>
double measure_by_groups(std::span<const Ball<D>> balls, const Measure& connected) {
  const std::vector<std::size_t> group = overlap_groups<D>(balls);
  std::vector<Ball<D>> members;
  double measure = 0.0;
  for (std::size_t g = 0; g < balls.size(); ++g) {
    double largest = 0.0;
    for (std::size_t i = 0; i < balls.size(); ++i)
      if (group[i] == g) largest = std::max(largest, balls[i].radius);
    if (!(largest > 0)) continue;  // no group here, or no ball of positive radius in it
    const int e = std::ilogb(largest);
    members.clear();
    for (std::size_t i = 0; i < balls.size(); ++i)
      if (group[i] == g) {
        const Vec<D> offset = balls[i].center - balls[g].center;
        members.push_back({offset.unaryExpr([e](double x) { return std::ldexp(x, -e); }), std::ldexp(balls[i].radius, -e)});
      }
    measure += std::ldexp(connected(std::span<const Ball<D>>(members)), D * e);
  }
  return measure;
}

double connected_disk_union_area(std::span<const Ball<2>> disks) {
  // Green: area = 1/2 ∮ (x dy - y dx) over the outline, i.e. over the exposed arcs.
  double twice_area = 0.0;
  for (const ExposedArc& a : exposed_arcs(disks)) {
    const Ball<2>& b = disks[a.ball];
    const double r = b.radius;
    twice_area += r * b.center.x() * (std::sin(a.t1) - std::sin(a.t0)) -
                  r * b.center.y() * (std::cos(a.t1) - std::cos(a.t0)) + r * r * (a.t1 - a.t0);
  }
  return 0.5 * twice_area;
}

double connected_ball_union_volume(std::span<const Ball<3>> balls);

}  // namespace

std::vector<ExposedArc> exposed_arcs(std::span<const Ball<2>> disks) {
  const std::vector<char> hidden = hidden_disks(disks);
  std::vector<ExposedArc> arcs;
  std::vector<std::pair<double, double>> covered;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (hidden[i]) continue;
    const double ri = disks[i].radius;
    covered.clear();
    for (std::size_t j = 0; j < disks.size(); ++j) {
      if (j == i || hidden[j]) continue;
      const double rj = disks[j].radius;
      const Vec2 dc = disks[j].center - disks[i].center;
      const double d = dc.norm();
      if (d >= ri + rj || d + rj <= ri) continue;  // apart, or j inside i
      // The arc of circle i inside disk j: centred on the direction to j, half-angle from the
      // law of cosines (clamped: near-equal circles round to half a circle each, as they should).
      const double cos_b = std::clamp((ri * ri + d * d - rj * rj) / (2 * ri * d), -1.0, 1.0);
      const double b = std::acos(cos_b);
      if (b <= 0) continue;
      if (b >= kPi) { covered.push_back({0.0, kTwoPi}); continue; }
      double lo = std::atan2(dc.y(), dc.x()) - b;
      while (lo < 0) lo += kTwoPi;
      while (lo >= kTwoPi) lo -= kTwoPi;
      const double hi = lo + 2 * b;
      if (hi > kTwoPi) {
        covered.push_back({lo, kTwoPi});
        covered.push_back({0.0, hi - kTwoPi});
      } else {
        covered.push_back({lo, hi});
      }
    }
    std::sort(covered.begin(), covered.end());
    double cursor = 0.0;
    for (const auto& [lo, hi] : covered) {
      if (lo > cursor) arcs.push_back({static_cast<int>(i), cursor, lo});
      cursor = std::max(cursor, hi);
    }
    if (cursor < kTwoPi) arcs.push_back({static_cast<int>(i), cursor, kTwoPi});
  }
  return arcs;
}

double disk_union_area(std::span<const Ball<2>> disks) {
  return measure_by_groups<2>(disks, connected_disk_union_area);
}

double ball_union_volume(std::span<const Ball<3>> balls) {
  return measure_by_groups<3>(balls, connected_ball_union_volume);
}

namespace {

double connected_ball_union_volume(std::span<const Ball<3>> balls) {
  if (balls.empty()) return 0.0;
  // Breakpoints: where a ball starts or ends, and the z-extent of every intersection circle
  // (there two slice disks become tangent, so the slice topology changes).
  std::vector<double> z;
  double bound = 0.0;  // sum of the ball volumes: scale of the absolute tolerance
  for (const auto& b : balls) {
    if (!(b.radius > 0)) continue;
    z.push_back(b.center.z() - b.radius);
    z.push_back(b.center.z() + b.radius);
    bound += ball_measure<3>(b.radius);
  }
  if (z.empty()) return 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      const double ri = balls[i].radius, rj = balls[j].radius;
      if (!(ri > 0) || !(rj > 0)) continue;
      const Vec3 dc = balls[j].center - balls[i].center;
      const double d = dc.norm();
      if (d >= ri + rj || d <= std::abs(ri - rj)) continue;
      const Vec3 n = dc / d;
      const double h = (d * d + ri * ri - rj * rj) / (2 * d);  // plane of the circle, from centre i
      const double rho = std::sqrt(std::max(0.0, ri * ri - h * h));
      const double pz = balls[i].center.z() + h * n.z();
      const double ext = rho * std::sqrt(std::max(0.0, 1 - n.z() * n.z()));
      z.push_back(pz - ext);
      z.push_back(pz + ext);
    }
  std::sort(z.begin(), z.end());
  z.erase(std::unique(z.begin(), z.end()), z.end());

  std::vector<Ball<2>> slice;
  auto area = [&](double zz) {
    slice.clear();
    for (const auto& b : balls) {
      const double dz = zz - b.center.z();
      const double r2 = b.radius * b.radius - dz * dz;
      if (b.radius > 0 && r2 > 0) slice.push_back({Vec2(b.center.x(), b.center.y()), std::sqrt(r2)});
    }
    return disk_union_area(slice);
  };
  const double tol = 1e-13 * bound;
  const double span = z.back() - z.front();
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < z.size(); ++k)
    volume += gauss_kronrod(area, z[k], z[k + 1], tol * (z[k + 1] - z[k]) / span, 0);
  return volume;
}

}  // namespace

}  // namespace fp
