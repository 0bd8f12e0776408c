#include "contact/polytope_wrapper_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <unordered_map>
#include <vector>

#include "contact/sphere_two_contact.hpp"
#include "shapes/convex_polytope_shape.hpp"

namespace fp {
namespace {

using V = Vec3;
using Poly = ConvexPolytopeShape<3>;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Starts spread along the curve of the first two bodies (every loop of it is walked once).
constexpr int kLoopSamples = 12;

/// The positions x of the mobile's reference point where it overlaps a body: the convex set
/// {x : n_k . (x - c) <= h_k for every k}, c the body's reference point (so the planes can be
/// kept while the frame moves). value() is 0 on the wrapper, > 0 apart, < 0 on overlap.
struct Obstacle {
  std::vector<V> n;
  std::vector<double> h;  ///< relative to `c`
  V c = V::Zero();

  /// max_k (n_k . (x - c) - h_k) and its plane.
  double value(const V& x, int& arg) const {
    double best = -kInf;
    arg = -1;
    const V y = x - c;
    for (std::size_t k = 0; k < n.size(); ++k)
      if (const double v = n[k].dot(y) - h[k]; v > best) best = v, arg = static_cast<int>(k);
    return best;
  }
  double value(const V& x) const {
    int arg;
    return value(x, arg);
  }
};

/// An edge's Gauss arc: the great-circle arc between its two faces' unit normals a and b, with
/// what every test against it needs (computed once per edge, not per edge pair).
struct GaussArc {
  V a, b, ab, sum;  ///< ab = a x b, sum = a + b
  V along;          ///< the edge's vector
  double length;

  GaussArc(const V& a_, const V& b_, const V& along_) : a(a_), b(b_), ab(a_.cross(b_)), sum(a_ + b_), along(along_), length(along_.norm()) {}
  /// Is the unit vector p (on the great circle through a and b) on the shorter arc from a to b?
  bool holds(const V& p) const {
    constexpr double kSlack = 1e-12;
    return a.cross(p).dot(ab) >= -kSlack && p.cross(b).dot(ab) >= -kSlack && p.dot(sum) > 0;
  }
};

double max_dot(const std::vector<V>& pts, const V& u) {
  double m = -kInf;
  for (const V& p : pts) m = std::max(m, u.dot(p));
  return m;
}

/// The mobile turned: vertices (about its reference point), plane normals, for one problem.
struct TurnedMobile {
  const Poly* shape = nullptr;
  Mat<3> rotation = Mat<3>::Identity();
  std::vector<V> vertices, normals;
  std::vector<GaussArc> arcs;  ///< per edge of -A: the arc between its faces' normals (of -A)

  void set(const Poly& s, const Mat<3>& R) {
    shape = &s, rotation = R;
    vertices.clear(), normals.clear(), arcs.clear();
    for (const V& v : s.vertices()) vertices.push_back(R * v);
    for (const V& n : s.plane_normals()) normals.push_back(R * n);
    for (const Poly::Edge& e : s.edges())
      arcs.emplace_back(-normals[static_cast<std::size_t>(e.plane0)], -normals[static_cast<std::size_t>(e.plane1)],
                        vertices[static_cast<std::size_t>(e.b)] - vertices[static_cast<std::size_t>(e.a)]);
  }
};

/// O = B (+) (-A) of a polyhedron B (rotation RB, reference point c) for the turned mobile A, by
/// its face planes: faces of B, faces of -A, and edge pairs whose Gauss arcs cross.
void polytope_obstacle(const Poly& B, const Mat<3>& RB, const V& c, const TurnedMobile& A, Obstacle& O) {
  thread_local std::vector<V> bv, bn;
  bv.clear(), bn.clear();
  for (const V& v : B.vertices()) bv.push_back(RB * v);
  for (const V& n : B.plane_normals()) bn.push_back(RB * n);
  O.n.clear(), O.h.clear();
  O.c = c;
  // Faces of B with the support of -A along their normal.
  for (std::size_t k = 0; k < bn.size(); ++k) {
    O.n.push_back(bn[k]);
    O.h.push_back(B.plane_offsets()[k] + max_dot(A.vertices, -bn[k]));
  }
  // Faces of -A (normals -RA n_g) with the support of B.
  const auto& a_offsets = A.shape->plane_offsets();
  for (std::size_t g = 0; g < A.normals.size(); ++g) {
    const V u = -A.normals[g];
    O.n.push_back(u);
    O.h.push_back(max_dot(bv, u) + a_offsets[g]);
  }
  // Edge-edge: the planes perpendicular to an edge of B and an edge of -A whose Gauss arcs (from
  // one adjacent face normal to the other) cross; both edges are supports along that normal.
  const std::vector<Poly::Edge>& a_edges = A.shape->edges();
  for (const Poly::Edge& eb : B.edges()) {
    const GaussArc arc_b(bn[static_cast<std::size_t>(eb.plane0)], bn[static_cast<std::size_t>(eb.plane1)],
                         bv[static_cast<std::size_t>(eb.b)] - bv[static_cast<std::size_t>(eb.a)]);
    for (std::size_t k = 0; k < a_edges.size(); ++k) {
      const GaussArc& arc_a = A.arcs[k];
      V p = arc_b.along.cross(arc_a.along);
      const double pn = p.norm();
      if (!(pn > 1e-12 * arc_b.length * arc_a.length)) continue;  // parallel edges: no edge-edge face
      p /= pn;
      if (p.dot(arc_b.sum) < 0) p = -p;
      if (!arc_b.holds(p) || !arc_a.holds(p)) continue;
      O.n.push_back(p);
      O.h.push_back(p.dot(bv[static_cast<std::size_t>(eb.a)]) - p.dot(A.vertices[static_cast<std::size_t>(a_edges[k].a)]));
    }
  }
}

/// The obstacle of a plane wall (inward normal m): the mobile crosses it where m . x <= c.
void plane_obstacle(const Wall<3>& w, const TurnedMobile& A, Obstacle& O) {
  O.n.assign(1, w.normal);
  O.c = w.point;
  O.h.assign(1, max_dot(A.vertices, -w.normal));  // m . (x - p) <= -min_j m . a_j
}

/// The obstacle of a reflex corner v (the mobile must not hold it): -A placed at v.
void corner_obstacle(const Wall<3>& w, const TurnedMobile& A, Obstacle& O) {
  O.n.clear(), O.h.clear();
  O.c = w.point;
  for (std::size_t g = 0; g < A.normals.size(); ++g) {
    O.n.push_back(-A.normals[g]);
    O.h.push_back(A.shape->plane_offsets()[g]);
  }
}

/// Obstacles of the particles met so far for one turned mobile (the front asks for many pairs
/// around one front particle with one mobile): each particle's planes are built once.
/// A cache key: a body by its address and position (the particles' vector may have moved, and a
/// stale pointer must not match another particle), hashed on the address.
struct BodyKey {
  const void* address;
  V point, normal;
  bool operator==(const BodyKey& o) const { return address == o.address && point == o.point && normal == o.normal; }
};
/// A wall (no address) by its point and normal.
inline BodyKey key_of(const Body<3>& b) {
  return b.is_wall() ? BodyKey{nullptr, b.wall->point, b.wall->normal} : BodyKey{b.shaped, b.center, V::Zero()};
}
struct PairKey {
  BodyKey first, second;
  bool operator==(const PairKey& o) const { return first == o.first && second == o.second; }
};
struct KeyHash {
  static std::size_t bits(double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return std::hash<std::uint64_t>{}(u);
  }
  std::size_t operator()(const BodyKey& k) const {
    return std::hash<const void*>{}(k.address) ^ (bits(k.point.x()) * 3) ^ (bits(k.point.y()) * 5) ^ (bits(k.point.z()) * 7);
  }
  std::size_t operator()(const PairKey& k) const { return (*this)(k.first) * 31 + (*this)(k.second); }
};

struct ObstacleCache {
  const Shape<3>* mobile = nullptr;
  Mat<3> rotation = Mat<3>::Identity();
  TurnedMobile turned;
  std::deque<Obstacle> obstacles;  ///< a deque: the references handed out stay valid as it grows
  std::unordered_map<BodyKey, std::size_t, KeyHash> index;

  void use(const Poly& shape, const Mat<3>& R) {
    if (&shape == mobile && R == rotation && obstacles.size() < 256) return;
    mobile = &shape, rotation = R;
    turned.set(shape, R);
    obstacles.clear(), index.clear();
  }
  const Obstacle& of(const Particle<3>& p, const Poly& shape) {
    const auto [it, added] = index.try_emplace(BodyKey{&p, p.pose.position, V::Zero()}, obstacles.size());
    if (!added) return obstacles[it->second];
    polytope_obstacle(shape, p.pose.rotation, p.pose.position, turned, obstacles.emplace_back());
    return obstacles.back();
  }
};

/// Damped Newton steps onto the curve where both gap functions vanish: each step goes to the
/// nearest point of the line where the two active planes meet, halved until |f_P| + |f_Q|
/// decreases (the active planes of piecewise-linear functions can otherwise alternate without
/// end). False if the active planes are parallel or no step decreases it.
bool onto_curve(const Obstacle& P, const Obstacle& Q, double tol, V& x, int& a, int& b) {
  double fp = P.value(x, a), fq = Q.value(x, b);
  for (int it = 0; it < 60; ++it) {
    const V na = P.n[a], nb = Q.n[b];
    const double g = na.dot(nb);
    const double det = 1 - g * g;  // unit normals: the Gram determinant
    if (!(det > 1e-12)) return false;
    // x - (l na + m nb) on both planes: [1 g; g 1] (l, m) = (fp, fq).
    const V step = -((fp - g * fq) / det * na + (fq - g * fp) / det * nb);
    const double merit = std::abs(fp) + std::abs(fq);
    bool moved = false;
    for (double lambda = 1; lambda >= 1.0 / 64 && !moved; lambda *= 0.5) {
      const V y = x + lambda * step;
      int ay, by;
      const double gp = P.value(y, ay), gq = Q.value(y, by);
      if (std::abs(gp) + std::abs(gq) < merit || (lambda == 1 && std::abs(gp) <= tol && std::abs(gq) <= tol)) {
        x = y, a = ay, b = by, fp = gp, fq = gq;
        moved = true;
      }
    }
    if (std::abs(fp) <= tol && std::abs(fq) <= tol) return true;
    if (!moved) return false;
  }
  return false;
}

/// A piece of the curve where the mobile touches two bodies: x + s t, s in [0, len].
struct Segment {
  V x, t;
  double len;
};

/// Walks every loop of the curve where P's and Q's boundaries meet (frame centred on s0), from
/// starts spread along where equivalent spheres touch the two bodies (a loop is walked once).
void walk_curve(const Obstacle& P, const Obstacle& Q, const std::vector<V>& starts, double scale, std::vector<Segment>& curve) {
  curve.clear();
  const double snap = 1e-13 * scale;  // Newton: close enough to both planes to walk from
  std::vector<std::pair<int, int>> walked;  // face pairs of the loops already walked
  for (V x : starts) {
    int a = -1, b = -1;
    if (!onto_curve(P, Q, snap, x, a, b)) continue;
    if (std::find(walked.begin(), walked.end(), std::make_pair(a, b)) != walked.end()) continue;
    // Face pair by face pair, in the direction n_a x n_b (one orientation for the whole loop).
    const V x0 = x;
    const int a0 = a, b0 = b;
    const int max_steps = 4 * static_cast<int>(P.n.size() + Q.n.size()) + 16;
    for (int step = 0; step < max_steps; ++step) {
      walked.emplace_back(a, b);
      V t = P.n[a].cross(Q.n[b]);
      const double tn = t.norm();
      if (!(tn > 1e-12)) break;  // parallel faces: a flush contact, no curve
      t /= tn;
      // The segment ends where another plane of P or Q is reached.
      double len = kInf;
      int next_p = -1, next_q = -1;
      for (int pass = 0; pass < 2; ++pass) {
        const Obstacle& S = pass == 0 ? P : Q;
        const int skip = pass == 0 ? a : b;
        for (std::size_t k = 0; k < S.n.size(); ++k) {
          if (static_cast<int>(k) == skip) continue;
          const double rate = S.n[k].dot(t);
          if (!(rate > 1e-15)) continue;
          const double at = std::max(0.0, (S.h[k] - S.n[k].dot(x - S.c)) / rate);
          if (at < len) len = at, next_p = pass == 0 ? static_cast<int>(k) : -1, next_q = pass == 1 ? static_cast<int>(k) : -1;
        }
      }
      if (!(len < kInf)) break;
      // Back on the first segment: up to the start, and the loop is closed.
      if (step > 0 && a == a0 && b == b0) {
        const double to_start = (x0 - x).dot(t);
        if (to_start >= 0 && to_start <= len) {
          curve.push_back({x, t, to_start});
          break;
        }
      }
      curve.push_back({x, t, len});
      x += len * t;
      if (next_p >= 0) a = next_p;
      else b = next_q;
    }
  }
}

/// The curves of the (front particle, body) pairs met so far, for one mobile: the front tries
/// each pair with many third bodies, and the curve does not depend on the third.
struct CurveCache {
  const Shape<3>* mobile = nullptr;
  Mat<3> rotation = Mat<3>::Identity();
  std::deque<std::vector<Segment>> curves;
  std::unordered_map<PairKey, std::size_t, KeyHash> index;

  void clear() { curves.clear(), index.clear(); }

  const std::vector<Segment>& of(const Body<3>& b0, const Body<3>& b1, const Obstacle& P, const Obstacle& Q, const Poly& shape,
                                 double scale) {
    const PairKey key{key_of(b0), key_of(b1)};
    if (const auto it = index.find(key); it != index.end()) return curves[it->second];
    if (curves.size() >= 256) clear();
    // Starts spread along where equivalent spheres touch the two bodies (every loop of the curve
    // lies near that circle).
    thread_local std::vector<V> starts;
    starts.clear();
    const auto mid = [](const Shape<3>& s) { return 0.5 * (s.bounding_radius() + s.inscribed_radius()); };
    Body<3> eq = b1;
    if (!eq.is_wall()) eq.radius = mid(*eq.shaped->shape);
    two_contact_positions(b0.center, mid(*b0.shaped->shape), eq, mid(shape), kLoopSamples, starts);
    for (V& x : starts) x -= b0.center;
    if (starts.empty()) starts.push_back(V::Zero());  // from s0's centre: Newton finds the curve if any
    index.emplace(key, curves.size());
    walk_curve(P, Q, starts, scale, curves.emplace_back());
    return curves.back();
  }
};

}  // namespace

int PolytopeWrapperSolver::solve(std::span<const Body<3>> fixed, const Mobile<3>& mobile, std::span<Placement<3>> out) const {
  if (fixed.size() != 3 || out.empty() || fixed[0].is_wall() || !fixed[0].shaped) return 0;
  const auto* mobile_shape = dynamic_cast<const Poly*>(mobile.shape.get());
  if (!mobile_shape) return 0;
  thread_local ObstacleCache cache;
  thread_local CurveCache curves;
  thread_local std::array<Obstacle, 3> walls;
  cache.use(*mobile_shape, mobile.rotation);
  if (curves.mobile != mobile_shape || curves.rotation != mobile.rotation) {
    curves.mobile = mobile_shape, curves.rotation = mobile.rotation;
    curves.clear();
  }
  std::array<const Obstacle*, 3> O{};
  std::array<double, 3> tol{};
  for (int i = 0; i < 3; ++i) {
    const Body<3>& b = fixed[static_cast<std::size_t>(i)];
    if (b.is_wall()) {
      Obstacle& w = walls[static_cast<std::size_t>(i)];
      if (b.wall->kind == WallKind::Plane) plane_obstacle(*b.wall, cache.turned, w);
      else if (b.wall->kind == WallKind::Vertex) corner_obstacle(*b.wall, cache.turned, w);
      else return 0;  // sphere and cylinder walls are not registered for polyhedra
      O[static_cast<std::size_t>(i)] = &w;
      tol[static_cast<std::size_t>(i)] = kContactTol * mobile.radius;
    } else {
      const auto* shape = b.shaped ? dynamic_cast<const Poly*>(b.shaped->shape.get()) : nullptr;
      if (!shape) return 0;
      O[static_cast<std::size_t>(i)] = &cache.of(*b.shaped, *shape);
      tol[static_cast<std::size_t>(i)] = kContactTol * std::min(b.radius, mobile.radius);
    }
  }
  // Everything in the frame of the first particle's reference point.
  const V origin = fixed[0].center;
  thread_local std::array<Obstacle, 3> local;
  for (int i = 0; i < 3; ++i) {
    local[static_cast<std::size_t>(i)] = *O[static_cast<std::size_t>(i)];
    local[static_cast<std::size_t>(i)].c -= origin;
  }
  const Obstacle& R = local[2];
  const double scale = fixed[0].radius + mobile.radius;
  const std::vector<Segment>& curve = curves.of(fixed[0], fixed[1], local[0], local[1], *mobile_shape, scale);

  std::vector<V> found;
  const auto keep = [&](const V& x) {
    if (found.size() >= out.size()) return;
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(local[static_cast<std::size_t>(i)].value(x)) <= tol[static_cast<std::size_t>(i)])) return;
    for (const V& y : found)
      if ((x - y).squaredNorm() <= 1e-18 * scale * scale) return;
    found.push_back(x);
  };
  // The points of each segment x + s t, s in [0, len], on R's boundary (where it enters or leaves R).
  const double slack = 1e-12 * scale;  // a crossing at a corner of the curve may round to just outside both segments
  // R's boundary lies within its body's circumscribed radius plus the mobile's of R.c (a wall has
  // no such bound): segments farther off are skipped.
  const double reach = fixed[2].is_wall() ? kInf : fixed[2].radius + mobile.radius;
  for (const Segment& g : curve) {
    if (reach < kInf) {
      const double along = std::clamp((R.c - g.x).dot(g.t), 0.0, g.len);
      if ((g.x + along * g.t - R.c).squaredNorm() > reach * reach * (1 + 1e-9)) continue;
    }
    double lo = -kInf, hi = kInf;
    bool beside = false;
    for (std::size_t k = 0; k < R.n.size() && !beside; ++k) {
      const double rate = R.n[k].dot(g.t), val = R.n[k].dot(g.x - R.c) - R.h[k];
      if (std::abs(rate) <= 1e-15) {
        beside = val > 0;  // the segment's whole line is outside this plane
        continue;
      }
      const double at = -val / rate;
      if (rate > 0) hi = std::min(hi, at);
      else lo = std::max(lo, at);
    }
    if (beside || lo > hi) continue;
    for (const double at : {lo, hi})
      if (at >= -slack && at <= g.len + slack) keep(g.x + std::clamp(at, 0.0, g.len) * g.t);
    if (found.size() >= out.size()) break;
  }
  for (std::size_t k = 0; k < found.size(); ++k) out[k].position = origin + found[k];
  return static_cast<int>(found.size());
}

}  // namespace fp
