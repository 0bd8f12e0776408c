// The whole analysis (packing_analysis.hpp: papers 000 Eqs. 15-17 and 002 Eqs. 1-2, Sect. 4-5)
// on lattices whose figures are known in closed form,
// without a container, with a distribution, and on an empty packing; the verdict `pack` reads
// from it is validate's, at the packer's allowance (tol x the smaller radius).
#include "core/metrics/packing_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/box_container.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

TEST(PackingAnalysis, SimpleCubicInATightBox) {
  const int n = 12;
  const auto lat = test::simple_cubic(n, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(n - 0.5));
  const PackingAnalysis a = analyze_packing<3>(lat.packing, &box, nullptr);
  EXPECT_EQ(a.dimension, 3);
  EXPECT_EQ(a.particles, std::uint64_t(n * n * n));
  EXPECT_EQ(a.r_min, 0.5);
  EXPECT_EQ(a.r_max, 0.5);
  EXPECT_FALSE(a.container_from_particles);
  EXPECT_EQ(a.contact_tolerance, 1e-9);

  // VF: the lattice tiles the box, and the core (shrunk by 2 r_max = 1) is 10 whole cells.
  EXPECT_TRUE(a.vf_container.exact);
  EXPECT_NEAR(a.vf_container.vf.value, kPi / 6.0, 1e-14);
  EXPECT_TRUE(a.vf_core.exact);
  EXPECT_EQ(a.vf_core.shrink, 1.0);
  EXPECT_NEAR(a.vf_core.vf.value, kPi / 6.0, 1e-14);
  // Paper 002 Sect. 5: 31 radii from r_max to a, half the side, about the centre.
  EXPECT_EQ(a.reference_center, (std::vector<double>{5.5, 5.5, 5.5}));
  EXPECT_EQ(a.reference_radius, 6.0);
  ASSERT_EQ(a.vf_curve.size(), 31u);
  EXPECT_EQ(a.vf_curve.front().first, 0.5);
  EXPECT_EQ(a.vf_curve.back().first, 6.0);
  EXPECT_EQ(a.vf_reference, a.vf_curve.back().second);
  EXPECT_NEAR(a.vf_reference, kPi / 6.0, 0.01);

  // Contacts: 6 in the bulk, one wall contact per surface particle, no rattler.
  EXPECT_EQ(a.coordination.contacts, std::uint64_t(3 * n * n * (n - 1)));
  EXPECT_DOUBLE_EQ(a.coordination.mean_coordination, 6.0 * (n - 1) / n);
  EXPECT_EQ(a.coordination.wall_contacts, std::uint64_t(n * n * n - (n - 2) * (n - 2) * (n - 2)));
  EXPECT_EQ(a.coordination.rattlers, 0u);
  EXPECT_EQ(a.coordination.histogram[6], std::uint64_t((n - 2) * (n - 2) * (n - 2)));
  EXPECT_DOUBLE_EQ(a.partial_coordination.z.front(), a.coordination.mean_coordination);
  EXPECT_LE(a.max_overlap_rel, 1e-12);
  EXPECT_LE(a.max_contact_gap_rel, 1e-12);
  for (const double e : a.fabric.per_contact.eigenvalues) EXPECT_NEAR(e, 1.0 / 3.0, 1e-12);
  for (const double e : a.fabric.per_particle.eigenvalues) EXPECT_NEAR(e, 1.0 / 3.0, 1e-12);
  for (const KsResult& k : a.projections.ks) EXPECT_NEAR(k.d, 2.0 / 3.0, 1e-15);

  // Homogeneity: the centres 1 .. n-2 of the core (the box less 2 r_max = 1) against uniform on
  // [0.5, n - 1.5]: F_n reaches k / (n - 2) at site k where F is (k - 1/2) / (n - 2), D = 1/(2(n - 2)).
  for (const KsResult& k : a.homogeneity.axis) {
    EXPECT_EQ(k.n, std::uint64_t((n - 2) * (n - 2) * (n - 2)));
    EXPECT_NEAR(k.d, 0.5 / (n - 2), 1e-15);
  }
  EXPECT_EQ(a.homogeneity.reference_points, 0u);  // a box: exact
  EXPECT_FALSE(a.radii_fit.computed());
  EXPECT_EQ(a.distribution, "");

  // g(r): nothing closer than one diameter, 6 neighbours there.
  ASSERT_GT(a.rdf.reference_particles, 0u);
  const auto first = std::find_if(a.rdf.g.begin(), a.rdf.g.end(), [](double g) { return g > 0.0; }) - a.rdf.g.begin();
  EXPECT_NEAR(a.rdf.r[first], 1.025, 1e-12);  // bin [1, 1.05)
  EXPECT_NEAR(a.rdf.g[first] * a.rdf.density * (ball_measure<3>(1.05) - ball_measure<3>(1.0)), 6.0, 1e-9);

  ASSERT_TRUE(a.validation.has_value());
  EXPECT_TRUE(a.validation->ok);
  EXPECT_GE(a.timings.size(), 6u);
  const std::string s = a.summary();
  for (const char* key : {"VF reference ball    0.52", "VF core              0.523599 (exact), 2 r_max = 1 inside",
                          "coordination z       5.5000",
                          "fabric per contact   (0.3333, 0.3333, 0.3333)", "validate: OK"})
    EXPECT_NE(s.find(key), std::string::npos) << key << "\n" << s;
}

TEST(PackingAnalysis, HexagonalDisksWithoutAContainer) {
  const auto lat = test::hexagonal(60, 50, 1.0, Vec2(3.0, -2.0));
  const PackingAnalysis a = analyze_packing<2>(lat.packing, nullptr, nullptr);
  EXPECT_EQ(a.dimension, 2);
  EXPECT_TRUE(a.container_from_particles);
  EXPECT_EQ(a.container.rfind("rectangle", 0), 0u) << a.container;
  EXPECT_EQ(a.coordination.histogram.size(), 7u);
  EXPECT_GT(a.coordination.histogram[6], lat.packing.size() / 2);
  EXPECT_NEAR(a.vf_reference, kPi / (2.0 * std::sqrt(3.0)), 0.01);
  EXPECT_NEAR(a.vf_core.vf.value, kPi / (2.0 * std::sqrt(3.0)), 0.01);
  for (const double e : a.fabric.per_contact.eigenvalues) EXPECT_NEAR(e, 0.5, 0.01);
  EXPECT_EQ(a.fabric.per_contact.tensor.size(), 4u);
  EXPECT_EQ(a.homogeneity.axis.size(), 2u);
  EXPECT_EQ(a.projections.histogram.size(), 2u);
  ASSERT_TRUE(a.validation.has_value());
  EXPECT_TRUE(a.validation->ok) << a.validation->summary();
}

TEST(PackingAnalysis, RadiiAgainstTheRequestedDistribution) {
  const auto p = test::jittered_lattice<3>(15, 0.5, 0.9, 0.05, 17, 1.0);  // sites 1, 3, .., 29
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(30.0));
  const UniformRadius dist(0.5, 0.9);
  AnalysisOptions o;
  o.contact_tolerance = 0.25;  // the lattice has gaps; a wide tolerance makes a network
  const PackingAnalysis a = analyze_packing<3>(p, &box, &dist, o);
  EXPECT_EQ(a.distribution, dist.describe());
  EXPECT_EQ(a.radii_fit.n, p.size());
  EXPECT_EQ(a.radii_fit.test, "K-S");
  EXPECT_EQ(a.radii_fit.statistic, a.validation->radii().statistic);
  EXPECT_EQ(a.radii_fit.p, a.validation->radii().p);
  EXPECT_GT(a.radii_fit.p, 0.01);
  // Without the validation the analysis runs the same test itself.
  o.validate = false;
  const PackingAnalysis b = analyze_packing<3>(p, &box, &dist, o);
  EXPECT_FALSE(b.validation.has_value());
  EXPECT_EQ(b.radii_fit.statistic, a.radii_fit.statistic);
  EXPECT_EQ(b.radii_fit.p, a.radii_fit.p);
  EXPECT_EQ(a.contact_tolerance, 0.25);
  EXPECT_EQ(a.validation->tolerance, 0.25);
  EXPECT_GT(a.coordination.contacts, 0u);
  EXPECT_GT(a.max_contact_gap_rel, 0.0);
  EXPECT_LE(a.max_contact_gap_rel, 0.25 * 0.9 / a.r_min);
  EXPECT_EQ(a.max_overlap_rel, 0.0);
  EXPECT_LT(a.vf_container.vf.value, a.vf_core.vf.value + 0.1);
  AnalysisOptions quiet = o;
  quiet.validate = false;
  EXPECT_FALSE(analyze_packing<3>(p, &box, &dist, quiet).validation.has_value());
}

// A box two particles wide has no core: the figures that need one say why instead of zeros.
TEST(PackingAnalysis, FiguresWithoutRoomSayWhy) {
  const auto lat = test::simple_cubic(2, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(1.5));
  const std::string s = analyze_packing<3>(lat.packing, &box, nullptr).summary();
  EXPECT_NE(s.find("K-S centres x        none: no centre lies 1 (2 r_max) inside the container"), std::string::npos) << s;
  EXPECT_NE(s.find("g(r)                 none: no centre lies"), std::string::npos) << s;
  EXPECT_NE(s.find("VF cells             none:"), std::string::npos) << s;
  EXPECT_EQ(s.find("nan"), std::string::npos) << s;
  EXPECT_EQ(s.find("0 reference particles"), std::string::npos) << s;
}

TEST(PackingAnalysis, EmptyPacking) {
  const PackingAnalysis none = analyze_packing<3>(Packing<3>{}, nullptr, nullptr);
  EXPECT_EQ(none.particles, 0u);
  EXPECT_TRUE(none.container.empty());
  const BoxContainer<2> rect(Vec2::Zero(), Vec2::Ones());
  const PackingAnalysis boxed = analyze_packing<2>(Packing<2>{}, &rect, nullptr);
  EXPECT_EQ(boxed.vf_container.vf.value, 0.0);
  EXPECT_EQ(boxed.coordination.contacts, 0u);
  EXPECT_FALSE(boxed.summary().empty());
}

}  // namespace
}  // namespace fp

namespace fp {
namespace {

// `frontpack pack` takes its verdict from analyze_packing(...).validation: crafted pairs of
// unequal radii overlapping by 0.8e-9 and 1.2e-9 of the smaller radius (0.5; r_min of the
// packing 0.4, so 0.8e-9 is 1.0e-9 r_min) pass and fail there exactly as in validate_packing.
TEST(PackingAnalysis, PacksVerdictIsValidatesAtTheSmallerRadius) {
  const DiscreteRadius dist({{0.4, 1.0}, {0.5, 1.0}, {0.6, 1.0}});
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(40.0));
  auto crafted = [](double of_smaller) {
    Packing<3> p;
    for (int k = 0; k < 300; ++k) p.add(Vec3(2.0 + 2.0 * (k % 15), 2.0 + 2.0 * (k / 15 % 15), 2.0 + 2.0 * (k / 225)),
                                        0.4 + 0.1 * (k % 3));
    p.radii[1] = 0.5;  // x-neighbours 1 (0.5) and 2 (0.6), pushed together
    p.centers[1] = p.centers[2] - Vec3(1.1 - of_smaller * 0.5, 0.0, 0.0);
    return p;
  };
  AnalysisOptions o;
  o.contact_tolerance = 1e-9;
  for (const double of_smaller : {0.8e-9, 1.2e-9}) {
    const Packing<3> p = crafted(of_smaller);
    const PackingAnalysis a = analyze_packing<3>(p, &box, &dist, o);
    const ValidationReport v = validate_packing<3>(p, box, &dist, 1e-9);
    ASSERT_TRUE(a.validation.has_value());
    EXPECT_EQ(a.validation->ok, of_smaller < 1e-9) << of_smaller << "\n" << a.validation->summary();
    EXPECT_EQ(a.validation->ok, v.ok);
    EXPECT_EQ(a.validation->max_overlap_rel, v.max_overlap_rel);
    EXPECT_NEAR(v.max_overlap_rel, of_smaller, 1e-13);
    EXPECT_EQ(a.radii_fit.test, "chi-square");
    EXPECT_TRUE(a.validation->sizes_ok());
  }
}

}  // namespace
}  // namespace fp
