#include "core/metrics/mesh_distance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "core/metrics/point_triangle.hpp"

namespace fp {
namespace {

// Sign of orient2d(a, b, q) in the (y, z) plane, for a < b in the canonical vertex order, with q
// moved by (eps, eps^2) when q is on the line ab (simulation of simplicity): a ray through an edge
// or a vertex then passes on one well-defined side of it.
int edge_side(const Vec3& a, const Vec3& b, const Vec3& q) {
  const double du = b.y() - a.y(), dv = b.z() - a.z();
  const double o = du * (q.z() - a.z()) - dv * (q.y() - a.y());
  if (o != 0.0) return o > 0.0 ? 1 : -1;
  if (dv != 0.0) return dv > 0.0 ? -1 : 1;
  return du > 0.0 ? 1 : (du < 0.0 ? -1 : 0);
}

}  // namespace

MeshDistance::MeshDistance(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles)
    : v_(std::move(vertices)), tri_(std::move(triangles)) {
  if (tri_.empty()) throw std::invalid_argument("mesh distance: the surface has no triangles");
  const int nv = static_cast<int>(v_.size());
  for (const auto& t : tri_)
    for (const int k : t)
      if (k < 0 || k >= nv) throw std::invalid_argument("mesh distance: a triangle names a vertex that does not exist");

  // Pseudo-normals: faces (unit), edges (sum of the two faces), vertices (angle-weighted sum).
  face_normal_.resize(tri_.size());
  vertex_normal_.assign(v_.size(), Vec3::Zero());
  std::vector<std::tuple<int, int, int>> edges;  // (low vertex, high vertex, 3 * triangle + k)
  edges.reserve(3 * tri_.size());
  for (std::size_t t = 0; t < tri_.size(); ++t) {
    const auto& T = tri_[t];
    const Vec3 n = (v_[T[1]] - v_[T[0]]).cross(v_[T[2]] - v_[T[0]]);
    const double len = n.norm();
    face_normal_[t] = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = v_[T[(k + 1) % 3]] - v_[T[k]], w = v_[T[(k + 2) % 3]] - v_[T[k]];
      vertex_normal_[T[k]] += std::atan2(u.cross(w).norm(), u.dot(w)) * face_normal_[t];
      edges.emplace_back(std::min(T[k], T[(k + 1) % 3]), std::max(T[k], T[(k + 1) % 3]), static_cast<int>(3 * t) + k);
    }
  }
  std::sort(edges.begin(), edges.end());
  tri_edge_.resize(tri_.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool same = e > 0 && std::get<0>(edges[e]) == std::get<0>(edges[e - 1]) &&
                      std::get<1>(edges[e]) == std::get<1>(edges[e - 1]);
    if (!same) edge_normal_.push_back(Vec3::Zero());
    const int slot = std::get<2>(edges[e]);
    tri_edge_[static_cast<std::size_t>(slot / 3)][slot % 3] = static_cast<int>(edge_normal_.size()) - 1;
    edge_normal_.back() += face_normal_[static_cast<std::size_t>(slot / 3)];
  }

  // The grid: about one cell per triangle over the (slightly padded) bounding box.
  Aabb<3> box;
  for (const auto& t : tri_)
    for (const int k : t) box.extend(v_[k]);
  const double diag = box.size().norm();
  const Vec3 pad = Vec3::Constant(1e-9 * diag);
  lo_ = box.lo - pad;
  const Vec3 size = box.size() + 2.0 * pad;
  h_ = std::cbrt(size.prod() / static_cast<double>(tri_.size()));
  h_ = std::max({h_, 1e-6 * diag, size.maxCoeff() / 256.0});
  if (!(h_ > 0.0) || !std::isfinite(h_)) throw std::invalid_argument("mesh distance: the surface has no extent");
  for (int a = 0; a < 3; ++a) n_[a] = std::max(1, static_cast<int>(std::ceil(size[a] / h_)));
  const std::size_t cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  auto cell_range = [&](const std::array<int, 3>& T, std::array<int, 3>& c0, std::array<int, 3>& c1) {
    for (int a = 0; a < 3; ++a) {
      const double lo = std::min({v_[T[0]][a], v_[T[1]][a], v_[T[2]][a]});
      const double hi = std::max({v_[T[0]][a], v_[T[1]][a], v_[T[2]][a]});
      c0[a] = cell_coord(lo, a);
      c1[a] = cell_coord(hi, a);
    }
  };
  std::vector<int> count(cells + 1, 0);
  std::array<int, 3> c0{}, c1{};
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t t = 0; t < tri_.size(); ++t) {
      cell_range(tri_[t], c0, c1);
      for (int z = c0[2]; z <= c1[2]; ++z)
        for (int y = c0[1]; y <= c1[1]; ++y)
          for (int x = c0[0]; x <= c1[0]; ++x) {
            const std::size_t c = (static_cast<std::size_t>(z) * n_[1] + y) * n_[0] + x;
            if (pass == 0) ++count[c + 1];
            else cell_items_[static_cast<std::size_t>(cell_start_[c] + count[c]++)] = static_cast<int>(t);
          }
    }
    if (pass == 0) {
      for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
      cell_start_ = count;
      cell_items_.resize(static_cast<std::size_t>(count[cells]));
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

int MeshDistance::cell_coord(double x, int axis) const {
  const double c = std::floor((x - lo_[axis]) / h_);
  if (!(c >= 0.0)) return 0;  // also NaN
  return c >= n_[axis] - 1 ? n_[axis] - 1 : static_cast<int>(c);
}

void MeshDistance::consider(const Vec3& p, int t, Nearest& best) const {
  const auto& T = tri_[static_cast<std::size_t>(t)];
  const TriangleClosest c = closest_on_triangle(p, v_[T[0]], v_[T[1]], v_[T[2]]);
  if (c.distance < best.distance) {
    best.distance = c.distance;
    best.triangle = t;
    best.point = c.point;
    best.feature_kind = c.feature.kind;
    best.feature_index = c.feature.index;
  }
}

double MeshDistance::sign_of(const Vec3& p, const Nearest& best) const {
  const auto t = static_cast<std::size_t>(best.triangle);
  double s = 0.0;
  if (best.feature_kind == TriangleFeature::Face) s = (p - v_[tri_[t][0]]).dot(face_normal_[t]);
  else if (best.feature_kind == TriangleFeature::Edge) s = (p - best.point).dot(edge_normal_[tri_edge_[t][best.feature_index]]);
  else s = (p - best.point).dot(vertex_normal_[tri_[t][best.feature_index]]);
  if (s == 0.0) return inside_by_ray(p) ? -1.0 : 1.0;  // p - q orthogonal to the pseudo-normal: degenerate
  return s < 0.0 ? -1.0 : 1.0;
}

double MeshDistance::signed_distance(const Vec3& p, double reach) const {
  Nearest best;
  const double grid_diag = h_ * std::sqrt(double(n_[0]) * n_[0] + double(n_[1]) * n_[1] + double(n_[2]) * n_[2]);
  if (reach < grid_diag) {
    // Any triangle within reach has its nearest point in the query box, so in one of its cells
    // (cell_coord is monotone); the pad covers the rounding of p -/+ reach.
    const double r = reach * (1.0 + 1e-9) + 1e-14 * (p.cwiseAbs().maxCoeff() + h_);
    std::array<int, 3> c0{}, c1{};
    for (int a = 0; a < 3; ++a) {
      c0[a] = cell_coord(p[a] - r, a);
      c1[a] = cell_coord(p[a] + r, a);
    }
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x) {
          const std::size_t c = (static_cast<std::size_t>(z) * n_[1] + y) * n_[0] + x;
          for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) consider(p, cell_items_[static_cast<std::size_t>(k)], best);
        }
    if (best.distance > reach) {
      if (inside_by_ray(p)) return -reach;
      best = Nearest{};  // outside and far: the exact value by brute force (a broken packing only)
    }
  }
  if (best.triangle < 0)
    for (int t = 0; t < static_cast<int>(tri_.size()); ++t) consider(p, t, best);
  if (best.distance == 0.0) return 0.0;
  return sign_of(p, best) * best.distance;
}

bool MeshDistance::inside_by_ray(const Vec3& p) const {
  // The row of cells that the ray p + t e_x (t > 0) crosses; p beyond the grid is outside.
  const double fy = std::floor((p.y() - lo_.y()) / h_), fz = std::floor((p.z() - lo_.z()) / h_);
  if (!(fy >= 0.0 && fy < n_[1] && fz >= 0.0 && fz < n_[2])) return false;
  const double fx = std::floor((p.x() - lo_.x()) / h_);
  if (!(fx < n_[0])) return false;
  const int y = static_cast<int>(fy), z = static_cast<int>(fz), x0 = fx < 0.0 ? 0 : static_cast<int>(fx);
  std::vector<int> row;
  for (int x = x0; x < n_[0]; ++x) {
    const std::size_t c = (static_cast<std::size_t>(z) * n_[1] + y) * n_[0] + x;
    row.insert(row.end(), cell_items_.begin() + cell_start_[c], cell_items_.begin() + cell_start_[c + 1]);
  }
  std::sort(row.begin(), row.end());
  row.erase(std::unique(row.begin(), row.end()), row.end());
  int winding = 0;
  for (const int t : row) {
    const auto& T = tri_[static_cast<std::size_t>(t)];
    int side[3];
    for (int k = 0; k < 3; ++k) {
      const int a = T[k], b = T[(k + 1) % 3];
      const int s = a < b ? edge_side(v_[a], v_[b], p) : -edge_side(v_[b], v_[a], p);
      side[k] = s;
    }
    if (side[0] == 0 || side[0] != side[1] || side[1] != side[2]) continue;  // the ray misses it
    // It crosses the triangle's plane at t > 0 when p is on the side opposite to n_x's sign.
    const Vec3 n = (v_[T[1]] - v_[T[0]]).cross(v_[T[2]] - v_[T[0]]);
    const double d = (p - v_[T[0]]).dot(n);
    if (d * side[0] < 0.0) winding += side[0];
  }
  return winding != 0;
}

double MeshDistance::distance_brute_force(const Vec3& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& T : tri_) best = std::min(best, closest_on_triangle(p, v_[T[0]], v_[T[1]], v_[T[2]]).distance);
  return best;
}

}  // namespace fp
