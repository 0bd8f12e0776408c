#include "fill/tet_mesh_fill.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "contact/sphere_placement.hpp"
#include "contact/tangent_sphere.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/geometry/tet_locator.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

/// The stage's own random stream (radii drawn where the mesh's would exceed r_max).
constexpr std::uint64_t kStream = 0x7465746d65736866ULL;  // "tetmeshf"
/// Spheres nearest an aim from which the geometric procedure's 4-sets are taken (nearest first):
/// the paper's "list of spheres sorted from nearest to farthest".
constexpr int kNearest = 6;

/// The distinct simplices (edges, faces) of the tetrahedra, each with the first tetrahedron that
/// has it, sorted by their nodes.
template <std::size_t N>
std::vector<std::pair<std::array<std::uint32_t, N>, std::uint32_t>> unique_sorted(
    std::vector<std::pair<std::array<std::uint32_t, N>, std::uint32_t>> v) {
  for (auto& a : v) std::sort(a.first.begin(), a.first.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), v.end());
  return v;
}

/// What a region needs during the fill.
struct Region {
  const RadiusDistribution* radii;
  double r_min, r_max;
  std::optional<double> target;
  double measure = 0.0;  ///< the volume of its tetrahedra
  double solid = 0.0;    ///< of the spheres aimed in it
};

class TetFiller {
 public:
  TetFiller(const TetMesh& mesh, const Container<3>& container, const RadiusDistribution& dist, const TetFillOptions& o,
            std::uint64_t seed, double tol, Packing<3>& out)
      : mesh_(mesh), C_(container), o_(o), rng_(seed ^ kStream), regions_(regions_of(dist, o)),
        r_min_(smallest(regions_)), r_max_(largest(regions_)), P_(out), grid_(container.bounds(), r_min_, r_max_),
        place_(out, grid_, nullptr, r_min_, tol, o.overlap * r_min_, 0), tol_(tol) {
    if (!o.tet_region.empty()) locator_.emplace(mesh);
  }

  TetFillReport run() {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::pair<std::array<std::uint32_t, 2>, std::uint32_t>> edges;
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> faces;
    std::vector<std::uint32_t> node_tet(mesh_.nodes.size(), kNone);
    for (std::uint32_t ti = 0; ti < mesh_.tets.size(); ++ti) {
      const auto& t = mesh_.tets[ti];
      for (int i = 0; i < 4; ++i) {
        node_tet[t[static_cast<std::size_t>(i)]] = std::min(node_tet[t[static_cast<std::size_t>(i)]], ti);
        for (int j = i + 1; j < 4; ++j) {
          edges.push_back({{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(j)]}, ti});
          for (int k = j + 1; k < 4; ++k)
            faces.push_back({{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(j)], t[static_cast<std::size_t>(k)]}, ti});
        }
      }
      regions_[region_of(ti)].measure += tet_volume(mesh_, ti);
    }
    edges = unique_sorted(std::move(edges));
    faces = unique_sorted(std::move(faces));
    rep_.edges = edges.size(), rep_.faces = faces.size(), rep_.tets = mesh_.tets.size();
    const auto node = [&](std::uint32_t i) -> const Vec3& { return mesh_.nodes[i]; };

    // Steps 2 and 3: edge midpoints (r = l / 8), nodes (r = the shortest adjacent edge); each
    // reduced to the spheres already kept (z_min 0: no contact asked).
    std::vector<double> shortest(mesh_.nodes.size(), std::numeric_limits<double>::infinity());
    for (const auto& [e, t] : edges) {
      const double l = (node(e[1]) - node(e[0])).norm();
      shortest[e[0]] = std::min(shortest[e[0]], l), shortest[e[1]] = std::min(shortest[e[1]], l);
      rep_.edge_spheres += keep((node(e[0]) + node(e[1])) / 2, l / 8, region_of(t));
    }
    for (std::uint32_t i = 0; i < mesh_.nodes.size(); ++i)
      if (node_tet[i] != kNone) rep_.node_spheres += keep(node(i), shortest[i], region_of(node_tet[i])), ++rep_.nodes;
    rep_.removed_reduced = rep_.edges + rep_.nodes - rep_.edge_spheres - rep_.node_spheres;

    // Steps 4-6: the geometric procedure aimed at the faces, the tetrahedra, midway to the nodes.
    place_.set_z_min(o_.z_min);
    bool stop = reached();
    for (std::size_t f = 0; f < faces.size() && !stop; ++f) {
      const auto& [n, t] = faces[f];
      rep_.face_spheres += aim((node(n[0]) + node(n[1]) + node(n[2])) / 3, region_of(t));
      stop = reached();
    }
    if (!o_.loose) {
      for (std::uint32_t t = 0; t < mesh_.tets.size() && !stop; ++t) {
        rep_.tet_spheres += aim(barycentre(t), region_of(t));
        stop = reached();
      }
      for (std::uint32_t t = 0; t < mesh_.tets.size() && !stop; ++t)
        for (int k = 0; k < 4 && !stop; ++k) {
          rep_.midway_spheres += aim((barycentre(t) + node(mesh_.tets[t][static_cast<std::size_t>(k)])) / 2, region_of(t));
          stop = reached();
        }
    }
    rep_.reached_target = stop;

    // Step 7a: what is not inside the mesh's boundary goes.
    Packing<3> kept;
    kept.origin = P_.origin;
    kept.reserve(P_.size());
    const std::size_t mesh_spheres = rep_.edge_spheres + rep_.node_spheres;
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (C_.contains_ball(P_.centers[i], P_.radii[i], tol_)) {
        kept.add(P_.centers[i], P_.radii[i]);
        rep_.mesh_spheres_kept += i < mesh_spheres;
      }
    rep_.removed_boundary = P_.size() - kept.size();
    P_ = std::move(kept);
    rep_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rep_;
  }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  static std::vector<Region> regions_of(const RadiusDistribution& dist, const TetFillOptions& o) {
    std::vector<Region> out;
    const std::vector<TetRegion> given = o.regions.empty() ? std::vector<TetRegion>{TetRegion{}} : o.regions;
    for (const TetRegion& g : given) {
      const RadiusDistribution* law = g.radii ? g.radii : &dist;
      out.push_back({law, law->r_min(), law->r_max(), g.target_volume_fraction ? g.target_volume_fraction : o.target_volume_fraction});
    }
    return out;
  }
  static double smallest(const std::vector<Region>& r) {
    double x = r[0].r_min;
    for (const Region& g : r) x = std::min(x, g.r_min);
    return x;
  }
  static double largest(const std::vector<Region>& r) {
    double x = r[0].r_max;
    for (const Region& g : r) x = std::max(x, g.r_max);
    return x;
  }
  /// The region of the tetrahedron holding x (0 outside the mesh).
  std::size_t region_at(const Vec3& x) const {
    const int t = locator_->tet_at(x);
    return t < 0 ? 0 : region_of(static_cast<std::uint32_t>(t));
  }
  std::size_t region_of(std::uint32_t tet) const {
    return o_.tet_region.empty() ? 0 : static_cast<std::size_t>(o_.tet_region[tet]);
  }

  /// The paper's radius rule: above r_max a radius of the law, below r_min r_min.
  double rule(double r, const Region& g) {
    if (r > g.r_max) return g.radii->sample(rng_);
    return std::max(r, g.r_min);
  }

  /// Steps 2-3: the sphere (c, rule(r)) reduced to cancel its overlaps, kept if r >= r_min.
  bool keep(const Vec3& c, double r, std::size_t region) {
    Region& g = regions_[region];
    double radius = rule(r, g);
    if (!place_.try_place(c, radius, true, g.r_min)) return false;
    g.solid += ball_measure<3>(radius);
    return true;
  }

  Vec3 barycentre(std::size_t t) const {
    Vec3 b = Vec3::Zero();
    for (const std::uint32_t v : mesh_.tets[t]) b += mesh_.nodes[v] / 4.0;
    return b;
  }

  bool region_reached(const Region& g) const { return g.target && g.measure > 0 && g.solid / g.measure >= *g.target; }
  /// N0, or every region with a phi0 at it (and every region has one).
  bool reached() const {
    if (o_.max_particles && P_.size() >= *o_.max_particles) return true;
    for (const Region& g : regions_)
      if (!region_reached(g)) return false;
    return true;
  }

  /// Steps 4-6 at aim p: the spheres nearest p, their 4-sets nearest first, the sphere touching
  /// the four (Eqs. 1-9) whose centre is nearest p, kept if its radius is in [r_min, r_max] and
  /// it is accepted (contact/sphere_placement.hpp). Returns whether a sphere was added.
  bool aim(const Vec3& p, std::size_t region) {
    Region& g = regions_[region];
    if (region_reached(g)) return false;
    near_.clear();
    for (double reach = 2 * r_max_; near_.size() < 4 && reach < 64 * r_max_; reach *= 2) {
      near_.clear();
      grid_.for_each_within(p, reach, [&](int id, const Vec3&, double r, double d2) {
        near_.push_back({std::sqrt(d2) - r, id});
      });
    }
    if (near_.size() < 4) return false;
    const std::size_t k = std::min<std::size_t>(near_.size(), kNearest);
    std::partial_sort(near_.begin(), near_.begin() + static_cast<std::ptrdiff_t>(k), near_.end());
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b)
        for (std::size_t c = b + 1; c < k; ++c)
          for (std::size_t d = c + 1; d < k; ++d) {
            std::array<TangentBody<3>, 4> four;
            const std::size_t pick[4] = {a, b, c, d};
            for (int q = 0; q < 4; ++q) {
              const int id = near_[pick[q]].second;
              four[static_cast<std::size_t>(q)] = TangentBody<3>::sphere(P_.centers[static_cast<std::size_t>(id)],
                                                                         P_.radii[static_cast<std::size_t>(id)]);
            }
            ++rep_.procedures;
            TangentSpheres<3> s = spheres_tangent_to<3>(four);
            if (s.count == 2 && (s.at[1].centre - p).squaredNorm() < (s.at[0].centre - p).squaredNorm())
              std::swap(s.at[0], s.at[1]);
            for (int q = 0; q < s.count; ++q) {
              double r = s.at[static_cast<std::size_t>(q)].radius;
              if (r < g.r_min || r > g.r_max) continue;
              const Vec3& x = s.at[static_cast<std::size_t>(q)].centre;
              if (locator_ && region_at(x) != region) continue;  // a sphere of the region is centred in it
              if (place_.try_place(x, r, true, g.r_min)) {
                g.solid += ball_measure<3>(r);
                return true;
              }
            }
          }
    return false;
  }

  const TetMesh& mesh_;
  const Container<3>& C_;
  const TetFillOptions& o_;
  Rng rng_;
  std::vector<Region> regions_;
  double r_min_, r_max_;  ///< over every region
  Packing<3>& P_;
  NeighbourGrid<3> grid_;
  SpherePlacement<3> place_;
  double tol_;
  std::optional<TetLocator> locator_;          ///< with regions: which one a sphere's centre is in
  std::vector<std::pair<double, int>> near_;  ///< (distance to the surface, sphere) around an aim
  TetFillReport rep_;
};

}  // namespace

TetFillReport fill_tet_mesh(const TetMesh& mesh, const Container<3>& container, const RadiusDistribution& dist,
                            const TetFillOptions& options, std::uint64_t seed, double contact_tolerance, Packing<3>& out) {
  out.clear();
  out.origin = container.origin();
  return TetFiller(mesh, container, dist, options, seed, contact_tolerance, out).run();
}

}  // namespace fp
