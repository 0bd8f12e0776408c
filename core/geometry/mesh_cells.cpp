#include "core/geometry/mesh_cells.hpp"

#include <Eigen/Geometry>  // cross()

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/geometry/mesh_cgal.hpp"
#include "core/geometry/triangle_closest_point.hpp"

namespace fp::detail {
namespace {

// A cell's sample point: off its centre by an irrational-looking fraction of the cell, so that it
// lies on no axis-aligned facet or grid-aligned plane; nudge k > 0 moves it further (a sample
// found on the surface).
Vec3 sample_offset(int nudge) {
  return Vec3(0.5 + 0.0917 + 0.0313 * nudge, 0.5 + 0.0713 - 0.0271 * nudge, 0.5 + 0.0531 + 0.0197 * nudge);
}
constexpr int kMaxNudge = 8;
// A query that would compute more distances or crossings than this goes to the tree instead
// (particles far larger than the facets make long lists; the tree's search is logarithmic).
constexpr std::uint32_t kLongList = 128;

/// x as a float no larger than x (for lower bounds).
float down(double x) {
  const float f = static_cast<float>(x);
  return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

MeshCells::MeshCells(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles,
                     const std::vector<char>& solid, double cell, double margin, std::size_t max_cells,
                     std::size_t max_entries, const std::function<int(const Vec3&)>& side_of)
    : margin_(margin) {
  if (!(margin > 0.0) || !std::isfinite(margin) || !(cell > 0.0) || triangles.empty()) return;
  size_grid(vertices, cell, max_cells);
  tri_.resize(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) tri_[f][static_cast<std::size_t>(k)] = vertices[static_cast<std::size_t>(triangles[f][k])];
  std::vector<double> nearest2;
  if (!list_facets(solid, max_entries, nearest2)) return;  // not built: every query goes to the tree
  bound_distances(nearest2);
  built_ = find_sides(side_of);
}

void MeshCells::size_grid(const std::vector<Vec3>& vertices, double cell, std::size_t max_cells) {
  Aabb<3> box;
  for (const Vec3& v : vertices) box.extend(v);
  // Cells of the given size, coarser if there would be too many; one padding cell each side.
  h_ = cell;
  for (;;) {
    double count = 1.0;
    for (int a = 0; a < 3; ++a) count *= std::ceil(box.size()[a] / h_) + 2.0;
    if (count <= double(max_cells)) break;
    h_ *= 1.01 * std::cbrt(count / double(max_cells));
  }
  for (int a = 0; a < 3; ++a) n_[a] = static_cast<long>(std::ceil(box.size()[a] / h_)) + 2;
  lo_ = box.lo - Vec3::Constant(h_);
  half_diagonal_ = 0.5 * std::sqrt(3.0) * h_ * (1 + 1e-9);  // widened against rounding
}

bool MeshCells::list_facets(const std::vector<char>& solid, std::size_t max_entries, std::vector<double>& nearest2) {
  const long cells = n_[0] * n_[1] * n_[2];
  // Every cell whose box comes within the margin of a facet lists it: the test is on the centre,
  // against margin + half a diagonal (widened against rounding).
  const double list_reach = (margin_ + 0.5 * std::sqrt(3.0) * h_) * (1 + 1e-9);
  struct Listing {
    std::uint32_t cell;
    float distance;  // from the cell's centre, rounded down
    std::int32_t facet;
  };
  std::vector<Listing> pairs;
  nearest2.assign(static_cast<std::size_t>(cells), std::numeric_limits<double>::infinity());
  for (std::size_t f = 0; f < tri_.size(); ++f) {
    if (!solid[f]) continue;
    const auto& t = tri_[f];
    std::array<long, 3> from{}, to{};
    for (int a = 0; a < 3; ++a) {
      const double lo = std::min({t[0][a], t[1][a], t[2][a]}) - list_reach, hi = std::max({t[0][a], t[1][a], t[2][a]}) + list_reach;
      from[a] = std::clamp(static_cast<long>(std::floor((lo - lo_[a]) / h_ - 0.5)), 0L, n_[a] - 1);
      to[a] = std::clamp(static_cast<long>(std::floor((hi - lo_[a]) / h_ + 0.5)), 0L, n_[a] - 1);
    }
    // A cheap first test against the facet's plane, for facets whose computed normal is accurate
    // (not slivers), with room for its rounding.
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], cross = e1.cross(e2);
    const bool well_shaped = cross.norm() > 1e-3 * e1.norm() * e2.norm();
    const Vec3 normal = well_shaped ? Vec3(cross.normalized()) : Vec3::Zero();
    const double plane = normal.dot(t[0]), slab = list_reach + 1e-6 * (list_reach + e1.norm() + e2.norm());
    for (long k = from[2]; k <= to[2]; ++k)
      for (long j = from[1]; j <= to[1]; ++j)
        for (long i = from[0]; i <= to[0]; ++i) {
          const Vec3 c = lo_ + h_ * Vec3(i + 0.5, j + 0.5, k + 0.5);
          if (std::abs(normal.dot(c) - plane) > slab) continue;  // the facet's plane is farther
          const double d2 = (closest_on_triangle(c, t[0], t[1], t[2]) - c).squaredNorm();
          if (d2 > list_reach * list_reach) continue;
          const long cell = i + n_[0] * (j + n_[1] * k);
          pairs.push_back({static_cast<std::uint32_t>(cell), down(std::sqrt(d2)), static_cast<std::int32_t>(f)});
          nearest2[static_cast<std::size_t>(cell)] = std::min(nearest2[static_cast<std::size_t>(cell)], d2);
          if (pairs.size() > max_entries) return false;
        }
  }
  // By cell (counting sort), then each cell's short list nearest first.
  start_.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (const Listing& l : pairs) ++start_[l.cell + 1];
  for (long c = 0; c < cells; ++c) start_[static_cast<std::size_t>(c) + 1] += start_[static_cast<std::size_t>(c)];
  std::vector<std::pair<float, std::int32_t>> sorted(pairs.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (const Listing& l : pairs) sorted[fill[l.cell]++] = {l.distance, l.facet};
  pairs = {};
  items_.resize(sorted.size());
  item_distance_.resize(sorted.size());
  for (long c = 0; c < cells; ++c) {
    const auto from = sorted.begin() + start_[static_cast<std::size_t>(c)], to = sorted.begin() + start_[static_cast<std::size_t>(c) + 1];
    std::sort(from, to);
    for (auto it = from; it != to; ++it) {
      const auto q = static_cast<std::size_t>(it - sorted.begin());
      item_distance_[q] = it->first;
      items_[q] = it->second;
    }
  }
  return true;
}

void MeshCells::bound_distances(const std::vector<double>& nearest2) {
  // A listed cell: its nearest listed facet's distance from the centre, less half a diagonal (an
  // unlisted facet is farther than that). An unlisted cell k cells (Chebyshev) from the nearest
  // listed one: margin + (k - 1) h (every point within the margin of a facet is in a listed
  // cell). Rounded down (float), with a relative allowance for rounding.
  const long cells = n_[0] * n_[1] * n_[2];
  lower_bound_.assign(static_cast<std::size_t>(cells), 0.0f);
  std::vector<std::int32_t> steps(static_cast<std::size_t>(cells), -1);
  std::vector<long> queue;
  for (long c = 0; c < cells; ++c)
    if (listed(c)) {
      steps[static_cast<std::size_t>(c)] = 0;
      queue.push_back(c);
    }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const long c = queue[q];
    const std::array<long, 3> ijk = coords(c);
    for (long dk = -1; dk <= 1; ++dk)
      for (long dj = -1; dj <= 1; ++dj)
        for (long di = -1; di <= 1; ++di) {
          const long a = ijk[0] + di, b = ijk[1] + dj, e = ijk[2] + dk;
          if (a < 0 || b < 0 || e < 0 || a >= n_[0] || b >= n_[1] || e >= n_[2]) continue;
          const long d = a + n_[0] * (b + n_[1] * e);
          if (steps[static_cast<std::size_t>(d)] >= 0) continue;
          steps[static_cast<std::size_t>(d)] = steps[static_cast<std::size_t>(c)] + 1;
          queue.push_back(d);
        }
  }
  const double half_diagonal = 0.5 * std::sqrt(3.0) * h_;
  for (long c = 0; c < cells; ++c) {
    const auto s = static_cast<std::size_t>(c);
    const double bound = steps[s] == 0 ? std::sqrt(nearest2[s]) - half_diagonal
                         : steps[s] > 0 ? margin_ + double(steps[s] - 1) * h_
                                        : std::numeric_limits<double>::max();  // no facet at all (cannot happen)
    lower_bound_[s] = std::max(0.0f, down(bound * (1 - 1e-9)));
  }
}

bool MeshCells::find_sides(const std::function<int(const Vec3&)>& side_of) {
  // The padding is outside; from there, across every shared face, the parity of the crossings of
  // the segment between the two samples (it lies in the two cells, so their lists hold every
  // facet it can meet).
  const long cells = n_[0] * n_[1] * n_[2];
  side_.assign(static_cast<std::size_t>(cells), 0);
  nudge_.assign(static_cast<std::size_t>(cells), 0);
  std::vector<long> queue;
  for (long c = 0; c < cells; ++c) {
    const std::array<long, 3> ijk = coords(c);
    bool padding = false;
    for (int a = 0; a < 3; ++a) padding |= ijk[a] == 0 || ijk[a] == n_[a] - 1;
    if (!padding) continue;
    side_[static_cast<std::size_t>(c)] = -1;
    queue.push_back(c);
  }
  const long stride[3] = {1, n_[0], n_[0] * n_[1]};
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const long c = queue[q];
    const std::array<long, 3> ijk = coords(c);
    for (int a = 0; a < 3; ++a)
      for (const long step : {-1L, 1L}) {
        if (ijk[a] + step < 0 || ijk[a] + step >= n_[a]) continue;
        const long d = c + step * stride[a];
        std::int8_t& sd = side_[static_cast<std::size_t>(d)];
        if (sd != 0) continue;
        const Crossings x = listed(c) || listed(d) ? crossings(sample(c), sample(d), c, d) : Crossings{};
        if (!x.degenerate) {
          sd = static_cast<std::int8_t>(x.parity ? -side_[static_cast<std::size_t>(c)] : side_[static_cast<std::size_t>(c)]);
        } else {
          int s = 0;
          for (int nudge = 0; nudge <= kMaxNudge && s == 0; ++nudge) {
            nudge_[static_cast<std::size_t>(d)] = static_cast<std::uint8_t>(nudge);
            s = side_of(sample(d));
          }
          if (s == 0) return false;  // a surface through every sample tried: never seen
          sd = static_cast<std::int8_t>(s);
        }
        queue.push_back(d);
      }
  }
  return true;
}

bool MeshCells::listed(long cell) const {
  return start_[static_cast<std::size_t>(cell) + 1] > start_[static_cast<std::size_t>(cell)];
}

std::array<long, 3> MeshCells::coords(long cell) const {
  return {cell % n_[0], (cell / n_[0]) % n_[1], cell / (n_[0] * n_[1])};
}

long MeshCells::cell_of(const Vec3& p) const {
  long cell = 0, stride = 1;
  for (int a = 0; a < 3; ++a) {
    const double x = (p[a] - lo_[a]) / h_;
    if (!(x >= 0.0) || x >= double(n_[a])) return -1;
    cell += stride * static_cast<long>(x);
    stride *= n_[a];
  }
  return cell;
}

Vec3 MeshCells::sample(long cell) const {
  const std::array<long, 3> ijk = coords(cell);
  return lo_ + h_ * (Vec3(double(ijk[0]), double(ijk[1]), double(ijk[2])) + sample_offset(nudge_[static_cast<std::size_t>(cell)]));
}

int MeshCells::cross(const Vec3& p, const Vec3& q, int facet) const {
  const auto& t = tri_[static_cast<std::size_t>(facet)];
  const int op = orientation(t[0], t[1], t[2], p), oq = orientation(t[0], t[1], t[2], q);
  if (op == 0 || oq == 0) return -1;
  if (op == oq) return 0;
  const int e0 = orientation(p, q, t[0], t[1]), e1 = orientation(p, q, t[1], t[2]), e2 = orientation(p, q, t[2], t[0]);
  if ((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0)) return 1;
  if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) return -1;  // through an edge or corner
  return 0;
}

MeshCells::Crossings MeshCells::crossings(const Vec3& p, const Vec3& q, long cell, long other) const {
  // Only facets that meet a cell's box can cross a segment inside it: those listed within half a
  // diagonal of its centre, the head of its list. A facet in both heads is counted once.
  Crossings x;
  for (const long c : {cell, other}) {
    if (c < 0) continue;
    const auto s = static_cast<std::size_t>(c);
    for (std::uint32_t k = start_[s]; k < start_[s + 1] && double(item_distance_[k]) <= half_diagonal_; ++k) {
      const std::int32_t f = items_[k];
      if (c == other && listed_in_head(f, cell)) continue;
      const int crossing = cross(p, q, f);
      if (crossing < 0) {
        x.degenerate = true;
        return x;
      }
      x.parity ^= crossing;
    }
  }
  return x;
}

bool MeshCells::listed_in_head(std::int32_t facet, long cell) const {
  const auto s = static_cast<std::size_t>(cell);
  for (std::uint32_t k = start_[s]; k < start_[s + 1] && double(item_distance_[k]) <= half_diagonal_; ++k)
    if (items_[k] == facet) return true;
  return false;
}

int MeshCells::side(const Vec3& p) const {
  const long c = cell_of(p);
  if (c < 0) return -1;  // outside the surface's bounding box
  const auto s = static_cast<std::size_t>(c);
  if (!listed(c)) return side_[s];
  // A cell crossed by many facets (particles far larger than them): the tree's ray is cheaper.
  if (start_[s + 1] - start_[s] > kLongList && double(item_distance_[start_[s] + kLongList]) <= half_diagonal_) return 0;
  const Crossings x = crossings(p, sample(c), c, -1);
  if (x.degenerate) return 0;
  return x.parity ? -side_[s] : side_[s];
}

MeshCells::Answer MeshCells::ball_inside(const Vec3& p, double clearance) const {
  const long c = cell_of(p);
  if (c < 0) return Answer::No;
  const auto s = static_cast<std::size_t>(c);
  if (!listed(c)) {
    if (side_[s] < 0) return Answer::No;
    return double(lower_bound_[s]) >= clearance ? Answer::Yes : Answer::Unknown;
  }
  // Listed nearest first (from the centre): a facet farther than clearance + half a diagonal
  // from the centre is not closer than clearance to p, nor is any after it.
  const double limit2 = clearance * clearance, beyond = clearance + half_diagonal_;
  if (double(lower_bound_[s]) < clearance)
    for (std::uint32_t q = start_[s]; q < start_[s + 1] && double(item_distance_[q]) < beyond; ++q) {
      if (q - start_[s] == kLongList) return Answer::Unknown;  // the tree is cheaper
      const auto& t = tri_[static_cast<std::size_t>(items_[q])];
      if ((p - closest_on_triangle(p, t[0], t[1], t[2])).squaredNorm() < limit2) return Answer::No;
    }
  // Beyond the margin, a facet missing from the list may still be closer.
  if (clearance > margin_ && double(lower_bound_[s]) < clearance) return Answer::Unknown;
  const int sd = side(p);
  return sd > 0 ? Answer::Yes : sd < 0 ? Answer::No : Answer::Unknown;
}

bool MeshCells::nearest(const Vec3& p, Vec3& closest, int& sd) const {
  const long c = cell_of(p);
  if (c < 0) return false;
  const auto s = static_cast<std::size_t>(c);
  double best2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t q = start_[s]; q < start_[s + 1]; ++q) {
    const double beyond = double(item_distance_[q]) - half_diagonal_;  // no nearer to p than this
    if (beyond > 0.0 && beyond * beyond > best2) break;
    if (q - start_[s] == kLongList) return false;  // the tree is cheaper
    const auto& t = tri_[static_cast<std::size_t>(items_[q])];
    const Vec3 x = closest_on_triangle(p, t[0], t[1], t[2]);
    const double d2 = (p - x).squaredNorm();
    if (d2 < best2) best2 = d2, closest = x;
  }
  if (!(best2 <= margin_ * margin_)) return false;
  sd = best2 == 0.0 ? 0 : side(p);
  return true;
}

double MeshCells::distance_lower_bound(const Vec3& p) const {
  const long c = cell_of(p);
  return c < 0 ? 0.0 : double(lower_bound_[static_cast<std::size_t>(c)]);
}

}  // namespace fp::detail
