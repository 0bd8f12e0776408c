#include "core/metrics/containment_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/bed_region.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/metrics/mesh_distance.hpp"

namespace fp {

template <int D>
struct ContainmentCheck<D>::Kind {
  virtual ~Kind() = default;
  virtual double signed_distance(const Vec<D>& p, double reach) const = 0;
};

namespace {

template <int D>
using KindBase = typename ContainmentCheck<D>::Kind;

// Box: per axis the excess beyond the nearer face; inside, the nearest face; outside, the length
// of the positive excesses (the distance to the nearest corner, edge or face).
template <int D>
struct BoxKind final : KindBase<D> {
  Vec<D> lo, hi;
  double signed_distance(const Vec<D>& p, double) const override {
    const Vec<D> e = (lo - p).cwiseMax(p - hi);
    if ((e.array() <= 0.0).all()) return e.maxCoeff();
    return e.cwiseMax(0.0).norm();
  }
};

template <int D>
struct BallKind final : KindBase<D> {
  Vec<D> center;
  double radius = 0.0;
  double signed_distance(const Vec<D>& p, double) const override { return (p - center).norm() - radius; }
};

// Cylinder: axial coordinate t and distance rho = |a x (p - base)| from the axis (the cross
// product keeps rho's digits near the axis, where |d|^2 - t^2 would lose them).
struct CylinderKind final : KindBase<3> {
  Vec3 base, axis;
  double radius = 0.0, height = 0.0;
  double signed_distance(const Vec3& p, double) const override {
    const Vec3 d = p - base;
    const double t = d.dot(axis), rho = axis.cross(d).norm();
    if (t >= 0.0 && t <= height && rho <= radius) return -std::min({t, height - t, radius - rho});
    const double dt = std::max({-t, t - height, 0.0}), dr = std::max(rho - radius, 0.0);
    return std::hypot(dt, dr);
  }
};

// Simple polygon: the nearest edge segment for the distance, the crossing number of a ray along
// +x for the side (half-open rule on y: a vertex on the ray counts for exactly one of its edges).
struct PolygonKind final : KindBase<2> {
  std::vector<Vec2> v;
  double signed_distance(const Vec2& p, double) const override {
    double best2 = std::numeric_limits<double>::infinity();
    bool in = false;
    const std::size_t n = v.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2& a = v[j];
      const Vec2& b = v[i];
      const Vec2 ab = b - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best2 = std::min(best2, (p - (a + t * ab)).squaredNorm());
      if ((a.y() > p.y()) != (b.y() > p.y())) {
        const double x = a.x() + (p.y() - a.y()) / (b.y() - a.y()) * ab.x();
        if (p.x() < x) in = !in;
      }
    }
    const double d = std::sqrt(best2);
    return in ? -d : d;
  }
};

struct MeshKind final : KindBase<3> {
  explicit MeshKind(const MeshContainer& m) : mesh(m.vertices(), m.triangles()) {}
  MeshDistance mesh;
  double signed_distance(const Vec3& p, double reach) const override { return mesh.signed_distance(p, reach); }
};

template <int D>
std::unique_ptr<const KindBase<D>> make_kind(const Container<D>& c);

// A bed: its container's check, cut by the plane of its level (the larger signed distance:
// exact inside, where the check decides).
template <int D>
struct BedKind final : KindBase<D> {
  std::unique_ptr<const KindBase<D>> base;
  Vec<D> up;
  double level = 0.0;
  double signed_distance(const Vec<D>& p, double reach) const override {
    return std::max(base->signed_distance(p, reach), up.dot(p) - level);
  }
};

template <int D>
std::unique_ptr<const KindBase<D>> make_kind(const Container<D>& c) {
  if (const auto* bed = dynamic_cast<const BedRegion<D>*>(&c)) {
    auto k = std::make_unique<BedKind<D>>();
    k->base = make_kind<D>(bed->base());
    k->up = bed->up();
    k->level = bed->level();
    return k;
  }
  if (const auto* box = dynamic_cast<const BoxContainer<D>*>(&c)) {
    auto k = std::make_unique<BoxKind<D>>();
    k->lo = box->lo();
    k->hi = box->hi();
    return k;
  }
  if (const auto* ball = dynamic_cast<const BallContainer<D>*>(&c)) {
    auto k = std::make_unique<BallKind<D>>();
    k->center = ball->center();
    k->radius = ball->radius();
    return k;
  }
  if constexpr (D == 2) {
    if (const auto* poly = dynamic_cast<const PolygonContainer*>(&c)) {
      auto k = std::make_unique<PolygonKind>();
      k->v = poly->vertices();
      return k;
    }
  } else {
    if (const auto* cyl = dynamic_cast<const CylinderContainer*>(&c)) {
      auto k = std::make_unique<CylinderKind>();
      k->base = cyl->base_center();
      k->axis = cyl->axis().normalized();
      k->radius = cyl->radius();
      k->height = cyl->height();
      return k;
    }
    if (const auto* mesh = dynamic_cast<const MeshContainer*>(&c)) return std::make_unique<MeshKind>(*mesh);
  }
  throw std::invalid_argument("validation: no independent containment check for the container " + c.describe() +
                              "; it cannot be validated");
}

}  // namespace

template <int D>
ContainmentCheck<D>::ContainmentCheck(const Container<D>& container) : kind_(make_kind<D>(container)) {}
template <int D>
ContainmentCheck<D>::~ContainmentCheck() = default;
template <int D>
ContainmentCheck<D>::ContainmentCheck(ContainmentCheck&&) noexcept = default;
template <int D>
ContainmentCheck<D>& ContainmentCheck<D>::operator=(ContainmentCheck&&) noexcept = default;

template <int D>
double ContainmentCheck<D>::signed_distance(const Vec<D>& p, double reach) const {
  return kind_->signed_distance(p, reach);
}

template class ContainmentCheck<2>;
template class ContainmentCheck<3>;

}  // namespace fp
