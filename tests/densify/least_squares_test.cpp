// Least-squares densification (densify/least_squares.hpp, paper 001) of loose packings, checked by
// the independent brute-force code of tests/front: every particle kept, no overlap beyond the
// stage's tolerance, every ball inside, radii in the law's range (Range) or unchanged to
// kClipAllowance (Fixed), the solid fraction up, contacts made, byte-identical reruns, the same
// result 2^30 away and scaled by 2^+-60, and the packing given back unharmed when the overlap
// removal cannot finish.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "densify/least_squares.hpp"
#include "front/pack.hpp"
#include "tests/front/front_checks.hpp"

namespace fptest {
namespace {

using fp::LeastSquaresOptions;
using fp::LeastSquaresRadii;
using fp::Packing;

constexpr double kTol = 1e-6;  // the stage's default tolerance

/// A loose packing with radii in [r_min, r_max]: the front's packing of [r_min, r_max] / 0.8,
/// each radius times 0.8 (solid fraction times 0.512, every ball inside, nothing touching).
template <int D>
Packing<D> loose(const fp::Scene& big) {
  Packing<D> P = fp::pack<D>(big).packing;
  for (double& r : P.radii) r *= 0.8;
  return P;
}

std::string scene_text(int dimension, const std::string& container, double r_min, double r_max) {
  char law[200];
  if (r_min == r_max) std::snprintf(law, sizeof law, "{distribution: constant, value: %.17g}", r_min);
  else std::snprintf(law, sizeof law, "{distribution: uniform, min: %.17g, max: %.17g}", r_min, r_max);
  return "dimension: " + std::to_string(dimension) + "\nseed: 3\ncontainer: " + container + "\nparticles: {radius: " + law + "}\n";
}

std::string box(double lo, double hi) {
  char text[200];
  std::snprintf(text, sizeof text, "{type: box, min: [%.17g, %.17g, %.17g], max: [%.17g, %.17g, %.17g]}", lo, lo, lo, hi, hi, hi);
  return text;
}

/// Independent checks at the stage's tolerance: same count, no overlap, inside, radii in range.
template <int D>
void expect_sound(const Packing<D>& P, std::size_t count, const SignedDistance<D>& sd, double r_min, double r_max,
                  const std::string& what) {
  ASSERT_EQ(P.size(), count) << what << ": a particle was lost";
  const OverlapReport o = overlaps<D>(P);
  EXPECT_LE(o.max_over_pair_rmin, kTol) << what << ": " << o.worst_i << " and " << o.worst_j << " overlap";
  const ContainmentReport c = containment<D>(P, sd, kTol);
  EXPECT_LE(c.max_outside_over_r, kTol) << what << ": particle " << c.worst << " sticks out";
  const auto [lo, hi] = std::minmax_element(P.radii.begin(), P.radii.end());
  EXPECT_GE(*lo, r_min) << what;
  EXPECT_LE(*hi, r_max) << what;
}

template <int D>
double mean_contacts(const Packing<D>& P) {
  const std::vector<int> z = particle_contacts<D>(P, kTol);
  double s = 0;
  for (const int k : z) s += k;
  return s / static_cast<double>(P.size());
}

TEST(LeastSquares, RangeModeDensifiesALooseBoxKeepingEveryParticle) {
  const fp::Scene big = scene_from_yaml(scene_text(3, box(0, 1), 0.0125, 0.0625));
  const fp::Scene scene = scene_from_yaml(scene_text(3, box(0, 1), 0.01, 0.05));
  Packing<3> P = loose<3>(big);
  const std::size_t n = P.size();
  ASSERT_GT(n, 500u);
  const double before = volume_fraction<3>(P, 1.0);
  const double z_before = mean_contacts<3>(P);
  const fp::LeastSquaresReport r = fp::densify_least_squares<3>(P, *scene.container3, 0.01, 0.05, LeastSquaresOptions{}, kTol);
  const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(1, 1, 1));
  expect_sound<3>(P, n, sd, 0.01, 0.05, "range");
  const double after = volume_fraction<3>(P, 1.0);
  // Measured 0.33 -> 0.41 (experiments/labra-densification holds the figures).
  EXPECT_GT(after, before + 0.04) << "from " << before;
  EXPECT_NEAR(r.solid_after / (1.0), after, 1e-12);
  EXPECT_NEAR(r.solid_before / (1.0), before, 1e-12);
  EXPECT_EQ(r.kept_share, 1.0);
  EXPECT_GT(r.radii_grown, n / 4);
  // z from about 0 to 2.08 (measured; 1.99 when sin was rounded differently: the figure moves
  // with the last bits of the path).
  EXPECT_GT(mean_contacts<3>(P), z_before + 1.5) << "pairs drawn into contact";
  EXPECT_GT(r.edges, 2 * n);
  EXPECT_GT(r.boundary_terms, 0u);
}

TEST(LeastSquares, FixedModeKeepsTheRadiiAndTheSolid) {
  const fp::Scene big = scene_from_yaml(scene_text(3, box(0, 1), 0.0125, 0.0625));
  const fp::Scene scene = scene_from_yaml(scene_text(3, box(0, 1), 0.01, 0.05));
  Packing<3> P = loose<3>(big);
  const Packing<3> given = P;
  LeastSquaresOptions o;
  o.radii = LeastSquaresRadii::Fixed;
  const fp::LeastSquaresReport r = fp::densify_least_squares<3>(P, *scene.container3, 0.01, 0.05, o, kTol);
  expect_sound<3>(P, given.size(), box_distance<3>(Vec3(0, 0, 0), Vec3(1, 1, 1)), 0.01, 0.05, "fixed");
  for (std::size_t i = 0; i < P.size(); ++i) {
    ASSERT_LE(P.radii[i], given.radii[i]) << i;
    ASSERT_GE(P.radii[i], given.radii[i] * (1 - fp::kClipAllowance)) << i;
  }
  EXPECT_EQ(r.radii_grown, 0u);
  EXPECT_GT(r.mean_move, 0.01) << "the centres moved";
  EXPECT_NEAR(r.solid_after, r.solid_before, 1e-3 * r.solid_before);
}

TEST(LeastSquares, DisksInADiskAndSpheresInACylinder) {
  {
    const std::string disk = "{type: disk, center: [0, 0], radius: 1}";
    const fp::Scene big = scene_from_yaml(scene_text(2, disk, 0.025, 0.0625));
    const fp::Scene scene = scene_from_yaml(scene_text(2, disk, 0.02, 0.05));
    Packing<2> P = loose<2>(big);
    const double before = volume_fraction<2>(P, M_PI);
    fp::densify_least_squares<2>(P, *scene.container2, 0.02, 0.05, LeastSquaresOptions{}, kTol);
    expect_sound<2>(P, fp::pack<2>(big).packing.size(), ball_distance<2>(Vec2(0, 0), 1.0), 0.02, 0.05, "2D");
    EXPECT_GT(volume_fraction<2>(P, M_PI), before + 0.05);
  }
  {
    const std::string cyl = "{type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.4, height: 0.6}";
    const fp::Scene big = scene_from_yaml(scene_text(3, cyl, 0.0125, 0.0625));
    const fp::Scene scene = scene_from_yaml(scene_text(3, cyl, 0.01, 0.05));
    Packing<3> P = loose<3>(big);
    const std::size_t n = P.size();
    const double volume = M_PI * 0.16 * 0.6;
    const double before = volume_fraction<3>(P, volume);
    fp::densify_least_squares<3>(P, *scene.container3, 0.01, 0.05, LeastSquaresOptions{}, kTol);
    expect_sound<3>(P, n, cylinder_distance(Vec3(0, 0, 0), Vec3(0, 0, 1), 0.4, 0.6), 0.01, 0.05, "cylinder");
    EXPECT_GT(volume_fraction<3>(P, volume), before + 0.03);
  }
}

TEST(LeastSquares, RerunsAreByteIdentical) {
  const fp::Scene big = scene_from_yaml(scene_text(3, box(0, 0.6), 0.0125, 0.0625));
  const fp::Scene scene = scene_from_yaml(scene_text(3, box(0, 0.6), 0.01, 0.05));
  Packing<3> a = loose<3>(big), b = a;
  fp::densify_least_squares<3>(a, *scene.container3, 0.01, 0.05, LeastSquaresOptions{}, kTol);
  fp::densify_least_squares<3>(b, *scene.container3, 0.01, 0.05, LeastSquaresOptions{}, kTol);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.radii[i], b.radii[i]) << i;
    ASSERT_EQ(a.centers[i], b.centers[i]) << i;
  }
}

/// The minimiser works in a frame centred on the packing and scaled by its mean radius: 2^30 away
/// (the container's local frame holds the same numbers) and scaled by 2^+-60 the result is the
/// plain one, bit for bit up to the scale; 1e9 away (not a power of two: the front differs by
/// roundings) it is as sound and gains as much within 0.01.
TEST(LeastSquares, FarAndScaledScenesDensifyAsThePlainOne) {
  const auto run = [](double lo, double scale, Packing<3>& P) {
    const double hi = lo + 0.75 * scale;
    const fp::Scene big = scene_from_yaml(scene_text(3, box(lo, hi), 0.0125 * scale, 0.0625 * scale));
    const fp::Scene scene = scene_from_yaml(scene_text(3, box(lo, hi), 0.01 * scale, 0.05 * scale));
    P = loose<3>(big);
    const std::size_t n = P.size();
    const double before = volume_fraction<3>(P, std::pow(0.75 * scale, 3));
    fp::densify_least_squares<3>(P, *scene.container3, 0.01 * scale, 0.05 * scale, LeastSquaresOptions{}, kTol);
    expect_sound<3>(P, n, box_distance<3>(Vec3(lo, lo, lo), Vec3(hi, hi, hi)), 0.01 * scale, 0.05 * scale,
                    "at " + std::to_string(lo) + " scaled " + std::to_string(scale));
    return volume_fraction<3>(P, std::pow(0.75 * scale, 3)) - before;
  };
  Packing<3> plain;
  const double gain = run(0, 1, plain);
  EXPECT_GT(gain, 0.04);
  struct Case { const char* name; double shift, scale; };
  for (const Case c : {Case{"2^30 away", std::ldexp(1.0, 30), 1.0}, Case{"2^-60", 0.0, std::ldexp(1.0, -60)},
                       Case{"2^60", 0.0, std::ldexp(1.0, 60)}}) {
    Packing<3> P;
    run(c.shift, c.scale, P);
    ASSERT_EQ(P.size(), plain.size()) << c.name;
    for (std::size_t i = 0; i < P.size(); ++i) {
      ASSERT_EQ(P.radii[i], plain.radii[i] * c.scale) << c.name << " sphere " << i;
      ASSERT_EQ(P.centers[i], plain.centers[i] * c.scale) << c.name << " sphere " << i;
    }
  }
  Packing<3> far;
  EXPECT_NEAR(run(1e9, 1, far), gain, 0.01);
}

/// Equal spheres with their radii fixed cannot give up an overlap from the radii (their floor is
/// the law's r_min); without the penalty rounds, with every edge, the optimum's overlaps (of the
/// particles' size) are more than the sweeps can undo: the move is taken back by halves until
/// the packing is valid. Nothing is lost and nothing overlaps, whatever share is kept.
TEST(LeastSquares, WhenTheOverlapsCannotBeRemovedTheMoveIsTakenBack) {
  const fp::Scene big = scene_from_yaml(scene_text(3, box(0, 0.6), 0.03, 0.03));
  const fp::Scene scene = scene_from_yaml(scene_text(3, box(0, 0.6), 0.024, 0.024));
  Packing<3> P = loose<3>(big);
  const std::size_t n = P.size();
  LeastSquaresOptions o;
  o.radii = LeastSquaresRadii::Fixed;
  o.relax_rounds = 0;
  o.edge_gap = 0;  // every edge: the optimum overlaps most
  const fp::LeastSquaresReport r = fp::densify_least_squares<3>(P, *scene.container3, 0.024, 0.024, o, kTol);
  EXPECT_GT(r.max_overlap_solved, 0.1);
  EXPECT_LT(r.kept_share, 1.0);
  expect_sound<3>(P, n, box_distance<3>(Vec3(0, 0, 0), Vec3(0.6, 0.6, 0.6)), 0.024, 0.024, "taken back");
}

/// r_max / r_min = 1000: a loose lattice of spheres of 1 with a sphere of 0.001 in each of its
/// cells; and a box one particle thick. Both stay sound and gain solid.
TEST(LeastSquares, ExtremeRadiusRatioAndAOneParticleThickBox) {
  {
    Packing<3> P;
    const int k = 4;
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        for (int c = 0; c < k; ++c) {
          P.add(Vec3(1.1 + 2.2 * a, 1.1 + 2.2 * b, 1.1 + 2.2 * c), 0.9);
          if (a + 1 < k && b + 1 < k && c + 1 < k) P.add(Vec3(2.2 + 2.2 * a, 2.2 + 2.2 * b, 2.2 + 2.2 * c), 0.001);
        }
    const double edge = 2.2 * k;
    const fp::Scene scene = scene_from_yaml(scene_text(3, box(0, edge), 0.001, 1.0));
    const std::size_t n = P.size();
    const double before = volume_fraction<3>(P, edge * edge * edge);
    fp::densify_least_squares<3>(P, *scene.container3, 0.001, 1.0, LeastSquaresOptions{}, kTol);
    expect_sound<3>(P, n, box_distance<3>(Vec3(0, 0, 0), Vec3(edge, edge, edge)), 0.001, 1.0, "R = 1000");
    EXPECT_GT(volume_fraction<3>(P, edge * edge * edge), before);
  }
  {
    const std::string thin = "{type: box, min: [0, 0, 0], max: [6, 6, 0.4]}";
    const fp::Scene big = scene_from_yaml(scene_text(3, thin, 0.125, 0.1875));
    const fp::Scene scene = scene_from_yaml(scene_text(3, thin, 0.1, 0.15));
    Packing<3> P = loose<3>(big);
    const std::size_t n = P.size();
    ASSERT_GT(n, 100u);
    const double before = volume_fraction<3>(P, 6 * 6 * 0.4);
    fp::densify_least_squares<3>(P, *scene.container3, 0.1, 0.15, LeastSquaresOptions{}, kTol);
    expect_sound<3>(P, n, box_distance<3>(Vec3(0, 0, 0), Vec3(6, 6, 0.4)), 0.1, 0.15, "one particle thick");
    EXPECT_GT(volume_fraction<3>(P, 6 * 6 * 0.4), before + 0.02);
  }
}

}  // namespace
}  // namespace fptest
