// The ball wrapper solver (contact/ball_wrapper_solver.cpp): spheres and clusters (disks and
// clusters of disks in 2D) against each other and the walls, by wrapper intersection.
//  1. every returned position touches each fixed body within 1e-9 of the smaller size and
//     overlaps none, by the independent long-double gaps of general_contact_support.hpp;
//  2. the positions are exactly those of an independent brute force (every choice of members,
//     long-double trilateration of the member spheres, kept when it overlaps nothing);
//  3. every position the minimisation solver finds is one of them (and how many more the
//     wrapper finds is printed);
//  4. sphere problems give the analytic sphere solver's positions; far apart gives none;
//  5. extremes: size ratio 1:100, coordinates offset by 1e6, overlapping members.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <deque>

#include "contact/ball_wrapper_solver.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

constexpr double kTol = 1e-9;  // the contact accuracy, relative to the smaller size

template <int D>
using Out = std::array<Placement<D>, ContactSolver<D>::kMaxCandidates>;

template <int D>
std::span<const Placement<D>> first(const Out<D>& out, int n) {
  return {out.data(), static_cast<std::size_t>(n)};
}

// ================================================================ 1. touching and overlap-free

template <int D>
Tally run_constructed(const char* name, Kind mobile, const std::array<Kind, D>& fixed, int trials, std::uint64_t seed,
                      const Sizes& sizes = Sizes{}) {
  const BallWrapperSolver<D> solver;
  const Tally t = run_constructed_with<D>(solver, name, mobile, fixed, trials, seed, kTol, 1e-7, sizes);
  print_tally<D>(name, t);
  return t;
}

// The constructed position is a solution of the problem; the wrapper is exact, so it finds it
// unless the problem has more than kMaxCandidates positions (never seen here): 100 %.
TEST(BallWrapperSolver, EveryPositionTouchesEveryBodyAndOverlapsNone2D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 2> fixed; };
  const Case cases[] = {
      {"cluster | cluster cluster", K::Cluster, {K::Cluster, K::Cluster}},
      {"cluster | sphere sphere", K::Cluster, {K::Sphere, K::Sphere}},
      {"sphere | cluster cluster", K::Sphere, {K::Cluster, K::Cluster}},
      {"cluster | plane cluster", K::Cluster, {K::Plane, K::Cluster}},
      {"cluster | sphere-wall cluster", K::Cluster, {K::SphereWall, K::Cluster}},
      {"sphere | plane cluster", K::Sphere, {K::Plane, K::Cluster}},
  };
  std::uint64_t seed = 7000;
  for (const Case& c : cases) {
    const Tally t = run_constructed<2>(c.name, c.mobile, c.fixed, 60, seed++);
    EXPECT_EQ(t.known_found, t.built) << c.name;
  }
}

TEST(BallWrapperSolver, EveryPositionTouchesEveryBodyAndOverlapsNone3D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 3> fixed; };
  const Case cases[] = {
      {"cluster | cluster x3", K::Cluster, {K::Cluster, K::Cluster, K::Cluster}},
      {"cluster | sphere x3", K::Cluster, {K::Sphere, K::Sphere, K::Sphere}},
      {"sphere | cluster x3", K::Sphere, {K::Cluster, K::Cluster, K::Cluster}},
      {"cluster | plane cluster cluster", K::Cluster, {K::Plane, K::Cluster, K::Cluster}},
      {"cluster | plane plane cluster", K::Cluster, {K::Plane, K::Plane, K::Cluster}},
      {"cluster | sphere-wall cluster sphere", K::Cluster, {K::SphereWall, K::Cluster, K::Sphere}},
      {"cluster | cylinder-wall cluster x2", K::Cluster, {K::CylinderWall, K::Cluster, K::Cluster}},
      {"sphere | plane cluster sphere", K::Sphere, {K::Plane, K::Cluster, K::Sphere}},
  };
  std::uint64_t seed = 8000;
  for (const Case& c : cases) {
    const Tally t = run_constructed<3>(c.name, c.mobile, c.fixed, 60, seed++);
    EXPECT_EQ(t.known_found, t.built) << c.name;
  }
}

// ================================================================== 2. independent brute force

using LD = long double;

/// A ball of the independent reference, in long double.
template <int D>
struct BallL {
  VL<D> c;
  LD r;
};

/// The member balls of a fixed body or the mobile (at offset 0), from the shape's own members.
template <int D>
std::vector<BallL<D>> balls_of(const Shape<D>& s, const Mat<D>& rotation, const Vec<D>& position) {
  std::vector<BallL<D>> out;
  if (const auto* c = dynamic_cast<const ClusterShape<D>*>(&s))
    for (const Ball<D>& b : c->members()) out.push_back({ld<D>(position) + ld<D>(rotation * b.center), b.radius});
  else
    out.push_back({ld<D>(position), s.bounding_radius()});
  return out;
}

/// Points at distance r[i] from c[i] for every i: 2 circles (2D), 3 spheres (3D), in long double.
template <int D>
std::vector<VL<D>> trilaterate(const std::array<VL<D>, D>& c, const std::array<LD, D>& r) {
  std::vector<VL<D>> out;
  // Radical hyperplanes against sphere 0: 2 (c_i - c_0).x = r0^2 - ri^2 + |c_i|^2 - |c_0|^2.
  Eigen::Matrix<LD, D - 1, D> A;
  Eigen::Matrix<LD, D - 1, 1> b;
  for (int i = 1; i < D; ++i) {
    A.row(i - 1) = 2 * (c[i] - c[0]).transpose();
    b[i - 1] = r[0] * r[0] - r[i] * r[i] + c[i].squaredNorm() - c[0].squaredNorm();
  }
  // Particular solution (least norm) and the null direction of A.
  const Eigen::JacobiSVD<Eigen::Matrix<LD, D - 1, D>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  if (svd.singularValues()[D - 2] <= 1e-12L * svd.singularValues()[0]) return out;
  const VL<D> p = svd.solve(b);
  const VL<D> u = svd.matrixV().col(D - 1);
  // |p + t u - c0|^2 = r0^2.
  const VL<D> q = p - c[0];
  const LD bq = q.dot(u), cq = q.squaredNorm() - r[0] * r[0];
  const LD disc = bq * bq - cq;
  if (disc < 0) return out;
  const LD s = std::sqrt(disc);
  out.push_back(p + (-bq + s) * u);
  if (s > 0) out.push_back(p + (-bq - s) * u);
  return out;
}

/// Every position of the mobile touching each body and overlapping none, by brute force over
/// member choices (particles only: spheres and clusters).
template <int D>
std::vector<Vec<D>> brute_force(const Problem<D>& pb) {
  const auto mob = balls_of<D>(*pb.mobile_shape, pb.mobile_rotation, Vec<D>::Zero());
  std::array<std::vector<BallL<D>>, D> fixed;
  for (int i = 0; i < D; ++i) {
    const Particle<D>& p = *pb.fixed[i].shaped;
    fixed[i] = balls_of<D>(*p.shape, p.pose.rotation, p.pose.position);
  }
  // Every choice: one (fixed member, mobile member) per body.
  std::vector<Vec<D>> found;
  std::array<std::size_t, D> k{}, j{};
  const auto valid = [&](const VL<D>& x) {
    for (int i = 0; i < D; ++i)
      for (const auto& f : fixed[i])
        for (const auto& m : mob)
          if ((x + m.c - f.c).norm() - f.r - m.r < -kTol * std::min(f.r, m.r)) return false;
    return true;
  };
  const double scale = pb.mobile_shape->bounding_radius();
  std::function<void(int)> choose = [&](int i) {
    if (i == D) {
      std::array<VL<D>, D> c;
      std::array<LD, D> r;
      for (int a = 0; a < D; ++a) {
        c[a] = fixed[a][k[a]].c - mob[j[a]].c;
        r[a] = fixed[a][k[a]].r + mob[j[a]].r;
      }
      for (const VL<D>& x : trilaterate<D>(c, r)) {
        if (!valid(x)) continue;
        Vec<D> xd;
        for (int a = 0; a < D; ++a) xd[a] = static_cast<double>(x[a]);
        bool duplicate = false;
        for (const Vec<D>& y : found) duplicate = duplicate || (xd - y).norm() <= 1e-9 * scale;
        if (!duplicate) found.push_back(xd);
      }
      return;
    }
    for (k[i] = 0; k[i] < fixed[i].size(); ++k[i])
      for (j[i] = 0; j[i] < mob.size(); ++j[i]) choose(i + 1);
  };
  choose(0);
  return found;
}

template <int D>
void brute_force_round(int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  const BallWrapperSolver<D> solver;
  Rng rng(seed);
  int built = 0, positions = 0, several = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Problem<D> pb;
    std::array<Kind, D> kinds;
    kinds.fill(Kind::Cluster);
    if (!construct_problem<D>(pb, np, Kind::Cluster, kinds, Sizes{}, rng)) continue;
    ++built;
    Out<D> out;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    const std::vector<Vec<D>> ref = brute_force<D>(pb);
    positions += n;
    several += ref.size() > 2;
    const double scale = pb.mobile_shape->bounding_radius();
    ASSERT_EQ(static_cast<std::size_t>(n), ref.size()) << "trial " << trial << pb.literal();
    for (const Vec<D>& x : ref) {
      const auto [q, dist] = closest<D>(first<D>(out, n), x);
      EXPECT_LE(dist, 1e-9 * scale) << "trial " << trial << ": brute-force position " << vec_literal<D>(x) << " missing";
    }
  }
  std::printf("  %dD cluster x%d: %d problems, %d positions, %d with more than 2 (non-convex wrappers)\n", D, D + 1, built,
              positions, several);
  EXPECT_GE(built, trials * 9 / 10);
}

TEST(BallWrapperSolver, SameAsBruteForce2D) { brute_force_round<2>(150, 7100); }
TEST(BallWrapperSolver, SameAsBruteForce3D) { brute_force_round<3>(100, 8100); }

// =============================================================== 3. against the minimisation

template <int D>
void minimisation_round(int trials, std::uint64_t seed) {
  const BallWrapperSolver<D> wrapper;
  const KindDraw<D> clusters = [](Rng&, Kind& mobile, std::array<Kind, D>& fixed) { mobile = Kind::Cluster, fixed.fill(Kind::Cluster); };
  EXPECT_EQ(missed_minimisation_positions<D>(wrapper, "cluster | clusters", clusters, trials, seed), 0);
}

TEST(BallWrapperSolver, FindsEveryPositionOfTheMinimisation2D) { minimisation_round<2>(60, 7200); }
TEST(BallWrapperSolver, FindsEveryPositionOfTheMinimisation3D) { minimisation_round<3>(40, 8200); }

// ============================================ 3b. obstacles: only what the front would reject

// With obstacles (the front's V), the solver returns exactly the positions it returns without
// them that overlap no obstacle beyond tol x the smaller circumscribed radius (checked here by
// the member balls' own distances): nothing the front would keep is lost. Obstacles are copies
// of the mobile near the positions found, so that they cut some and spare others.
TEST(BallWrapperSolver, ObstaclesLeaveOutExactlyWhatTheFrontRejects) {
  constexpr double kFrontTol = 1e-6;
  NarrowPhase<3> np;
  const BallWrapperSolver<3> solver;
  Rng rng(8700);
  int trials = 0, kept = 0, cut = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Problem<3> pb;
    std::array<Kind, 3> kinds;
    kinds.fill(Kind::Cluster);
    if (!construct_problem<3>(pb, np, Kind::Cluster, kinds, Sizes{}, rng)) continue;
    Out<3> all;
    solver.set_obstacles({}, kFrontTol);
    const int n_all = solver.solve(pb.span(), pb.mobile(), all);
    if (n_all == 0 || n_all == static_cast<int>(all.size())) continue;  // a full buffer may hide positions
    const double R = pb.mobile_shape->bounding_radius();
    std::deque<Particle<3>> obstacles;
    for (int k = 0; k < 3; ++k) {
      Particle<3> q;
      q.shape = pb.mobile_shape;
      q.pose.rotation = random_rotation<3>(rng);
      Vec3 dir = Vec3(rng.uniform01() - 0.5, rng.uniform01() - 0.5, rng.uniform01() - 0.5).normalized();
      q.pose.position = all[static_cast<std::size_t>(rng.uniform01() * n_all) % n_all].position + (0.8 + 1.4 * rng.uniform01()) * R * dir;
      obstacles.push_back(q);
    }
    // The front's verdict for each position: the largest overlap of member balls, relative.
    const auto overlap_rel = [&](const Vec3& x, const Particle<3>& q) {
      double worst = -1e300;
      for (const BallL<3>& a : balls_of<3>(*pb.mobile_shape, pb.mobile_rotation, x))
        for (const BallL<3>& b : balls_of<3>(*q.shape, q.pose.rotation, q.pose.position))
          worst = std::max(worst, static_cast<double>(a.r + b.r - (a.c - b.c).norm()));
      return worst / std::min(R, q.shape->bounding_radius());
    };
    std::vector<Vec3> expected;
    bool ambiguous = false;
    for (int i = 0; i < n_all; ++i) {
      double worst = -1e300;
      for (const Particle<3>& q : obstacles) worst = std::max(worst, overlap_rel(all[static_cast<std::size_t>(i)].position, q));
      ambiguous = ambiguous || std::abs(worst - kFrontTol) < 1e-7;
      if (worst <= kFrontTol) expected.push_back(all[static_cast<std::size_t>(i)].position);
    }
    if (ambiguous) continue;
    ++trials;
    std::vector<const Particle<3>*> pointers;
    for (const Particle<3>& q : obstacles) pointers.push_back(&q);
    solver.set_obstacles(pointers, kFrontTol);
    Out<3> some;
    const int n = solver.solve(pb.span(), pb.mobile(), some);
    solver.set_obstacles({}, kFrontTol);
    ASSERT_EQ(static_cast<std::size_t>(n), expected.size()) << "trial " << trial << pb.literal();
    for (const Vec3& x : expected) {
      const auto [q, dist] = closest<3>(first<3>(some, n), x);
      EXPECT_LE(dist, 1e-12 * R) << "trial " << trial << ": a position no obstacle overlaps was left out";
    }
    kept += n;
    cut += n_all - n;
  }
  std::printf("  3D clusters with obstacles: %d problems, %d positions kept, %d left out\n", trials, kept, cut);
  EXPECT_GE(trials, 50);
  EXPECT_GT(cut, 20);
  EXPECT_GT(kept, 20);
}

// ========================================================= 4. spheres, and nothing to find

TEST(BallWrapperSolver, SpheresGiveTheAnalyticPositions2D) { expect_analytic_positions_for_spheres<2>(BallWrapperSolver<2>{}, 100, 7300); }
TEST(BallWrapperSolver, SpheresGiveTheAnalyticPositions3D) { expect_analytic_positions_for_spheres<3>(BallWrapperSolver<3>{}, 100, 8300); }

TEST(BallWrapperSolver, FarApartGivesNothing2D) {
  expect_nothing_when_one_is_far<2>(BallWrapperSolver<2>{}, Kind::Cluster, {Kind::Cluster, Kind::Cluster}, 100, 1, 1, 2);
}
TEST(BallWrapperSolver, FarApartGivesNothing3D) {
  expect_nothing_when_one_is_far<3>(BallWrapperSolver<3>{}, Kind::Cluster, {Kind::Cluster, Kind::Cluster, Kind::Cluster}, 100, 1, 1, 3);
}

// ====================================================================== 5. extremes

TEST(BallWrapperSolver, SizeRatioOneToHundred) {
  Sizes tiny;
  tiny.mobile = 0.01;
  tiny.allow_fixed_overlap = true;  // a tiny mobile cannot touch three big clusters that do not overlap
  using K = Kind;
  Tally t = run_constructed<3>("small cluster | cluster x3", K::Cluster, {K::Cluster, K::Cluster, K::Cluster}, 40, 8400, tiny);
  EXPECT_EQ(t.known_found, t.built);
  Sizes big;
  big.fixed = {0.01, 0.01, 0.01};
  t = run_constructed<3>("big cluster | small cluster x3", K::Cluster, {K::Cluster, K::Cluster, K::Cluster}, 40, 8401, big);
  EXPECT_EQ(t.known_found, t.built);
  t = run_constructed<2>("small cluster | cluster x2", K::Cluster, {K::Cluster, K::Cluster}, 40, 7400, tiny);
  EXPECT_EQ(t.known_found, t.built);
}

template <int D>
void offset_round(std::uint64_t seed) {
  std::array<Kind, D> kinds;
  kinds.fill(Kind::Cluster);
  kinds[0] = Kind::Plane;
  expect_same_when_shifted<D>(BallWrapperSolver<D>(), Kind::Cluster, kinds, kTol, seed);
}

TEST(BallWrapperSolver, CoordinatesOffsetByAMillion2D) { offset_round<2>(7500); }
TEST(BallWrapperSolver, CoordinatesOffsetByAMillion3D) { offset_round<3>(8500); }

}  // namespace
}  // namespace fp::general_test
