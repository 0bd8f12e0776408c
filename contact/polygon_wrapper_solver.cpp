#include "contact/polygon_wrapper_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/geometry/convex_polygon.hpp"

namespace fp {
namespace {

using V = Vec2;

using convex_polygon::append_hull;
using convex_polygon::append_minkowski_difference;
using convex_polygon::cross;
using convex_polygon::hull;
using convex_polygon::outward;
using convex_polygon::signed_distance;
using convex_polygon::strictly_convex_ccw;

/// A piece of a wrapper's boundary: a segment [a, b], a line through a along unit b, or an arc of
/// centre c and radius r from direction n0 to n1 counter-clockwise (a full circle if `full`).
struct Prim {
  enum Kind { Seg, Line, Arc } kind = Seg;
  V a = V::Zero(), b = V::Zero(), c = V::Zero(), n0 = V::Zero(), n1 = V::Zero();
  double r = 0;
  bool full = false;
  V lo = V::Constant(-std::numeric_limits<double>::infinity());  ///< bounding box (a line: the plane)
  V hi = V::Constant(std::numeric_limits<double>::infinity());
  double extent = std::numeric_limits<double>::infinity();      ///< the box's width plus height

  void box() {
    if (kind == Seg) lo = a.cwiseMin(b), hi = a.cwiseMax(b);
    if (kind == Arc) lo = c.array() - r, hi = c.array() + r;
    extent = (hi - lo).sum();
  }
};

/// Can P and Q meet (boxes within `margin`)? Most pairs of a wrapper's boundary pieces cannot: a
/// convex boundary crosses another at two points. The margin covers what intersect() accepts
/// beyond the pieces: the segments' parameter slack (kEps of their length) and `flush`.
bool boxes_meet(const Prim& P, const Prim& Q, double margin) {
  return (P.lo.array() <= Q.hi.array() + margin).all() && (Q.lo.array() <= P.hi.array() + margin).all();
}

/// A wrapper (locus of the mobile's reference point), in the frame centred on s0. Its core points
/// and edge normals live in its set's shared arrays (Loci).
struct Locus {
  enum Kind { Rounded, Line, Circle } kind = Rounded;
  std::uint32_t first = 0, count = 0;  ///< Rounded: Minkowski core, counter-clockwise: Loci::points[first, first + count)
  double rho = 0;         ///< Rounded: thickening; Circle: radius
  V n = V::Zero();        ///< Line: unit normal, gap = n.x - h
  double h = 0;
  V c = V::Zero();        ///< Circle: centre, gap = rho - |x - c| (the mobile inside)
  V centre = V::Zero();   ///< bounding circle (Rounded, Circle)
  double reach = 0;
  double size = 1;        ///< tolerance size
  std::uint32_t prim_first = 0, prim_count = 0;  ///< its boundary pieces: Loci::prims[prim_first, prim_first + prim_count)
  Prim box;               ///< the box of all its pieces (infinite with a line)
};

/// The wrappers of one body, stored flat: rebuilt for every neighbour without allocating.
struct Loci {
  std::vector<Locus> list;
  std::vector<V> points;   ///< the rounded wrappers' core points
  std::vector<V> normals;  ///< parallel to points, for cores of 2 points or more: outward unit normal of edge i -> i + 1 (close_rounded())
  std::vector<Prim> prims; ///< the wrappers' boundary pieces (loci_of())

  void clear() { list.clear(), points.clear(), normals.clear(), prims.clear(); }
  std::span<const Prim> prims_of(const Locus& L) const { return {prims.data() + L.prim_first, L.prim_count}; }
  std::span<const V> q(const Locus& L) const { return {points.data() + L.first, L.count}; }
  std::span<const V> normals_of(const Locus& L) const { return {normals.data() + L.first, L.count}; }
  /// Starts a rounded wrapper whose core points the caller appends to `points`.
  Locus& open_rounded() {
    Locus& L = list.emplace_back();
    L.first = static_cast<std::uint32_t>(points.size());
    return L;
  }
  double gap(const Locus& L, const V& x) const {
    switch (L.kind) {
      case Locus::Rounded: return signed_distance(q(L), normals_of(L), x) - L.rho;
      case Locus::Line: return L.n.dot(x) - L.h;
      case Locus::Circle: return L.rho - (x - L.c).norm();
    }
    return 0;
  }
  double least_gap(const V& x) const {
    double g = std::numeric_limits<double>::infinity();
    for (const Locus& L : list) g = std::min(g, gap(L, x));
    return g;
  }
};

void add_prims(const Loci& set, const Locus& L, std::vector<Prim>& out) {
  if (L.kind == Locus::Line) {
    Prim p;
    p.kind = Prim::Line, p.a = L.h * L.n, p.b = V(-L.n.y(), L.n.x());
    out.push_back(p);  // unbounded
    return;
  }
  const std::span<const V> q = set.q(L);
  if (L.kind == Locus::Circle || q.size() == 1) {
    if (!(L.rho > 0)) return;  // a point: no curve
    Prim p;
    p.kind = Prim::Arc, p.c = L.kind == Locus::Circle ? L.c : q[0], p.r = L.rho, p.full = true;
    p.box();
    out.push_back(p);
    return;
  }
  const std::size_t m = q.size();
  const std::span<const V> normal = set.normals_of(L);
  for (std::size_t i = 0; i < m; ++i) {
    Prim s;
    s.kind = Prim::Seg, s.a = q[i] + L.rho * normal[i], s.b = q[(i + 1) % m] + L.rho * normal[i];
    s.box();
    out.push_back(s);
    if (L.rho > 0) {
      Prim a;
      a.kind = Prim::Arc, a.c = q[i], a.r = L.rho, a.n0 = normal[(i + m - 1) % m], a.n1 = normal[i];
      a.box();
      out.push_back(a);
    }
  }
}

constexpr double kEps = 1e-12;
/// Segments whose directions make a sine below this may lie within the tolerance of each other
/// over a stretch (checked).
constexpr double kFlushSine = 1e-6;

bool in_arc(const Prim& a, const V& p) {
  if (a.full) return true;
  const V u = p - a.c;
  const double slack = kEps * u.norm();
  return cross(a.n0, u) >= -slack && cross(u, a.n1) >= -slack;
}

/// Points of a segment or line (p + t d, t in [0, 1] for a segment) on the circle (c, r).
void line_circle(const V& p, const V& d, bool segment, const Prim& arc, std::vector<V>& out) {
  const V f = p - arc.c;
  const double A = d.squaredNorm(), B = f.dot(d), C = (f.norm() - arc.r) * (f.norm() + arc.r);
  const double disc = B * B - A * C;
  if (disc < 0) return;
  const double s = std::sqrt(disc);
  for (const double t : {(-B - s) / A, (-B + s) / A}) {
    if (segment && (t < -kEps || t > 1 + kEps)) continue;
    const V x = p + t * d;
    if (in_arc(arc, x)) out.push_back(x);
    if (s == 0) break;
  }
}

/// Intersections of two primitives; two segments (or a segment and a line) closer than `flush`
/// to each other along a common stretch give its two ends.
void intersect(const Prim& P, const Prim& Q, double flush, std::vector<V>& out) {
  if (P.kind == Prim::Arc && Q.kind == Prim::Arc) {
    const V d = Q.c - P.c;
    const double dist = d.norm();
    if (!(dist > 0) || dist > P.r + Q.r || dist < std::abs(P.r - Q.r)) return;
    const double x = 0.5 * (dist + (P.r - Q.r) * (P.r + Q.r) / dist);
    const double y2 = (P.r - x) * (P.r + x);
    const double y = y2 > 0 ? std::sqrt(y2) : 0.0;
    const V u = d / dist, v(-u.y(), u.x());
    for (const double sgn : {1.0, -1.0}) {
      const V p = P.c + x * u + sgn * y * v;
      if (in_arc(P, p) && in_arc(Q, p)) out.push_back(p);
      if (y == 0) break;
    }
    return;
  }
  if (P.kind == Prim::Arc || Q.kind == Prim::Arc) {
    const Prim& arc = P.kind == Prim::Arc ? P : Q;
    const Prim& lin = P.kind == Prim::Arc ? Q : P;
    const bool seg = lin.kind == Prim::Seg;
    line_circle(lin.a, seg ? V(lin.b - lin.a) : lin.b, seg, arc, out);
    return;
  }
  // Two segments or lines: a + t r = c + u s.
  const V r = P.kind == Prim::Seg ? V(P.b - P.a) : P.b;
  const V s = Q.kind == Prim::Seg ? V(Q.b - Q.a) : Q.b;
  const V w = Q.a - P.a;
  const double rn = r.norm(), sn = s.norm();
  const double sine = std::abs(cross(r, s)) / (rn * sn);
  const bool p_seg = P.kind == Prim::Seg, q_seg = Q.kind == Prim::Seg;
  if (sine > kEps) {
    const double denom = cross(r, s);
    const double t = cross(w, s) / denom, u = cross(w, r) / denom;
    if ((!p_seg || (t >= -kEps && t <= 1 + kEps)) && (!q_seg || (u >= -kEps && u <= 1 + kEps))) out.push_back(P.a + t * r);
  }
  // Nearly parallel and within `flush` of each other along a common stretch (a flat side sliding
  // along a flat side or a wall: a continuum of positions, within the tolerance): the ends of that
  // stretch, which the exact intersection (far away, or none) does not give.
  if (sine > kFlushSine || (!p_seg && !q_seg)) return;
  const Prim& seg = p_seg ? P : Q;
  const Prim& other = p_seg ? Q : P;
  const V d = seg.b - seg.a;
  double lo = 0, hi = 1;
  if (other.kind == Prim::Seg) {
    const double tc = (other.a - seg.a).dot(d) / d.squaredNorm(), td = (other.b - seg.a).dot(d) / d.squaredNorm();
    lo = std::max(0.0, std::min(tc, td)), hi = std::min(1.0, std::max(tc, td));
    if (lo > hi) return;
  }
  const V od = other.kind == Prim::Seg ? V(other.b - other.a) : other.b;
  const V normal = V(-od.y(), od.x()).normalized();
  for (const double t : {lo, hi})
    if (!(std::abs(normal.dot(seg.a + t * d - other.a)) <= flush)) return;
  out.push_back(seg.a + lo * d);
  out.push_back(seg.a + hi * d);
}

/// The cores of a fixed particle (frame-local) or the mobile (offsets), with their radii, into
/// `cores` (its storage reused).
void cores_of(const Shape<2>* shape, const Mat<2>& rotation, const V& position, double radius, std::vector<RoundedCore<2>>& cores) {
  if (shape == nullptr) {
    cores.resize(1);
    cores[0].points.assign(1, position), cores[0].radius = radius;
    return;
  }
  shape->rounded_cores(cores);
  for (auto& c : cores)
    for (V& p : c.points) p = position + rotation * p;
}

/// Closes the rounded wrapper last opened (its core points appended to set.points): its point
/// count, edge normals (computed once: every gap evaluation needs them) and bounding circle.
void close_rounded(Loci& set, Locus& L) {
  L.count = static_cast<std::uint32_t>(set.points.size() - L.first);
  const std::span<const V> q = set.q(L);
  const std::size_t m = q.size();
  for (std::size_t i = 0; i < m; ++i)  // a segment's two sides too (add_prims); none for a point
    set.normals.push_back(m >= 2 ? outward(q[(i + 1) % m] - q[i]) : V::Zero());
  V c = V::Zero();
  for (const V& p : q) c += p;
  c /= static_cast<double>(m);
  double r = 0;
  for (const V& p : q) r = std::max(r, (p - c).norm());
  L.centre = c, L.reach = r + L.rho;
}

/// The mobile's cores (offsets at its orientation) and their hulls, built once per mobile.
struct MobileCores {
  std::vector<RoundedCore<2>> cores;
  std::vector<std::vector<V>> hulls;
};

/// The wrappers of one fixed body for the mobile cores (frame centred on `o`), without their pieces.
void build_loci(const Body<2>& b, const V& o, const MobileCores& mobile, double mobile_radius, Loci& out) {
  out.clear();
  thread_local std::vector<V> scratch, core_hull, sum;
  if (b.is_wall()) {
    const Wall<2>& w = *b.wall;
    for (const RoundedCore<2>& M : mobile.cores) {
      if (w.kind == WallKind::Plane) {
        Locus& L = out.list.emplace_back();
        L.kind = Locus::Line, L.n = w.normal, L.size = mobile_radius;
        double lowest = std::numeric_limits<double>::infinity();
        for (const V& p : M.points) lowest = std::min(lowest, w.normal.dot(p));
        L.h = w.normal.dot(w.point - o) + M.radius - lowest;
      } else if (w.kind == WallKind::Sphere) {
        for (const V& p : M.points) {
          Locus L;
          L.kind = Locus::Circle, L.c = w.point - o - p, L.rho = w.radius - M.radius, L.size = mobile_radius;
          L.centre = L.c, L.reach = L.rho;
          if (L.rho > 0) out.list.push_back(L);
        }
      } else if (w.kind == WallKind::Vertex) {
        scratch.clear();
        for (const V& p : M.points) scratch.push_back(w.point - o - p);
        Locus& L = out.open_rounded();
        L.rho = M.radius, L.size = mobile_radius;
        append_hull(scratch, out.points);
        close_rounded(out, L);
      }
    }
    return;
  }
  const Particle<2>* q = b.shaped;
  thread_local std::vector<RoundedCore<2>> fixed;
  cores_of(q ? q->shape.get() : nullptr, q ? q->pose.rotation : Mat<2>::Identity(), b.center - o, b.radius, fixed);
  const double size = std::min(b.radius, mobile_radius);
  for (const RoundedCore<2>& F : fixed) {
    core_hull.clear();
    if (strictly_convex_ccw(F.points)) {
      core_hull.assign(F.points.begin(), F.points.end());
    } else {
      scratch.assign(F.points.begin(), F.points.end());
      append_hull(scratch, core_hull);
    }
    for (std::size_t k = 0; k < mobile.cores.size(); ++k) {
      Locus& L = out.open_rounded();
      L.rho = F.radius + mobile.cores[k].radius, L.size = size;
      append_minkowski_difference(core_hull, mobile.hulls[k], sum, out.points);
      close_rounded(out, L);
    }
  }
}

/// The wrappers of one fixed body for the mobile cores (frame centred on `o`), with their pieces.
void loci_of(const Body<2>& b, const V& o, const MobileCores& mobile, double mobile_radius, Loci& out) {
  build_loci(b, o, mobile, mobile_radius, out);
  for (Locus& L : out.list) {
    L.prim_first = static_cast<std::uint32_t>(out.prims.size());
    add_prims(out, L, out.prims);
    L.prim_count = static_cast<std::uint32_t>(out.prims.size() - L.prim_first);
    L.box.lo = V::Constant(std::numeric_limits<double>::infinity()), L.box.hi = -L.box.lo;
    for (const Prim& Q : out.prims_of(L)) L.box.lo = L.box.lo.cwiseMin(Q.lo), L.box.hi = L.box.hi.cwiseMax(Q.hi);
    L.box.extent = (L.box.hi - L.box.lo).sum();
  }
}

bool may_meet(const Locus& a, const Locus& b) {
  if (a.kind == Locus::Line || b.kind == Locus::Line) {
    const Locus& l = a.kind == Locus::Line ? a : b;
    const Locus& o = a.kind == Locus::Line ? b : a;
    return o.kind == Locus::Line || std::abs(l.n.dot(o.centre) - l.h) <= o.reach;
  }
  const double r = a.reach + b.reach;
  return (a.centre - b.centre).squaredNorm() <= r * r * (1 + 1e-9);
}

}  // namespace

int PolygonWrapperSolver::solve(std::span<const Body<2>> fixed, const Mobile<2>& mobile, std::span<Placement<2>> out) const {
  if (fixed.size() != 2 || out.empty()) return 0;
  thread_local Loci loci0, loci1;
  thread_local std::vector<V> points, found;
  // Frame on the first particle (its reference point): offsets of 1e6 keep their digits.
  const Body<2>* frame = fixed[0].is_wall() ? &fixed[1] : &fixed[0];
  const V o = frame->is_wall() ? frame->wall->point : frame->center;
  // The front solves one s0 (the frame's body) against each neighbour with one mobile: the mobile's
  // cores and s0's wrappers are built once for them. A particle is known by its address, centre
  // and radius together (the particles' vector may have moved: a stale address must not match).
  thread_local struct {
    const Shape<2>* shape = nullptr;
    Mat<2> rotation = Mat<2>::Identity();
    double radius = -1;
    MobileCores mobile;
    const Particle<2>* first = nullptr;  ///< whose wrappers loci0 holds (none: nullptr)
    V first_center = V::Zero();
    double first_radius = -1;
  } cache;
  if (cache.shape != mobile.shape.get() || cache.rotation != mobile.rotation || cache.radius != mobile.radius || !cache.shape) {
    cache.shape = mobile.shape.get(), cache.rotation = mobile.rotation, cache.radius = mobile.radius;
    cores_of(mobile.shape.get(), mobile.rotation, V::Zero(), mobile.radius, cache.mobile.cores);
    cache.mobile.hulls.clear();
    for (const RoundedCore<2>& M : cache.mobile.cores) cache.mobile.hulls.push_back(hull(M.points));
    cache.first = nullptr;
  }
  const MobileCores& mob = cache.mobile;
  if (mob.cores.empty()) return 0;
  const Body<2>& b0 = fixed[0];
  if (b0.is_wall() || !b0.shaped || cache.first != b0.shaped || cache.first_center != b0.center || cache.first_radius != b0.radius) {
    loci_of(b0, o, mob, mobile.radius, loci0);
    cache.first = b0.is_wall() ? nullptr : b0.shaped;
    cache.first_center = b0.center, cache.first_radius = b0.radius;
  }
  loci_of(fixed[1], o, mob, mobile.radius, loci1);
  if (loci0.list.empty() || loci1.list.empty()) return 0;  // e.g. a disk wall too small for the mobile

  found.clear();  // distinct: positions closer than 1e-9 of the sizes are one
  const double scale = mobile.radius + (fixed[0].is_wall() ? 0 : fixed[0].radius);
  for (const Locus& A : loci0.list) {
    const std::span<const Prim> prims0 = loci0.prims_of(A);
    for (const Locus& B : loci1.list) {
      if (!may_meet(A, B)) continue;
      const std::span<const Prim> prims1 = loci1.prims_of(B);
      points.clear();
      const double flush = 0.5 * kContactTol * std::min(A.size, B.size);
      // The box of all B's pieces: a piece of A beyond it (by more than any pair's margin) meets
      // none of them, which spares most of the piece pairs their box tests.
      const Prim& all_b = B.box;
      for (const Prim& P : prims0) {
        const double reach = P.extent + all_b.extent;
        if (std::isfinite(reach) && !boxes_meet(P, all_b, flush + 1e-9 * reach)) continue;
        for (const Prim& Q : prims1) {
          const double extent = P.extent + Q.extent;  // inf for a line
          if (std::isfinite(extent) && !boxes_meet(P, Q, flush + 1e-9 * extent)) continue;
          intersect(P, Q, flush, points);
        }
      }
      for (const V& x : points) {
        bool duplicate = false;
        for (const V& y : found) duplicate = duplicate || (x - y).squaredNorm() <= 1e-18 * scale * scale;
        if (duplicate) continue;
        const double g0 = loci0.least_gap(x), g1 = loci1.least_gap(x);
        const double tol0 = kContactTol * loci0.list.front().size, tol1 = kContactTol * loci1.list.front().size;
        if (std::abs(g0) <= tol0 && std::abs(g1) <= tol1) found.push_back(x);
        if (found.size() == out.size()) break;
      }
      if (found.size() == out.size()) break;
    }
    if (found.size() == out.size()) break;
  }
  for (std::size_t k = 0; k < found.size(); ++k) out[k].position = o + found[k];
  return static_cast<int>(found.size());
}

}  // namespace fp
