// Partial coordination z(xi) (paper 000 Sect. 3.2): contacts among the particles of radius
// >= r_min + xi (r_max - r_min), per such particle.
#include "core/metrics/partial_coordination.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

TEST(PartialCoordination, HandCountedNetwork) {
  // Radii 1, 2, 3, 4, 5 (xi = 0, 1/4, 1/2, 3/4, 1); contacts 0-1, 1-2, 2-3, 3-4, 2-4, 0-4.
  const std::vector<double> radii{1, 2, 3, 4, 5};
  const std::vector<PairContact> contacts{{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {2, 4, 0}, {0, 4, 0}};
  const PartialCoordination z = partial_coordination(radii, contacts, 5);
  ASSERT_EQ(z.xi.size(), 5u);
  EXPECT_EQ(z.xi, (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_EQ(z.radius, (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(z.particles, (std::vector<std::uint64_t>{5, 4, 3, 2, 1}));
  EXPECT_EQ(z.contacts, (std::vector<std::uint64_t>{6, 4, 3, 1, 0}));
  EXPECT_DOUBLE_EQ(z.z[0], 12.0 / 5);  // z(0) = z of Eq. 15
  EXPECT_DOUBLE_EQ(z.z[1], 2.0);
  EXPECT_DOUBLE_EQ(z.z[2], 2.0);
  EXPECT_DOUBLE_EQ(z.z[3], 1.0);
  EXPECT_DOUBLE_EQ(z.z[4], 0.0);
}

TEST(PartialCoordination, StartsAtTheMeanCoordinationOfALattice) {
  auto lat = test::simple_cubic(6, 1.0, Vec3::Zero());
  for (std::size_t i = 0; i < lat.packing.size(); ++i) lat.packing.radii[i] = 0.5 - 1e-6 * (i % 7);  // r_min < r_max
  const auto contacts = find_pair_contacts(lat.packing, 1e-4);
  const PartialCoordination z = partial_coordination(lat.packing.radii, contacts);
  ASSERT_EQ(z.xi.size(), 21u);
  EXPECT_DOUBLE_EQ(z.z[0], 2.0 * contacts.size() / lat.packing.size());
  EXPECT_EQ(z.particles[0], lat.packing.size());
  for (std::size_t k = 1; k < z.z.size(); ++k) EXPECT_LE(z.contacts[k], z.contacts[k - 1]);
  EXPECT_EQ(z.particles.back(), lat.packing.size() / 7 + 1);  // the i % 7 == 0 sites
}

TEST(PartialCoordination, IgnoresUnusableRadiiAndRejectsFewPoints) {
  const std::vector<double> radii{1, std::numeric_limits<double>::quiet_NaN(), 2};
  const std::vector<PairContact> contacts{{0, 1, 0}, {0, 2, 0}};
  const PartialCoordination z = partial_coordination(radii, contacts, 2);
  EXPECT_EQ(z.particles, (std::vector<std::uint64_t>{2, 1}));
  EXPECT_EQ(z.contacts, (std::vector<std::uint64_t>{1, 0}));
  EXPECT_THROW(partial_coordination(radii, contacts, 1), std::invalid_argument);
  const PartialCoordination none = partial_coordination({}, {}, 3);
  EXPECT_EQ(none.z, (std::vector<double>{0, 0, 0}));
}

}  // namespace
}  // namespace fp
