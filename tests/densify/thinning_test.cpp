// Thinning to a target measure (densify/thinning.hpp) on contact networks whose answers are known:
// a lattice, a chain, size classes. Checked from the mask it returns, independently of its report.
#include "densify/thinning.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {
namespace {

// n^3 simple cubic sites: contacts with the six face neighbours; the boundary sites touch walls.
struct Network {
  std::vector<double> measure, size;
  std::vector<ThinningContact> contacts;
  std::vector<std::uint32_t> walls;
  ThinningInput input() const { return {measure, size, contacts, walls}; }
  std::vector<std::uint32_t> contacts_left(const std::vector<char>& keep) const {
    std::vector<std::uint32_t> z(walls);
    for (const ThinningContact& c : contacts)
      if (keep[c.i] && keep[c.j]) ++z[c.i], ++z[c.j];
    return z;
  }
  std::vector<std::uint32_t> contacts_before() const { return contacts_left(std::vector<char>(measure.size(), 1)); }
};

Network cubic(int n, bool graded) {
  Network net;
  auto id = [n](int i, int j, int k) { return static_cast<std::uint32_t>((i * n + j) * n + k); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        // Graded: 16 sizes in a pattern that mixes them over space, n^3 / 16 of each when n is 16.
        const double r = graded ? 1.0 + ((i * 7 + j * 3 + k * 5) % 16) / 15.0 : 1.0;
        net.size.push_back(r);
        net.measure.push_back(ball_measure<3>(r));
        std::uint32_t w = 0;
        for (const int c : {i, j, k}) w += (c == 0) + (c == n - 1);
        net.walls.push_back(w);
        if (i + 1 < n) net.contacts.push_back({id(i, j, k), id(i + 1, j, k)});
        if (j + 1 < n) net.contacts.push_back({id(i, j, k), id(i, j + 1, k)});
        if (k + 1 < n) net.contacts.push_back({id(i, j, k), id(i, j, k + 1)});
      }
  return net;
}

double kept_measure(const Network& net, const std::vector<char>& keep) {
  double s = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) s += keep[i] ? net.measure[i] : 0.0;
  return s;
}

TEST(Thinning, ReachesTheTargetWithinHalfAParticleKeepingContacts) {
  const Network net = cubic(16, true);
  double total = 0, largest = 0;
  for (const double m : net.measure) total += m, largest = std::max(largest, m);
  const auto z0 = net.contacts_before();
  for (const double share : {0.9, 0.75, 0.6}) {
    Rng rng(3);
    ThinningReport rep;
    const std::vector<char> keep = thin_to_measure(net.input(), share * total, 3, rng, rep);
    const double kept = kept_measure(net, keep);
    EXPECT_LE(std::abs(kept - share * total), largest / 2) << share;
    EXPECT_NEAR(rep.measure_after, kept, 1e-9 * total);
    EXPECT_EQ(rep.removed, static_cast<std::uint64_t>(std::count(keep.begin(), keep.end(), 0)));
    EXPECT_TRUE(rep.reached);
    // Every particle left kept min(level, its contacts) contacts.
    const auto z = net.contacts_left(keep);
    for (std::size_t i = 0; i < keep.size(); ++i)
      if (keep[i]) ASSERT_GE(z[i], std::min<std::uint32_t>(static_cast<std::uint32_t>(rep.level), z0[i])) << i;
    // The size classes keep their proportions: each of the 16 sizes loses the same share, to a
    // few particles of its 256.
    std::vector<double> before(16, 0), after(16, 0);
    for (std::size_t i = 0; i < keep.size(); ++i) {
      const int c = static_cast<int>(std::lround((net.size[i] - 1.0) * 15));
      before[c] += 1;
      after[c] += keep[i];
    }
    const double removed_share = static_cast<double>(rep.removed) / static_cast<double>(keep.size());
    for (int c = 0; c < 16; ++c) EXPECT_NEAR(1 - after[c] / before[c], removed_share, 4.0 / 256) << "class " << c;
  }
}

TEST(Thinning, IsDeterministicForAGivenStreamAndDiffersForAnother) {
  const Network net = cubic(10, true);
  double total = 0;
  for (const double m : net.measure) total += m;
  ThinningReport a, b, c;
  Rng r1(5), r2(5), r3(6);
  const auto ka = thin_to_measure(net.input(), 0.7 * total, 3, r1, a);
  EXPECT_EQ(thin_to_measure(net.input(), 0.7 * total, 3, r2, b), ka);
  EXPECT_NE(thin_to_measure(net.input(), 0.7 * total, 3, r3, c), ka);
}

TEST(Thinning, RelaxesTheContactLevelOnlyWhenItMust) {
  // A chain of 10 equal particles, the ends on walls: every particle has 2 contacts. No removal
  // keeps every neighbour at 2; at level 1 a removal leaves its neighbours one each.
  Network chain;
  for (int i = 0; i < 10; ++i) {
    chain.measure.push_back(1.0);
    chain.size.push_back(1.0);
    chain.walls.push_back(i == 0 || i == 9);
    if (i + 1 < 10) chain.contacts.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
  }
  Rng rng(1);
  ThinningReport rep;
  const auto keep = thin_to_measure(chain.input(), 8.0, 3, rng, rep);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), 0), 2);
  EXPECT_EQ(rep.level, 1);
  EXPECT_EQ(rep.lost_every_contact, 0u);
  const auto z = chain.contacts_left(keep);
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) EXPECT_GE(z[i], 1u);
  // Down to 2 of 10: particles must lose every contact (level 0), and it is said.
  Rng again(1);
  const auto few = thin_to_measure(chain.input(), 2.0, 3, again, rep);
  EXPECT_EQ(std::count(few.begin(), few.end(), 1), 2);
  EXPECT_EQ(rep.level, 0);
}

TEST(Thinning, NothingToRemoveAndBadInput) {
  const Network net = cubic(4, false);
  Rng rng(1);
  ThinningReport rep;
  const auto keep = thin_to_measure(net.input(), 1e9, 3, rng, rep);  // above the packing
  EXPECT_EQ(std::count(keep.begin(), keep.end(), 0), 0);
  EXPECT_EQ(rep.removed, 0u);
  EXPECT_EQ(rep.level, 3);
  EXPECT_THROW(thin_to_measure(net.input(), -1.0, 3, rng, rep), std::invalid_argument);
  Network bad = net;
  bad.size.pop_back();
  EXPECT_THROW(thin_to_measure(bad.input(), 1.0, 3, rng, rep), std::invalid_argument);
}

}  // namespace
}  // namespace fp
