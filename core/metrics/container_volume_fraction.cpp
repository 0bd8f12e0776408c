#include "core/metrics/container_volume_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/metrics/ball_box.hpp"
#include "core/metrics/compensated_sum.hpp"
#include "core/metrics/lens.hpp"

namespace fp {
namespace {

enum class CutKind { Outside, Inside, Exact, Sample };
struct Cut {
  CutKind kind;
  double measure = 0.0;  // of the ball's part in the region, unless kind == Sample
};

// The region {x : signed_distance(x) <= -shrink} of one container, with its measure when that
// is known in closed form.
template <int D>
class Region {
 public:
  explicit Region(std::optional<double> measure) : measure_(measure) {}
  virtual ~Region() = default;
  virtual Cut cut(const Vec<D>& c, double r) const = 0;
  virtual bool contains(const Vec<D>& x) const = 0;
  /// A box holding it (for sampling its measure).
  virtual Aabb<D> bounds() const = 0;
  std::optional<double> exact_measure() const { return measure_; }

 private:
  std::optional<double> measure_;
};

// A ball that crosses the boundary by at most kTouching * r counts as inside: balls tangent to a
// wall (walls are bodies for the packer) cross it by rounding only, 1e-15 r, and the cap left
// out is below 1e-17 of the ball. Without this every wall contact went to QMC sampling and the
// "exact" container VF of a valid packing carried a 1e-4 sampling error.
constexpr double kTouching = 1e-9;

template <int D>
class BoxRegion final : public Region<D> {
 public:
  BoxRegion(const Vec<D>& lo, const Vec<D>& hi, double measure) : Region<D>(measure), lo_(lo), hi_(hi) {}
  Cut cut(const Vec<D>& c, double r) const override {
    int crossed = 0;
    double t = 0.0;
    for (int a = 0; a < D; ++a) {
      if (c[a] + r <= lo_[a] || c[a] - r >= hi_[a]) return {CutKind::Outside};
      if (c[a] - r < lo_[a] - kTouching * r) ++crossed, t = c[a] - lo_[a];
      if (c[a] + r > hi_[a] + kTouching * r) ++crossed, t = hi_[a] - c[a];
    }
    if (crossed == 0) return {CutKind::Inside, ball_measure<D>(r)};
    if (crossed == 1) return {CutKind::Exact, ball_inside_plane<D>(r, t)};
    return {CutKind::Sample};  // an edge or a corner of the box cuts the ball
  }
  bool contains(const Vec<D>& x) const override {
    return (x.array() >= lo_.array()).all() && (x.array() <= hi_.array()).all();
  }
  Aabb<D> bounds() const override { return {lo_, hi_}; }

 private:
  Vec<D> lo_, hi_;
};

template <int D>
class BallRegion final : public Region<D> {
 public:
  BallRegion(const Vec<D>& center, double radius, double measure)
      : Region<D>(measure), center_(center), radius_(radius) {}
  Cut cut(const Vec<D>& c, double r) const override {
    if (!(radius_ > 0.0)) return {CutKind::Outside};
    const double d = (c - center_).norm();
    if (d >= r + radius_) return {CutKind::Outside};
    if (d + r <= radius_ + kTouching * r) return {CutKind::Inside, ball_measure<D>(r)};
    return {CutKind::Exact, ball_intersection_measure<D>(r, radius_, d)};
  }
  bool contains(const Vec<D>& x) const override { return (x - center_).norm() <= radius_; }
  Aabb<D> bounds() const override { return {center_ - Vec<D>::Constant(radius_), center_ + Vec<D>::Constant(radius_)}; }

 private:
  Vec<D> center_;
  double radius_;
};

// Any container, through its signed distance (1-Lipschitz, so the classification is safe).
template <int D>
class GenericRegion final : public Region<D> {
 public:
  GenericRegion(const Container<D>& container, double s, std::optional<double> measure)
      : Region<D>(measure), container_(container), shrink_(s) {}
  // As tests of a ball's clearance where they can be (contains_ball): a mesh answers those from
  // its cells, without the nearest facet of a point deep inside. A tie goes to Sample, which is
  // always right.
  Cut cut(const Vec<D>& c, double r) const override {
    const double inner = shrink_ + r - kTouching * r;  // inside iff the signed distance <= -inner
    if (inner > 0.0 ? container_.contains_ball(c, inner, 0.0) : container_.signed_distance(c) <= -inner)
      return {CutKind::Inside, ball_measure<D>(r)};
    // Outside iff the signed distance >= r - shrink.
    if (shrink_ > r ? !container_.contains_ball(c, shrink_ - r, 0.0) : container_.signed_distance(c) >= r - shrink_)
      return {CutKind::Outside};
    return {CutKind::Sample};
  }
  bool contains(const Vec<D>& x) const override {
    return shrink_ == 0.0 ? container_.inside(x) : container_.contains_ball(x, shrink_, 0.0);
  }
  Aabb<D> bounds() const override {
    const Aabb<D> b = container_.bounds();
    return {b.lo + Vec<D>::Constant(shrink_), b.hi - Vec<D>::Constant(shrink_)};
  }

 private:
  const Container<D>& container_;
  double shrink_;
};

// The whole container keeps the container's own measure; shrunk boxes, balls and cylinders are
// boxes, balls and cylinders.
template <int D>
std::unique_ptr<Region<D>> make_region(const Container<D>& container, double s) {
  if (!(s >= 0.0) || !std::isfinite(s)) throw std::invalid_argument("volume fraction: shrink must be finite and >= 0");
  const auto whole = s == 0.0 ? std::optional<double>(container.measure()) : std::nullopt;
  if (const auto* box = dynamic_cast<const BoxContainer<D>*>(&container)) {
    const Vec<D> lo = box->lo() + Vec<D>::Constant(s), hi = box->hi() - Vec<D>::Constant(s);
    return std::make_unique<BoxRegion<D>>(lo, hi, whole.value_or((hi - lo).cwiseMax(0.0).prod()));
  }
  if (const auto* ball = dynamic_cast<const BallContainer<D>*>(&container)) {
    const double r = ball->radius() - s;
    return std::make_unique<BallRegion<D>>(ball->center(), r, whole.value_or(r > 0.0 ? ball_measure<D>(r) : 0.0));
  }
  std::optional<double> measure = whole;
  if constexpr (D == 3) {
    if (const auto* cyl = dynamic_cast<const CylinderContainer*>(&container); cyl && s > 0.0) {
      const double r = cyl->radius() - s, h = cyl->height() - 2.0 * s;
      measure = r > 0.0 && h > 0.0 ? kPi * r * r * h : 0.0;
    }
  }
  return std::make_unique<GenericRegion<D>>(container, s, measure);
}

// One value per replicate: exact (all equal) or QMC over the region's bounding box.
template <int D>
std::vector<double> measure_replicates(const Region<D>& region, const QmcOptions& qmc,
                                       const std::vector<Vec<D>>& shifts) {
  if (const auto m = region.exact_measure()) return std::vector<double>(shifts.size(), *m);
  const Aabb<D> b = region.bounds();
  const Vec<D> size = b.size();
  if (!((size.array() > 0.0).all())) return std::vector<double>(shifts.size(), 0.0);
  const std::vector<Vec<D>> pts = halton_points<D>(qmc.region_points);
  std::vector<double> out;
  for (const Vec<D>& shift : shifts) {
    std::size_t hits = 0;
    for (const Vec<D>& u : pts) hits += region.contains(b.lo + size.cwiseProduct(shifted<D>(u, shift))) ? 1 : 0;
    out.push_back(size.prod() * static_cast<double>(hits) / static_cast<double>(pts.size()));
  }
  return out;
}

// The measure as an Estimate: exact (error 0) or the mean of the replicates.
template <int D>
Estimate measure_estimate(const Region<D>& region, const std::vector<double>& replicates) {
  if (const auto m = region.exact_measure()) return {*m, 0.0};
  return mean_and_error(replicates);
}

}  // namespace

template <int D>
Estimate region_measure(const Container<D>& container, double shrink, const QmcOptions& qmc) {
  const auto region = make_region(container, shrink);
  return measure_estimate(*region, measure_replicates(*region, qmc, qmc_shifts<D>(qmc)));
}

namespace {

// Balls: cut in closed form where the region allows it, sampled against the ball otherwise.
template <int D>
struct BallBodies {
  const Packing<D>& p;
  std::size_t size() const { return p.size(); }
  bool valid(std::size_t i) const { return p.radii[i] >= 0.0 && std::isfinite(p.radii[i]) && p.centers[i].allFinite(); }
  const Vec<D>& centre(std::size_t i) const { return p.centers[i]; }
  double radius(std::size_t i) const { return p.radii[i]; }
  Cut cut(const Region<D>& region, std::size_t i) const { return region.cut(p.centers[i], p.radii[i]); }
  bool contains(std::size_t i, const Vec<D>& offset) const { return offset.squaredNorm() <= p.radii[i] * p.radii[i]; }
};

// Bodies of any shape: whole (their exact measure) when their bounding ball is inside the region,
// nothing when it is outside, sampled against the body otherwise.
template <int D>
struct GeneralBodies {
  const RegionBodies<D>& b;
  std::size_t size() const { return b.centres.size(); }
  bool valid(std::size_t i) const {
    return b.bounding_radii[i] >= 0.0 && std::isfinite(b.bounding_radii[i]) && std::isfinite(b.measures[i]) &&
           b.centres[i].allFinite();
  }
  const Vec<D>& centre(std::size_t i) const { return b.centres[i]; }
  double radius(std::size_t i) const { return b.bounding_radii[i]; }
  Cut cut(const Region<D>& region, std::size_t i) const {
    const Cut ball = region.cut(b.centres[i], b.bounding_radii[i]);
    if (ball.kind == CutKind::Inside) return {CutKind::Inside, b.measures[i]};
    if (ball.kind == CutKind::Outside) return ball;
    return {CutKind::Sample, 0.0};
  }
  bool contains(std::size_t i, const Vec<D>& offset) const { return b.contains(i, b.centres[i] + offset); }
};

template <int D, class Bodies>
RegionVolumeFraction vf_region_of(const Bodies& bodies, const Container<D>& container, double shrink,
                                  const QmcOptions& qmc) {
  const auto region = make_region(container, shrink);
  const std::vector<Vec<D>> shifts = qmc_shifts<D>(qmc);
  const std::vector<double> measures = measure_replicates(*region, qmc, shifts);
  RegionVolumeFraction out;
  out.shrink = shrink;
  out.measure = measure_estimate(*region, measures);
  const bool measure_exact = region->exact_measure().has_value();
  if (!(out.measure.value > 0.0)) {
    out.vf.value = std::numeric_limits<double>::quiet_NaN();
    out.method = "empty region";
    return out;
  }

  CompensatedSum whole;
  std::vector<std::size_t> sampled;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies.valid(i)) continue;
    const Cut cut = bodies.cut(*region, i);
    switch (cut.kind) {
      case CutKind::Outside: break;
      case CutKind::Inside: ++out.balls_inside; whole.add(cut.measure); break;
      case CutKind::Exact: ++out.balls_cut_exact; whole.add(cut.measure); break;
      case CutKind::Sample: sampled.push_back(i); break;
    }
  }
  out.balls_sampled = sampled.size();

  // Straddling balls: points of the ball's bounding cube, counted when in the ball and the region.
  // Each ball has its own shifts: streams (id + 1) * replicates + k, after those of the measure.
  std::size_t per_ball = qmc.points_per_ball;
  if (!sampled.empty() && per_ball * shifts.size() * sampled.size() > qmc.max_ball_points)
    per_ball = std::max<std::size_t>(4, qmc.max_ball_points / (shifts.size() * sampled.size()));
  const std::vector<Vec<D>> pts = halton_points<D>(sampled.empty() ? 0 : per_ball);
  std::vector<CompensatedSum> parts(shifts.size(), whole);
  for (const std::size_t i : sampled) {
    const Vec<D>& c = bodies.centre(i);
    const double r = bodies.radius(i);
    for (std::size_t k = 0; k < shifts.size(); ++k) {
      const Vec<D> shift = qmc_shift<D>(qmc.seed, (i + 1) * shifts.size() + k);
      std::size_t hits = 0;
      for (const Vec<D>& u : pts) {
        const Vec<D> offset = r * (2.0 * shifted<D>(u, shift).array() - 1.0).matrix();
        hits += bodies.contains(i, offset) && region->contains(c + offset) ? 1 : 0;
      }
      parts[k].add(std::pow(2.0 * r, D) * static_cast<double>(hits) / static_cast<double>(pts.size()));
    }
  }
  std::vector<double> vf;
  for (std::size_t k = 0; k < shifts.size(); ++k)
    vf.push_back(parts[k].value() / (measures[k] > 0.0 ? measures[k] : out.measure.value));
  out.vf = mean_and_error(vf);
  out.exact = measure_exact && sampled.empty();
  if (out.exact) out.vf = {whole.value() / out.measure.value, 0.0};

  char buf[200];
  std::string method = out.exact ? "exact" : "QMC:";
  if (!measure_exact) {
    std::snprintf(buf, sizeof buf, " measure (%d x %zu points)", qmc.replicates, qmc.region_points);
    method += buf;
  }
  if (!sampled.empty()) {
    std::snprintf(buf, sizeof buf, "%s %zu straddling balls (%d x %zu points each)", measure_exact ? "" : ";",
                  sampled.size(), qmc.replicates, per_ball);
    method += buf;
  }
  out.method = method;
  return out;
}

}  // namespace

template <int D>
RegionVolumeFraction vf_region(const Packing<D>& packing, const Container<D>& container, double shrink,
                               const QmcOptions& qmc) {
  return vf_region_of<D>(BallBodies<D>{packing}, container, shrink, qmc);
}

template <int D>
RegionVolumeFraction vf_region(const RegionBodies<D>& bodies, const Container<D>& container, double shrink,
                               const QmcOptions& qmc) {
  return vf_region_of<D>(GeneralBodies<D>{bodies}, container, shrink, qmc);
}

template Estimate region_measure<2>(const Container<2>&, double, const QmcOptions&);
template Estimate region_measure<3>(const Container<3>&, double, const QmcOptions&);
template RegionVolumeFraction vf_region<2>(const Packing<2>&, const Container<2>&, double, const QmcOptions&);
template RegionVolumeFraction vf_region<3>(const Packing<3>&, const Container<3>&, double, const QmcOptions&);
template RegionVolumeFraction vf_region<2>(const RegionBodies<2>&, const Container<2>&, double, const QmcOptions&);
template RegionVolumeFraction vf_region<3>(const RegionBodies<3>&, const Container<3>&, double, const QmcOptions&);

}  // namespace fp
