// Template shares by volume (or mass) converted to shares by number (shapes/template_fractions.hpp):
// hand-computed cases, and the scene's forms of `fraction` with their refusals.
#include "shapes/template_fractions.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/io/scene_error.hpp"
#include "core/io/scene_yaml.hpp"

namespace fp {
namespace {

const std::string kBox = "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [10, 10, 10]}\nparticles:\n";

std::string two_spheres(const std::string& a, const std::string& b) {
  return kBox + "  - {shape: sphere, size: {distribution: constant, value: 1}" + a + "}\n" +
         "  - {shape: sphere, size: {distribution: constant, value: 2}" + b + "}\n";
}

TEST(TemplateFractions, ByVolumeEachTemplateGetsItsShareOfTheSolid) {
  // Spheres of radius 1 and 2, half the volume each: 8 small ones for each large one.
  for (const char* basis : {"volume", "mass"}) {
    const Scene s = parse_scene(two_spheres(std::string(", fraction: {") + basis + ": 0.5}", std::string(", fraction: {") + basis + ": 0.5}"), "s.yaml");
    EXPECT_EQ(s.particle_templates[0].fraction_basis, FractionBasis::Volume);
    const std::vector<double> n = number_fractions<3>(s);
    EXPECT_NEAR(n[0], 8.0 / 9.0, 1e-12) << basis;
    EXPECT_NEAR(n[1], 1.0 / 9.0, 1e-12) << basis;
  }
  // By number (plain or named), the shares as given.
  for (const auto& [a, b] : {std::pair<std::string, std::string>{", fraction: 3", ", fraction: 1"},
                             {", fraction: {number: 3}", ", fraction: {number: 1}"}}) {
    const std::vector<double> n = number_fractions<3>(parse_scene(two_spheres(a, b), "s.yaml"));
    EXPECT_DOUBLE_EQ(n[0], 0.75);
    EXPECT_DOUBLE_EQ(n[1], 0.25);
  }
  // A template without a fraction takes 1 on the first one's basis: 2D disks of radius 1 and 3,
  // volume 1 : 1, so 9 : 1 by number.
  const Scene disks = parse_scene("dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [20, 20]}\nparticles:\n"
                                  "  - {shape: sphere, size: {distribution: constant, value: 1}, fraction: {volume: 1}}\n"
                                  "  - {shape: sphere, size: {distribution: constant, value: 3}}\n", "d.yaml");
  EXPECT_NEAR(number_fractions<2>(disks)[0], 0.9, 1e-12);
}

TEST(TemplateFractions, BadFormsAreRefusedAtTheirKey) {
  const auto refused = [](const std::string& text, const std::string& part) {
    try {
      parse_scene(text, "s.yaml");
      ADD_FAILURE() << "no error for\n" << text;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
      EXPECT_NE(e.key().find("fraction"), std::string::npos) << e.what();
    }
  };
  refused(two_spheres(", fraction: {volume: 0.5, mass: 0.5}", ""), "give one of number, volume or mass");
  refused(two_spheres(", fraction: {weight: 0.5}", ""), "weight");
  refused(two_spheres(", fraction: {volume: -1}", ""), "positive");
  refused(two_spheres(", fraction: {volume: 0.5}", ", fraction: 0.5"), "the same basis");
}

}  // namespace
}  // namespace fp
