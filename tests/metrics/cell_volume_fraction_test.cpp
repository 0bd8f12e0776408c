// The solid fraction in cells (core/metrics/cell_volume_fraction.hpp): a lattice holds the same
// fraction in every cell whose edge is a multiple of its period, wherever the cell planes cut
// its balls; half a lattice shows the spread; scaled and shifted scenes give the same figures.
#include "core/metrics/cell_volume_fraction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/box_container.hpp"
#include "core/metrics/ball_box.hpp"

namespace fp {
namespace {

// n^D touching balls of radius 1/2 at the integer points, times `scale`, in a box from -0.3 (so
// the cell planes, every 8 from the low corner, cut balls) to n + 0.3.
template <int D>
Packing<D> lattice(int n, double scale, double keep_below_x = 1e300) {
  Packing<D> p;
  std::array<int, D> at{};
  for (;;) {
    Vec<D> c;
    for (int k = 0; k < D; ++k) c[k] = at[k] * scale;
    if (c[0] < keep_below_x * scale) p.add(c, 0.5 * scale);
    int k = 0;
    while (k < D && at[k] == n - 1) at[k] = 0, ++k;
    if (k == D) break;
    ++at[k];
  }
  return p;
}

template <int D>
BoxContainer<D> box(int n, double scale, const Vec<D>& origin = Vec<D>::Zero()) {
  return BoxContainer<D>::from_local(Vec<D>::Constant(-0.3 * scale), Vec<D>::Constant((n + 0.3) * scale), origin);
}

TEST(CellVolumeFraction, LatticeIsUniformInEveryCell) {
  const Packing<3> p = lattice<3>(40, 1.0);
  const CellVolumeFraction f = cell_volume_fraction(p, box<3>(40, 1.0), 8.0, 1.0);
  EXPECT_EQ(f.cells, 27u);  // 5 cells per axis, the 3 inner ones 7.93 from the walls
  EXPECT_NEAR(f.mean, kPi / 6, 1e-9);
  EXPECT_LT(f.std_dev, 1e-9);
  EXPECT_NEAR(f.min, kPi / 6, 1e-9);
  EXPECT_NEAR(f.max, kPi / 6, 1e-9);

  const Packing<2> q = lattice<2>(40, 1.0);
  const CellVolumeFraction g = cell_volume_fraction(q, box<2>(40, 1.0), 8.0, 1.0);
  EXPECT_EQ(g.cells, 9u);
  EXPECT_NEAR(g.mean, kPi / 4, 1e-13);
  EXPECT_LT(g.std_dev, 1e-13);
}

TEST(CellVolumeFraction, HalfALatticeShowsTheSpread) {
  const Packing<3> p = lattice<3>(40, 1.0, 20.0);  // x < 20 only
  const CellVolumeFraction f = cell_volume_fraction(p, box<3>(40, 1.0), 8.0, 1.0);
  ASSERT_EQ(f.cells, 27u);
  // Cells [7.7, 15.7] full; [15.7, 23.7] holds the balls at x = 17, 18, 19 and the part of those
  // at x = 16 beyond the plane 0.3 from their centres: (3 + f) of its 8 periods; [23.7, 31.7] empty.
  const double part = ball_inside_plane<3>(0.5, 0.3) / ball_measure<3>(0.5);
  const double middle = kPi / 6 * (3 + part) / 8;
  EXPECT_NEAR(f.max, kPi / 6, 1e-9);
  EXPECT_NEAR(f.min, 0.0, 1e-15);
  EXPECT_NEAR(f.mean, (kPi / 6 + middle) / 3, 1e-9);
  const double var = (std::pow(kPi / 6 - f.mean, 2) + std::pow(middle - f.mean, 2) + std::pow(f.mean, 2)) / 3;
  EXPECT_NEAR(f.std_dev, std::sqrt(var), 1e-9);
  EXPECT_NEAR(f.worst, kPi / 6, 1e-9);  // the full cells are farthest from the mean
  ASSERT_EQ(f.worst_centre.size(), 3u);
  EXPECT_NEAR(f.worst_centre[0], 11.7, 1e-12);
}

TEST(CellVolumeFraction, ScaledAndShiftedScenesGiveTheSameFigures) {
  const CellVolumeFraction plain = cell_volume_fraction(lattice<3>(24, 1.0), box<3>(24, 1.0), 4.0, 1.0);
  ASSERT_GT(plain.cells, 0u);
  for (const double scale : {0x1p-60, 0x1p60}) {
    const CellVolumeFraction s = cell_volume_fraction(lattice<3>(24, scale), box<3>(24, scale), 4.0 * scale, scale);
    EXPECT_EQ(s.cells, plain.cells);
    EXPECT_DOUBLE_EQ(s.mean, plain.mean);
    EXPECT_NEAR(s.std_dev, plain.std_dev, 1e-12);
  }
  Packing<3> far = lattice<3>(24, 1.0);
  far.origin = Vec3::Constant(1e9);  // local coordinates: the same cells
  const CellVolumeFraction shifted = cell_volume_fraction(far, box<3>(24, 1.0, far.origin), 4.0, 1.0);
  EXPECT_EQ(shifted.mean, plain.mean);
  EXPECT_NEAR(shifted.worst_centre[0], plain.worst_centre[0] + 1e9, 1e-6);
}

TEST(CellVolumeFraction, AutomaticCellsAndNone) {
  const Packing<3> p = lattice<3>(40, 1.0);
  const CellVolumeFraction a = cell_volume_fraction_auto(p, box<3>(40, 1.0), 0.5, 0.5);
  EXPECT_EQ(a.diameters, 8.0);
  EXPECT_EQ(a.edge, 8.0);
  EXPECT_EQ(a.cells, 27u);
  // A box 6 diameters wide: no cell of 8; of 2 diameters, 2 r_max inside: one per axis.
  const Packing<3> small = lattice<3>(6, 1.0);
  const CellVolumeFraction b = cell_volume_fraction_auto(small, box<3>(6, 1.0), 0.5, 0.5);
  EXPECT_EQ(b.diameters, 2.0);
  EXPECT_GT(b.cells, 0u);
  const CellVolumeFraction none = cell_volume_fraction_auto(lattice<3>(3, 1.0), box<3>(3, 1.0), 0.5, 0.5);
  EXPECT_FALSE(none.computed());
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_THROW(cell_volume_fraction(p, box<3>(40, 1.0), 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(cell_volume_fraction(p, box<3>(40, 1.0), 8.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fp
