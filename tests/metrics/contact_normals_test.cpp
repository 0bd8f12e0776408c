// Relative projections of contact normals (paper 002 Sect. 1): histograms of |n . e_k| and K-S
// against the isotropic law (uniform in 3D, arcsine in 2D).
#include "core/metrics/contact_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/metrics/analysis_test_util.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

// A centre at the origin and one particle along each direction, with the contacts spelled out.
template <int D>
std::pair<Packing<D>, std::vector<PairContact>> star(const std::vector<Vec<D>>& dirs) {
  Packing<D> p;
  p.add(Vec<D>::Zero(), 1.0);
  std::vector<PairContact> contacts;
  for (const Vec<D>& d : dirs) {
    contacts.push_back({0, static_cast<std::uint32_t>(p.size()), 0.0});
    p.add(2.0 * d, 1.0);
  }
  return {p, contacts};
}

TEST(RelativeProjections, SimpleCubicContactsAreZeroOrOne) {
  const auto lat = test::simple_cubic(5, 1.0, Vec3::Zero());
  const auto contacts = find_pair_contacts(lat.packing);
  const RelativeProjections r = relative_projections(lat.packing, contacts, 10);
  EXPECT_EQ(r.contacts, contacts.size());
  ASSERT_EQ(r.histogram.size(), 3u);
  const std::uint64_t per_axis = contacts.size() / 3;  // 5 * 5 * 4 along each axis
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(r.histogram[a].front(), 2 * per_axis);
    EXPECT_EQ(r.histogram[a].back(), per_axis);
    // Two thirds at 0, one third at 1, against uniform: D = 2/3.
    EXPECT_NEAR(r.ks[a].d, 2.0 / 3.0, 1e-15);
  }
  EXPECT_EQ(r.reference, "uniform on [0, 1]");
}

TEST(RelativeProjections, IsotropicDirectionsPassInBothDimensions) {
  const auto [p3, c3] = star<3>(test::random_directions<3>(20000, 11));
  const RelativeProjections r3 = relative_projections(p3, c3);
  for (const KsResult& k : r3.ks) EXPECT_GT(k.p, 0.01) << k.d;
  for (const auto& h : r3.histogram)
    for (const std::uint64_t count : h) EXPECT_NEAR(count, 1000.0, 150.0);  // uniform: 20000 / 20 each

  const auto [p2, c2] = star<2>(test::random_directions<2>(20000, 12));
  const RelativeProjections r2 = relative_projections(p2, c2);
  for (const KsResult& k : r2.ks) EXPECT_GT(k.p, 0.01) << k.d;
  EXPECT_EQ(r2.reference, "arcsine, (2/pi) asin t");
  EXPECT_GT(r2.histogram[0].back(), 3 * r2.histogram[0].front());  // piles up near 1
  // Against the 3D law (uniform) the 2D projections fail.
  std::vector<double> x;
  for (const auto& c : c2) x.push_back(std::abs(p2.centers[c.j].x()) / 2.0);
  EXPECT_LT(ks_one_sample(x, isotropic_projection_cdf<3>).p, 1e-10);
}

TEST(RelativeProjections, IsotropicLaws) {
  EXPECT_EQ(isotropic_projection_cdf<3>(0.25), 0.25);
  EXPECT_EQ(isotropic_projection_cdf<3>(1.5), 1.0);
  EXPECT_NEAR(isotropic_projection_cdf<2>(0.5), 1.0 / 3.0, 1e-15);  // asin(1/2) = pi/6
  EXPECT_EQ(isotropic_projection_cdf<2>(-0.1), 0.0);
  EXPECT_THROW(relative_projections(Packing<2>{}, {}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fp
