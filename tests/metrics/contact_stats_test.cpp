// Contacts and coordination on lattices, where every particle's coordination is known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/geometry/box_container.hpp"
#include "core/metrics/contact_stats.hpp"
#include "core/metrics/contacts.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

template <int D>
void expect_lattice_coordination(const test::Lattice<D>& lat, std::uint32_t z_bulk) {
  const auto contacts = find_pair_contacts(lat.packing);
  const auto z = coordination_numbers(lat.packing.size(), contacts);
  const auto expected = lat.expected_coordination();
  ASSERT_EQ(z.size(), expected.size());
  std::size_t bulk = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    EXPECT_EQ(z[i], expected[i]) << "site " << i;
    bulk += expected[i] == z_bulk ? 1 : 0;
  }
  EXPECT_GT(bulk, z.size() / 3);  // the interior is really at the bulk value
  EXPECT_EQ(*std::max_element(z.begin(), z.end()), z_bulk);
  const ContactStats s = contact_stats<D>(lat.packing, nullptr);
  EXPECT_EQ(s.contacts, contacts.size());
  EXPECT_EQ(s.histogram.size(), z_bulk + 1);
  EXPECT_EQ(s.histogram[z_bulk], bulk);
  EXPECT_DOUBLE_EQ(s.mean_coordination, std::accumulate(expected.begin(), expected.end(), 0.0) / z.size());
  EXPECT_LE(s.max_overlap_rel, 1e-12);
}

TEST(ContactStats, SimpleCubicHasSixInTheBulk) {
  const int n = 12;
  const auto lat = test::simple_cubic(n, 0.02, Vec3(3.0, -1.0, 2.0));
  expect_lattice_coordination(lat, 6);
  const ContactStats s = contact_stats<3>(lat.packing, nullptr);
  EXPECT_EQ(s.contacts, 3u * n * n * (n - 1));
  EXPECT_EQ(s.histogram[6], std::uint64_t((n - 2) * (n - 2) * (n - 2)));
  EXPECT_EQ(s.histogram[5], std::uint64_t(6 * (n - 2) * (n - 2)));
  EXPECT_EQ(s.histogram[4], std::uint64_t(12 * (n - 2)));
  EXPECT_EQ(s.histogram[3], 8u);
  EXPECT_EQ(s.rattlers, 0u);
}

TEST(ContactStats, FaceCentredCubicHasTwelveInTheBulk) {
  expect_lattice_coordination(test::fcc(6, 0.5, Vec3(0.1, 0.2, 0.3)), 12);
}

TEST(ContactStats, HexagonalDisksHaveSixInTheBulk) {
  expect_lattice_coordination(test::hexagonal(40, 30, 1.0, Vec2(-5.0, 7.0)), 6);
}

TEST(ContactStats, WallContactsInATightBox) {
  // The lattice touches the six faces of its box: each surface particle has one wall contact.
  const int n = 10;
  const auto lat = test::simple_cubic(n, 1.0, Vec3(0.5, 0.5, 0.5));
  const BoxContainer<3> box(Vec3(0, 0, 0), Vec3(n, n, n));
  const ContactStats s = contact_stats<3>(lat.packing, &box);
  EXPECT_EQ(s.wall_contacts, std::uint64_t(n * n * n - (n - 2) * (n - 2) * (n - 2)));
  EXPECT_DOUBLE_EQ(s.mean_coordination_with_walls,
                   s.mean_coordination + static_cast<double>(s.wall_contacts) / (n * n * n));
  const auto walls = find_wall_contacts(lat.packing, box);
  for (const auto& w : walls) EXPECT_NEAR(w.gap, 0.0, 1e-12);
  // Pushed away from every wall by 1e-6: no wall contact at tolerance 1e-9.
  const BoxContainer<3> loose(Vec3(-1e-6, -1e-6, -1e-6), Vec3(n + 1e-6, n + 1e-6, n + 1e-6));
  EXPECT_EQ(contact_stats<3>(lat.packing, &loose).wall_contacts, 0u);
}

TEST(ContactStats, PerturbedLatticeHasNoContacts) {
  // Spacing grown by 1e-6 (gaps 1e-6 * d >> tol) and then jittered by less than the gap.
  auto lat = test::fcc(5, 0.5, Vec3(0.0, 0.0, 0.0));
  Rng rng(3);
  for (auto& c : lat.packing.centers)
    c = c * (1.0 + 4e-6) + Vec3(rng.uniform(-4e-7, 4e-7), rng.uniform(-4e-7, 4e-7), rng.uniform(-4e-7, 4e-7));
  const ContactStats s = contact_stats<3>(lat.packing, nullptr);
  EXPECT_EQ(s.contacts, 0u);
  EXPECT_EQ(s.mean_coordination, 0.0);
  EXPECT_EQ(s.histogram.size(), 1u);
  EXPECT_EQ(s.rattlers, lat.packing.size());
  EXPECT_EQ(s.max_overlap_rel, 0.0);
  EXPECT_EQ(s.worst_i, -1);
  // A looser tolerance sees them again.
  EXPECT_EQ(contact_stats<3>(lat.packing, nullptr, 1e-4).contacts, find_pair_contacts(test::fcc(5, 0.5, Vec3(0, 0, 0)).packing).size());
}

TEST(ContactStats, ContactListMatchesBruteForceInPairOrder) {
  // Random overlapping balls with a 1:20 radius ratio; a loose tolerance makes many contacts.
  Rng rng(17);
  Packing<3> p;
  for (int k = 0; k < 2500; ++k)
    p.add(Vec3(rng.uniform(0, 12), rng.uniform(0, 12), rng.uniform(0, 12)), 0.05 * std::pow(20.0, rng.uniform01()));
  const double tol = 0.05;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      const double gap = (p.centers[i] - p.centers[j]).norm() - p.radii[i] - p.radii[j];
      if (gap <= tol * std::min(p.radii[i], p.radii[j])) expected.emplace_back(i, j);
    }
  const auto found = find_pair_contacts(p, tol);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found[k].i, expected[k].first);
    EXPECT_EQ(found[k].j, expected[k].second);
  }
  EXPECT_GT(found.size(), 1000u);
}

TEST(ContactStats, ToleranceIsRelativeToTheSmallerBall) {
  Packing<3> p;
  p.add(Vec3(0, 0, 0), 1.0);
  p.add(Vec3(1.0 + 0.01 + 0.9e-9 * 0.01, 0, 0), 0.01);  // gap 0.9e-9 * r_small: contact
  p.add(Vec3(-(1.0 + 0.01 + 1.1e-9 * 0.01), 0, 0), 0.01);  // gap 1.1e-9 * r_small: none
  const auto c = find_pair_contacts(p, 1e-9);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].i, 0u);
  EXPECT_EQ(c[0].j, 1u);
}

TEST(ContactStats, OverlapIsAContactAndItsWorstPairIsReported) {
  auto lat = test::simple_cubic(6, 1.0, Vec3(0, 0, 0));
  lat.packing.radii[40] = 0.5 + 0.3;  // overlaps its six neighbours by 0.3 (r_min = 0.5)
  lat.packing.radii[41] = 0.5 + 0.05; // and its neighbour 41 by 0.35
  const ContactStats s = contact_stats<3>(lat.packing, nullptr);
  EXPECT_NEAR(s.max_overlap_rel, 0.35 / 0.5, 1e-12);
  EXPECT_EQ(s.worst_i, 40);
  EXPECT_EQ(s.worst_j, 41);
  EXPECT_EQ(s.contacts, 3u * 36 * 5);  // overlapping lattice pairs are still the lattice contacts
  EXPECT_NE(s.summary().find("max overlap 0.7 r_min"), std::string::npos) << s.summary();
}

TEST(ContactStats, RattlersFollowThePaperConvention) {
  // 2D: three disks in a row; the ends have z = 1 (< 2: rattlers), the middle z = 2.
  Packing<2> p;
  for (int k = 0; k < 3; ++k) p.add(Vec2(2.0 * k, 0.0), 1.0);
  const ContactStats s = contact_stats<2>(p, nullptr);
  EXPECT_EQ(s.rattlers, 2u);
  EXPECT_EQ(s.histogram, (std::vector<std::uint64_t>{0, 2, 1}));
  // In a box that touches the two ends, walls count toward stability.
  const BoxContainer<2> box(Vec2(-1.0, -5.0), Vec2(5.0, 5.0));
  const ContactStats w = contact_stats<2>(p, &box);
  EXPECT_EQ(w.wall_contacts, 2u);
  EXPECT_EQ(w.rattlers, 0u);
  EXPECT_THROW(contact_stats<2>(p, nullptr, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fp
