#include "core/geometry/mesh_container.hpp"

#include <Eigen/Geometry>  // cross()

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/geometry/container_checks.hpp"
#include "core/geometry/deepest_point.hpp"
#include "core/geometry/mesh_cells.hpp"
#include "core/geometry/mesh_cgal.hpp"
#include "core/system/available_memory.hpp"

namespace fp {
namespace {

/// Memory per face of a mesh container in a whole run (its index, the validation's own grid):
/// 440-470 B measured as peak RSS over faces for binary STL spheres of 0.6 and 2.6 M faces
/// (experiments/extremes/RESULTS.md, "Limits"); rounded up.
constexpr double kBytesPerFacet = 500;

// The cell index (prepare_queries): at most this many cells (10 bytes each) and facet listings
// (8 bytes each, 20 while built: at most ~330 MB for the largest); beyond, the queries stay with
// the tree (a mesh of millions of facets far smaller than the particles).
constexpr std::size_t kMaxCells = std::size_t(1) << 22;
constexpr std::size_t kMaxCellEntriesPerFacet = 256;
constexpr std::size_t kMaxCellEntries = std::size_t(1) << 24;
constexpr double kCellMarginOverReach = 2.0;
constexpr double kCellOverReach = 1.5;

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
  throw std::invalid_argument("mesh '" + name + "' " + why);
}

Vec3 area_vector(const std::vector<Vec3>& v, const std::array<int, 3>& t) {
  return 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
}

/// Merges bit-identical vertices, drops unused ones and facets that use a vertex twice.
/// Returns the number of facets dropped.
int merge_duplicates(std::vector<Vec3>& vertices, std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(vertices.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto lex_less = [&](int a, int b) {
    const Vec3 &p = vertices[a], &q = vertices[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), lex_less);
  std::vector<int> representative(n);
  for (int k = 0; k < n; ++k)
    representative[order[k]] = (k > 0 && vertices[order[k]] == vertices[order[k - 1]]) ? representative[order[k - 1]]
                                                                                      : order[k];
  int dropped = 0;
  std::vector<std::array<int, 3>> kept;
  kept.reserve(triangles.size());
  for (auto t : triangles) {
    for (int& i : t) i = representative[i];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++dropped;
      continue;
    }
    kept.push_back(t);
  }
  // Compact: keep only vertices some facet uses, in first-use order (deterministic).
  std::vector<int> new_index(n, -1);
  std::vector<Vec3> used;
  for (auto& t : kept)
    for (int& i : t) {
      if (new_index[i] < 0) {
        new_index[i] = static_cast<int>(used.size());
        used.push_back(vertices[i]);
      }
      i = new_index[i];
    }
  vertices = std::move(used);
  triangles = std::move(kept);
  return dropped;
}

struct EdgeUse {
  int lo, hi;     ///< vertex ids, lo < hi
  int facet, k;   ///< the facet and its edge k (from corner k to corner k+1)
  bool operator<(const EdgeUse& o) const {
    return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : facet < o.facet);
  }
};

int corner_of(const std::array<int, 3>& t, int v) {
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// Checks that the surface is a closed 2-manifold (every edge in exactly two facets, one fan
/// of facets around every vertex), then flips facets so that each pair walks its shared edge
/// in opposite directions. Returns the connected component of each facet.
std::vector<int> orient_consistently(const std::string& name, std::vector<std::array<int, 3>>& triangles,
                                     int num_vertices) {
  const int nf = static_cast<int>(triangles.size());
  std::vector<EdgeUse> uses;
  uses.reserve(3 * nf);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  std::sort(uses.begin(), uses.end());
  std::size_t boundary = 0, non_manifold = 0;
  std::vector<std::array<int, 3>> neighbour(nf, {-1, -1, -1});  // across edge k
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j - i == 1) ++boundary;
    else if (j - i > 2 || uses[i].facet == uses[i + 1].facet) ++non_manifold;
    else {
      neighbour[uses[i].facet][uses[i].k] = uses[i + 1].facet;
      neighbour[uses[i + 1].facet][uses[i + 1].k] = uses[i].facet;
    }
    i = j;
  }
  if (non_manifold > 0)
    refuse(name, "is not manifold: " + std::to_string(non_manifold) + " non-manifold edges (in more than 2 facets)" +
                     (boundary > 0 ? " and " + std::to_string(boundary) + " boundary edges" : ""));
  if (boundary > 0) refuse(name, "is not closed: " + std::to_string(boundary) + " boundary edges");

  // Around a manifold vertex the facets form one fan: join the corners at the two ends of every
  // shared edge, then count vertices whose corners fall into more than one group.
  std::vector<int> parent(3 * nf);
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = neighbour[f][k];
      for (int end = 0; end < 2; ++end) {
        const int corner = (k + end) % 3;
        const int a = find_root(parent, 3 * f + corner);
        const int b = find_root(parent, 3 * g + corner_of(triangles[g], triangles[f][corner]));
        if (a != b) parent[a] = b;
      }
    }
  std::vector<int> root_of_vertex(num_vertices, -1);
  std::vector<char> pinched(num_vertices, 0);
  for (int c = 0; c < 3 * nf; ++c) {
    const int v = triangles[c / 3][c % 3];
    const int r = find_root(parent, c);
    if (root_of_vertex[v] < 0) root_of_vertex[v] = r;
    else if (root_of_vertex[v] != r) pinched[v] = 1;
  }
  const auto pinched_count = std::count(pinched.begin(), pinched.end(), 1);
  if (pinched_count > 0)
    refuse(name, "is not manifold: " + std::to_string(pinched_count) +
                     " non-manifold vertices (where separate sheets of the surface touch)");

  // Breadth-first flood per component: a neighbour walking the shared edge the same way is flipped.
  std::vector<int> component(nf, -1);
  std::vector<char> flip(nf, 0);
  std::vector<int> queue;
  int components = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (component[seed] >= 0) continue;
    component[seed] = components;
    queue.assign(1, seed);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int f = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int g = neighbour[f][k];
        // Same direction: g walks the edge from triangles[f][k] to triangles[f][k+1] too.
        const int a = triangles[f][k];
        const int b = triangles[f][(k + 1) % 3];
        const bool same = triangles[g][(corner_of(triangles[g], a) + 1) % 3] == b;
        const char want = flip[f] ^ static_cast<char>(same);
        if (component[g] < 0) {
          component[g] = components;
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          refuse(name, "is not orientable (a closed surface in 3D without self-intersections always is)");
        }
      }
    }
    ++components;
  }
  for (int f = 0; f < nf; ++f)
    if (flip[f]) std::swap(triangles[f][1], triangles[f][2]);
  return component;
}

}  // namespace

std::shared_ptr<MeshContainer> MeshContainer::from_file(const std::string& path, double scale, FrameChoice frame,
                                                        const std::optional<Vec3>& explicit_origin) {
  const std::string name = base_name(path);
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("MeshContainer: scale must be positive and finite, got " + detail::format_number(scale) +
                                " (file '" + path + "')");
  detail::PolygonSoup soup;
  std::string error;
  if (!detail::read_polygon_soup(path, soup, error))
    throw std::invalid_argument("mesh '" + path + "' cannot be read: " + error);
  // Its index and the validation's own grid take about kBytesPerFacet each: a mesh too large for
  // the machine is refused before they are built (the kernel would kill the process instead).
  if (const MemoryBudget memory = available_memory(); double(soup.polygons.size()) * kBytesPerFacet > double(memory.bytes))
    throw std::invalid_argument("mesh '" + path + "' has " + std::to_string(soup.polygons.size()) + " faces, which need about " +
                                std::to_string(std::llround(double(soup.polygons.size()) * kBytesPerFacet / 1e6)) +
                                " MB to index, more than the " + std::to_string(memory.bytes / 1000000) +
                                " MB this process may use (" + memory.source + "); simplify the surface");
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(soup.polygons.size());
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& poly = soup.polygons[f];
    if (poly.size() < 3) refuse(name, "has a face with fewer than 3 vertices (face " + std::to_string(f) + ")");
    for (std::size_t i : poly)
      if (i >= soup.points.size()) refuse(name, "has a vertex index out of range in face " + std::to_string(f));
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      triangles.push_back({static_cast<int>(poly[0]), static_cast<int>(poly[k]), static_cast<int>(poly[k + 1])});
  }
  Aabb<3> box;
  for (Vec3& p : soup.points) {
    p *= scale;
    if (p.allFinite()) box.extend(p);
  }
  const Vec3 origin = explicit_origin ? *explicit_origin
                     : frame == FrameChoice::Local && !soup.points.empty() ? frame_origin<3>(box) : Vec3::Zero();
  return std::shared_ptr<MeshContainer>(new MeshContainer(std::move(soup.points), std::move(triangles), name, origin));
}

std::shared_ptr<MeshContainer> MeshContainer::from_triangles(std::vector<Vec3> vertices,
                                                             std::vector<std::array<int, 3>> triangles,
                                                             const std::string& name, const Vec3& origin) {
  return std::shared_ptr<MeshContainer>(new MeshContainer(std::move(vertices), std::move(triangles), name, origin));
}

MeshContainer::MeshContainer(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles, std::string name,
                             const Vec3& origin)
    : Container<3>(origin), name_(std::move(name)), vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  detail::require_finite<3>(origin, "MeshContainer", "origin");
  const int nv = static_cast<int>(vertices_.size());
  for (int i = 0; i < nv; ++i)
    if (!vertices_[i].allFinite())
      refuse(name_, "has a non-finite vertex " + std::to_string(i) + ": " + detail::format_vec<3>(vertices_[i]));
  for (Vec3& v : vertices_) v -= origin;  // exact for every vertex near the origin's magnitude (local_frame.hpp)
  for (std::size_t f = 0; f < triangles_.size(); ++f)
    for (int i : triangles_[f])
      if (i < 0 || i >= nv) refuse(name_, "has a vertex index out of range in facet " + std::to_string(f));
  dropped_degenerate_ = merge_duplicates(vertices_, triangles_);
  if (triangles_.empty()) refuse(name_, "is empty (no facets)");
  const std::vector<int> component = orient_consistently(name_, triangles_, static_cast<int>(vertices_.size()));
  for (const Vec3& v : vertices_) box_.extend(v);
  const double diag = box_.size().norm();

  bool any_area = false;
  for (const auto& t : triangles_) any_area = any_area || area_vector(vertices_, t).squaredNorm() > 0.0;
  if (!any_area) refuse(name_, "encloses no volume (all facets have zero area)");
  try {
    index_ = std::make_unique<detail::TriangleSurfaceIndex>(vertices_, triangles_);
  } catch (const std::invalid_argument& e) {
    refuse(name_, std::string("cannot be indexed: ") + e.what());
  }
  // Inside and outside are meaningless where the surface crosses itself or two shells overlap.
  if (int f = 0, g = 0; index_->find_crossing_facets(f, g)) {
    const auto centre = [&](int k) {
      const auto& t = triangles_[k];
      return Vec3((vertices_[t[0]] + vertices_[t[1]] + vertices_[t[2]]) / 3.0);
    };
    refuse(name_, "intersects itself: two of its facets cross, near " + detail::format_vec<3>(0.5 * (centre(f) + centre(g))) +
                      " (a surface folding through itself, or two closed parts that overlap)");
  }

  // Orient each component outward: step off its largest facets along the normal; outside must
  // be out and the opposite side in. Works for nested shells (a cavity gets inward normals).
  const int nf = static_cast<int>(triangles_.size());
  const int ncomp = *std::max_element(component.begin(), component.end()) + 1;
  std::vector<std::vector<int>> by_area(ncomp);
  for (int f = 0; f < nf; ++f) by_area[component[f]].push_back(f);
  for (int c = 0; c < ncomp; ++c) {
    auto& fs = by_area[c];
    const std::size_t tries = std::min<std::size_t>(fs.size(), 16);
    std::partial_sort(fs.begin(), fs.begin() + tries, fs.end(), [&](int a, int b) {
      const double sa = area_vector(vertices_, triangles_[a]).squaredNorm();
      const double sb = area_vector(vertices_, triangles_[b]).squaredNorm();
      return sa > sb || (sa == sb && a < b);
    });
    int verdict = 0;  // +1 outward, -1 inward
    for (std::size_t k = 0; k < tries && verdict == 0; ++k) {
      const auto& t = triangles_[fs[k]];
      const Vec3 av = area_vector(vertices_, t);
      const double area = av.norm();
      if (!(area > 0.0)) continue;
      const Vec3 n = av / area;
      const Vec3 g = (vertices_[t[0]] + vertices_[t[1]] + vertices_[t[2]]) / 3.0;
      const double eps = std::min(1e-7 * diag, 1e-3 * std::sqrt(area));
      const int ahead = index_->side(g + eps * n), behind = index_->side(g - eps * n);
      if (ahead < 0 && behind > 0) verdict = 1;
      else if (ahead > 0 && behind < 0) verdict = -1;
    }
    if (verdict == 0) refuse(name_, "has a component whose inside cannot be told from its outside (self-intersecting?)");
    if (verdict < 0)
      for (int f : fs) std::swap(triangles_[f][1], triangles_[f][2]);
  }

  const Vec3 o = box_.center();  // about the centre: less cancellation far from the origin
  double six_volume = 0.0;
  inward_.resize(nf);
  sides_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = triangles_[f];
    six_volume += (vertices_[t[0]] - o).dot((vertices_[t[1]] - o).cross(vertices_[t[2]] - o));
    const Vec3 av = area_vector(vertices_, t);
    const double area = av.norm();
    inward_[f] = area > 0.0 ? Vec3(-av / area) : Vec3::Zero();
    if (!(area > 0.0)) continue;  // never offered as a wall
    for (int k = 0; k < 3; ++k) {  // out of the facet, in its plane
      const Vec3 &a = vertices_[t[k]], &b = vertices_[t[(k + 1) % 3]], &c = vertices_[t[(k + 2) % 3]];
      Vec3 m = (b - a).cross(inward_[f]).normalized();
      if (m.dot(c - a) > 0.0) m = -m;
      sides_[f][k] = {m, m.dot(a), a};
    }
  }
  volume_ = six_volume / 6.0;
  if (!(volume_ > 1e-12 * diag * diag * diag)) refuse(name_, "encloses no volume");

  std::vector<Vec3> candidates;
  const int stride = std::max(1, nf / 256);
  for (int f = 0; f < nf; f += stride) {
    const auto& t = triangles_[f];
    const Vec3 g = (vertices_[t[0]] + vertices_[t[1]] + vertices_[t[2]]) / 3.0;
    candidates.push_back(g + 1e-3 * (vertices_[t[1]] - vertices_[t[0]]).norm() * inward_[f]);
  }
  interior_ = detail::deepest_point<3>(*this, 16, candidates, 1e-3);
}

MeshContainer::~MeshContainer() = default;

void MeshContainer::prepare_queries(double reach) const {
  const double inv = index_->inverse_scale();
  // Lists to twice the reach (the analysis's core region is the container shrunk by 2 r_max);
  // cells of 1.5 times it: femur, U[0.005, 0.01], the fastest whole run of cells 1, 1.5 and 2
  // (experiments/mesh-speed/RESULTS.md).
  const double cell = kCellOverReach * reach * inv, margin = kCellMarginOverReach * reach * inv;
  if (!(margin > 0.0) || !std::isfinite(margin) || (cells_ && cells_->margin() == margin)) return;
  std::vector<Vec3> scaled(vertices_.size());
  for (std::size_t v = 0; v < vertices_.size(); ++v) scaled[v] = vertices_[v] * inv;  // CGAL's frame, exactly
  const detail::TriangleSurfaceIndex& index = *index_;
  const double scale = index_->scale();
  auto built = std::make_unique<const detail::MeshCells>(scaled, triangles_, index_->solid_facets(), cell, margin, kMaxCells,
                                                         std::min(kMaxCellEntriesPerFacet * triangles_.size() + kMaxCells, kMaxCellEntries),
                                                         [&](const Vec3& q) { return index.side(q * scale); });
  cells_ = built->built() ? std::move(built) : nullptr;
}

std::array<std::size_t, 2> MeshContainer::cell_index_size() const {
  return cells_ ? std::array<std::size_t, 2>{cells_->cells(), cells_->entries()} : std::array<std::size_t, 2>{0, 0};
}

bool MeshContainer::inside(const Vec3& p) const {
  if (cells_)
    if (const int side = cells_->side(p * index_->inverse_scale()); side != 0) return side > 0;
  return index_->side(p) >= 0;
}

double MeshContainer::signed_distance(const Vec3& p) const {
  if (cells_) {
    Vec3 q;
    int side = 0;
    if (cells_->nearest(p * index_->inverse_scale(), q, side)) {
      if (side == 0) side = index_->side(p);
      if (side == 0) return 0.0;
      const double d = (p - q * index_->scale()).norm();
      return side > 0 ? -d : d;
    }
  }
  const int side = index_->side(p);
  if (side == 0) return 0.0;
  const double d = (p - index_->closest_point(p, nullptr)).norm();
  return side > 0 ? -d : d;
}

void MeshContainer::walls_near(const Vec3& p, double reach, std::vector<Wall<3>>& out) const {
  if (cells_ && cells_->distance_lower_bound(p * index_->inverse_scale()) > reach * index_->inverse_scale()) return;
  thread_local std::vector<int> facets;  // scratch, reused across calls
  facets.clear();
  index_->facets_within(p, reach, facets);
  for (int f : facets) out.push_back(Wall<3>::plane(vertices_[triangles_[f][0]], inward_[f], f).over(sides_[f]));
}

bool MeshContainer::contains_ball(const Vec3& c, double r, double rel_tol) const {
  const double clearance = r - rel_tol * r;
  if (!(clearance > 0.0)) return signed_distance(c) <= -clearance;
  if (cells_) {
    const double inv = index_->inverse_scale();
    const auto answer = cells_->ball_inside(c * inv, clearance * inv);
    if (answer != detail::MeshCells::Answer::Unknown) return answer == detail::MeshCells::Answer::Yes;
  }
  return index_->side(c) > 0 && !index_->any_facet_closer_than(c, clearance);
}

std::string MeshContainer::describe() const {
  return "mesh " + name_ + " (" + std::to_string(triangles_.size()) + " facets, volume " +
         detail::format_short(volume_) + ")";
}

}  // namespace fp
