#include "contact/ball_wrapper_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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
  std::vector<Piece<D>> pieces;
  std::vector<int> live;
  std::vector<Ball<D>> scratch;

  /// Forgets everything unless `m` is the mobile the loci were folded for.
  void use(const Mobile<D>& m) {
    if (m.shape.get() == shape && m.radius == radius && m.rotation == rotation && blocks.size() < 1024) return;
    shape = m.shape.get(), rotation = m.rotation, radius = m.radius;
    balls_of<D>(shape, rotation, Vec<D>::Zero(), radius, mobile);
    double smallest = mobile[0].radius;
    for (const Ball<D>& b : mobile) smallest = std::min(smallest, b.radius);
    r0 = 0.5 * smallest;
    blocks.clear(), pieces.clear(), live.clear();
  }

  /// The block of a particle body, built if new.
  const Block& block(const Body<D>& b) {
    for (const Block& k : blocks)
      if (k.particle == b.shaped && k.center == b.center && k.radius == b.radius) return k;
    Block k;
    k.particle = b.shaped, k.center = b.center, k.radius = b.radius;
    k.first = static_cast<int>(pieces.size());
    append_loci<D>(b, mobile, r0, scratch, pieces);
    k.count = static_cast<int>(pieces.size()) - k.first;
    k.live_first = static_cast<int>(live.size());
    append_live<D>(pieces, k.first, k.first + k.count, 0, live);
    k.live_count = static_cast<int>(live.size()) - k.live_first;
    blocks.push_back(k);
    return blocks.back();
  }
};

}  // namespace

template <int D>
int BallWrapperSolver<D>::solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const {
  if (fixed.size() != static_cast<std::size_t>(D) || out.empty()) return 0;
  thread_local LociCache<D> cache;
  thread_local std::vector<Piece<D>> walls;         // this call's wall loci
  thread_local std::array<std::vector<int>, D> live;  // per body: its live loci (walls: ~index - 1)
  thread_local std::vector<Vec<D>> found;
  cache.use(mobile);
  const double r0 = cache.r0;
  if (!(r0 > 0)) return 0;
  // Loci are named by an int: a particle's by its index in cache.pieces, a wall's by ~index
  // (negative) in `walls`. `all` lists every locus of each body, for the overlap check.
  walls.clear();
  std::array<std::pair<int, int>, D> all;  // [first, last) in cache.pieces, or negative for walls
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
    const auto& k = cache.block(b);
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
  const auto try_choice = [&](const std::array<int, D>& choice) {
    for (int i = 0; i < D; ++i) folded[static_cast<std::size_t>(i)] = piece(choice[static_cast<std::size_t>(i)]).as_body();
    const int n = spheres.solve(std::span<const Body<D>>(folded.data(), D), point, sols);
    for (int k = 0; k < n && found.size() < out.size(); ++k) {
      const Vec<D>& x = sols[static_cast<std::size_t>(k)].position;
      bool duplicate = false;
      for (const Vec<D>& y : found) duplicate = duplicate || (x - y).squaredNorm() <= 1e-24 * scale * scale;
      if (!duplicate && keeps(x)) found.push_back(x);
    }
  };
  const auto meet = [&](int a, int b) { return may_meet(piece(a), piece(b), r0); };
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
