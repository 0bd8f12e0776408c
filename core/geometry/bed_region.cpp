#include "core/geometry/bed_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/container_checks.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"

namespace fp {

template <int D>
std::vector<Vec<D>> clip_below(const std::vector<Vec<D>>& corners, const Vec<D>& up, double level, bool closed) {
  std::vector<Vec<D>> out;
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double si = up.dot(corners[i]) - level;
    if (si <= 0.0) out.push_back(corners[i]);
    if (!closed && j == 0) break;
    const double sj = up.dot(corners[j]) - level;
    if ((si < 0.0 && sj > 0.0) || (si > 0.0 && sj < 0.0)) out.push_back(corners[i] + (si / (si - sj)) * (corners[j] - corners[i]));
  }
  return out;
}

namespace {

/// The measure below the plane up . x = level of a closed, outward-oriented boundary, by the
/// divergence theorem about o = level * up, a point of the plane: the cut face, on the plane,
/// adds nothing, so summing the clipped boundary pieces' cones from o is exact.
double measure_below(const std::vector<std::array<Vec3, 3>>& triangles, const Vec3& up, double level) {
  const Vec3 o = level * up;
  double sum = 0.0;
  for (const auto& t : triangles) {
    const std::vector<Vec3> p = clip_below<3>({t[0], t[1], t[2]}, up, level, true);
    for (std::size_t k = 1; k + 1 < p.size(); ++k) sum += (p[0] - o).dot((p[k] - o).cross(p[k + 1] - o));
  }
  return sum / 6.0;
}

double measure_below(const std::vector<std::array<Vec2, 2>>& edges, const Vec2& up, double level) {
  const Vec2 o = level * up;
  double sum = 0.0;
  for (const auto& e : edges) {
    const std::vector<Vec2> p = clip_below<2>({e[0], e[1]}, up, level, false);
    if (p.size() == 2) {
      const Vec2 a = p[0] - o, b = p[1] - o;
      sum += a.x() * b.y() - a.y() * b.x();
    }
  }
  return sum / 2.0;
}

std::vector<std::array<Vec3, 3>> box_triangles(const Vec3& lo, const Vec3& hi) {
  auto corner = [&](int i) { return Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()); };
  // Each face as two triangles wound outwards (corner bits: x = 1, y = 2, z = 4).
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  std::vector<std::array<Vec3, 3>> out;
  for (const auto& f : faces) {
    out.push_back({corner(f[0]), corner(f[1]), corner(f[2])});
    out.push_back({corner(f[0]), corner(f[2]), corner(f[3])});
  }
  return out;
}

std::vector<std::array<Vec2, 2>> polygon_edges(const std::vector<Vec2>& v) {  // counter-clockwise
  std::vector<std::array<Vec2, 2>> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back({v[i], v[(i + 1) % v.size()]});
  return out;
}

/// The area of the part {y . n >= d} of a disk of radius r about 0 (n unit), clamped in d; and
/// its antiderivative in d (continuous, zero at d = r), for the cylinder's integral.
double cap_area(double r, double d) {
  d = std::clamp(d, -r, r);
  return r * r * std::acos(d / r) - d * std::sqrt(std::max(r * r - d * d, 0.0));
}
double cap_area_integral(double r, double d) {
  const double below = std::min(d + r, 0.0);  // where the whole disk counts
  d = std::clamp(d, -r, r);
  const double q = std::max(r * r - d * d, 0.0);
  return r * r * (d * std::acos(d / r) - std::sqrt(q)) + q * std::sqrt(q) / 3.0 + kPi * r * r * below;
}

/// The cylinder below the plane: at axial coordinate t its disk is cut at distance
/// d(t) = (level - up . base - t (up . a)) / s from the axis, s = |up's part across the axis|;
/// d is linear in t, so the integral of the cut disk's area is closed-form.
double cylinder_below(const CylinderContainer& c, const Vec3& up, double level) {
  const double R = c.radius(), H = c.height(), ua = up.dot(c.axis()), full = kPi * R * R;
  const double free_height = level - up.dot(c.base_center());
  const double s = std::sqrt(std::max(1.0 - ua * ua, 0.0));
  if (s < 1e-12) {  // the plane across the axis: a shorter cylinder (t <= or >= free_height / ua)
    const double t = std::clamp(free_height / ua, 0.0, H);
    return full * (ua > 0 ? t : H - t);
  }
  const double d0 = free_height / s, slope = -ua / s;
  if (std::abs(slope) < 1e-12) return (full - cap_area(R, d0)) * H;
  const double dH = d0 + slope * H;
  return full * H - (cap_area_integral(R, dH) - cap_area_integral(R, d0)) / slope;
}

double radical_inverse(std::uint64_t i, std::uint64_t base) {
  double f = 1.0, r = 0.0;
  for (; i > 0; i /= base) f /= static_cast<double>(base), r += f * static_cast<double>(i % base);
  return r;
}

}  // namespace

template <int D>
double lowest_along(const Container<D>& c, const Vec<D>& up) {
  if (const auto* box = dynamic_cast<const BoxContainer<D>*>(&c)) return up.cwiseProduct(box->lo()).cwiseMin(up.cwiseProduct(box->hi())).sum();
  if (const auto* ball = dynamic_cast<const BallContainer<D>*>(&c)) return up.dot(ball->center()) - ball->radius();
  if constexpr (D == 3) {
    if (const auto* cyl = dynamic_cast<const CylinderContainer*>(&c)) {
      const double ua = up.dot(cyl->axis());
      const double ends = std::min(up.dot(cyl->base_center()), up.dot(cyl->base_center() + cyl->height() * cyl->axis()));
      return ends - cyl->radius() * std::sqrt(std::max(1.0 - ua * ua, 0.0));
    }
    if (const auto* mesh = dynamic_cast<const MeshContainer*>(&c)) {
      double low = std::numeric_limits<double>::infinity();
      for (const Vec3& v : mesh->vertices()) low = std::min(low, up.dot(v));
      return low;
    }
  } else {
    if (const auto* polygon = dynamic_cast<const PolygonContainer*>(&c)) {
      double low = std::numeric_limits<double>::infinity();
      for (const Vec2& v : polygon->vertices()) low = std::min(low, up.dot(v));
      return low;
    }
  }
  throw std::invalid_argument("bed: no floor for the container " + c.describe());
}

namespace {

template <int D>
double measure_below(const Container<D>& c, const Vec<D>& up, double level) {
  if (const auto* ball = dynamic_cast<const BallContainer<D>*>(&c)) {
    const double r = ball->radius(), d = level - up.dot(ball->center());
    if (d >= r) return ball->measure();
    if (d <= -r) return 0.0;
    if constexpr (D == 2) return kPi * r * r - cap_area(r, d);
    const double h = r + d;  // the cap's height
    return kPi * h * h * (3 * r - h) / 3.0;
  }
  if (const auto* box = dynamic_cast<const BoxContainer<D>*>(&c)) {
    if constexpr (D == 3) return measure_below(box_triangles(box->lo(), box->hi()), up, level);
    else return measure_below(polygon_edges({box->lo(), Vec2(box->hi().x(), box->lo().y()), box->hi(), Vec2(box->lo().x(), box->hi().y())}), up, level);
  }
  if constexpr (D == 3) {
    if (const auto* cyl = dynamic_cast<const CylinderContainer*>(&c)) return cylinder_below(*cyl, up, level);
    if (const auto* mesh = dynamic_cast<const MeshContainer*>(&c)) {
      std::vector<std::array<Vec3, 3>> triangles;
      for (const auto& t : mesh->triangles())
        triangles.push_back({mesh->vertices()[static_cast<std::size_t>(t[0])], mesh->vertices()[static_cast<std::size_t>(t[1])],
                             mesh->vertices()[static_cast<std::size_t>(t[2])]});
      return measure_below(triangles, up, level);
    }
  } else {
    if (const auto* polygon = dynamic_cast<const PolygonContainer*>(&c)) return measure_below(polygon_edges(polygon->vertices()), up, level);
  }
  throw std::invalid_argument("bed: no measure for the container " + c.describe());
}

}  // namespace

template <int D>
BedRegion<D>::BedRegion(ContainerPtr<D> base, const Vec<D>& up, double height, BedSurface surface)
    : Container<D>(base->origin()), base_(std::move(base)), surface_(surface) {
  detail::require_finite<D>(up, "bed", "up");
  detail::require_positive(height, "bed", "height");
  if (up.norm() == 0.0) throw std::invalid_argument("bed: up must be a non-zero vector");
  up_ = up.normalized();
  floor_ = lowest_along<D>(*base_, up_);
  level_ = floor_ + height;
  if (!std::isfinite(level_)) throw std::invalid_argument("bed: the level is not finite");
  const double top = -lowest_along<D>(*base_, Vec<D>(-up_));
  // Up to the container's top the region is the container itself: its own measure, exactly.
  measure_ = level_ >= top ? base_->measure() : std::min(measure_below<D>(*base_, up_, level_), base_->measure());
  if (!(measure_ > 0.0))
    throw std::invalid_argument("bed: nothing of the container lies below height " + detail::format_number(height));

  bounds_ = base_->bounds();
  for (int a = 0; a < D; ++a) {  // an axis direction cuts the bounds at the level
    if (up_[a] == 1.0) bounds_.hi[a] = std::min(bounds_.hi[a], level_);
    if (up_[a] == -1.0) bounds_.lo[a] = std::max(bounds_.lo[a], -level_);
  }

  // The seed: the deepest of 65 points between floor and level on the line along up through the
  // container's interior point; a container the line misses in the bed (an L-shaped mesh) by
  // the deepest of 4096 Halton points of the bounds.
  const Vec<D> through = base_->interior_point();
  double deepest = 0.0;
  interior_ = through;
  for (int k = 0; k < 65; ++k) {
    const double z = floor_ + (k + 0.5) / 65.0 * (level_ - floor_);
    const Vec<D> p = through + (z - up_.dot(through)) * up_;
    if (const double depth = -signed_distance(p); depth > deepest) deepest = depth, interior_ = p;
  }
  const std::uint64_t bases[3] = {2, 3, 5};
  for (std::uint64_t i = 1; deepest == 0.0 && i <= 4096; ++i) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = bounds_.lo[a] + radical_inverse(i, bases[a]) * (bounds_.hi[a] - bounds_.lo[a]);
    if (const double depth = -signed_distance(p); depth > deepest) deepest = depth, interior_ = p;
  }
}

template <int D>
double BedRegion<D>::measure_up_to(double h) const {
  if (!(h > 0.0)) return 0.0;
  if (h >= height()) return measure_;
  return std::min(measure_below<D>(*base_, up_, floor_ + h), measure_);
}

template <int D>
double BedRegion<D>::signed_distance(const Vec<D>& p) const {
  return std::max(base_->signed_distance(p), above(p));
}

template <int D>
void BedRegion<D>::walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const {
  base_->walls_near(p, reach, out);
  if (surface_ == BedSurface::Flat && std::abs(above(p)) <= reach) out.push_back(Wall<D>::plane(level_ * up_, -up_, kLidWall));
}

template <int D>
std::string BedRegion<D>::describe() const {
  return base_->describe() + " filled to height " + detail::format_short(height()) + " along " + detail::format_vec<D>(up_) +
         (surface_ == BedSurface::Free ? " (free surface)" : " (flat surface)");
}

template std::vector<Vec<2>> clip_below<2>(const std::vector<Vec<2>>&, const Vec<2>&, double, bool);
template std::vector<Vec<3>> clip_below<3>(const std::vector<Vec<3>>&, const Vec<3>&, double, bool);
template double lowest_along<2>(const Container<2>&, const Vec<2>&);
template double lowest_along<3>(const Container<3>&, const Vec<3>&);
template class BedRegion<2>;
template class BedRegion<3>;

}  // namespace fp
