// Fabric tensors (core/metrics/fabric.hpp): per contact (paper 000 Eq. 17) and per particle
// averaged (paper 002 Eq. 1) on isotropic sets (exactly I/D for lattices by symmetry, I/3 within
// sampling error for random directions), axial sets, and a hand-computed case where they differ.
#include "core/metrics/fabric.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/metrics/analysis_test_util.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

void expect_tensor(const FabricTensor& f, const std::vector<double>& diagonal, double tol) {
  const std::size_t d = diagonal.size();
  ASSERT_EQ(f.tensor.size(), d * d);
  for (std::size_t a = 0; a < d; ++a)
    for (std::size_t b = 0; b < d; ++b) EXPECT_NEAR(f.tensor[a * d + b], a == b ? diagonal[a] : 0.0, tol) << a << b;
  double trace = 0.0;
  for (const double e : f.eigenvalues) trace += e;
  EXPECT_NEAR(trace, 1.0, 1e-12);
}

template <int D>
void expect_isotropic_lattice(const test::Lattice<D>& lat) {
  const Fabric f = fabric_tensors(lat.packing, find_pair_contacts(lat.packing));
  const std::vector<double> iso(D, 1.0 / D);
  expect_tensor(f.per_contact, iso, 1e-12);
  expect_tensor(f.per_particle, iso, 1e-12);
  for (const double e : f.per_contact.eigenvalues) EXPECT_NEAR(e, 1.0 / D, 1e-12);
  EXPECT_EQ(f.per_particle.count, lat.packing.size());
}

TEST(Fabric, NeighbourDirectionsOfLatticesAreExactlyIsotropic) {
  std::vector<Vec3> sc, fcc;
  for (const auto& o : test::simple_cubic(1, 1.0, Vec3::Zero()).neighbour_offsets) sc.emplace_back(o[0], o[1], o[2]);
  for (const auto& o : test::fcc(1, 1.0, Vec3::Zero()).neighbour_offsets) fcc.emplace_back(o[0], o[1], o[2]);
  ASSERT_EQ(sc.size(), 6u);
  ASSERT_EQ(fcc.size(), 12u);
  expect_tensor(fabric_of_directions(sc), {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1e-15);
  expect_tensor(fabric_of_directions(fcc), {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1e-15);
  std::vector<Vec2> hex;
  for (int k = 0; k < 6; ++k) hex.emplace_back(std::cos(k * kPi / 3), std::sin(k * kPi / 3));
  expect_tensor(fabric_of_directions(hex), {0.5, 0.5}, 1e-15);
}

TEST(Fabric, LatticeContactNetworksAreIsotropicInBothForms) {
  // Boundary particles miss neighbours, but the cube (square) patch keeps the lattice symmetry.
  expect_isotropic_lattice(test::simple_cubic(7, 1.0, Vec3(0.1, 0.2, 0.3)));
  expect_isotropic_lattice(test::fcc(4, 0.5, Vec3(-3.0, 1.0, 2.0)));
  Packing<2> square;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) square.add(Vec2(i, j), 0.5);
  const Fabric f = fabric_tensors(square, find_pair_contacts(square));
  expect_tensor(f.per_contact, {0.5, 0.5}, 1e-12);
  expect_tensor(f.per_particle, {0.5, 0.5}, 1e-12);
}

TEST(Fabric, RandomDirectionsAreIsotropicWithinSamplingError) {
  const FabricTensor f = fabric_of_directions(test::random_directions<3>(200000, 2024));
  EXPECT_EQ(f.count, 200000u);
  // Each entry is a mean of 2e5 terms of standard deviation <= 0.3: error ~ 7e-4.
  expect_tensor(f, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 4e-3);
  EXPECT_GT(f.eigenvalues.front(), 1.0 / 3 - 4e-3);
  EXPECT_LT(f.eigenvalues.back(), 1.0 / 3 + 4e-3);
}

TEST(Fabric, AxialSets) {
  // A chain along z: (0, 0, 1); directions on a cone of half-angle 60 deg about z: transversely
  // isotropic, n_z^2 = 1/4, the rest shared by x and y.
  Packing<3> chain;
  for (int k = 0; k < 10; ++k) chain.add(Vec3(1.0, 2.0, 2.0 * k), 1.0);
  const Fabric f = fabric_tensors(chain, find_pair_contacts(chain));
  expect_tensor(f.per_contact, {0.0, 0.0, 1.0}, 1e-15);
  expect_tensor(f.per_particle, {0.0, 0.0, 1.0}, 1e-15);
  EXPECT_NEAR(f.per_contact.eigenvalues[2], 1.0, 1e-15);
  std::vector<Vec3> cone;
  for (int k = 0; k < 8; ++k)
    cone.emplace_back(std::sin(kPi / 3) * std::cos(k * kPi / 4), std::sin(kPi / 3) * std::sin(k * kPi / 4), 0.5);
  const FabricTensor c = fabric_of_directions(cone);
  expect_tensor(c, {0.375, 0.375, 0.25}, 1e-15);
  EXPECT_NEAR(c.eigenvalues[0], 0.25, 1e-15);
  EXPECT_NEAR(c.eigenvalues[2], 0.375, 1e-15);
}

TEST(Fabric, PerParticleAveragingWeighsParticlesNotContacts) {
  // A - B - C along x, D on A along y. Per contact: (2 xx + yy) / 3. Per particle:
  // A (xx + yy) / 2, B xx, C xx, D yy -> diag(2.5, 1.5) / 4.
  Packing<3> p;
  p.add(Vec3(0, 0, 0), 1.0);  // A
  p.add(Vec3(2, 0, 0), 1.0);  // B
  p.add(Vec3(4, 0, 0), 1.0);  // C
  p.add(Vec3(0, 2, 0), 1.0);  // D
  p.add(Vec3(9, 9, 9), 1.0);  // a rattler: no term, not counted
  const Fabric f = fabric_tensors(p, find_pair_contacts(p));
  EXPECT_EQ(f.per_contact.count, 3u);
  EXPECT_EQ(f.per_particle.count, 4u);
  expect_tensor(f.per_contact, {2.0 / 3, 1.0 / 3, 0.0}, 1e-15);
  expect_tensor(f.per_particle, {0.625, 0.375, 0.0}, 1e-15);
  EXPECT_NEAR(f.per_particle.eigenvalues[0], 0.0, 1e-15);
  EXPECT_NEAR(f.per_particle.eigenvalues[2], 0.625, 1e-15);
}

TEST(Fabric, NoContactsGiveZeros) {
  Packing<2> p;
  p.add(Vec2(0, 0), 1.0);
  const Fabric f = fabric_tensors(p, {});
  EXPECT_EQ(f.per_contact.count, 0u);
  EXPECT_EQ(f.per_contact.tensor, std::vector<double>(4, 0.0));
  EXPECT_EQ(f.per_particle.eigenvalues, std::vector<double>(2, 0.0));
}

}  // namespace
}  // namespace fp
