// The potential-minimisation contact solver (contact/minimisation_solver.cpp, paper 004 Eq. 4):
// every position it returns is checked with the independent long-double references of
// general_contact_support.hpp (never with the solver's own narrow phase), on seeded random
// configurations of every shape family, against the analytic sphere solver, against a brute-force
// count of the solutions in 2D, on failures, degenerate and extreme cases, and with every
// NLopt algorithm it offers. Recall figures (fractions of solutions found) are printed; the
// asserted floors sit below the measured values (see the comments).
#include <gtest/gtest.h>

#include <chrono>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

template <int D>
using Out = std::array<Placement<D>, ContactSolver<D>::kMaxSolutions>;

template <int D>
std::span<const Placement<D>> first(const Out<D>& out, int n) {
  return {out.data(), static_cast<std::size_t>(n)};
}

/// Runs the minimisation solver on `trials` constructed problems (run_constructed_with), timed.
template <int D>
Tally run_constructed(const char* name, Kind mobile, const std::array<Kind, D>& fixed, int trials, std::uint64_t seed,
                      const Sizes& sizes = Sizes{}, const MinimisationOptions& opt = MinimisationOptions{}) {
  const auto t0 = Clock::now();
  NarrowPhase<D> np;
  MinimisationSolver<D> solver(np, opt);
  const Tally t = run_constructed_with<D>(solver, name, mobile, fixed, trials, seed, opt.gap_tolerance, 1e-4, sizes);
  std::printf("  %dD %-34s %3d problems, %3d solved, %3d positions, known found %5.1f %%, worst |gap|/tol %.2g  (%.2f s)\n", D,
              name, t.built, t.with_solution, t.solutions, 100 * t.known_recall(), t.worst, seconds_since(t0));
  return t;
}

// ================================================================ 1. every shape pair, 2D / 3D

// Mobile kind x fixed kinds. The constructed position is found in most problems; the floor of
// 75 % leaves room for problems with several solutions per side or a nearly tangent known
// position (measured: 77-100 % per pair, see the printed table).
TEST(MinimisationSolver, EveryPositionTouchesEveryBody2D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 2> fixed; };
  const Case cases[] = {
      {"sphere | sphere sphere", K::Sphere, {K::Sphere, K::Sphere}},
      {"capsule | capsule capsule", K::Capsule, {K::Capsule, K::Capsule}},
      {"sphere | capsule capsule", K::Sphere, {K::Capsule, K::Capsule}},
      {"capsule | sphere sphere", K::Capsule, {K::Sphere, K::Sphere}},
      {"capsule | plane capsule", K::Capsule, {K::Plane, K::Capsule}},
      {"capsule | sphere-wall capsule", K::Capsule, {K::SphereWall, K::Capsule}},
      {"polygon | polygon polygon", K::Polytope, {K::Polytope, K::Polytope}},
      {"ellipse | ellipse ellipse", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid}},
      {"cluster | cluster cluster", K::Cluster, {K::Cluster, K::Cluster}},
      {"polygon | ellipse cluster", K::Polytope, {K::Ellipsoid, K::Cluster}},
      {"ellipse | capsule polygon", K::Ellipsoid, {K::Capsule, K::Polytope}},
      {"polygon | plane ellipse", K::Polytope, {K::Plane, K::Ellipsoid}},
  };
  std::uint64_t seed = 1000;
  for (const Case& c : cases) {
    const Tally t = run_constructed<2>(c.name, c.mobile, c.fixed, 40, seed++);
    EXPECT_GE(t.known_recall(), 0.75) << c.name;
  }
}

TEST(MinimisationSolver, EveryPositionTouchesEveryBody3D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 3> fixed; };
  const Case cases[] = {
      {"sphere | sphere x3", K::Sphere, {K::Sphere, K::Sphere, K::Sphere}},
      {"capsule | capsule x3", K::Capsule, {K::Capsule, K::Capsule, K::Capsule}},
      {"sphere | capsule x3", K::Sphere, {K::Capsule, K::Capsule, K::Capsule}},
      {"capsule | sphere x3", K::Capsule, {K::Sphere, K::Sphere, K::Sphere}},
      {"capsule | plane capsule capsule", K::Capsule, {K::Plane, K::Capsule, K::Capsule}},
      {"capsule | plane plane capsule", K::Capsule, {K::Plane, K::Plane, K::Capsule}},
      {"capsule | cylinder-wall capsule x2", K::Capsule, {K::CylinderWall, K::Capsule, K::Capsule}},
      {"polyhedron | polyhedron x3", K::Polytope, {K::Polytope, K::Polytope, K::Polytope}},
      {"ellipsoid | ellipsoid x3", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}},
      {"cluster | cluster x3", K::Cluster, {K::Cluster, K::Cluster, K::Cluster}},
      {"polyhedron | sphere capsule cluster", K::Polytope, {K::Sphere, K::Capsule, K::Cluster}},
      {"ellipsoid | sphere capsule ellipsoid", K::Ellipsoid, {K::Sphere, K::Capsule, K::Ellipsoid}},
      {"cylinder | sphere capsule cluster", K::Cylinder, {K::Sphere, K::Capsule, K::Cluster}},
      {"cluster | polyhedron plane sphere", K::Cluster, {K::Polytope, K::Plane, K::Sphere}},
  };
  std::uint64_t seed = 2000;
  for (const Case& c : cases) {
    const Tally t = run_constructed<3>(c.name, c.mobile, c.fixed, 25, seed++);
    EXPECT_GE(t.known_recall(), 0.75) << c.name;
  }
}

// ======================================================== 2. agreement with the analytic solver

/// Disks / spheres: MinimisationSolver on SphereShape against SphereContactSolver on the same
/// bodies. Every minimisation solution must be an analytic one (within 1e-6 r); the fraction of
/// analytic solutions found is printed and asserted (measured: see the output; floor below it).
template <int D>
double analytic_agreement(int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  MinimisationSolver<D> solver(np, MinimisationOptions{});
  const SphereContactSolver<D> analytic;
  Rng rng(seed);
  int analytic_total = 0, found = 0, extra = 0;
  for (int t = 0; t < trials; ++t) {
    std::array<Particle<D>, D> ps;
    std::array<Body<D>, D> bodies;
    for (int i = 0; i < D; ++i) {
      ps[i].shape = std::make_shared<SphereShape<D>>(log_uniform(rng, 0.3, 3));
      for (int a = 0; a < D; ++a) ps[i].pose.position[a] = rng.uniform(-2.5, 2.5);
      // Half the bodies as plain spheres (centre + radius only), half as shaped particles.
      bodies[i] = t % 2 ? Body<D>::of_particle(ps[i], i) : Body<D>::sphere(ps[i].pose.position, ps[i].bounding_radius(), i);
    }
    const double r = log_uniform(rng, 0.3, 3);
    Out<D> a, m;
    const int na = analytic.solve(bodies, plain_sphere<D>(r), a);
    const int nm = solver.solve(bodies, Mobile<D>::of_shape(std::make_shared<SphereShape<D>>(r), Mat<D>::Identity()), m);
    analytic_total += na;
    for (int q = 0; q < nm; ++q) {
      const auto [k, dist] = closest<D>(first<D>(a, na), m[q].position);
      if (k >= 0 && dist <= 1e-6 * r) ++found;
      else ++extra;
      EXPECT_TRUE(k >= 0 && dist <= 1e-6 * r) << "minimisation position " << vec_literal<D>(m[q].position)
                                              << " is no analytic solution (nearest at " << dist << ")";
    }
  }
  const double fraction = analytic_total ? double(found) / analytic_total : 0;
  std::printf("  %dD: %d analytic solutions, minimisation found %d (%.1f %%), %d not analytic\n", D, analytic_total, found,
              100 * fraction, extra);
  EXPECT_GT(analytic_total, trials / 2);
  return fraction;
}

// Measured: 2D 100 %, 3D 99.x % (printed). The floor of 95 % guards against a regression of the
// starting points (equivalent spheres) without being brittle.
TEST(MinimisationSolver, SpheresAgreeWithAnalyticSolver2D) { EXPECT_GE(analytic_agreement<2>(400, 301), 0.95); }
TEST(MinimisationSolver, SpheresAgreeWithAnalyticSolver3D) { EXPECT_GE(analytic_agreement<3>(400, 302), 0.95); }

// =========================================================== 3. brute-force count of solutions

// Capsule / polygon / ellipse mobiles against two fixed convex particles at random gaps (0 to
// 1.5 mobile diameters, as neighbours on a front are): the brute-force solutions are the
// crossings of the two touching contours. Every returned position must be one of them (and pass
// the independent gap check); the fraction of isolated crossings found is printed and asserted.
TEST(MinimisationSolver, FindsTheBruteForceSolutions2D) {
  const auto t0 = Clock::now();
  NarrowPhase<2> np;
  MinimisationSolver<2> solver(np, MinimisationOptions{});
  Rng rng(404);
  const Kind mobiles[] = {Kind::Capsule, Kind::Polytope, Kind::Ellipsoid};
  const Kind fixeds[] = {Kind::Sphere, Kind::Capsule, Kind::Polytope, Kind::Ellipsoid};
  int configs = 0, ambiguous = 0, all_found = 0, reference_total = 0, matched_total = 0;
  std::array<int, 8> histogram{};
  for (int trial = 0; trial < 150; ++trial) {
    Problem<2> pb;
    if (!gapped_pair_problem(pb, np, fixeds[rng.below(4)], fixeds[rng.below(4)], mobiles[rng.below(3)], rng)) continue;
    double angle = 180;
    const std::vector<Vec2> ref = brute_force_crossings(pb, angle);
    const double r_mob = pb.mobile_shape->bounding_radius();
    bool isolated = angle > 2;
    for (std::size_t i = 0; i < ref.size(); ++i)
      for (std::size_t j = i + 1; j < ref.size(); ++j) isolated &= (ref[i] - ref[j]).norm() > 2e-2 * r_mob;

    Out<2> out;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    ASSERT_TRUE(check_placements<2>(pb, first<2>(out, n), 1e-6)) << "trial " << trial;
    // Every returned position is a brute-force crossing (distinct ones).
    std::vector<bool> used(ref.size(), false);
    int matched = 0;
    for (int q = 0; q < n; ++q) {
      int best = -1;
      double bd = 0;
      for (std::size_t k = 0; k < ref.size(); ++k)
        if (!used[k] && (best < 0 || (ref[k] - out[q].position).norm() < bd)) best = static_cast<int>(k), bd = (ref[k] - out[q].position).norm();
      EXPECT_TRUE(best >= 0 && bd <= 1e-3 * r_mob)
          << "trial " << trial << ": solution " << vec_literal<2>(out[q].position) << " is no brute-force crossing (nearest "
          << bd << ", " << ref.size() << " crossings)" << pb.literal();
      if (best >= 0 && bd <= 1e-3 * r_mob) used[best] = true, ++matched;
    }
    ++configs;
    if (!isolated) { ++ambiguous; continue; }
    ++histogram[std::min<std::size_t>(ref.size(), 7)];
    reference_total += static_cast<int>(ref.size());
    matched_total += matched;
    all_found += matched == static_cast<int>(ref.size());
  }
  const int counted = configs - ambiguous;
  const double recall = reference_total ? double(matched_total) / reference_total : 1;
  const double complete = counted ? double(all_found) / counted : 0;
  std::printf("  %d configurations (%d near-tangent, not counted); crossings per configuration:", configs, ambiguous);
  for (int k = 0; k < 8; ++k)
    if (histogram[k]) std::printf(" %d:%d", k, histogram[k]);
  std::printf("\n  brute-force solutions found: %d / %d (%.1f %%); configurations with every solution found: %.1f %%  (%.2f s)\n",
              matched_total, reference_total, 100 * recall, 100 * complete, seconds_since(t0));
  EXPECT_GT(counted, 100);
  // Measured (printed above); floors below the measurement. Misses are configurations with four
  // crossings (two per side: the solver starts once per side) and far-off second solutions.
  EXPECT_GE(recall, 0.85);
  EXPECT_GE(complete, 0.75);
}

// ======================================================================== 4. failures reported

// Fixed bodies further apart than the mobile's diameter: nothing can touch them all; the solver
// returns 0 (never a position). Walls too far from the particles likewise.
TEST(MinimisationSolver, FarApartReturnsNothing) {
  NarrowPhase<2> np2;
  NarrowPhase<3> np3;
  MinimisationSolver<2> s2(np2, MinimisationOptions{});
  MinimisationSolver<3> s3(np3, MinimisationOptions{});
  Rng rng(44);
  const Kind kinds[] = {Kind::Sphere, Kind::Capsule, Kind::Polytope, Kind::Ellipsoid, Kind::Cluster};
  int returned = 0;
  for (int t = 0; t < 60; ++t) {
    {
      Problem<2> pb;
      pb.mobile_shape = random_shape<2>(kinds[rng.below(5)], 1.0, rng);
      pb.mobile_rotation = random_rotation<2>(rng);
      const double reach = 2 * pb.mobile_shape->bounding_radius();
      Particle<2> a, b;
      a.shape = random_shape<2>(kinds[rng.below(5)], log_uniform(rng, 0.5, 2), rng);
      b.shape = random_shape<2>(kinds[rng.below(5)], log_uniform(rng, 0.5, 2), rng);
      a.pose.rotation = random_rotation<2>(rng);
      b.pose.rotation = random_rotation<2>(rng);
      b.pose.position = (a.bounding_radius() + b.bounding_radius() + reach * rng.uniform(1.01, 3)) * random_unit<2>(rng);
      pb.set_particle(0, a);
      if (t % 3 == 0) {
        // A plane wall (container side towards a) beyond the mobile's reach from a.
        const Vec2 dir = random_unit<2>(rng);
        pb.set_wall(1, Wall<2>::plane(a.pose.position + (a.bounding_radius() + reach * rng.uniform(1.01, 3)) * dir, -dir));
      } else {
        pb.set_particle(1, b);
      }
      Out<2> out;
      const int n = s2.solve(pb.span(), pb.mobile(), out);
      returned += n;
      EXPECT_EQ(n, 0) << pb.literal();
    }
    {
      Problem<3> pb;
      pb.mobile_shape = random_shape<3>(kinds[rng.below(5)], 1.0, rng);
      pb.mobile_rotation = random_rotation<3>(rng);
      const double reach = 2 * pb.mobile_shape->bounding_radius();
      std::array<Particle<3>, 3> ps;
      for (int i = 0; i < 3; ++i) {
        ps[i].shape = random_shape<3>(kinds[rng.below(5)], log_uniform(rng, 0.5, 2), rng);
        ps[i].pose.rotation = random_rotation<3>(rng);
      }
      // Pairwise further apart than bounding radii + the mobile's diameter.
      const double spread = 2 * 2 + reach * rng.uniform(1.01, 3);
      ps[1].pose.position = Vec3(spread, 0, 0);
      ps[2].pose.position = Vec3(spread / 2, spread, rng.uniform(-1, 1));
      for (int i = 0; i < 3; ++i) pb.set_particle(i, ps[i]);
      Out<3> out;
      const int n = s3.solve(pb.span(), pb.mobile(), out);
      returned += n;
      EXPECT_EQ(n, 0) << pb.literal();
    }
  }
  EXPECT_EQ(returned, 0);
}

// Coincident centres (2D: two particles on the same reference point; 3D: two of three) and
// collinear centres (3D): no hyperplane through the centres, so the solver returns 0 or
// positions that pass the independent check, never anything else.
TEST(MinimisationSolver, DegenerateConfigurationsReturnValidPositionsOnly) {
  NarrowPhase<2> np2;
  NarrowPhase<3> np3;
  MinimisationSolver<2> s2(np2, MinimisationOptions{});
  MinimisationSolver<3> s3(np3, MinimisationOptions{});
  Rng rng(55);
  const Kind kinds[] = {Kind::Sphere, Kind::Capsule, Kind::Polytope, Kind::Ellipsoid};
  int positions = 0;
  for (int t = 0; t < 40; ++t) {
    {
      Problem<2> pb;
      pb.mobile_shape = random_shape<2>(kinds[rng.below(4)], 1.0, rng);
      pb.mobile_rotation = random_rotation<2>(rng);
      for (int i = 0; i < 2; ++i) {
        Particle<2> p;
        p.shape = random_shape<2>(kinds[rng.below(4)], log_uniform(rng, 0.5, 2), rng);
        p.pose.rotation = random_rotation<2>(rng);
        p.pose.position = Vec2(1.5, -2);  // both on the same point
        pb.set_particle(i, p);
      }
      Out<2> out;
      const int n = s2.solve(pb.span(), pb.mobile(), out);
      positions += n;
      EXPECT_TRUE(check_placements<2>(pb, first<2>(out, n), 1e-6));
    }
    {
      Problem<3> pb;
      pb.mobile_shape = random_shape<3>(kinds[rng.below(4)], 1.0, rng);
      pb.mobile_rotation = random_rotation<3>(rng);
      const Vec3 axis = random_unit<3>(rng);
      for (int i = 0; i < 3; ++i) {
        Particle<3> p;
        p.shape = random_shape<3>(kinds[rng.below(4)], log_uniform(rng, 0.5, 1.5), rng);
        p.pose.rotation = random_rotation<3>(rng);
        // t even: collinear centres 1.5 apart; t odd: the first two coincide.
        p.pose.position = t % 2 ? Vec3((i == 2 ? 1.8 : 0.0) * axis) : Vec3((i - 1) * 1.5 * axis);
        pb.set_particle(i, p);
      }
      Out<3> out;
      const int n = s3.solve(pb.span(), pb.mobile(), out);
      positions += n;
      EXPECT_TRUE(check_placements<3>(pb, first<3>(out, n), 1e-6));
    }
  }
  std::printf("  degenerate configurations: %d positions returned, all valid\n", positions);
}

// ================================================================================= 5. extremes

// Spherocylinders of aspect ratio 0.05 (width / length; equivalently length / width = 20) as
// the mobile, as the fixed particles and both. Thin capsules touching thin capsules have many
// solutions (up to four crossings per side of the centres' hyperplane) and the solver starts once
// per side from equivalent spheres, so it often returns another solution than the constructed
// one: asserted is that every position is valid and that most problems get one (measured and
// printed: known-position recall 15-90 %, solved 60-100 %).
TEST(MinimisationSolver, ThinCapsules) {
  Sizes s;
  s.jitter = 1.2;
  std::vector<Tally> t;
  t.push_back(run_constructed<2>("thin capsule | capsule capsule", Kind::ThinCapsule, {Kind::Capsule, Kind::Capsule}, 30, 501, s));
  t.push_back(run_constructed<2>("capsule | thin capsule x2", Kind::Capsule, {Kind::ThinCapsule, Kind::ThinCapsule}, 30, 502, s));
  t.push_back(run_constructed<2>("thin capsule | thin capsule x2", Kind::ThinCapsule, {Kind::ThinCapsule, Kind::ThinCapsule}, 30, 503, s));
  t.push_back(run_constructed<3>("thin capsule | capsule x3", Kind::ThinCapsule, {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 20, 504, s));
  t.push_back(run_constructed<3>("capsule | thin capsule x3", Kind::Capsule, {Kind::ThinCapsule, Kind::ThinCapsule, Kind::ThinCapsule}, 20, 505, s));
  t.push_back(run_constructed<3>("thin capsule | thin capsule x3", Kind::ThinCapsule,
                                 {Kind::ThinCapsule, Kind::ThinCapsule, Kind::ThinCapsule}, 20, 506, s));
  for (const Tally& x : t) EXPECT_GE(x.solved(), 0.5);
}

// Size ratio 1:100: a tiny mobile among big fixed particles (which then overlap each other: a
// tiny particle cannot touch three big disjoint ones) and a big mobile against tiny ones. The
// tolerance is relative to the smaller size, so the tiny body sets it.
TEST(MinimisationSolver, SizeRatioOneToHundred) {
  Sizes tiny_mobile;
  tiny_mobile.mobile = 0.01;
  tiny_mobile.jitter = 1.1;
  tiny_mobile.allow_fixed_overlap = true;
  Sizes big_mobile;
  big_mobile.fixed = {0.01, 0.01, 0.01};
  big_mobile.jitter = 1.1;
  std::vector<Tally> t;
  t.push_back(run_constructed<2>("tiny capsule | capsule capsule", Kind::Capsule, {Kind::Capsule, Kind::Capsule}, 25, 601, tiny_mobile));
  t.push_back(run_constructed<2>("big capsule | tiny capsule x2", Kind::Capsule, {Kind::Capsule, Kind::Capsule}, 25, 602, big_mobile));
  t.push_back(run_constructed<2>("tiny polygon | polygon ellipse", Kind::Polytope, {Kind::Polytope, Kind::Ellipsoid}, 25, 603, tiny_mobile));
  t.push_back(run_constructed<2>("big polygon | tiny polygon ellipse", Kind::Polytope, {Kind::Polytope, Kind::Ellipsoid}, 25, 604, big_mobile));
  t.push_back(run_constructed<3>("tiny capsule | capsule x3", Kind::Capsule, {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 20, 605, tiny_mobile));
  t.push_back(run_constructed<3>("big capsule | tiny capsule x3", Kind::Capsule, {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 20, 606, big_mobile));
  t.push_back(run_constructed<3>("tiny polyhedron | polyhedron x3", Kind::Polytope, {Kind::Polytope, Kind::Polytope, Kind::Polytope}, 15, 607, tiny_mobile));
  t.push_back(run_constructed<3>("big polyhedron | tiny polyhedron x3", Kind::Polytope, {Kind::Polytope, Kind::Polytope, Kind::Polytope}, 15, 608, big_mobile));
  for (const Tally& x : t) EXPECT_GE(x.solved(), 0.5);
}

/// The same problems translated by (1e6, -1e6, 1e6): the solutions, relative to the offset, are
/// solutions of the original problem within the gap tolerance times the size (independent check
/// in the original frame), and the original solutions to 1e-5 of the size (a position is fixed
/// to the gap tolerance divided by the conditioning of the contact normals; measured <= 3e-6).
template <int D>
void offset_round(const char* name, Kind mobile, const std::array<Kind, D>& fixed, int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  MinimisationSolver<D> solver(np, MinimisationOptions{});
  Rng rng(seed);
  Vec<D> offset;
  for (int a = 0; a < D; ++a) offset[a] = a % 2 ? -1e6 : 1e6;
  int same_count = 0, built = 0, compared = 0;
  double worst = 0;
  for (int t = 0; t < trials; ++t) {
    Problem<D> pb;
    if (!construct_problem<D>(pb, np, mobile, fixed, Sizes{}, rng)) continue;
    ++built;
    const Problem<D> far = pb.translated(offset);
    Out<D> o1, o2;
    const int n1 = solver.solve(pb.span(), pb.mobile(), o1);
    const int n2 = solver.solve(far.span(), far.mobile(), o2);
    EXPECT_TRUE(check_placements<D>(far, first<D>(o2, n2), 1e-6)) << name << far.literal();
    Out<D> back;
    for (int q = 0; q < n2; ++q) back[q].position = o2[q].position - offset;
    EXPECT_TRUE(check_placements<D>(pb, first<D>(back, n2), 1e-6)) << name << " (offset solutions moved back)" << pb.literal();
    same_count += n1 == n2;
    const double size = pb.mobile_shape->bounding_radius();
    for (int q = 0; q < n2; ++q) {
      const auto [k, dist] = closest<D>(first<D>(o1, n1), back[q].position);
      if (k < 0) continue;
      ++compared;
      worst = std::max(worst, dist / size);
      EXPECT_LE(dist, 1e-5 * size) << name << far.literal();
    }
  }
  std::printf("  %dD %-30s offset 1e6: %d problems, same count in %d, %d positions compared, worst shift %.1e of size\n", D, name,
              built, same_count, compared, worst);
  EXPECT_GE(same_count, built * 8 / 10);
}

TEST(MinimisationSolver, CoordinatesOffsetByAMillion) {
  offset_round<2>("capsule | capsule capsule", Kind::Capsule, {Kind::Capsule, Kind::Capsule}, 25, 701);
  offset_round<2>("polygon | polygon ellipse", Kind::Polytope, {Kind::Polytope, Kind::Ellipsoid}, 25, 702);
  offset_round<3>("capsule | capsule x3", Kind::Capsule, {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 20, 703);
  offset_round<3>("polyhedron | polyhedron sphere cluster", Kind::Polytope, {Kind::Polytope, Kind::Sphere, Kind::Cluster}, 15, 704);
  offset_round<3>("ellipsoid | ellipsoid x3", Kind::Ellipsoid, {Kind::Ellipsoid, Kind::Ellipsoid, Kind::Ellipsoid}, 15, 705);
}

// ============================================================================ 8. all algorithms

// Every algorithm the options accept solves a simple capsule case: gradient methods (Σω²) with
// the default budget, derivative-free ones (Σ|ω|, the paper's form) with a larger one.
// The names come from minimisation_algorithms(), so a new algorithm is covered here at once.
TEST(MinimisationSolver, EveryAlgorithmSolvesCapsules) {
  std::vector<std::string> names;
  for (std::string list = minimisation_algorithms(); !list.empty();) {
    const std::size_t comma = list.find(',');
    std::string name = list.substr(0, comma);
    name.erase(0, name.find_first_not_of(' '));
    names.push_back(name);
    list = comma == std::string::npos ? "" : list.substr(comma + 1);
  }
  for (const char* required : {"slsqp", "lbfgs", "nelder-mead", "cobyla", "sbplx"})
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  for (const std::string& name_s : names) {
    const char* name = name_s.c_str();
    MinimisationOptions opt;
    opt.algorithm = name;
    const bool derivative_free = name_s == "nelder-mead" || name_s == "cobyla" || name_s == "sbplx";
    opt.max_evaluations = derivative_free ? 3000 : 200;
    const std::string n2 = std::string(name) + ": capsule | capsule x2";
    const std::string n3 = std::string(name) + ": capsule | capsule x3";
    const Tally t2 = run_constructed<2>(n2.c_str(), Kind::Capsule, {Kind::Capsule, Kind::Capsule}, 15, 801, Sizes{}, opt);
    const Tally t3 = run_constructed<3>(n3.c_str(), Kind::Capsule, {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 15, 802, Sizes{}, opt);
    EXPECT_GE(t2.known_recall(), 0.6) << name;
    EXPECT_GE(t3.known_recall(), 0.6) << name;
  }
  NarrowPhase<2> np;
  MinimisationOptions unknown;
  unknown.algorithm = "gradient-descent";
  EXPECT_THROW(MinimisationSolver<2>(np, unknown), std::invalid_argument);
}

}  // namespace
}  // namespace fp::general_test
