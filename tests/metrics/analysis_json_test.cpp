// JSON of the analysis (core/io/analysis_json.hpp; the figures of papers 000 and 002): layout,
// values, null for NaN, determinism.
#include "core/io/analysis_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/geometry/box_container.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

TEST(AnalysisJson, LayoutAndValues) {
  const auto lat = test::simple_cubic(10, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(9.5));
  const PackingAnalysis a = analyze_packing<3>(lat.packing, &box, nullptr);
  const std::string text = analysis_json(a);
  ASSERT_EQ(text.back(), '\n');
  EXPECT_EQ(text, analysis_json(analyze_packing<3>(lat.packing, &box, nullptr)));  // byte for byte

  const auto j = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"dimension", "particles", "radii", "container", "contact_tolerance",
                                            "volume_fraction", "coordination", "overlap", "fabric", "homogeneity",
                                            "radii_fit", "relative_projections", "rdf", "validation"}));
  EXPECT_EQ(j["particles"], 1000);
  EXPECT_EQ(j["container"]["description"], box.describe());
  EXPECT_EQ(j["volume_fraction"]["curve"]["r_ref"].size(), 31u);
  EXPECT_EQ(j["volume_fraction"]["core"]["value"].get<double>(), a.vf_core.vf.value);
  EXPECT_EQ(j["volume_fraction"]["core"]["exact"], true);
  EXPECT_EQ(j["coordination"]["contacts"], a.coordination.contacts);
  EXPECT_EQ(j["coordination"]["histogram"].size(), 7u);
  EXPECT_EQ(j["coordination"]["partial"]["z"].size(), 21u);
  EXPECT_TRUE(j["overlap"]["worst_pair"].is_null());
  EXPECT_EQ(j["fabric"]["per_contact"]["tensor"].size(), 3u);
  EXPECT_EQ(j["fabric"]["per_contact"]["tensor"][1][1].get<double>(), a.fabric.per_contact.tensor[4]);
  EXPECT_EQ(j["homogeneity"]["axes"][2]["axis"], "z");
  EXPECT_EQ(j["homogeneity"]["axes"][0]["below_critical"], false);
  EXPECT_TRUE(j["radii_fit"]["statistic"].is_null());  // NaN: no distribution given
  EXPECT_EQ(j["radii_fit"]["test"], "");
  EXPECT_EQ(j["relative_projections"]["axes"][0]["histogram"].size(), 20u);
  EXPECT_EQ(j["rdf"]["g"].size(), 100u);
  EXPECT_EQ(j["validation"]["ok"], true);
  EXPECT_FALSE(j.contains("timings"));

  const auto timed = nlohmann::ordered_json::parse(analysis_json(a, true));
  ASSERT_TRUE(timed.contains("timings"));
  EXPECT_EQ(timed["timings"].size(), a.timings.size());
}

TEST(AnalysisJson, TwoDimensionsAndNoValidation) {
  const auto lat = test::hexagonal(20, 20, 1.0, Vec2::Zero());
  AnalysisOptions o;
  o.validate = false;
  const auto j = nlohmann::ordered_json::parse(analysis_json(analyze_packing<2>(lat.packing, nullptr, nullptr, o)));
  EXPECT_EQ(j["dimension"], 2);
  EXPECT_EQ(j["container"]["from_particles"], true);
  EXPECT_EQ(j["fabric"]["per_particle"]["tensor"].size(), 2u);
  EXPECT_EQ(j["homogeneity"]["axes"].size(), 2u);
  EXPECT_TRUE(j["validation"].is_null());
}

}  // namespace
}  // namespace fp
