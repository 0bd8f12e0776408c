// The validation and the analysis on several threads give what one thread gives, exactly: the
// report (counts, maxima, the worst issues), the contact network, every figure of the analysis
// JSON, g(r); and for_each_part runs every part once and passes on a part's exception.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/geometry/box_container.hpp"
#include "core/io/analysis_json.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/radial_distribution.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "core/system/parallel_parts.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

// A dense jittered FCC (every site touching or nearly touching twelve), with defects planted
// so that the worst-issue list overflows: overlaps, particles outside, a NaN and a bad radius.
Packing<3> packing_with_defects() {
  Packing<3> p = test::jittered_fcc(8, 5);
  for (std::size_t i = 0; i < p.size(); i += 37) p.radii[i] *= 1.2;  // overlaps with neighbours
  p.centers[11] = Vec3(-3, 4, 4);                                    // outside
  p.centers[12][2] = std::numeric_limits<double>::quiet_NaN();
  p.radii[13] = 0.9;                                                 // out of range of U[0.6, 0.71]
  return p;
}

void expect_same_report(const ValidationReport& a, const ValidationReport& b) {
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_EQ(a.pairs_checked, b.pairs_checked);
  EXPECT_EQ(a.max_overlap_rel, b.max_overlap_rel);
  EXPECT_EQ(a.max_outside_rel, b.max_outside_rel);
  EXPECT_EQ(a.overlap_count, b.overlap_count);
  EXPECT_EQ(a.outside_count, b.outside_count);
  EXPECT_EQ(a.radius_count, b.radius_count);
  EXPECT_EQ(a.non_finite_count, b.non_finite_count);
  EXPECT_EQ(a.contacts, b.contacts);
  EXPECT_EQ(a.wall_contacts, b.wall_contacts);
  EXPECT_EQ(a.max_contact_gap_rel, b.max_contact_gap_rel);
  EXPECT_EQ(a.radii().statistic, b.radii().statistic);
  EXPECT_EQ(a.radii().p, b.radii().p);
  ASSERT_EQ(a.worst.size(), b.worst.size());
  for (std::size_t k = 0; k < a.worst.size(); ++k) {
    EXPECT_EQ(a.worst[k].kind, b.worst[k].kind);
    EXPECT_EQ(a.worst[k].i, b.worst[k].i);
    EXPECT_EQ(a.worst[k].j, b.worst[k].j);
    EXPECT_EQ(a.worst[k].value_rel, b.worst[k].value_rel);
  }
  EXPECT_EQ(a.summary(), b.summary());
}

TEST(Threads, ValidationReportAndNetworkAreTheSameForEveryThreadCount) {
  const Packing<3> p = packing_with_defects();
  const BoxContainer<3> box(Vec3::Constant(-0.75), Vec3::Constant(15.75));
  const UniformRadius dist(0.6, 0.71);
  ContactNetwork<3> one;
  const ValidationReport single = validate_packing<3>(p, box, &dist, 1e-9, kRadiiAlpha, &one, 1);
  EXPECT_FALSE(single.ok);
  EXPECT_GT(single.overlap_count, 20u);  // more issues than the report keeps: the merge must pick the same 20
  EXPECT_EQ(single.worst.size(), 20u);
  EXPECT_GE(single.outside_count, 1u);
  EXPECT_EQ(single.non_finite_count, 1u);
  EXPECT_GE(single.radius_count, 1u);
  EXPECT_EQ(one.pairs.size(), single.contacts);
  EXPECT_TRUE(one.normals.empty());  // spheres: the centre lines
  for (const int threads : {2, 3, 8}) {
    ContactNetwork<3> many;
    const ValidationReport r = validate_packing<3>(p, box, &dist, 1e-9, kRadiiAlpha, &many, threads);
    expect_same_report(single, r);
    ASSERT_EQ(many.pairs.size(), one.pairs.size()) << threads << " threads";
    for (std::size_t k = 0; k < one.pairs.size(); ++k) {
      EXPECT_EQ(many.pairs[k].i, one.pairs[k].i);
      EXPECT_EQ(many.pairs[k].j, one.pairs[k].j);
      EXPECT_EQ(many.pairs[k].gap, one.pairs[k].gap);
    }
    ASSERT_EQ(many.walls.size(), one.walls.size());
    for (std::size_t k = 0; k < one.walls.size(); ++k) {
      EXPECT_EQ(many.walls[k].i, one.walls[k].i);
      EXPECT_EQ(many.walls[k].gap, one.walls[k].gap);
    }
  }
}

TEST(Threads, AnalysisIsTheSameForEveryThreadCount) {
  const Packing<3> p = test::jittered_fcc(9, 6);
  const BoxContainer<3> box(Vec3::Constant(-0.75), Vec3::Constant(17.75));
  const UniformRadius dist(0.6, 0.71);
  AnalysisOptions o;
  const std::string single = analysis_json(analyze_packing<3>(p, &box, &dist, o));
  for (const int threads : {2, 5}) {
    o.threads = threads;
    EXPECT_EQ(analysis_json(analyze_packing<3>(p, &box, &dist, o)), single) << threads << " threads";
  }
  // Without the validation the contacts are found by the analysis itself: the same figures.
  o.validate = false;
  o.threads = 1;
  const std::string unvalidated = analysis_json(analyze_packing<3>(p, &box, &dist, o));
  o.threads = 4;
  EXPECT_EQ(analysis_json(analyze_packing<3>(p, &box, &dist, o)), unvalidated);
  const auto lat = test::hexagonal(60, 60, 1.0, Vec2::Zero());
  AnalysisOptions o2;
  const std::string flat = analysis_json(analyze_packing<2>(lat.packing, nullptr, nullptr, o2));
  o2.threads = 3;
  EXPECT_EQ(analysis_json(analyze_packing<2>(lat.packing, nullptr, nullptr, o2)), flat);
}

TEST(Threads, RadialDistributionIsTheSameForEveryThreadCount) {
  const Packing<3> p = test::jittered_fcc(10, 7);
  const BoxContainer<3> box(Vec3::Constant(-0.75), Vec3::Constant(19.75));
  const RadialDistribution one = radial_distribution<3>(p, box, {}, 1);
  EXPECT_GT(one.reference_particles, 100u);
  for (const int threads : {2, 7}) {
    const RadialDistribution many = radial_distribution<3>(p, box, {}, threads);
    EXPECT_EQ(many.g, one.g);
    EXPECT_EQ(many.reference_particles, one.reference_particles);
  }
}

TEST(Threads, EveryPartRunsOnceAndAnErrorIsPassedOn) {
  for (const int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> runs(1000);
    for_each_part(runs.size(), threads, [&](std::size_t k) { ++runs[k]; });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
    EXPECT_THROW(for_each_part(100, threads,
                               [](std::size_t k) {
                                 if (k == 40) throw std::runtime_error("part 40");
                               }),
                 std::runtime_error);
  }
  for_each_part(0, 4, [](std::size_t) { FAIL() << "no part to run"; });
  EXPECT_EQ(thread_count(3), 3);
  EXPECT_GE(thread_count(0), 1);
}

}  // namespace
}  // namespace fp
