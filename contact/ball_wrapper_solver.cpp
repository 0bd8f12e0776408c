#include "contact/ball_wrapper_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {
namespace {

/// One locus of the mobile particle's reference point: fixed member (or wall) k against mobile
/// member j, folded to the common mobile radius r0 (a ball of radius r0 at x touches it exactly
/// where member j touches member k). Spheres: |x - center| = radius + r0. Walls: `wall`.
template <int D>
struct Piece {
  bool is_wall = false;
  Wall<D> wall;
  Vec<D> center = Vec<D>::Zero();
  double radius = 0.0;  ///< folded radius of the fixed ball (spheres only)
  int member = 0;       ///< which mobile member
  double size = 0.0;    ///< the smaller radius of the two balls (the mobile member's for a wall)

  Body<D> as_body() const { return is_wall ? Body<D>::of_wall(wall) : Body<D>::sphere(center, radius); }
  /// Signed gap of a ball of radius r0 at x against this locus (0 on it, < 0 inside).
  double gap(const Vec<D>& x, double r0) const { return is_wall ? wall.gap(x, r0) : (x - center).norm() - radius - r0; }
};

/// The balls of a shape at a pose (world), or of a plain sphere body.
template <int D>
void balls_of(const Shape<D>* shape, const Mat<D>& rotation, const Vec<D>& position, double radius, std::vector<Ball<D>>& out) {
  out.clear();
  if (shape != nullptr && std::strcmp(shape->kind(), ClusterShape<D>::kKind) == 0) {
    for (const Ball<D>& b : static_cast<const ClusterShape<D>*>(shape)->members())
      out.push_back({position + rotation * b.center, b.radius});
    return;
  }
  out.push_back({position, shape != nullptr ? shape->bounding_radius() : radius});
}

/// The wall's locus for a ball of radius rj at x + m, as a wall for a ball of radius r0 at x.
template <int D>
bool fold_wall(const Wall<D>& w, const Vec<D>& m, double rj, double r0, Piece<D>& p) {
  const double grow = rj - r0;  // > 0: r0 is half the smallest mobile member
  p.is_wall = true;
  p.wall = w;
  p.wall.point = w.point - m;
  switch (w.kind) {
    case WallKind::Plane:
      p.wall.point += grow * w.normal;
      return true;
    case WallKind::Sphere:
    case WallKind::Cylinder:
      p.wall.radius = w.radius - grow;
      return p.wall.radius > r0;  // the member does not fit inside at all otherwise
    case WallKind::Vertex:  // a point: a ball of radius grow around it
      p.is_wall = false;
      p.center = p.wall.point;
      p.radius = grow;
      return true;
  }
  return false;
}

/// Can a point lie on both loci? (Spheres: their distance between |ra - rb| and ra + rb; a sphere
/// and a plane: the plane within reach of the sphere. Other wall pairs: assumed yes.)
template <int D>
bool may_meet(const Piece<D>& a, const Piece<D>& b, double r0) {
  constexpr double kSlack = 1e-9;
  if (!a.is_wall && !b.is_wall) {
    const double ra = a.radius + r0, rb = b.radius + r0;
    const double d2 = (a.center - b.center).squaredNorm();
    const double outer = (ra + rb) * (1 + kSlack), inner = std::abs(ra - rb) - kSlack * (ra + rb);
    return d2 <= outer * outer && (inner <= 0 || d2 >= inner * inner);
  }
  const Piece<D>& s = a.is_wall ? b : a;
  const Piece<D>& w = a.is_wall ? a : b;
  if (s.is_wall || w.wall.kind != WallKind::Plane) return true;
  const double rs = s.radius + r0;
  return std::abs(w.wall.gap(s.center, r0)) <= rs * (1 + kSlack);
}

/// Appends the loci of body `b` folded for the mobile members (r0: the folded mobile radius).
template <int D>
void append_loci(const Body<D>& b, const std::vector<Ball<D>>& mobile, double r0, std::vector<Ball<D>>& scratch,
                 std::vector<Piece<D>>& out) {
  for (int j = 0; j < static_cast<int>(mobile.size()); ++j) {
    const Ball<D>& mj = mobile[static_cast<std::size_t>(j)];
    if (b.is_wall()) {
      Piece<D> p;
      p.member = j, p.size = mj.radius;
      if (fold_wall<D>(*b.wall, mj.center, mj.radius, r0, p)) out.push_back(p);
      continue;
    }
    const Particle<D>* q = b.shaped;
    balls_of<D>(q ? q->shape.get() : nullptr, q ? q->pose.rotation : Mat<D>::Identity(), b.center, b.radius, scratch);
    for (const Ball<D>& f : scratch) {
      Piece<D> p;
      p.member = j, p.size = std::min(f.radius, mj.radius);
      p.center = f.center - mj.center;
      p.radius = f.radius + mj.radius - r0;
      out.push_back(p);
    }
  }
}

/// Appends to `live` the loci of pieces[first, last) that can carry the body's boundary: those
/// not strictly inside another of its spheres.
template <int D>
void append_live(const std::vector<Piece<D>>& pieces, int first, int last, int tag_offset, std::vector<int>& live) {
  for (int a = first; a < last; ++a) {
    const Piece<D>& pa = pieces[static_cast<std::size_t>(a)];
    bool covered = false;
    if (!pa.is_wall)
      for (int c = first; c < last && !covered; ++c) {
        const Piece<D>& pc = pieces[static_cast<std::size_t>(c)];
        if (c == a || pc.is_wall) continue;
        const double room = pc.radius - pa.radius;  // |d| + ra < rc
        covered = room > 0 && (pa.center - pc.center).squaredNorm() < room * room;
      }
    if (!covered) live.push_back(a + tag_offset);
  }
}

/// 3D: one pair circle, piece a of a body against piece b of another, seen in a's frame (origin
/// a's centre, unit = a's locus radius, so a's locus is |y| = 1): the circle |y| = 1, n.y = h.
/// Only the part of it outside every other piece of the two bodies can carry a position; that
/// part is kept as exposed angular intervals, so a third body's pieces are tried only there.
struct Arc {
  int a = 0, b = 0;     ///< the two pieces (names in LociCache::pieces)
  Vec3 origin;          ///< a's centre (world)
  double scale = 1.0;   ///< a's locus radius
  Vec3 y1, u, v;        ///< the circle's centre and an orthonormal basis of its plane (frame)
  double rho = 0.0;     ///< its radius (frame)
  bool careful = false; ///< nearly a point (spheres almost tangent): every choice by the sphere solver
  enum class Exposure { None, Intervals } exposure = Exposure::None;
  int first = 0, count = 0;  ///< exposed intervals [lo, hi] of the turn (turn_of), in LociCache::intervals
};

/// A point (c, s) of the unit circle (c along u, s along v) as a "diamond angle" in [0, 4): a
/// monotone stand-in for its angle, without trigonometry.
inline double turn_of(double c, double s) {
  if (s >= 0) return c >= 0 ? s / (c + s) : 1 + -c / (-c + s);
  return c < 0 ? 2 + -s / (-c - s) : 3 + c / (c - s);
}
constexpr double kFullTurn = 4.0;

/// The two points (c, s) of the unit circle where A c + B s = k M (M = |(A, B)|, |k| < 1): the
/// direction of (A, B) turned by +-acos(k). First the one turned counter-clockwise.
inline std::array<std::array<double, 2>, 2> points_at(double A, double B, double M, double k) {
  const double ca = k, sa = std::sqrt((1 - k) * (1 + k));
  const double ex = A / M, ey = B / M;  // e and e_perp = (-ey, ex)
  return {{{ca * ex - sa * ey, ca * ey + sa * ex}, {ca * ex + sa * ey, ca * ey - sa * ex}}};
}

/// The circle of pieces a and b (both spheres) in a's frame. False when they do not meet in a
/// circle (apart, or concentric: the sphere solver finds nothing there either).
inline bool circle_of(const Piece<3>& pa, const Piece<3>& pb, double r0, Arc& arc) {
  arc.origin = pa.center;
  arc.scale = pa.radius + r0;
  const double inv = 1.0 / arc.scale;
  const Vec3 n = (pb.center - pa.center) * inv;
  const double q = n.norm();
  const double rb = (pb.radius + r0) * inv;
  if (!(q > 1e-9)) return false;
  const double h = 0.5 * ((q - rb) * (q + rb) + 1.0) / q;  // distance of the circle's plane from 0
  const double rho2 = (1.0 - h) * (1.0 + h);
  if (rho2 < -1e-9) return false;
  const Vec3 k = n / q;
  arc.y1 = h * k;
  arc.u = k.unitOrthogonal();
  arc.v = k.cross(arc.u);
  arc.rho = std::sqrt(std::max(rho2, 0.0));
  arc.careful = rho2 < 1e-8;
  return true;
}

/// A piece that covers circles, and by how much it is shrunk first (an absolute length).
struct Cover {
  const Piece<3>* piece;
  double shrink;
};

/// The pieces of one obstacle particle, shrunk alike, all within `reach` of `center` (its
/// circumscribed radius plus the mobile's): a circle farther than that from the centre meets none.
struct CoverGroup {
  Vec3 center;
  double reach;
  int first, count;  ///< in the pieces
  double shrink;
};

/// The exposed intervals of the circle, appended to `exposed`: what neither `others` (every
/// piece of its two bodies) nor `groups` (the obstacles near them, their pieces in `pieces`)
/// cover. Covered means strictly inside a piece shrunk first: by twice the overlap tolerance for
/// the two bodies' own pieces (a position the final check, overlap <= kOverlapTol, would keep is
/// never dropped), by the front's tolerance for an obstacle's (a position the front would keep is
/// never dropped).
inline void find_exposure(Arc& arc, const Vec3& a_center, double r0, std::vector<Cover>& others,
                          const std::vector<Piece<3>>& pieces, const std::vector<CoverGroup>& groups,
                          std::vector<std::array<double, 2>>& exposed) {
  arc.exposure = Arc::Exposure::None;
  const double inv = 1.0 / arc.scale, rho2 = arc.rho * arc.rho;
  // Covered intervals: |y(t) - p|^2 < re^2, i.e. A cos t + B sin t < C.
  thread_local std::vector<std::array<double, 2>> covered;
  covered.clear();
  // The interval(s) a cover hides, in [0, 4); true when it hides the whole circle.
  const auto hidden = [&](const Cover& cover, std::array<std::array<double, 2>, 2>& iv, int& n) {
    n = 0;
    const Piece<3>* e = cover.piece;
    const double re = (e->radius + r0 - cover.shrink) * inv;
    if (!(re > 0)) return false;
    const Vec3 w = arc.y1 - (e->center - a_center) * inv;
    const double wn = w.norm();
    const double C = (re - wn) * (re + wn) - rho2;
    if (C <= -2 * arc.rho * wn) return false;  // M <= 2 rho |w|: e misses the circle
    const double A = 2 * arc.rho * arc.u.dot(w), B = 2 * arc.rho * arc.v.dot(w);
    const double M = std::sqrt(A * A + B * B);
    if (C <= -M) return false;
    const double k = C / M;
    if (!(k < 1 - 1e-15)) return true;
    // A c + B s < C: the arc from the point turned +acos(k) from (A, B), counter-clockwise, to
    // the one turned -acos(k).
    const auto ends = points_at(A, B, M, k);
    const double start = turn_of(ends[0][0], ends[0][1]), end = turn_of(ends[1][0], ends[1][1]);
    if (start <= end) {
      iv[n++] = {start, end};
    } else {
      iv[n++] = {start, kFullTurn};
      iv[n++] = {0.0, end};
    }
    return false;
  };
  std::array<std::array<double, 2>, 2> iv;
  int n = 0;
  for (std::size_t i = 0; i < others.size(); ++i) {
    if (hidden(others[i], iv, n)) {  // the whole circle is inside, which is tried first for the next circle
      std::swap(others[0], others[i]);
      return;
    }
    for (int q = 0; q < n; ++q) covered.push_back(iv[static_cast<std::size_t>(q)]);
  }
  // What the two bodies leave exposed: the complement of what their pieces hide.
  std::sort(covered.begin(), covered.end());
  thread_local std::vector<std::array<double, 2>> open, next;
  open.clear();
  double at = 0.0;
  for (const auto& c : covered) {
    if (c[0] > at) open.push_back({at, c[0]});
    at = std::max(at, c[1]);
  }
  if (at < kFullTurn) open.push_back({at, kFullTurn});
  if (!open.empty() && !groups.empty()) {
    // Then what the obstacles leave of it; one farther from the circle
    // (in the world) than its reach hides none of it.
    const Vec3 centre = a_center + arc.scale * arc.y1, normal = arc.u.cross(arc.v);
    const double radius = arc.scale * arc.rho;
    for (const CoverGroup& g : groups) {
      const Vec3 d = g.center - centre;
      const double off = d.dot(normal), in = (d - off * normal).norm() - radius;
      if (off * off + in * in >= g.reach * g.reach) continue;
      for (int c = g.first; c < g.first + g.count && !open.empty(); ++c) {
        if (hidden(Cover{&pieces[static_cast<std::size_t>(c)], g.shrink}, iv, n)) return;
        for (int q = 0; q < n; ++q) {
          const auto [lo, hi] = iv[static_cast<std::size_t>(q)];
          next.clear();
          for (const auto& o : open) {
            if (o[1] <= lo || o[0] >= hi) { next.push_back(o); continue; }
            if (o[0] < lo) next.push_back({o[0], lo});
            if (o[1] > hi) next.push_back({hi, o[1]});
          }
          open.swap(next);
        }
      }
      if (open.empty()) return;
    }
  }
  // Widened a little: the final check decides at the edges.
  constexpr double kSlack = 1e-7;
  arc.first = static_cast<int>(exposed.size());
  for (const auto& o : open) exposed.push_back({o[0] - kSlack, o[1] + kSlack});
  arc.count = static_cast<int>(exposed.size()) - arc.first;
  if (arc.count > 0) arc.exposure = Arc::Exposure::Intervals;
}

/// The loci of the particles met so far, folded for one mobile (same shape, rotation, radius).
/// The front calls the solver for many pairs around one front particle with one mobile: each
/// particle's loci are built once for it. Walls are built at each call (a few loci; the front's
/// wall list is rebuilt at each pick, so a pointer does not identify a wall).
template <int D>
struct LociCache {
  struct Block {
    const Particle<D>* particle = nullptr;  ///< identity, with centre and radius: the particles'
    Vec<D> center = Vec<D>::Zero();         ///< vector may have moved, and a stale pointer must
    double radius = 0.0;                    ///< not match another particle
    int first = 0, count = 0;               ///< its loci in `pieces`
    int live_first = 0, live_count = 0;     ///< those that can carry its boundary, in `live`
  };
  const Shape<D>* shape = nullptr;
  Mat<D> rotation = Mat<D>::Identity();
  double radius = -1.0;
  std::vector<Ball<D>> mobile;  ///< mobile members: offset from the reference point, radius
  double r0 = 0.0;              ///< the common folded mobile radius: half the smallest member
  std::vector<Block> blocks;
  std::unordered_map<const Particle<D>*, int> block_index;  ///< particle blocks by address
  std::vector<Piece<D>> pieces;
  std::vector<int> live;
  std::vector<Ball<D>> scratch;
  // 3D: the exposed pair circles of two blocks, by (block, block): the front solves one front
  // particle against many pairs of neighbours, so each (front particle, neighbour) pair recurs.
  std::unordered_map<std::uint64_t, std::pair<int, int>> pair_arcs;  ///< [first, first + count) in arcs
  std::vector<Arc> arcs;
  std::vector<std::array<double, 2>> intervals;
  // 3D: the placement's other particles made of balls (ContactSolver::set_obstacles) and the
  // front's tolerance: the pair circles are cut down to what they leave exposed too.
  std::vector<const Particle<D>*> obstacles;
  std::vector<int> obstacle_block;  ///< per obstacle: its block, -1 until built for this mobile
  std::vector<double> obstacle_radius;  ///< per obstacle: its circumscribed radius
  double obstacle_tol = 0.0;

  const void* obstacles_owner = nullptr;  ///< the solver that set them (others see none)

  /// New obstacles: the circles cut by the old ones are forgotten (the loci stay).
  void set_obstacles(const void* owner, std::span<const Particle<D>* const> given, double tol) {
    obstacles_owner = owner;
    obstacles.clear();
    for (const Particle<D>* q : given)
      if (std::strcmp(q->shape->kind(), ClusterShape<D>::kKind) == 0 || std::strcmp(q->shape->kind(), SphereShape<D>::kKind) == 0)
        obstacles.push_back(q);
    obstacle_radius.clear();
    for (const Particle<D>* q : obstacles) obstacle_radius.push_back(q->bounding_radius());
    obstacle_block.assign(obstacles.size(), -1);
    obstacle_tol = tol;
    pair_arcs.clear(), arcs.clear(), intervals.clear();
  }

  /// Forgets everything unless `m` is the mobile the loci were folded for.
  void use(const Mobile<D>& m) {
    if (m.shape.get() == shape && m.radius == radius && m.rotation == rotation && blocks.size() < 1024) return;
    shape = m.shape.get(), rotation = m.rotation, radius = m.radius;
    balls_of<D>(shape, rotation, Vec<D>::Zero(), radius, mobile);
    double smallest = mobile[0].radius;
    for (const Ball<D>& b : mobile) smallest = std::min(smallest, b.radius);
    r0 = 0.5 * smallest;
    blocks.clear(), block_index.clear(), pieces.clear(), live.clear();
    pair_arcs.clear(), arcs.clear(), intervals.clear();
    obstacle_block.assign(obstacles.size(), -1);
  }

  /// The index of a particle body's block, built if new.
  int block(const Body<D>& b) {
    const auto same = [&](const Block& k) { return k.particle == b.shaped && k.center == b.center && k.radius == b.radius; };
    if (b.shaped) {  // a particle: by its address (checked against its centre and radius)
      if (const auto it = block_index.find(b.shaped); it != block_index.end() && same(blocks[static_cast<std::size_t>(it->second)]))
        return it->second;
    } else {
      for (std::size_t i = 0; i < blocks.size(); ++i)
        if (same(blocks[i])) return static_cast<int>(i);
    }
    if (b.shaped) block_index[b.shaped] = static_cast<int>(blocks.size());
    Block k;
    k.particle = b.shaped, k.center = b.center, k.radius = b.radius;
    k.first = static_cast<int>(pieces.size());
    append_loci<D>(b, mobile, r0, scratch, pieces);
    k.count = static_cast<int>(pieces.size()) - k.first;
    k.live_first = static_cast<int>(live.size());
    append_live<D>(pieces, k.first, k.first + k.count, 0, live);
    k.live_count = static_cast<int>(live.size()) - k.live_first;
    blocks.push_back(k);
    return static_cast<int>(blocks.size()) - 1;
  }

  /// 3D: the circles of every live pair (piece of block i, piece of block j) that meet and are
  /// exposed somewhere (most are not: in clusters of overlapping members the pieces overlap).
  std::pair<int, int> arcs_of(int i, int j, double overlap_tol) requires(D == 3) {
    const std::uint64_t key = (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
    if (auto it = pair_arcs.find(key); it != pair_arcs.end()) return it->second;
    // The obstacles a mobile touching both bodies can reach, as blocks (built first: building
    // one moves the pieces and blocks).
    thread_local std::vector<std::pair<int, double>> near;  // obstacle, shrink of its pieces
    near.clear();
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      const Particle<D>* q = obstacles[o];
      const Block& bi = blocks[static_cast<std::size_t>(i)];
      const Block& bj = blocks[static_cast<std::size_t>(j)];
      if (q == bi.particle || q == bj.particle) continue;
      const double rq = obstacle_radius[o];
      const double ri = bi.radius + 2 * radius + rq, rj = bj.radius + 2 * radius + rq;
      if ((q->pose.position - bi.center).squaredNorm() >= ri * ri || (q->pose.position - bj.center).squaredNorm() >= rj * rj)
        continue;
      if (obstacle_block[o] < 0) obstacle_block[o] = block(Body<D>::of_particle(*q));
      near.push_back({static_cast<int>(o), obstacle_tol * std::min(radius, rq)});
    }
    const Block& bi = blocks[static_cast<std::size_t>(i)];
    const Block& bj = blocks[static_cast<std::size_t>(j)];
    thread_local std::vector<Cover> others;
    others.clear();
    for (const Block* k : {&bi, &bj})
      for (int e = k->first; e < k->first + k->count; ++e) {
        const Piece<D>& p = pieces[static_cast<std::size_t>(e)];
        others.push_back({&p, 2 * overlap_tol * p.size});
      }
    thread_local std::vector<CoverGroup> groups;
    groups.clear();
    for (const auto& [o, shrink] : near) {
      const Particle<D>* q = obstacles[static_cast<std::size_t>(o)];
      const Block& k = blocks[static_cast<std::size_t>(obstacle_block[static_cast<std::size_t>(o)])];
      groups.push_back({q->pose.position, obstacle_radius[static_cast<std::size_t>(o)] + radius, k.first, k.count, shrink});
    }
    const int first = static_cast<int>(arcs.size());
    for (int x = bi.live_first; x < bi.live_first + bi.live_count; ++x)
      for (int y = bj.live_first; y < bj.live_first + bj.live_count; ++y) {
        const int a = live[static_cast<std::size_t>(x)], b = live[static_cast<std::size_t>(y)];
        const Piece<D>& pa = pieces[static_cast<std::size_t>(a)];
        const Piece<D>& pb = pieces[static_cast<std::size_t>(b)];
        if (!may_meet<D>(pa, pb, r0)) continue;
        Arc arc;
        arc.a = a, arc.b = b;
        if (!circle_of(pa, pb, r0, arc)) continue;
        if (!arc.careful) find_exposure(arc, pa.center, r0, others, pieces, groups, intervals);
        if (arc.careful || arc.exposure == Arc::Exposure::Intervals) arcs.push_back(arc);
      }
    return pair_arcs[key] = {first, static_cast<int>(arcs.size()) - first};
  }

  /// 3D: is the point at `turn` of arc k outside the other pieces of its two blocks?
  /// (Conservatively: an arc position the final check would keep is always exposed.)
  bool exposed(int k, double turn) const requires(D == 3) {
    const Arc& arc = arcs[static_cast<std::size_t>(k)];
    if (arc.exposure == Arc::Exposure::None) return false;
    for (int e = arc.first; e < arc.first + arc.count; ++e) {
      const auto& iv = intervals[static_cast<std::size_t>(e)];
      if ((turn >= iv[0] && turn <= iv[1]) || turn + kFullTurn <= iv[1] || turn - kFullTurn >= iv[0]) return true;
    }
    return false;
  }
};

template <int D>
LociCache<D>& loci_cache() {
  thread_local LociCache<D> cache;
  return cache;
}

}  // namespace

template <int D>
void BallWrapperSolver<D>::set_obstacles(std::span<const Particle<D>* const> obstacles, double tol) const {
  if constexpr (D == 3) loci_cache<D>().set_obstacles(this, obstacles, tol);
}

template <int D>
BallWrapperSolver<D>::~BallWrapperSolver() {
  // The cache outlives the solver: its obstacles (the packing's particles) must not.
  LociCache<D>& cache = loci_cache<D>();
  if (cache.obstacles_owner == this) cache.set_obstacles(nullptr, {}, 0.0);
}

template <int D>
int BallWrapperSolver<D>::solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const {
  if (fixed.size() != static_cast<std::size_t>(D) || out.empty()) return 0;
  LociCache<D>& cache = loci_cache<D>();
  if (cache.obstacles_owner != this && !cache.obstacles.empty()) cache.set_obstacles(nullptr, {}, 0.0);
  thread_local std::vector<Piece<D>> walls;         // this call's wall loci
  thread_local std::array<std::vector<int>, D> live;  // per body: its live loci (walls: ~index - 1)
  thread_local std::vector<Vec<D>> found;
  cache.use(mobile);
  const double r0 = cache.r0;
  if (!(r0 > 0)) return 0;
  if constexpr (D == 3) {
    // Two particle bodies first whose pair circles are all covered (by each other or by V, most
    // pairs of a scan): no third body can add a position, and its loci need not be built.
    if (!fixed[0].is_wall() && !fixed[1].is_wall() &&
        cache.arcs_of(cache.block(fixed[0]), cache.block(fixed[1]), kOverlapTol).second == 0)
      return 0;
  }
  // Loci are named by an int: a particle's by its index in cache.pieces, a wall's by ~index
  // (negative) in `walls`. `all` lists every locus of each body, for the overlap check.
  walls.clear();
  std::array<std::pair<int, int>, D> all;  // [first, last) in cache.pieces, or negative for walls
  std::array<int, D> block_of;             // the cache block of each particle body (-1: a wall)
  block_of.fill(-1);
  for (int i = 0; i < D; ++i) {
    const Body<D>& b = fixed[static_cast<std::size_t>(i)];
    auto& l = live[static_cast<std::size_t>(i)];
    l.clear();
    if (b.is_wall()) {
      const int first = static_cast<int>(walls.size());
      append_loci<D>(b, cache.mobile, r0, cache.scratch, walls);
      for (int a = first; a < static_cast<int>(walls.size()); ++a) l.push_back(~a);
      all[static_cast<std::size_t>(i)] = {~first, ~static_cast<int>(walls.size())};
      continue;
    }
    block_of[static_cast<std::size_t>(i)] = cache.block(b);
    const auto& k = cache.blocks[static_cast<std::size_t>(block_of[static_cast<std::size_t>(i)])];
    l.assign(cache.live.begin() + k.live_first, cache.live.begin() + k.live_first + k.live_count);
    all[static_cast<std::size_t>(i)] = {k.first, k.first + k.count};
  }
  const auto piece = [&](int a) -> const Piece<D>& {
    return a >= 0 ? cache.pieces[static_cast<std::size_t>(a)] : walls[static_cast<std::size_t>(~a)];
  };

  // Every position is checked against every locus of every body: it overlaps none. The locus
  // that rejected the previous position is tried first (it usually rejects the next).
  int last_violator = 0;
  bool have_violator = false;
  const auto violates = [&](int a, const Vec<D>& x) {
    const Piece<D>& p = piece(a);
    return p.gap(x, r0) < -kOverlapTol * p.size;
  };
  const auto keeps = [&](const Vec<D>& x) {
    if (have_violator && violates(last_violator, x)) return false;
    for (const auto& [first, last] : all) {
      const int lo = first >= 0 ? first : ~first, hi = first >= 0 ? last : ~last;
      for (int a = lo; a < hi; ++a) {
        const int name = first >= 0 ? a : ~a;
        if (violates(name, x)) {
          last_violator = name, have_violator = true;
          return false;
        }
      }
    }
    return true;
  };
  const double scale = 2 * fixed[0].radius + 2 * mobile.radius;  // duplicates: closer than 1e-12 of this
  found.clear();
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> sols;
  std::array<Body<D>, D> folded;
  const SphereContactSolver<D> spheres;
  Mobile<D> point;
  point.radius = r0;
  const auto accept = [&](const Vec<D>& x) {
    if (found.size() >= out.size()) return;
    for (const Vec<D>& y : found)
      if ((x - y).squaredNorm() <= 1e-24 * scale * scale) return;
    if (keeps(x)) found.push_back(x);
  };
  const auto try_choice = [&](const std::array<int, D>& choice) {
    for (int i = 0; i < D; ++i) folded[static_cast<std::size_t>(i)] = piece(choice[static_cast<std::size_t>(i)]).as_body();
    const int n = spheres.solve(std::span<const Body<D>>(folded.data(), D), point, sols);
    for (int k = 0; k < n; ++k) accept(sols[static_cast<std::size_t>(k)].position);
  };
  const auto meet = [&](int a, int b) { return may_meet(piece(a), piece(b), r0); };
  if constexpr (D == 3) {
    // Two particle bodies: their exposed pair circles against the third body's loci.
    std::array<int, 3> order{0, 1, 2};
    std::stable_partition(order.begin(), order.end(), [&](int i) { return block_of[static_cast<std::size_t>(i)] >= 0; });
    if (block_of[static_cast<std::size_t>(order[1])] >= 0) {
      const auto [first, count] = cache.arcs_of(block_of[static_cast<std::size_t>(order[0])],
                                                block_of[static_cast<std::size_t>(order[1])], kOverlapTol);
      const std::vector<int>& third = live[static_cast<std::size_t>(order[2])];
      for (int i = first; i < first + count && found.size() < out.size(); ++i) {
        const Arc& arc = cache.arcs[static_cast<std::size_t>(i)];
        for (const int c : third) {
          if (arc.careful) { try_choice({arc.a, arc.b, c}); continue; }
          const Piece<D>& pc = piece(c);
          // The third locus as a plane a2.y = b2 in the arc's frame (radical plane for a sphere).
          Vec3 a2;
          double b2;
          const double inv = 1.0 / arc.scale;
          if (!pc.is_wall) {
            a2 = (pc.center - arc.origin) * inv;
            const double q = a2.norm(), rc = (pc.radius + r0) * inv;
            b2 = 0.5 * ((q - rc) * (q + rc) + 1.0);
          } else if (pc.wall.kind == WallKind::Plane) {
            a2 = pc.wall.normal;
            b2 = (r0 + pc.wall.normal.dot(pc.wall.point - arc.origin)) * inv;
          } else {
            try_choice({arc.a, arc.b, c});
            continue;
          }
          // On the circle y(t) = y1 + rho (cos t u + sin t v): A cos t + B sin t = C.
          const double A = arc.rho * a2.dot(arc.u), B = arc.rho * a2.dot(arc.v), C = b2 - a2.dot(arc.y1);
          const double M = std::sqrt(A * A + B * B);
          if (!(M > 1e-2 * arc.rho * a2.norm())) {  // the plane nearly parallel to the circle's
            try_choice({arc.a, arc.b, c});
            continue;
          }
          const double ratio = C / M;
          if (std::abs(ratio) > 1 + 1e-6) continue;        // misses the circle
          if (std::abs(ratio) > 1 - 1e-8) {                // nearly tangent: the verified solver
            try_choice({arc.a, arc.b, c});
            continue;
          }
          for (const auto& [ct, st] : points_at(A, B, M, ratio)) {
            if (!cache.exposed(i, turn_of(ct, st))) continue;
            const Vec3 x = arc.origin + arc.scale * (arc.y1 + arc.rho * (ct * arc.u + st * arc.v));
            // The sphere solver's guarantee: every gap within kTangencyTol of the smaller size.
            bool tangent = true;
            for (const int k : {arc.a, arc.b, c}) {
              const Piece<D>& pk = piece(k);
              const double size = pk.is_wall ? r0 : std::min(r0, pk.radius);
              tangent = tangent && std::abs(pk.gap(x, r0)) <= SphereContactSolver<D>::kTangencyTol * size;
            }
            if (tangent) accept(x);
            else try_choice({arc.a, arc.b, c});
          }
        }
      }
      for (std::size_t k = 0; k < found.size(); ++k) out[k].position = found[k];
      return static_cast<int>(found.size());
    }
  }
  for (const int a : live[0]) {
    for (const int b : live[1]) {
      if (!meet(a, b)) continue;
      if constexpr (D == 2) {
        try_choice({a, b});
      } else {
        for (const int c : live[2])
          if (meet(a, c) && meet(b, c)) try_choice({a, b, c});
      }
      if (found.size() >= out.size()) break;
    }
    if (found.size() >= out.size()) break;
  }
  for (std::size_t k = 0; k < found.size(); ++k) out[k].position = found[k];
  return static_cast<int>(found.size());
}

template class BallWrapperSolver<2>;
template class BallWrapperSolver<3>;

}  // namespace fp
