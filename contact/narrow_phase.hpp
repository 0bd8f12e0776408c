#pragma once
// Narrow phase for general particles: the signed gap between two particles (or a particle and
// a wall) and its gradient with respect to the second one's position. This is the gap function
// ω of paper 004 (Eq. 3) in its distance form: ω = 0 at outer contact, < 0 on overlap (minus
// the penetration depth), > 0 apart, and |∇ω| = 1 wherever it is smooth.
//
// Exact without FCL: two convex polygons (separating axes on overlap, nearest points apart,
// core/geometry/convex_polygon.hpp). Analytic fast paths (registered by kind pair):
// sphere-sphere, sphere-spherocylinder and spherocylinder-spherocylinder through segment distance
// (paper 004 Eq. 5-6), clusters of balls against those, ellipsoids against ellipsoids and
// spheres (Newton on the support functions, ellipsoid_gap.hpp), and convex polytopes against
// spheres and clusters (a ball's centre against the face planes inside, the nearest point of the
// facets outside). Every other pair goes through FCL's distance query with the libccd GJK
// solver (exact when apart; the INDEP solver is wrong, see dependencies.md). On overlap the depth
// comes from our own separating-axis search over support functions, not from FCL's EPA, whose
// assertion aborts the process on some touching polytopes (seen packing cubes). Clusters are
// handled piece by piece (the minimum over their member pairs).
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/geometry/wall.hpp"
#include "shapes/particle.hpp"

namespace fp {

template <int D>
struct Gap {
  double value = 0.0;               ///< signed gap
  Vec<D> normal = Vec<D>::Zero();   ///< unit; d(value)/d(position of the second body)
};

template <int D>
class NarrowPhase {
 public:
  /// Analytic gap of a kind pair; returns the gap of (a, b) with the gradient for b.
  using PairGap = std::function<Gap<D>(const Particle<D>& a, const Particle<D>& b)>;

  NarrowPhase();  ///< with the analytic fast paths registered
  ~NarrowPhase();
  NarrowPhase(const NarrowPhase&) = delete;
  NarrowPhase& operator=(const NarrowPhase&) = delete;

  /// Registers an analytic gap for (kind_a, kind_b); (kind_b, kind_a) follows by symmetry.
  void add_pair(const std::string& kind_a, const std::string& kind_b, PairGap gap);

  /// Signed gap between two particles and its gradient with respect to b's position.
  Gap<D> gap(const Particle<D>& a, const Particle<D>& b) const;
  /// gap(a, b).value < -allowed, decided without a distance query for two convex polytopes (by
  /// the separating-axis theorem, which is exact for them: the first axis that separates them
  /// by more than -allowed ends it), and mostly without the full search for an ellipsoid with an
  /// ellipsoid or a sphere (smooth_convex_overlap_beyond).
  bool overlap_beyond(const Particle<D>& a, const Particle<D>& b, double allowed) const;
  /// gap(a, b).value > d; for two convex polytopes a separating axis that shows more than d (a
  /// lower bound of the gap) answers without a distance query.
  bool gap_exceeds(const Particle<D>& a, const Particle<D>& b, double d) const;
  /// Signed gap between a container wall (the particle on its container side) and a particle.
  /// Planes, sphere and cylinder walls: exact for shapes whose hull balls span them (balls,
  /// spherocylinders, clusters, polytopes); conservative (never reports too large a gap) for
  /// curved shapes with circumscribing hull balls. Vertex walls (reflex corners) use FCL.
  Gap<D> gap(const Wall<D>& wall, const Particle<D>& b) const;

  /// FCL distance queries made so far (the analytic paths do not count).
  std::uint64_t fcl_queries() const { return fcl_queries_; }
  /// Forgets the FCL geometry of one shape (a mobile draft that was not placed) or of all.
  void forget(const Shape<D>* s) const;
  void clear_cache() const;

 private:
  struct FclShape;
  const FclShape& fcl_of(const ShapePtr<D>& s) const;
  Gap<D> fcl_gap(const Particle<D>& a, const Particle<D>& b) const;
  /// FCL's length unit, a power of two: 1 unless the first pair FCL sees is far from unit size
  /// (then about its size); fixed from then on, as the cached geometry is built in it.
  double fcl_unit(double size) const;
  /// Two convex polygons (2D): the separating axes on overlap, the nearest points apart; exact
  /// to rounding, no FCL geometry built.
  Gap<D> polygon_gap(const Particle<D>& a, const FclShape& fa, const Particle<D>& b, const FclShape& fb) const;
  /// Two convex polytopes: the largest separation s(u) over the separating-axis candidates (with
  /// `edges`, every one: their gap on overlap; a lower bound of the gap in any case), stopped
  /// early once it exceeds `enough`.
  double polytope_separation(const Particle<D>& a, const FclShape& fa, const Particle<D>& b, const FclShape& fb, double enough,
                             bool edges) const;

  /// The analytic gap of a kind pair, or null for FCL; memoised by the kind() pointers, since a
  /// string-keyed lookup per query cost as much as a capsule gap.
  const PairGap* pair_of(const char* kind_a, const char* kind_b) const;

  std::map<std::pair<std::string, std::string>, PairGap> pairs_;
  struct Memo {
    const char* a;
    const char* b;
    const PairGap* gap;
  };
  mutable std::vector<Memo> memo_;
  mutable std::unordered_map<const Shape<D>*, std::unique_ptr<FclShape>> cache_;
  mutable std::uint64_t fcl_queries_ = 0;
  mutable double unit_ = 0;  ///< fcl_unit(); 0 until the first FCL query
  mutable std::vector<Vec<D>> axes_scratch_, world_a_, world_b_;
};

}  // namespace fp
