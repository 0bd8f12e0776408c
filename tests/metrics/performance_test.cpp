// Timing of contact_stats, validate and the reference-sphere VF on large packings (printed, not asserted: the machine is
// shared). The 1,000,000-sphere case is disabled; run it with --gtest_also_run_disabled_tests.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "core/geometry/box_container.hpp"
#include "core/metrics/contact_stats.hpp"
#include "core/metrics/validate.hpp"
#include "core/metrics/volume_fraction.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// 4 n^3 spheres on a jittered FCC lattice: dense, every sphere has 12 near neighbours.
void run(int n) {
  const auto p = test::jittered_fcc(n, 1234);
  const BoxContainer<3> box(Vec3::Constant(-1.0), Vec3::Constant(2.0 * n));
  auto t0 = std::chrono::steady_clock::now();
  // Tolerance 0.25 reaches every FCC neighbour (gaps <= 0.15): 12 contacts in the bulk.
  const ContactStats s = contact_stats<3>(p, &box, 0.25);
  const double t_contacts = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const ValidationReport rep = validate_packing<3>(p, box, nullptr);
  const double t_validate = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const double vf = vf_reference_sphere<3>(p, Vec3::Constant(n - 0.5), n - 1.0);
  const double t_vf = seconds_since(t0);
  std::printf("[ perf ] %zu spheres: contact_stats %.3f s (%llu contacts, z %.2f), validate %.3f s (%llu pairs), "
              "vf_reference_sphere %.3f s (vf %.3f)\n",
              p.size(), t_contacts, static_cast<unsigned long long>(s.contacts), s.mean_coordination, t_validate,
              static_cast<unsigned long long>(rep.pairs_checked), t_vf, vf);
  EXPECT_TRUE(rep.ok) << rep.summary();
  EXPECT_GT(s.mean_coordination, 11.0);
  EXPECT_GT(rep.pairs_checked, 5 * p.size());
}

TEST(MetricsPerformance, TwoHundredThousandSpheres) { run(37); }   // 202,612 spheres

TEST(MetricsPerformance, DISABLED_OneMillionSpheres) { run(63); }  // 1,000,188 spheres

TEST(MetricsPerformance, WideRadiusRatio) {
  // Big spheres (r = 5) on a coarse lattice, small ones (r = 0.1 .. 0.2) filling the gaps
  // between them: r_max / r_min = 50.
  Packing<3> p;
  Rng rng(99);
  const int n = 12;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) p.add(Vec3(12.0 * i, 12.0 * j, 12.0 * k), 5.0);
  const std::size_t big = p.size();
  for (int i = 0; p.size() < 200000; ++i) {
    const Vec3 c(rng.uniform(0, 12.0 * n), rng.uniform(0, 12.0 * n), rng.uniform(0, 12.0 * n));
    const Vec3 nearest_big = (c / 12.0).array().round().matrix() * 12.0;
    if ((c - nearest_big).norm() > 5.3) p.add(c, rng.uniform(0.1, 0.2));
  }
  auto t0 = std::chrono::steady_clock::now();
  const ContactStats s = contact_stats<3>(p, nullptr, 0.2);
  const double t_contacts = seconds_since(t0);
  const BoxContainer<3> box(Vec3::Constant(-6.0), Vec3::Constant(12.0 * n));
  t0 = std::chrono::steady_clock::now();
  const ValidationReport rep = validate_packing<3>(p, box, nullptr);
  const double t_validate = seconds_since(t0);
  std::printf("[ perf ] wide ratio, %zu spheres (%zu big): contact_stats %.3f s (%llu contacts), validate %.3f s "
              "(%llu pairs)\n",
              p.size(), big, t_contacts, static_cast<unsigned long long>(s.contacts), t_validate,
              static_cast<unsigned long long>(rep.pairs_checked));
  EXPECT_GT(s.contacts, 0u);
  EXPECT_GT(rep.overlap_count, 0u);  // the small spheres were placed without looking at each other
}

}  // namespace
}  // namespace fp
