#pragma once
// Where a large and a small ball still fit, on a lattice over the container, as the front fills
// it: a lattice point is open for a radius while a ball of that radius centred there lies inside
// the container and overlaps no placed particle. Points only close (particles are only added).
// The front uses it for laws with a rare large class (sand with some gravel): the share of the
// container the small particles have closed to large centres, against the share closed to small
// centres (filled), says how many large particles the filled part should hold by now, and the
// open point nearest the seed point is where one is placed ahead of the front
// (AdvancingFront::place_large_ahead). Large particles close points to large centres too (they
// may not overlap), but that is not counted: it is room they took, not room the small ones left
// them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "core/geometry/container.hpp"

namespace fp {

template <int D>
class ClosingLattice {
 public:
  /// Points of spacing `spacing` (coarser if there would be more than `max_points`) over the
  /// container's bounds; `key(p)` orders the open points (nearest_open_large()).
  template <class Key>
  ClosingLattice(const Container<D>& container, double spacing, double r_large, double r_small, double max_points,
                 Key&& key)
      : r_large_(r_large), r_small_(r_small) {
    const Aabb<D> box = container.bounds();
    for (;;) {
      double points = 1;
      for (int a = 0; a < D; ++a) {
        dims_[a] = static_cast<std::int64_t>(std::floor(box.size()[a] / spacing)) + 1;
        points *= static_cast<double>(dims_[a]);
      }
      if (points <= max_points) break;
      spacing *= 1.26;
    }
    h_ = spacing;
    for (int a = 0; a < D; ++a) lo_[a] = box.lo[a] + 0.5 * (box.size()[a] - static_cast<double>(dims_[a] - 1) * h_);
    std::int64_t n = 1;
    for (int a = 0; a < D; ++a) n *= dims_[a];
    state_.assign(static_cast<std::size_t>(n), 0);
    std::vector<double> keys(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const Vec<D> p = point(i);
      std::uint8_t s = 0;
      if (container.contains_ball(p, r_large_, 0.0)) s |= kOpenLarge | kUnreachedLarge, ++open_large_at_start_;
      if (container.contains_ball(p, r_small_, 0.0)) s |= kOpenSmall, ++open_small_at_start_;
      state_[static_cast<std::size_t>(i)] = s;
      keys[static_cast<std::size_t>(i)] = key(p);
    }
    for (std::int64_t i = 0; i < n; ++i)
      if (state_[static_cast<std::size_t>(i)] & kOpenLarge) by_key_.push_back(i);
    std::stable_sort(by_key_.begin(), by_key_.end(),
                     [&](std::int64_t a, std::int64_t b) { return keys[static_cast<std::size_t>(a)] < keys[static_cast<std::size_t>(b)]; });
  }

  /// A ball (c, r) was placed (`small`: of the small class): the points it closes, for large and
  /// for small centres.
  void add_ball(const Vec<D>& c, double r, bool small) {
    if (exhausted_) return;
    const double reach = r + std::max(r_large_, r_small_);
    std::int64_t from[D], to[D];
    for (int a = 0; a < D; ++a) {
      from[a] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil((c[a] - reach - lo_[a]) / h_)));
      to[a] = std::min<std::int64_t>(dims_[a] - 1, static_cast<std::int64_t>(std::floor((c[a] + reach - lo_[a]) / h_)));
      if (from[a] > to[a]) return;
    }
    const double large2 = (r + r_large_) * (r + r_large_), small2 = (r + r_small_) * (r + r_small_);
    std::int64_t idx[D];
    for (int a = 0; a < D; ++a) idx[a] = from[a];
    for (;;) {
      std::int64_t flat = 0;
      for (int a = D - 1; a >= 0; --a) flat = flat * dims_[a] + idx[a];
      std::uint8_t& s = state_[static_cast<std::size_t>(flat)];
      if (s) {
        const double d2 = (point_at(idx) - c).squaredNorm();
        if (d2 < large2) {
          s &= ~kOpenLarge;
          if (small && (s & kUnreachedLarge)) s &= ~kUnreachedLarge, ++reached_large_;
        }
        if ((s & kOpenSmall) && d2 < small2) s &= ~kOpenSmall, ++closed_small_;
      }
      int a = 0;
      while (a < D && ++idx[a] > to[a]) idx[a] = from[a], ++a;
      if (a == D) break;
    }
  }

  /// Shares of the points open at the start that are closed now: to large centres by small
  /// particles, and to small centres (by any). Frozen once no point is open for large centres.
  double closed_large_share() const { return open_large_at_start_ ? double(reached_large_) / open_large_at_start_ : 1.0; }
  double closed_small_share() const { return open_small_at_start_ ? double(closed_small_) / open_small_at_start_ : 1.0; }

  /// The open point for large centres with the smallest key; none when every point is closed.
  /// Amortised O(1): the points passed over are closed for good.
  std::optional<Vec<D>> nearest_open_large() {
    while (cursor_ < by_key_.size() && !(state_[static_cast<std::size_t>(by_key_[cursor_])] & kOpenLarge)) ++cursor_;
    if (cursor_ == by_key_.size()) {
      exhausted_ = true;  // no large particle fits any more: add_ball() need not follow the rest
      return std::nullopt;
    }
    return point(by_key_[cursor_]);
  }
  /// Closes that point (a large particle did not fit there after all: it is larger than r_large).
  void close_nearest_open_large() {
    if (cursor_ < by_key_.size()) state_[static_cast<std::size_t>(by_key_[cursor_])] &= ~kOpenLarge;
  }

  double spacing() const { return h_; }

 private:
  // kUnreachedLarge: open for large centres at the start, and no small particle has closed it.
  static constexpr std::uint8_t kOpenLarge = 1, kOpenSmall = 2, kUnreachedLarge = 4;

  Vec<D> point(std::int64_t flat) const {
    std::int64_t idx[D];
    for (int a = 0; a < D; ++a) idx[a] = flat % dims_[a], flat /= dims_[a];
    return point_at(idx);
  }
  Vec<D> point_at(const std::int64_t* idx) const {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = lo_[a] + static_cast<double>(idx[a]) * h_;
    return p;
  }

  double r_large_, r_small_;
  double h_ = 0;
  std::int64_t dims_[D] = {};
  Vec<D> lo_ = Vec<D>::Zero();
  std::vector<std::uint8_t> state_;   // per point: kOpenLarge | kOpenSmall | kUnreachedLarge
  std::vector<std::int64_t> by_key_;  // points open for large centres at the start, by key
  std::size_t cursor_ = 0;
  bool exhausted_ = false;  // no point open for large centres (nearest_open_large found none)
  std::int64_t open_large_at_start_ = 0, open_small_at_start_ = 0, reached_large_ = 0, closed_small_ = 0;
};

}  // namespace fp
