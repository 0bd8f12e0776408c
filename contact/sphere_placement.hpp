#pragma once
// Placing one sphere (disk) among fixed ones the way paper 000 (Jerier et al. 2010, Sect. 2.1)
// accepts the geometric procedure's answer: overlaps up to the allowance epsilon r_min; beyond
// it, "in last resort", the radius reduced to cancel them; kept only with a radius of at least
// r_min and z_min contacts (the container's wall counts as one). Shared by the tetrahedral-mesh
// fill (fill/) and the void filling (densify/). The spheres live in a Packing and a
// NeighbourGrid it keeps in step.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/geometry/container.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/geometry/packing.hpp"

namespace fp {

struct PlacementRejections {
  std::uint64_t tried = 0;        ///< positions checked
  std::uint64_t container = 0;    ///< not inside the container
  std::uint64_t overlap = 0;      ///< overlapping beyond the allowance (radius fixed)
  std::uint64_t contacts = 0;     ///< fewer than z_min contacts, or reduced below r_min
  std::uint64_t reduced = 0;      ///< placed with a reduced radius
};

template <int D>
class SpherePlacement {
 public:
  /// `grid` must cover the container's bounds and the radii to come; every sphere of `packing`
  /// is inserted. `tol`: the contact tolerance (relative to the smaller radius); `allowance`:
  /// the overlap allowed between spheres (absolute, epsilon r_min).
  SpherePlacement(Packing<D>& packing, NeighbourGrid<D>& grid, const Container<D>* container, double r_min, double tol,
                  double allowance, int z_min)
      : P_(packing), grid_(grid), C_(container), r_min_(r_min), tol_(tol), allowance_(allowance), z_min_(z_min) {
    for (std::size_t i = 0; i < P_.size(); ++i) grid_.insert(static_cast<int>(i), P_.centers[i], P_.radii[i]);
  }

  /// Adds the sphere (x, r) if it is inside the container (when there is one), overlaps no
  /// sphere beyond the allowance (with `may_reduce`: after reducing r to cancel such overlaps,
  /// and the protrusion out of the container) with r >= r_min, and has z_min contacts. Returns
  /// whether it was added; r is the radius it got.
  bool try_place(const Vec<D>& x, double& r, bool may_reduce) { return try_place(x, r, may_reduce, r_min_); }
  /// The same with the smallest radius of its own (a region's law).
  bool try_place(const Vec<D>& x, double& r, bool may_reduce, double r_min) {
    ++rej_.tried;
    bool reduced = false;
    double wall_gap = 0;  // (distance to the boundary) - r, when there is a container
    if (C_) {
      const double sd = C_->signed_distance(x);
      if (!(sd < 0)) {
        ++rej_.container;
        return false;
      }
      if (-sd < r * (1 - tol_)) {  // contains_ball's rule: sd <= -r + tol r
        if (!may_reduce) {
          ++rej_.container;
          return false;
        }
        r = -sd;
        reduced = true;
      }
      wall_gap = -sd - r;
    }
    double limit = r;
    bool blocked = false;
    grid_.for_each_within(x, r * (1 + tol_), [&](int, const Vec<D>&, double rj, double d2) {
      const double d = std::sqrt(d2);
      if (r + rj - d > std::max(allowance_, tol_ * std::min(r, rj))) {
        blocked = true;
        limit = std::min(limit, d - rj + allowance_);
      }
    });
    if (blocked) {
      if (!may_reduce) {
        ++rej_.overlap;
        return false;
      }
      wall_gap += r - limit;
      r = limit;
      reduced = true;
    }
    if (r < r_min * (1 - 1e-12)) {
      ++rej_.contacts;
      return false;
    }
    int z = C_ && wall_gap <= tol_ * r ? 1 : 0;
    double deepest = 0;
    grid_.for_each_within(x, r * (1 + tol_), [&](int, const Vec<D>&, double rj, double d2) {
      const double gap = std::sqrt(d2) - r - rj;
      if (gap <= tol_ * std::min(r, rj)) ++z;
      deepest = std::max(deepest, -gap);
    });
    if (z < z_min_) {
      ++rej_.contacts;
      return false;
    }
    if (reduced) ++rej_.reduced;
    const int id = P_.add(x, r);
    grid_.insert(id, x, r);
    deepest_ = std::max(deepest_, deepest);
    return true;
  }

  /// The largest ball centred at x inside the container and overlapping no sphere beyond the
  /// allowance, up to `cap`.
  double free_radius(const Vec<D>& x, double cap) const {
    double free = C_ ? std::min(cap, -C_->signed_distance(x)) : cap;
    grid_.for_each_within(x, std::max(free, 0.0), [&](int, const Vec<D>&, double rj, double d2) {
      free = std::min(free, std::sqrt(d2) - rj + allowance_);
    });
    return free;
  }

  /// The contacts a sphere needs from now on.
  void set_z_min(int z_min) { z_min_ = z_min; }

  const PlacementRejections& rejections() const { return rej_; }
  /// The deepest overlap of a placed sphere with another, when it was placed.
  double deepest_overlap() const { return deepest_; }

 private:
  Packing<D>& P_;
  NeighbourGrid<D>& grid_;
  const Container<D>* C_;
  double r_min_, tol_, allowance_;
  int z_min_;
  PlacementRejections rej_;
  double deepest_ = 0.0;
};

}  // namespace fp
