#pragma once
// A deterministic "point deep inside" for non-convex containers: the point of (nearly) largest
// clearance -signed_distance, by branch and bound over cells (the "polylabel" idea, in D
// dimensions). The signed distance is 1-Lipschitz, so no point of a cell is deeper than its
// centre's depth plus its half-diagonal; cells that cannot beat the best by `precision` are dropped.
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"

namespace fp::detail {

/// Depth within rel_precision * (largest bounding-box side) of the deepest point, unless the
/// evaluation budget runs out first (then the best found). `extra_candidates` seed the search
/// (useful for thin containers that a coarse grid can miss).
template <int D>
Vec<D> deepest_point(const Container<D>& c, int cells_per_axis, const std::vector<Vec<D>>& extra_candidates,
                     double rel_precision, int max_evaluations = 40000) {
  struct Cell {
    Vec<D> center, half;
    double potential;
    long order;  ///< creation order: ties break the same way on every platform
    bool operator<(const Cell& o) const { return potential < o.potential || (potential == o.potential && order > o.order); }
  };
  const Aabb<D> box = c.bounds();
  const double precision = rel_precision * box.size().maxCoeff();
  Vec<D> best = Vec<D>::Zero();
  double best_depth = -std::numeric_limits<double>::infinity();
  int evaluations = 0;
  long created = 0;
  std::priority_queue<Cell> queue;

  auto visit = [&](const Vec<D>& center, const Vec<D>& half) {
    const double depth = -c.signed_distance(center);
    ++evaluations;
    if (depth > best_depth && depth >= 0.0) {
      best_depth = depth;
      best = center;
    }
    const double potential = depth + half.norm();
    if (potential > best_depth + precision) queue.push(Cell{center, half, potential, created++});
  };

  for (const Vec<D>& p : extra_candidates) {
    const double depth = -c.signed_distance(p);
    if (depth > best_depth && depth >= 0.0) {
      best_depth = depth;
      best = p;
    }
  }
  const Vec<D> half0 = 0.5 * box.size() / cells_per_axis;
  int idx[D] = {};
  for (;;) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = box.lo[a] + (2 * idx[a] + 1) * half0[a];
    visit(p, half0);
    int a = 0;
    while (a < D && ++idx[a] == cells_per_axis) idx[a++] = 0;
    if (a == D) break;
  }
  while (!queue.empty() && evaluations < max_evaluations) {
    const Cell cell = queue.top();
    queue.pop();
    if (cell.potential <= best_depth + precision) break;  // the best remaining cannot improve enough
    const Vec<D> half = 0.5 * cell.half;
    for (int child = 0; child < (1 << D); ++child) {
      Vec<D> p = cell.center;
      for (int a = 0; a < D; ++a) p[a] += (child >> a & 1) ? half[a] : -half[a];
      visit(p, half);
    }
  }
  if (!(best_depth >= 0.0)) throw std::runtime_error("deepest_point: no inside point found for " + c.describe());
  return best;
}

}  // namespace fp::detail
