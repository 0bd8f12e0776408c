// Narrow phase (contact/narrow_phase.cpp): the signed gap ω of paper 004 (Eq. 3) in distance form
// and its gradient, on every path (analytic sphere/capsule/cluster pairs, FCL otherwise, walls),
// against the independent long-double references of general_contact_support.hpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

/// A random pair of the given kinds: b at a random direction from a, at a centre distance that
/// makes the gap `target` (bisection on the narrow phase: only the construction uses it).
template <int D>
bool random_pair(const NarrowPhase<D>& np, Kind ka, Kind kb, double target_rel, Rng& rng, Particle<D>& a, Particle<D>& b,
                 double size_a = 1, double size_b = 1) {
  a.shape = random_shape<D>(ka, size_a * log_uniform(rng, 0.7, 1.4), rng);
  a.pose.rotation = random_rotation<D>(rng);
  for (int k = 0; k < D; ++k) a.pose.position[k] = rng.uniform(-3, 3);
  b.shape = random_shape<D>(kb, size_b * log_uniform(rng, 0.7, 1.4), rng);
  b.pose.rotation = random_rotation<D>(rng);
  const Vec<D> d = random_unit<D>(rng);
  const double target = target_rel * std::min(a.bounding_radius(), b.bounding_radius());
  auto f = [&](double t) {
    b.pose.position = a.pose.position + t * d;
    return np.gap(a, b).value - target;
  };
  const double far = 1.5 * (a.bounding_radius() + b.bounding_radius()) + std::abs(target);
  if (!(f(0) < 0) || !(f(far) > 0)) return false;
  b.pose.position = a.pose.position + bisect_zero(f, 0, far) * d;
  return true;
}

template <int D>
std::string pair_literal(const Particle<D>& a, const Particle<D>& b) {
  auto one = [](const Particle<D>& p, const char* name) {
    return std::string("fp::Particle<") + std::to_string(D) + "> " + name + "; " + name + ".shape = " + shape_literal<D>(*p.shape) +
           ";\n" + name + ".pose.position = " + vec_literal<D>(p.pose.position) + "; " + name +
           ".pose.rotation = " + mat_literal<D>(p.pose.rotation) + ";\n";
  };
  return "\n// ---- failing pair, ready to paste ----\n" + one(a, "a") + one(b, "b");
}

struct PairCase {
  Kind a, b;
};

/// Per pair kind: worst |narrow - reference| (relative to the smaller circumscribed radius) on
/// exact references, binned: apart, near contact (overlap up to 1e-2 size, where the solvers
/// work) and deep overlap; sign agreements on the non-exact references.
struct Agreement {
  int exact = 0, signs = 0, skipped = 0;
  double worst_apart = 0, worst_near = 0, worst_deep = 0;
};

/// tol: bound on |narrow - reference| / size apart and near contact. Deeper overlaps (where the
/// FCL overlap path settles for a bound: support-function ascent plus pulls, no EPA) must be
/// within 2 % of the depth.
template <int D>
Agreement check_against_reference(Kind ka, Kind kb, int trials, std::uint64_t seed, double tol) {
  NarrowPhase<D> np;
  Rng rng(seed);
  Agreement ag;
  const auto t0 = std::chrono::steady_clock::now();
  for (int t = 0; t < trials; ++t) {
    Particle<D> a, b;
    // Half near contact (|gap| <= 0.1 size), half anywhere from deep overlap to well apart.
    const double target = t % 2 ? rng.uniform(-0.1, 0.1) : rng.uniform(-0.6, 1.0);
    if (!random_pair<D>(np, ka, kb, target, rng, a, b)) { ++ag.skipped; continue; }
    const double size = std::min(a.bounding_radius(), b.bounding_radius());
    const Gap<D> g = np.gap(a, b);
    const RefGap r = ref_gap<D>(a, b);
    EXPECT_TRUE(r.supported);
    const double ref = static_cast<double>(r.value);
    const std::string what = std::string(kind_name(ka)) + "-" + kind_name(kb) + " narrow " + num(g.value) + " reference " + num(ref) +
                             pair_literal<D>(a, b);
    if (r.exact) {
      const double err = std::abs(g.value - ref) / size;
      ++ag.exact;
      if (ref >= -1e-2 * size) {
        (ref >= 0 ? ag.worst_apart : ag.worst_near) = std::max(ref >= 0 ? ag.worst_apart : ag.worst_near, err);
        EXPECT_LE(err, tol) << what;
      } else {
        ag.worst_deep = std::max(ag.worst_deep, err);
        EXPECT_LE(err * size, 2e-2 * std::abs(ref)) << what;
      }
    } else if (std::abs(ref) > 1e-6 * size) {
      ++ag.signs;
      EXPECT_EQ(g.value < 0, ref < 0) << what;
    }
  }
  std::printf("  %dD %-10s - %-10s: %3d exact (worst / size: apart %.1e, overlap < 1e-2 %.1e, deeper %.1e), %3d sign-only, %d skipped (%.2f s)\n",
              D, kind_name(ka), kind_name(kb), ag.exact, ag.worst_apart, ag.worst_near, ag.worst_deep, ag.signs, ag.skipped,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return ag;
}

// ------------------------------------------------------------------------- sign and depth

// Spheres and capsules: the gap is the distance apart and minus the penetration depth on
// overlap (paper 004 Eq. 5-6 in distance form), checked against the analytic depth |c1 - c2| -
// r1 - r2 (spheres) and the golden-section segment distance minus the radii (capsules whose
// segments do not cross), and by the depth's meaning: moving b out by -gap along the normal
// brings the gap to zero.
template <int D>
void sign_and_depth_round() {
  NarrowPhase<D> np;
  Rng rng(11 + D);
  const std::array<PairCase, 3> cases = {{{Kind::Sphere, Kind::Sphere}, {Kind::Capsule, Kind::Capsule}, {Kind::Sphere, Kind::Capsule}}};
  for (const PairCase& c : cases) {
    int overlaps = 0, apart = 0;
    double worst = 0;
    for (int t = 0; t < 300; ++t) {
      Particle<D> a, b;
      if (!random_pair<D>(np, c.a, c.b, rng.uniform(-0.8, 0.8), rng, a, b)) continue;
      const double size = std::min(a.bounding_radius(), b.bounding_radius());
      const Gap<D> g = np.gap(a, b);
      const RefGap r = ref_gap<D>(a, b);
      if (!r.exact) continue;  // crossing segments: Eq. 6 gives -(r1 + r2), not the depth
      if (c.a == Kind::Sphere && c.b == Kind::Sphere) {
        const LD analytic = (ld<D>(a.pose.position) - ld<D>(b.pose.position)).norm() - LD(a.bounding_radius()) - LD(b.bounding_radius());
        EXPECT_NEAR(g.value, static_cast<double>(analytic), 1e-14 * size);
      }
      worst = std::max(worst, std::abs(g.value - static_cast<double>(r.value)) / size);
      EXPECT_NEAR(g.value, static_cast<double>(r.value), 1e-12 * size) << pair_literal<D>(a, b);
      (g.value < 0 ? overlaps : apart)++;
      Particle<D> moved = b;
      moved.pose.position -= g.value * g.normal;  // out by the depth (in by the distance)
      EXPECT_LE(std::abs(np.gap(a, moved).value), 1e-12 * size) << pair_literal<D>(a, b);
    }
    std::printf("  %dD %s-%s: %d overlapping, %d apart, worst |narrow - reference| %.1e of size\n", D, kind_name(c.a),
                kind_name(c.b), overlaps, apart, worst);
    EXPECT_GT(overlaps, 50);
    EXPECT_GT(apart, 50);
  }
}

TEST(NarrowPhase, SignIsOverlapDepthForSpheresAndCapsules2D) { sign_and_depth_round<2>(); }
TEST(NarrowPhase, SignIsOverlapDepthForSpheresAndCapsules3D) { sign_and_depth_round<3>(); }

// Two capsules whose segments cross: the gap is negative (overlap) whatever its magnitude.
TEST(NarrowPhase, CrossingCapsulesOverlap) {
  NarrowPhase<2> np;
  Particle<2> a, b;
  a.shape = b.shape = std::make_shared<SpherocylinderShape<2>>(1.0, 0.2);
  b.pose.rotation = rotation_2d(kPi / 2);
  EXPECT_LT(np.gap(a, b).value, -0.39);
}

// ------------------------------------------------------- FCL and cluster paths vs references

// Reference tolerances (relative to the smaller circumscribed radius): exact pairs (analytic,
// polytope-polytope through separating axes, ellipsoids against ellipsoids and spheres through
// Newton on their support functions, polytopes against spheres and clusters by their facets) to
// rounding; pairs with a curved FCL shape to 5e-8:
// GJK's distance on curved supports is good to ~2e-8 (measured; its stopping rule), far below the
// solver's gap tolerance of 1e-6.
TEST(NarrowPhase, FclAndClusterPathsAgreeWithReferences2D) {
  std::printf("2D (FCL sees prisms / tall ellipsoids: the distance must equal the 2D reference)\n");
  check_against_reference<2>(Kind::Polytope, Kind::Polytope, 120, 21, 1e-12);
  check_against_reference<2>(Kind::Ellipsoid, Kind::Ellipsoid, 120, 22, 1e-12);
  check_against_reference<2>(Kind::Polytope, Kind::Ellipsoid, 120, 23, 5e-8);
  check_against_reference<2>(Kind::Capsule, Kind::Polytope, 120, 24, 5e-8);
  check_against_reference<2>(Kind::Sphere, Kind::Ellipsoid, 120, 25, 1e-12);
  check_against_reference<2>(Kind::Cluster, Kind::Cluster, 120, 26, 1e-12);
  check_against_reference<2>(Kind::Cluster, Kind::Polytope, 120, 27, 1e-12);
  check_against_reference<2>(Kind::Sphere, Kind::Polytope, 120, 29, 1e-12);
  check_against_reference<2>(Kind::Capsule, Kind::Ellipsoid, 120, 28, 5e-8);
}

TEST(NarrowPhase, FclAndClusterPathsAgreeWithReferences3D) {
  check_against_reference<3>(Kind::Polytope, Kind::Polytope, 100, 31, 1e-12);
  check_against_reference<3>(Kind::Ellipsoid, Kind::Ellipsoid, 60, 32, 1e-12);
  check_against_reference<3>(Kind::Sphere, Kind::Polytope, 100, 33, 1e-12);
  check_against_reference<3>(Kind::Capsule, Kind::Polytope, 100, 34, 5e-8);
  check_against_reference<3>(Kind::Sphere, Kind::Ellipsoid, 100, 35, 1e-12);
  check_against_reference<3>(Kind::Capsule, Kind::Ellipsoid, 60, 36, 5e-8);
  check_against_reference<3>(Kind::Cluster, Kind::Cluster, 100, 37, 1e-12);
  check_against_reference<3>(Kind::Cluster, Kind::Polytope, 60, 38, 1e-12);
  check_against_reference<3>(Kind::Polytope, Kind::Ellipsoid, 40, 39, 5e-8);
  check_against_reference<3>(Kind::Cylinder, Kind::Sphere, 100, 40, 5e-8);
  check_against_reference<3>(Kind::Cylinder, Kind::Capsule, 60, 41, 5e-8);
  check_against_reference<3>(Kind::Cylinder, Kind::Ellipsoid, 40, 42, 5e-8);
}

// ------------------------------------------------------------ predicates of the front

/// overlap_beyond and gap_exceeds (the front's overlap and reach tests; for two polytopes by
/// separating axes, without a distance query) give the verdict of the independent reference
/// gap, wherever it is not within `margin` of the size of the threshold (1e-12 for polytope
/// pairs; the narrow phase's own accuracy, 5e-8, for the pairs that go through gap()).
template <int D>
void predicates_round(Kind ka, Kind kb, int trials, std::uint64_t seed, double margin) {
  NarrowPhase<D> np;
  Rng rng(seed);
  int decided = 0;
  for (int t = 0; t < trials; ++t) {
    Particle<D> a, b;
    // Around each threshold below, and anywhere from deep overlap to well apart.
    const double targets[] = {rng.uniform(-2e-9, 0), rng.uniform(-0.06, -0.04), rng.uniform(0.29, 0.31), rng.uniform(-0.6, 1.0)};
    if (!random_pair<D>(np, ka, kb, targets[t % 4], rng, a, b)) continue;
    const double size = std::min(a.bounding_radius(), b.bounding_radius());
    const double ref = static_cast<double>(ref_gap<D>(a, b).value);
    for (const double allowed : {1e-9 * size, 0.05 * size}) {
      if (std::abs(ref + allowed) <= margin * size) continue;
      ++decided;
      EXPECT_EQ(np.overlap_beyond(a, b, allowed), ref < -allowed) << "allowed " << allowed << " reference " << num(ref) << pair_literal<D>(a, b);
    }
    for (const double d : {0.0, 0.3 * size}) {
      if (std::abs(ref - d) <= margin * size) continue;
      ++decided;
      EXPECT_EQ(np.gap_exceeds(a, b, d), ref > d) << "d " << d << " reference " << num(ref) << pair_literal<D>(a, b);
    }
  }
  std::printf("  %dD %-10s - %-10s: %d verdicts\n", D, kind_name(ka), kind_name(kb), decided);
  EXPECT_GT(decided, trials);
}

TEST(NarrowPhase, OverlapAndReachPredicatesAgreeWithTheReference) {
  predicates_round<2>(Kind::Polytope, Kind::Polytope, 200, 51, 1e-12);
  predicates_round<3>(Kind::Polytope, Kind::Polytope, 200, 52, 1e-12);
  predicates_round<3>(Kind::Sphere, Kind::Polytope, 60, 53, 1e-12);  // by the facets
  predicates_round<3>(Kind::Cluster, Kind::Polytope, 60, 54, 1e-12);
  // Ellipsoids with ellipsoids and spheres: one ascent, a point deep inside both, or the full search.
  predicates_round<2>(Kind::Ellipsoid, Kind::Ellipsoid, 200, 55, 1e-12);
  predicates_round<3>(Kind::Ellipsoid, Kind::Ellipsoid, 200, 56, 1e-12);
  predicates_round<3>(Kind::Sphere, Kind::Ellipsoid, 200, 57, 1e-12);
  predicates_round<3>(Kind::ThinEllipsoid, Kind::Ellipsoid, 200, 58, 1e-12);
}

// ------------------------------------------------------------------- gradient and symmetry

/// Central differences of the gap with respect to b's position against the returned normal,
/// where the gap is smooth (differences with steps h and h/2 agree); symmetry of value and normal.
/// Analytic and polytope paths: h = 1e-5 size, agreement 1e-5. Curved FCL pairs: GJK's values
/// carry ~1e-8 of noise, so h = 1e-3 size (truncation ~h^2 curvature ~1e-6) and gaps from -1e-2
/// size up (where the overlap path is exact; deeper it returns a lower bound); their normal is
/// GJK's nearest-point direction, good to ~1e-4 only (measured), so agreement 5e-4.
template <int D>
void gradient_and_symmetry(Kind ka, Kind kb, int trials, std::uint64_t seed, bool curved_fcl) {
  NarrowPhase<D> np;
  Rng rng(seed);
  const double tol = curved_fcl ? 5e-4 : 1e-5;
  int checked = 0, kinks = 0;
  double worst = 0, worst_sym = 0;
  for (int t = 0; t < trials; ++t) {
    Particle<D> a, b;
    if (!random_pair<D>(np, ka, kb, curved_fcl ? rng.uniform(-0.01, 0.5) : rng.uniform(-0.3, 0.5), rng, a, b)) continue;
    const double size = std::min(a.bounding_radius(), b.bounding_radius());
    const Gap<D> g = np.gap(a, b);
    // Symmetry.
    const Gap<D> h = np.gap(b, a);
    worst_sym = std::max(worst_sym, std::abs(g.value - h.value) / size);
    EXPECT_NEAR(g.value, h.value, (curved_fcl ? 5e-8 : 1e-12) * size) << pair_literal<D>(a, b);
    EXPECT_LE((g.normal + h.normal).norm(), tol) << pair_literal<D>(a, b);
    EXPECT_NEAR(g.normal.norm(), 1.0, 1e-9);
    // Finite differences.
    auto fd = [&](double step) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) {
        Particle<D> p = b, m = b;
        p.pose.position[k] += step;
        m.pose.position[k] -= step;
        d[k] = (np.gap(a, p).value - np.gap(a, m).value) / (2 * step);
      }
      return d;
    };
    const double step = (curved_fcl ? 1e-3 : 1e-5) * size;
    const Vec<D> d1 = fd(step), d2 = fd(step / 2);
    if ((d1 - d2).norm() > tol) { ++kinks; continue; }
    ++checked;
    worst = std::max(worst, (d2 - g.normal).norm());
    EXPECT_LE((d2 - g.normal).norm(), tol) << kind_name(ka) << "-" << kind_name(kb) << " gap " << g.value << " normal "
                                            << g.normal.transpose() << " finite differences " << d2.transpose()
                                            << pair_literal<D>(a, b);
  }
  std::printf("  %dD %-12s - %-12s: gradient checked %3d (worst %.1e), skipped at kinks %d; worst asymmetry %.1e\n", D,
              kind_name(ka), kind_name(kb), checked, worst, kinks, worst_sym);
  EXPECT_GE(checked, trials / 2);
}

TEST(NarrowPhase, GradientIsFiniteDifferenceAndSymmetric2D) {
  gradient_and_symmetry<2>(Kind::Sphere, Kind::Sphere, 60, 51, false);
  gradient_and_symmetry<2>(Kind::Capsule, Kind::Capsule, 60, 52, false);
  gradient_and_symmetry<2>(Kind::Sphere, Kind::Capsule, 60, 53, false);
  gradient_and_symmetry<2>(Kind::Cluster, Kind::Capsule, 60, 54, false);
  gradient_and_symmetry<2>(Kind::Polytope, Kind::Polytope, 60, 55, false);
  gradient_and_symmetry<2>(Kind::Ellipsoid, Kind::Ellipsoid, 60, 56, true);
  gradient_and_symmetry<2>(Kind::Polytope, Kind::Capsule, 60, 57, true);
  gradient_and_symmetry<2>(Kind::Polytope, Kind::Sphere, 60, 58, false);
  gradient_and_symmetry<2>(Kind::Cluster, Kind::Polytope, 60, 59, false);
}

TEST(NarrowPhase, GradientIsFiniteDifferenceAndSymmetric3D) {
  gradient_and_symmetry<3>(Kind::Sphere, Kind::Sphere, 60, 61, false);
  gradient_and_symmetry<3>(Kind::Capsule, Kind::Capsule, 60, 62, false);
  gradient_and_symmetry<3>(Kind::Sphere, Kind::Capsule, 60, 63, false);
  gradient_and_symmetry<3>(Kind::Cluster, Kind::Sphere, 60, 64, false);
  gradient_and_symmetry<3>(Kind::Polytope, Kind::Polytope, 60, 65, false);
  gradient_and_symmetry<3>(Kind::Polytope, Kind::Sphere, 60, 68, false);
  gradient_and_symmetry<3>(Kind::Cluster, Kind::Polytope, 60, 69, false);
  gradient_and_symmetry<3>(Kind::Ellipsoid, Kind::Ellipsoid, 60, 66, true);
  gradient_and_symmetry<3>(Kind::Polytope, Kind::Capsule, 60, 67, true);
  gradient_and_symmetry<3>(Kind::Cylinder, Kind::Sphere, 60, 68, true);
}

// ----------------------------------------------------------------------------------- walls

/// Wall gaps against the sampled references: exact for shapes whose hull balls span them
/// (balls, capsules, clusters, polytopes); for curved shapes with circumscribing hull balls
/// (ellipsoids, cylinders) never larger than the true gap and at most the cover's slack below it.
/// Plane walls read the support function: exact for every shape.
template <int D>
void wall_round(Kind k, int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  Rng rng(seed);
  const bool exact = k != Kind::Ellipsoid && k != Kind::Cylinder;
  double worst[3] = {0, 0, 0};
  for (int t = 0; t < trials; ++t) {
    Particle<D> p;
    p.shape = random_shape<D>(k, log_uniform(rng, 0.5, 2), rng);
    p.pose.rotation = random_rotation<D>(rng);
    for (int a = 0; a < D; ++a) p.pose.position[a] = rng.uniform(-3, 3);
    const double size = p.bounding_radius();
    const RefBody<D> ref = ref_of<D>(p);
    std::vector<Wall<D>> walls;
    const Vec<D> n = random_unit<D>(rng);
    walls.push_back(Wall<D>::plane(p.pose.position - rng.uniform(-0.5, 1.5) * size * n, n));
    walls.push_back(Wall<D>::sphere(p.pose.position + rng.uniform(0, 2) * size * random_unit<D>(rng), size * rng.uniform(1, 4)));
    if constexpr (D == 3)
      walls.push_back(Wall<D>::cylinder(p.pose.position + rng.uniform(0, 2) * size * random_unit<D>(rng), random_unit<D>(rng),
                                        size * rng.uniform(1, 4)));
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const double got = np.gap(walls[w], p).value;
      const double want = static_cast<double>(ref_wall_gap<D>(walls[w], ref));
      worst[w] = std::max(worst[w], std::abs(got - want) / size);
      const std::string what = std::string(kind_name(k)) + " against " + wall_literal<D>(walls[w]) + pair_literal<D>(p, p);
      if (exact || w == 0) {
        EXPECT_NEAR(got, want, 1e-9 * size) << what;
      } else {
        EXPECT_LE(got, want + 1e-9 * size) << what;
        EXPECT_GE(got, want - 0.006 * size) << what;
      }
      // The normal is the gradient for the particle's position (finite differences).
      const double step = 1e-5 * size;
      Vec<D> fd;
      for (int a = 0; a < D; ++a) {
        Particle<D> q = p, m = p;
        q.pose.position[a] += step;
        m.pose.position[a] -= step;
        fd[a] = (np.gap(walls[w], q).value - np.gap(walls[w], m).value) / (2 * step);
      }
      EXPECT_LE((fd - np.gap(walls[w], p).normal).norm(), 1e-4) << what;
    }
  }
  std::printf("  %dD %-12s worst |narrow - sampled| / size: plane %.1e, sphere %.1e, cylinder %.1e\n", D, kind_name(k), worst[0],
              worst[1], worst[2]);
}

TEST(NarrowPhase, WallGapsAgreeWithSampling2D) {
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid}) wall_round<2>(k, 40, 70 + static_cast<int>(k));
}

TEST(NarrowPhase, WallGapsAgreeWithSampling3D) {
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid, Kind::Cylinder})
    wall_round<3>(k, 30, 80 + static_cast<int>(k));
}

/// Vertex walls (a reflex corner is a point the particle stays outside of): the signed distance
/// from the point, exact both ways for convex shapes.
template <int D>
void vertex_round(Kind k, int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  Rng rng(seed);
  double worst = 0;
  for (int t = 0; t < trials; ++t) {
    Particle<D> p;
    p.shape = random_shape<D>(k, 1.0, rng);
    p.pose.rotation = random_rotation<D>(rng);
    const Wall<D> w = Wall<D>::vertex(rng.uniform(0.2, 1.5) * random_unit<D>(rng));
    const double got = np.gap(w, p).value;
    const double want = static_cast<double>(ref_wall_gap<D>(w, ref_of<D>(p)));
    worst = std::max(worst, std::abs(got - want));
    EXPECT_NEAR(got, want, 1e-6) << kind_name(k) << " against " << wall_literal<D>(w) << pair_literal<D>(p, p);
  }
  std::printf("  %dD %-12s vertex wall worst |narrow - reference| %.1e\n", D, kind_name(k), worst);
}

// Ellipsoids (ellipses) against ellipsoids and spheres go through Newton on their support
// functions (contact/ellipsoid_gap.hpp). At the extremes of the issue — semi-axis ratios 20
// (aspect 0.05), sizes 1 : 100, a scene 1e6 from the origin — the gap still equals the
// independent long-double reference to 1e-9 of the smaller size (plus the rounding of the
// coordinates: 1e6 carries ~1e-10 absolute), apart, touching and overlapping.
template <int D>
void ellipsoid_extremes_round(std::uint64_t seed) {
  NarrowPhase<D> np;
  Rng rng(seed);
  int checked = 0;
  double worst = 0;
  for (int t = 0; t < 300; ++t) {
    const bool tiny_b = t % 3 == 1, sphere_a = t % 5 == 4;
    const double offset = t % 2 ? 1e6 : 0.0;
    auto thin_axes = [&](double size) {
      Vec<D> ax;
      ax[0] = size;
      ax[D - 1] = size / 20;
      if constexpr (D == 3) ax[1] = size * std::pow(20.0, -rng.uniform01());
      return ax;
    };
    Particle<D> a, b;
    if (sphere_a) a.shape = std::make_shared<SphereShape<D>>(rng.uniform(0.05, 1.0));
    else a.shape = std::make_shared<EllipsoidShape<D>>(thin_axes(1.0));
    b.shape = std::make_shared<EllipsoidShape<D>>(thin_axes(tiny_b ? 0.01 : rng.uniform(0.5, 1.0)));
    a.pose.rotation = random_rotation<D>(rng);
    b.pose.rotation = random_rotation<D>(rng);
    a.pose.position = Vec<D>::Constant(offset);
    const Vec<D> dir = random_unit<D>(rng);
    const double size = std::min(a.bounding_radius(), b.bounding_radius());
    const double target = size * (t % 4 == 0 ? rng.uniform(0.0, 0.5) : t % 4 == 1 ? rng.uniform(-1e-9, 1e-9) : rng.uniform(-0.04, 0.0));
    auto f = [&](double x) {
      b.pose.position = a.pose.position + x * dir;
      return np.gap(a, b).value - target;
    };
    const double far = 1.5 * (a.bounding_radius() + b.bounding_radius()) + std::abs(target);
    if (!(f(0) < 0) || !(f(far) > 0)) continue;
    b.pose.position = a.pose.position + bisect_zero(f, 0, far) * dir;
    const double ref = static_cast<double>(ref_gap<D>(a, b).value);
    const double got = np.gap(a, b).value;
    const double tol = 1e-9 * size + 1e-15 * offset * 100;
    ++checked;
    worst = std::max(worst, std::abs(got - ref) / size);
    EXPECT_NEAR(got, ref, tol) << "size " << size << " offset " << offset << pair_literal<D>(a, b);
    // The gradient for b is the maximising direction: a unit vector.
    const Gap<D> g = np.gap(a, b);
    EXPECT_NEAR(g.normal.norm(), 1.0, 1e-12);
  }
  std::printf("  %dD ellipsoid extremes: %d pairs, worst |narrow - reference| / size %.2g\n", D, checked, worst);
  EXPECT_GT(checked, 200);
}

TEST(NarrowPhase, EllipsoidGapsAtTheExtremes2D) { ellipsoid_extremes_round<2>(71); }
TEST(NarrowPhase, EllipsoidGapsAtTheExtremes3D) { ellipsoid_extremes_round<3>(72); }

TEST(NarrowPhase, VertexWalls) {
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid}) vertex_round<2>(k, 40, 90 + static_cast<int>(k));
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid}) vertex_round<3>(k, 40, 95 + static_cast<int>(k));
}

// ---------------------------------------------------------------- the references themselves

/// The references read the shapes' parameters, not their support(): both must agree.
template <int D>
void support_agrees(Kind k, std::uint64_t seed) {
  Rng rng(seed);
  for (int t = 0; t < 20; ++t) {
    Particle<D> p;
    p.shape = random_shape<D>(k, log_uniform(rng, 0.3, 3), rng);
    p.pose.rotation = random_rotation<D>(rng);
    for (int a = 0; a < D; ++a) p.pose.position[a] = rng.uniform(-3, 3);
    const RefBody<D> ref = ref_of<D>(p);
    for (int s = 0; s < 20; ++s) {
      const Vec<D> u = random_unit<D>(rng);
      LD mine = -kInfL;
      for (const Piece<D>& q : ref.pieces) mine = std::max(mine, support_value<D>(q, ld<D>(u)));
      EXPECT_NEAR(static_cast<double>(mine), u.dot(p.support(u)), 1e-12 * p.bounding_radius()) << kind_name(k);
    }
  }
}

TEST(NarrowPhase, ReferenceSupportMatchesShapes) {
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid}) support_agrees<2>(k, 100 + static_cast<int>(k));
  for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Cluster, Kind::Polytope, Kind::Ellipsoid, Kind::Cylinder})
    support_agrees<3>(k, 110 + static_cast<int>(k));
}

/// The golden-section and closed-form segment distances agree (two independent methods).
TEST(NarrowPhase, ReferenceSegmentDistancesAgree) {
  Rng rng(5);
  for (int t = 0; t < 300; ++t) {
    VL<3> p[4];
    for (auto& q : p) q = ld<3>(Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    if (t % 3 == 0) p[3] = p[2] + (p[1] - p[0]) * LD(0.7);  // parallel segments
    EXPECT_NEAR(static_cast<double>(segment_segment_golden<3>(p[0], p[1], p[2], p[3])),
                static_cast<double>(segment_segment_cf<3>(p[0], p[1], p[2], p[3])), 1e-15);
  }
}

}  // namespace
}  // namespace fp::general_test
