// Void filling (densify/void_filling.hpp, paper 000 step 7b) after the front, checked by the
// independent brute-force code of tests/front: no overlap beyond epsilon r_min, every sphere
// inside, radii in range, every new sphere with z_min contacts (counted by brute force), the
// requested law kept in distribution mode, phi0 and N0 honoured, byte-identical reruns, and the
// same packing 1e9 away or scaled by 2^+-60.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "core/metrics/radii_fit.hpp"
#include "core/metrics/validate.hpp"
#include "densify/void_filling.hpp"
#include "front/pack.hpp"
#include "tests/front/front_checks.hpp"

namespace fptest {
namespace {

using fp::DensifyOptions;
using fp::Packing;
using fp::VoidRadii;

template <int D>
double ball_measure(double r) {
  return D == 3 ? 4.0 / 3.0 * std::numbers::pi * r * r * r : std::numbers::pi * r * r;
}

template <int D>
double solid(const Packing<D>& P, std::size_t from = 0) {
  double s = 0;
  for (std::size_t i = from; i < P.size(); ++i) s += ball_measure<D>(P.radii[i]);
  return s;
}

/// Per sphere i >= from: its contacts with every other sphere (|gap| <= tol min(ri, rj), or an
/// overlap) and with the walls (sd(c) + r >= -tol r), by brute force over all pairs.
template <int D>
std::vector<int> contacts_of_new(const Packing<D>& P, std::size_t from, const SignedDistance<D>& sd, double tol) {
  std::vector<int> z(P.size() - from, 0);
  for (std::size_t i = from; i < P.size(); ++i) {
    for (std::size_t j = 0; j < P.size(); ++j) {
      if (j == i) continue;
      const double gap = (P.centers[i] - P.centers[j]).norm() - P.radii[i] - P.radii[j];
      if (gap <= tol * std::min(P.radii[i], P.radii[j])) ++z[i - from];
    }
    if (sd(P.centers[i], P.origin) + P.radii[i] >= -tol * P.radii[i]) ++z[i - from];
  }
  return z;
}

struct Filled {
  Packing<3> packing;
  std::size_t before = 0;
  fp::VoidFillingReport report;
};

Filled front_then_fill(const fp::Scene& scene, const DensifyOptions& o) {
  Filled f;
  f.packing = fp::pack<3>(scene).packing;
  f.before = f.packing.size();
  f.report = fp::fill_voids<3>(f.packing, *scene.container3, *scene.radii, o, scene.seed, scene.packer.contact_tolerance);
  return f;
}

std::string box_scene(double lo, double hi, double r_min, double r_max, int seed = 5) {
  char text[512];
  std::snprintf(text, sizeof text,
                "dimension: 3\nseed: %d\ncontainer: {type: box, min: [%.17g, %.17g, %.17g], max: [%.17g, %.17g, %.17g]}\n"
                "particles: {radius: {distribution: uniform, min: %.17g, max: %.17g}}\n",
                seed, lo, lo, lo, hi, hi, hi, r_min, r_max);
  return text;
}

TEST(VoidFilling, FitModeFillsABoxWithoutOverlapAndEveryNewSphereTouchesZMin) {
  const fp::Scene scene = scene_from_yaml(box_scene(0, 0.45, 0.01, 0.07));
  DensifyOptions o;
  o.radii = VoidRadii::Fit;
  const Filled f = front_then_fill(scene, o);
  const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(0.45, 0.45, 0.45));
  expect_valid<3>(f.packing, sd, 0.01, 0.07, "fit");
  ASSERT_GT(f.report.added, f.before / 2) << "R = 7: the voids of a front packing hold many small spheres";
  EXPECT_EQ(f.report.added, f.packing.size() - f.before);
  EXPECT_EQ(f.report.stop, fp::VoidFillingStop::NoVoidFits);
  EXPECT_NEAR(f.report.solid_after, solid<3>(f.packing), 1e-12 * f.report.solid_after);
  EXPECT_GT(f.report.solid_after / 0.45 / 0.45 / 0.45, f.report.solid_before / 0.45 / 0.45 / 0.45 + 0.05);
  const std::vector<int> z = contacts_of_new<3>(f.packing, f.before, sd, 1e-9);
  EXPECT_GE(*std::min_element(z.begin(), z.end()), 3) << "z_min defaults to the dimension";
  // The paper's geometric procedure: spheres of the voids' own radius touch four bodies.
  const auto four = std::count_if(z.begin(), z.end(), [](int c) { return c >= 4; });
  EXPECT_GT(static_cast<double>(four), 0.5 * static_cast<double>(z.size()));
  // The project's validator agrees (its own cell list and container code), radii in range only.
  const fp::ValidationReport v = fp::validate_packing<3>(f.packing, *scene.container3, scene.radii.get(), 1e-9, 0.0);
  EXPECT_TRUE(v.ok) << v.summary();
}

TEST(VoidFilling, DistributionModeKeepsTheLawAndLeavesAtMostThePoolUnplaced) {
  // A law with many small spheres (uniform by count on [0.01, 0.07] would draw mostly spheres the
  // voids cannot take): a mixture where half the count is small.
  const std::string text =
      "dimension: 3\nseed: 9\ncontainer: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}\n"
      "particles: {radius: {distribution: discrete, values: [[0.012, 0.8], [0.05, 0.2]]}}\n";
  const fp::Scene scene = scene_from_yaml(text);
  DensifyOptions o;
  o.radius_pool = 8;
  const Filled f = front_then_fill(scene, o);
  const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(0.4, 0.4, 0.4));
  expect_valid<3>(f.packing, sd, 0.012, 0.05, "distribution");
  // A fifth of the draws are large: the pool fills with them after some 40 draws.
  EXPECT_GT(f.report.added, 20u);
  EXPECT_LE(f.report.radii_unplaced, 8u);
  EXPECT_EQ(f.report.radii_drawn, f.report.added + f.report.radii_unplaced);
  for (std::size_t i = f.before; i < f.packing.size(); ++i)
    EXPECT_TRUE(f.packing.radii[i] == 0.012 || f.packing.radii[i] == 0.05) << "radius " << f.packing.radii[i];
  const fp::RadiiFit fit = fp::radii_fit(f.packing.radii, *scene.radii);
  EXPECT_GE(fit.p, 1e-3) << fit.describe();
  const std::vector<int> z = contacts_of_new<3>(f.packing, f.before, sd, 1e-9);
  EXPECT_GE(*std::min_element(z.begin(), z.end()), 3);
}

TEST(VoidFilling, FallbackToRMinFillsMoreVoidsWithSpheresOfRMin) {
  const fp::Scene scene = scene_from_yaml(box_scene(0, 0.4, 0.01, 0.07, 12));
  DensifyOptions fit, fallback;
  fit.radii = fallback.radii = VoidRadii::Fit;
  fallback.fallback_r_min = true;
  const Filled a = front_then_fill(scene, fit), b = front_then_fill(scene, fallback);
  const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(0.4, 0.4, 0.4));
  expect_valid<3>(b.packing, sd, 0.01, 0.07, "fallback");
  EXPECT_GT(b.report.solid_after, a.report.solid_after);
  const auto at_r_min = std::count(b.packing.radii.begin() + static_cast<std::ptrdiff_t>(b.before), b.packing.radii.end(), 0.01);
  EXPECT_GT(static_cast<std::size_t>(at_r_min), b.report.added / 4) << "many voids took a sphere of r_min";
  const std::vector<int> z = contacts_of_new<3>(b.packing, b.before, sd, 1e-9);
  EXPECT_GE(*std::min_element(z.begin(), z.end()), 3);
}

TEST(VoidFilling, AllowedOverlapStaysWithinEpsilonRMin) {
  const fp::Scene scene = scene_from_yaml(box_scene(0, 0.4, 0.01, 0.07, 3));
  DensifyOptions exact, loose;
  exact.radii = loose.radii = VoidRadii::Fit;
  loose.overlap = 0.05;
  const Filled a = front_then_fill(scene, exact), b = front_then_fill(scene, loose);
  const OverlapReport oa = overlaps<3>(a.packing), ob = overlaps<3>(b.packing);
  EXPECT_LE(oa.max_over_rmin, 1e-9) << "epsilon = 0: no overlap beyond the contact tolerance";
  EXPECT_LE(ob.max_over_rmin, 0.05 * (1 + 1e-9));
  EXPECT_GT(ob.max_over_rmin, 0.01) << "the allowance is used: radii reduced to an overlap of epsilon r_min";
  const double smallest = *std::min_element(b.packing.radii.begin(), b.packing.radii.end());
  EXPECT_NEAR(b.report.max_overlap_over_r_min, ob.max_over_rmin * smallest / 0.01, 1e-9)
      << "the stage's own figure is the brute force's";
}

TEST(VoidFilling, StopsAtTheTargetSolidFractionAndCount) {
  const fp::Scene scene = scene_from_yaml(box_scene(0, 0.4, 0.01, 0.07, 4));
  const double volume = 0.4 * 0.4 * 0.4;
  DensifyOptions o;
  o.radii = VoidRadii::Fit;
  const Filled all = front_then_fill(scene, o);
  const double phi_front = all.report.solid_before / volume, phi_all = all.report.solid_after / volume;
  o.target_volume_fraction = 0.5 * (phi_front + phi_all);
  const Filled phi = front_then_fill(scene, o);
  EXPECT_EQ(phi.report.stop, fp::VoidFillingStop::VolumeFraction);
  const double reached = solid<3>(phi.packing) / volume;
  EXPECT_GE(reached, *o.target_volume_fraction);
  EXPECT_LT(reached - ball_measure<3>(phi.packing.radii.back()) / volume, *o.target_volume_fraction)
      << "checked after every sphere: the last one crossed phi0";
  o.target_volume_fraction.reset();
  o.max_particles = all.before + all.report.added / 3;
  const Filled count = front_then_fill(scene, o);
  EXPECT_EQ(count.report.stop, fp::VoidFillingStop::ParticleCount);
  EXPECT_EQ(count.packing.size(), *o.max_particles);
  o.max_particles.reset();
  o.rounds = 1;
  const Filled one = front_then_fill(scene, o);
  EXPECT_EQ(one.report.rounds, 1);
  EXPECT_EQ(one.report.stop, fp::VoidFillingStop::Rounds);
  EXPECT_LT(one.report.added, all.report.added);
}

TEST(VoidFilling, RerunsAreByteIdentical) {
  const fp::Scene scene = scene_from_yaml(box_scene(0, 0.35, 0.01, 0.05, 8));
  for (const VoidRadii mode : {VoidRadii::Fit, VoidRadii::Distribution}) {
    DensifyOptions o;
    o.radii = mode;
    const Filled a = front_then_fill(scene, o), b = front_then_fill(scene, o);
    ASSERT_EQ(a.packing.size(), b.packing.size());
    EXPECT_EQ(0, std::memcmp(a.packing.centers.data(), b.packing.centers.data(), a.packing.size() * sizeof(Vec3)));
    EXPECT_EQ(0, std::memcmp(a.packing.radii.data(), b.packing.radii.data(), a.packing.size() * sizeof(double)));
  }
}

TEST(VoidFilling, CurvedWallsSphereAndCylinder) {
  for (const char* container : {"{type: sphere, center: [0.1, 0.2, 0.3], radius: 0.25}",
                                "{type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.2, height: 0.4}"}) {
    const fp::Scene scene = scene_from_yaml(std::string("dimension: 3\nseed: 2\ncontainer: ") + container +
                                            "\nparticles: {radius: {distribution: uniform, min: 0.008, max: 0.04}}\n");
    DensifyOptions o;
    o.radii = VoidRadii::Fit;
    const Filled f = front_then_fill(scene, o);
    const auto sd = std::strstr(container, "sphere") ? ball_distance<3>(Vec3(0.1, 0.2, 0.3), 0.25)
                                                     : cylinder_distance(Vec3(0, 0, 0), Vec3(0, 0, 1), 0.2, 0.4);
    expect_valid<3>(f.packing, sd, 0.008, 0.04, container);
    EXPECT_GT(f.report.added, f.before / 3) << container;
    EXPECT_GT(f.report.mirrored, 0u) << container;
    const std::vector<int> z = contacts_of_new<3>(f.packing, f.before, sd, 1e-9);
    EXPECT_GE(*std::min_element(z.begin(), z.end()), 3) << container;
    // Spheres were added against the curved wall, not only inside.
    std::size_t at_wall = 0;
    for (std::size_t i = f.before; i < f.packing.size(); ++i)
      at_wall += sd(f.packing.centers[i], f.packing.origin) + f.packing.radii[i] >= -1e-9 * f.packing.radii[i];
    EXPECT_GT(at_wall, 10u) << container;
  }
}

TEST(VoidFilling, DisksIn2D) {
  for (const VoidRadii mode : {VoidRadii::Fit, VoidRadii::Distribution}) {
    const fp::Scene scene = scene_from_yaml(
        "dimension: 2\nseed: 3\ncontainer: {type: disk, center: [0, 0], radius: 1}\n"
        "particles: {radius: {distribution: discrete, values: [[0.01, 0.7], [0.05, 0.3]]}}\n");
    Packing<2> P = fp::pack<2>(scene).packing;
    const std::size_t before = P.size();
    DensifyOptions o;
    o.radii = mode;
    const fp::VoidFillingReport r = fp::fill_voids<2>(P, *scene.container2, *scene.radii, o, 3, 1e-9);
    const auto sd = ball_distance<2>(Vec2(0, 0), 1.0);
    expect_valid<2>(P, sd, 0.01, 0.05, "2D");
    EXPECT_GT(r.added, 20u);
    const std::vector<int> zz = contacts_of_new<2>(P, before, sd, 1e-9);
    EXPECT_GE(*std::min_element(zz.begin(), zz.end()), 2) << "z_min defaults to the dimension";
  }
}

/// Far and scaled scenes fill as the plain one. Shifted by 2^30 and scaled by 2^+-60 the
/// container's local frame holds the same numbers (times the scale): the same spheres, bit for bit
/// up to the scale. Shifted by 1e9 its far face moves by a rounding (1e9 + 0.5 is not 0.5 away),
/// so the front differs: the solid fraction after filling within 0.01, its gain within 0.01.
TEST(VoidFilling, FarAndScaledScenesFillAsThePlainOne) {
  DensifyOptions o;
  o.radii = VoidRadii::Fit;
  const Filled plain = front_then_fill(scene_from_yaml(box_scene(0, 0.25, 0.01, 0.05, 6)), o);
  ASSERT_GT(plain.report.added, 50u);
  struct Case { const char* name; double shift, scale; };
  for (const Case c : {Case{"2^30 away", std::ldexp(1.0, 30), 1.0}, Case{"2^-60", 0.0, std::ldexp(1.0, -60)},
                       Case{"2^60", 0.0, std::ldexp(1.0, 60)}}) {
    const double lo = c.shift, hi = c.shift + 0.25 * c.scale;
    const fp::Scene scene = scene_from_yaml(box_scene(lo, hi, 0.01 * c.scale, 0.05 * c.scale, 6));
    const Filled f = front_then_fill(scene, o);
    expect_valid<3>(f.packing, box_distance<3>(Vec3(lo, lo, lo), Vec3(hi, hi, hi)), 0.01 * c.scale, 0.05 * c.scale, c.name);
    ASSERT_EQ(f.packing.size(), plain.packing.size()) << c.name;
    for (std::size_t i = 0; i < f.packing.size(); ++i) {
      ASSERT_EQ(f.packing.radii[i], plain.packing.radii[i] * c.scale) << c.name << " sphere " << i;
      ASSERT_EQ(f.packing.centers[i], plain.packing.centers[i] * c.scale) << c.name << " sphere " << i;
    }
  }
  const double volume = 0.5 * 0.5 * 0.5;
  const Filled near = front_then_fill(scene_from_yaml(box_scene(0, 0.5, 0.01, 0.05, 6)), o);
  const Filled far = front_then_fill(scene_from_yaml(box_scene(1e9, 1e9 + 0.5, 0.01, 0.05, 6)), o);
  expect_valid<3>(far.packing, box_distance<3>(Vec3(1e9, 1e9, 1e9), Vec3(1e9 + 0.5, 1e9 + 0.5, 1e9 + 0.5)), 0.01, 0.05, "1e9");
  EXPECT_NEAR(far.report.solid_after / volume, near.report.solid_after / volume, 0.01);
  EXPECT_NEAR((far.report.solid_after - far.report.solid_before) / volume,
              (near.report.solid_after - near.report.solid_before) / volume, 0.01);
}

}  // namespace
}  // namespace fptest
