// The family registry and the parameter reader: every family resolves in the dimensions it
// exists in, and every bad template is a SceneError that names the file, line and key.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "core/io/scene_error.hpp"
#include "shape_test_support.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/shape_parameters.hpp"

namespace fp {
namespace {

using test::make_spec;
using test::numbers;

/// The SceneError of resolving `spec` in dimension D ("" if it resolves).
template <int D>
std::string error_of(const ParticleTemplateSpec& spec) {
  try {
    ShapeFamilies::builtin().prototype<D>(spec);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeFamilies, BuiltinFamilies) {
  const std::vector<std::string> expected = {"cluster", "cylinder", "ellipse", "ellipsoid", "polygon",
                                             "polyhedron", "sphere", "spherocylinder"};
  EXPECT_EQ(ShapeFamilies::builtin().names(), expected);
  for (const auto& name : expected) EXPECT_TRUE(ShapeFamilies::builtin().has(name));
}

TEST(ShapeFamilies, AddRejectsDuplicatesAndEmptyFamilies) {
  ShapeFamilies f;
  register_builtin_shapes(f);
  EXPECT_THROW(f.add("sphere", nullptr, [](const ShapeParameters& p) { return test::prototype<3>("sphere", p); }),
               std::logic_error);
  EXPECT_THROW(f.add("nothing", nullptr, nullptr), std::logic_error);
}

TEST(ShapeFamilies, SizeOnMustNameADimension) {
  auto spec = make_spec("spherocylinder", numbers({{"aspect_ratio", 0.5}}));
  spec.size_on = "width";
  EXPECT_EQ(error_of<3>(spec), "");
  spec.size_on = "girth";
  EXPECT_EQ(error_of<3>(spec),
            "scene.yaml:7:3: key 'particles[0].size_on': shape 'spherocylinder' has no dimension 'girth' (its "
            "dimensions: circumscribed_radius, cylinder_length, equivalent_radius, length, radius, width)");
}

TEST(ShapeFamilies, UnknownFamilyListsTheKnownOnes) {
  EXPECT_EQ(error_of<3>(make_spec("blob")),
            "scene.yaml:7:3: key 'particles[0].shape': unknown shape 'blob' (known in 3D: cluster, cylinder, "
            "ellipsoid, polyhedron, sphere, spherocylinder)");
  EXPECT_NE(error_of<2>(make_spec("blob")).find("known in 2D: cluster, ellipse, polygon, sphere, spherocylinder)"),
            std::string::npos);
}

TEST(ShapeFamilies, FamilyMissingInThisDimension) {
  EXPECT_EQ(error_of<3>(make_spec("polygon", numbers({{"sides", 5}}))),
            "scene.yaml:7:3: key 'particles[0].shape': shape 'polygon' does not exist in 3D (known in 3D: cluster, "
            "cylinder, ellipsoid, polyhedron, sphere, spherocylinder)");
  EXPECT_NE(error_of<2>(make_spec("cylinder", numbers({{"aspect_ratio", 1}}))).find("does not exist in 2D"),
            std::string::npos);
  EXPECT_NE(error_of<2>(make_spec("polyhedron", numbers({{"platonic", 6}}))).find("does not exist in 2D"),
            std::string::npos);
}

TEST(ShapeFamilies, BadAspectRatioIsReportedWhereItWasWritten) {
  ShapeParameters p = numbers({{"aspect_ratio", 1.5}});
  p.spots["aspect_ratio"] = SourceSpot{"scene.yaml", 9, 21, "particles[0].aspect_ratio"};
  EXPECT_EQ(error_of<3>(make_spec("spherocylinder", p)),
            "scene.yaml:9:21: key 'particles[0].aspect_ratio': must be in (0, 1] (width / total length; got 1.5)");
  p.numbers["aspect_ratio"] = 0;
  EXPECT_NE(error_of<2>(make_spec("spherocylinder", p)).find("got 0)"), std::string::npos);
  p.numbers["aspect_ratio"] = -2;
  EXPECT_EQ(error_of<3>(make_spec("cylinder", p)),
            "scene.yaml:9:21: key 'particles[0].aspect_ratio': must be > 0 (diameter / height; got -2)");
  // Missing: reported at the template, under the key it should have had.
  EXPECT_EQ(error_of<3>(make_spec("spherocylinder")),
            "scene.yaml:7:3: key 'particles[0].elongation': missing: total length / width (or aspect_ratio = width / "
            "total length)");
}

TEST(ShapeFamilies, ElongationIsTheInverseOfTheOlderAspectRatioForCapsulesAndCylinders) {
  // The same shape from either key: elongation 2 is aspect_ratio 0.5 exactly.
  for (const char* family : {"spherocylinder", "cylinder"}) {
    const auto by_elongation = make_spec(family, numbers({{"elongation", 2}}));
    const auto by_aspect = make_spec(family, numbers({{"aspect_ratio", 0.5}}));
    const auto a = ShapeFamilies::builtin().prototype<3>(by_elongation), b = ShapeFamilies::builtin().prototype<3>(by_aspect);
    EXPECT_EQ(a.shape->definition_json(), b.shape->definition_json()) << family;
    EXPECT_EQ(a.dimensions, b.dimensions) << family;
  }
  // A capsule is never shorter than wide; a cylinder may be a disc.
  ShapeParameters p = numbers({{"elongation", 0.5}});
  p.spots["elongation"] = SourceSpot{"scene.yaml", 9, 21, "particles[0].elongation"};
  EXPECT_EQ(error_of<3>(make_spec("spherocylinder", p)),
            "scene.yaml:9:21: key 'particles[0].elongation': must be >= 1 (total length / width; got 0.5)");
  EXPECT_EQ(error_of<3>(make_spec("cylinder", p)), "");
  p.numbers["elongation"] = 0;
  EXPECT_NE(error_of<3>(make_spec("cylinder", p)).find("must be > 0 (height / diameter; got 0)"), std::string::npos);
  // Both keys: refused, at the older one.
  EXPECT_NE(error_of<3>(make_spec("cylinder", numbers({{"elongation", 2}, {"aspect_ratio", 0.5}})))
                .find("'particles[0].aspect_ratio': give elongation (height / diameter) or aspect_ratio (its inverse"),
            std::string::npos);
}

TEST(ShapeFamilies, UnknownParameter) {
  EXPECT_EQ(error_of<3>(make_spec("sphere", numbers({{"radius", 2}}))),
            "scene.yaml:7:3: key 'particles[0].radius': unknown parameter 'radius' of shape 'sphere' (it takes none)");
  EXPECT_NE(error_of<3>(make_spec("spherocylinder", numbers({{"aspect_ratio", 0.5}, {"aspect", 2}})))
                .find("key 'particles[0].aspect': unknown parameter 'aspect' of shape 'spherocylinder' (known: "),
            std::string::npos);
}

TEST(ShapeFamilies, WrongVertexDimension) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{0, 0, 0}, {1, 0, 0}, {0, 1}, {0, 0, 1}};
  p.spots["vertices"] = SourceSpot{"scene.yaml", 12, 15, "particles[0].vertices"};
  EXPECT_EQ(error_of<3>(make_spec("polyhedron", p)),
            "scene.yaml:12:15: key 'particles[0].vertices': point 2 has 2 coordinates; a 3D scene needs 3 (the "
            "vertices, a list of points)");
  p.point_lists["vertices"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NE(error_of<2>(make_spec("polygon", p)).find("point 0 has 3 coordinates; a 2D scene needs 2"), std::string::npos);
}

TEST(ShapeFamilies, DegenerateVertices) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_EQ(error_of<3>(make_spec("polyhedron", p)),
            "scene.yaml:7:3: key 'particles[0].vertices': the vertices are coplanar: a polyhedron needs volume");
  p.point_lists["vertices"] = {{0, 0}, {1, 1}, {3, 3}};
  EXPECT_NE(error_of<2>(make_spec("polygon", p)).find("collinear"), std::string::npos);
  EXPECT_NE(error_of<2>(make_spec("polygon")).find("key 'particles[0].vertices': missing"), std::string::npos);
  p.numbers["sides"] = 5;
  EXPECT_NE(error_of<2>(make_spec("polygon", p)).find("give one of 'vertices', 'sides'"), std::string::npos);
}

TEST(ShapeFamilies, BadShortcuts) {
  EXPECT_NE(error_of<2>(make_spec("polygon", numbers({{"sides", 2.5}}))).find("key 'particles[0].sides': must be a whole number >= 3"),
            std::string::npos);
  EXPECT_NE(error_of<3>(make_spec("polyhedron", numbers({{"platonic", 7}}))).find("must be 4, 6, 8, 12 or 20"),
            std::string::npos);
}

// Found by tests/fuzz (a hang: 'sides: 155201' built its face planes in vertices x faces). The
// largest accepted count is built, the next one refused.
TEST(ShapeFamilies, TooManySidesOrVertices) {
  constexpr int kMax = ConvexPolytopeShape<2>::kMaxTemplatePoints;
  EXPECT_EQ(error_of<2>(make_spec("polygon", numbers({{"sides", kMax}}))), "");
  EXPECT_NE(error_of<2>(make_spec("polygon", numbers({{"sides", kMax + 1}}))).find("key 'particles[0].sides': at most 10000 sides"),
            std::string::npos);
  ShapeParameters p;
  for (int k = 0; k <= kMax; ++k) {
    const double t = 2 * 3.141592653589793 * k / (kMax + 1);
    p.point_lists["vertices"].push_back({std::cos(t), std::sin(t)});
  }
  EXPECT_NE(error_of<2>(make_spec("polygon", p)).find("at most 10000 vertices (got 10001)"), std::string::npos);
}

TEST(ShapeFamilies, BadClusters) {
  ShapeParameters p;
  p.point_lists["centers"] = {{0, 0, 0}, {1, 0, 0}};
  p.lists["radii"] = {1.0};
  EXPECT_EQ(error_of<3>(make_spec("cluster", p)),
            "scene.yaml:7:3: key 'particles[0].radii': has 1 radii for 2 centres (one radius per centre)");
  p.lists["radii"] = {1.0, -0.5};
  EXPECT_NE(error_of<3>(make_spec("cluster", p)).find("radius 1 must be positive (got -0.5)"), std::string::npos);
  p.point_lists.erase("centers");
  p.lists["centers"] = {};
  EXPECT_NE(error_of<3>(make_spec("cluster", p)).find("key 'particles[0].centers': a cluster needs at least one member"),
            std::string::npos);
  p.lists["centers"] = {1.0, 2.0, 3.0};
  EXPECT_NE(error_of<3>(make_spec("cluster", p)).find("expected a list of 3D points"), std::string::npos);
}

/// The members of a cluster preset in dimension D.
template <int D>
std::vector<Ball<D>> preset_members(const std::string& name) {
  ParticleTemplateSpec spec;
  spec.family = "cluster";
  spec.parameters.strings["preset"] = name;
  const ShapePrototype<D> p = ShapeFamilies::builtin().prototype<D>(spec);
  EXPECT_NEAR(p.shape->bounding_radius(), 1.0, 1e-12) << name;
  return dynamic_cast<const ClusterShape<D>&>(*p.shape).members();
}

TEST(ShapeFamilies, ClusterPresetsAreTheSameClumpIn2DAnd3D) {
  for (const auto& [name, count] : std::vector<std::pair<std::string, std::size_t>>{{"dimer", 2}, {"trimer", 3}}) {
    const auto m2 = preset_members<2>(name);
    const auto m3 = preset_members<3>(name);
    ASSERT_EQ(m2.size(), count) << name;
    ASSERT_EQ(m3.size(), count) << name;
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_NEAR(m2[i].radius, m2[0].radius, 1e-15) << name;  // equal members
      EXPECT_NEAR(m3[i].radius, m2[i].radius, 1e-15) << name;
      EXPECT_NEAR((m3[i].center.head<2>() - m2[i].center).norm(), 0.0, 1e-15) << name;
      EXPECT_EQ(m3[i].center.z(), 0.0) << name;  // in the plane z = 0
      for (std::size_t j = 0; j < i; ++j)          // each touching the others
        EXPECT_NEAR((m2[i].center - m2[j].center).norm(), 2 * m2[0].radius, 1e-14) << name;
    }
  }
  ParticleTemplateSpec spec;
  spec.family = "cluster";
  spec.parameters.strings["preset"] = "tetramer";
  EXPECT_NE(error_of<3>(spec).find("unknown cluster preset 'tetramer' (dimer: "), std::string::npos) << error_of<3>(spec);
  spec.parameters.strings["preset"] = "dimer";
  spec.parameters.lists["radii"] = {1.0};
  EXPECT_NE(error_of<2>(spec).find("give either a preset or centers and radii"), std::string::npos) << error_of<2>(spec);
}

/// Every family's description is what its factory does: a template of each, in each dimension
/// the family exists in, has exactly the dimensions the description lists, and every parameter
/// the description names is accepted (the registry refuses any other).
TEST(ShapeFamilies, TheDescriptionsAreTheFactories) {
  const ShapeFamilies& families = ShapeFamilies::builtin();
  std::map<std::string, ShapeParameters> examples;
  examples["sphere"];
  examples["spherocylinder"].numbers["aspect_ratio"] = 0.5;
  examples["cluster"].strings["preset"] = "dimer";
  examples["polygon"].numbers["sides"] = 5;
  examples["polyhedron"].strings["preset"] = "cube";
  examples["ellipse"].lists["axes"] = {1, 0.5};
  examples["ellipsoid"].lists["axes"] = {1, 0.5, 0.3};
  examples["cylinder"].numbers["aspect_ratio"] = 1;
  for (const std::string& name : families.names()) {
    SCOPED_TRACE(name);
    ASSERT_EQ(examples.count(name), 1u) << "add an example of the new family here";
    const ShapeFamilyInfo& info = families.info(name);
    EXPECT_FALSE(info.summary.empty());
    ASSERT_FALSE(info.size_on.empty());
    EXPECT_EQ(info.size_on.front(), "circumscribed_radius");
    for (const auto& [parameter, meaning] : info.parameters) EXPECT_FALSE(meaning.empty()) << parameter;
    const auto dimensions_of = [](const auto& proto) {
      std::vector<std::string> names{"circumscribed_radius"};
      for (const auto& [n, v] : proto.dimensions)
        if (n != "circumscribed_radius") names.push_back(n);
      return names;
    };
    ParticleTemplateSpec spec = make_spec(name, examples[name]);
    if (families.in_dimension(name, 2)) EXPECT_EQ(dimensions_of(families.prototype<2>(spec)), info.size_on);
    if (families.in_dimension(name, 3)) EXPECT_EQ(dimensions_of(families.prototype<3>(spec)), info.size_on);
    // A parameter the description does not name is refused, naming those it does.
    spec.parameters.numbers["bogus"] = 1;
    const std::string error = families.in_dimension(name, 3) ? error_of<3>(spec) : error_of<2>(spec);
    EXPECT_NE(error.find("unknown parameter 'bogus' of shape '" + name + "'"), std::string::npos) << error;
    for (const auto& [parameter, meaning] : info.parameters) EXPECT_NE(error.find(parameter), std::string::npos) << error;
  }
}

TEST(ShapeFamilies, BadEllipseAxes) {
  ShapeParameters p;
  p.lists["axes"] = {1.0, 0.5, 0.2};
  EXPECT_NE(error_of<2>(make_spec("ellipse", p)).find("needs 2 semi-axes in 2D (got 3)"), std::string::npos);
  p.lists["axes"] = {1.0, 0.0, 0.2};
  EXPECT_NE(error_of<3>(make_spec("ellipsoid", p)).find("semi-axis 1 must be positive"), std::string::npos);
  // Positive but negligible: refused with the ratio (it ran out of memory in the analysis).
  p.lists["axes"] = {1.0, 1e-300, 1.0};
  EXPECT_NE(error_of<3>(make_spec("ellipsoid", p)).find("the smallest semi-axis is 1e-300 of the largest"), std::string::npos);
  p.lists["axes"] = {1e-13, 0.2};
  EXPECT_NE(error_of<2>(make_spec("ellipse", p)).find("below 1e-12"), std::string::npos) << error_of<2>(make_spec("ellipse", p));
  p.lists["axes"] = {1.0, 1e-12, 1.0};
  EXPECT_EQ(error_of<3>(make_spec("ellipsoid", p)), "");
}

TEST(ParameterReader, TypesRangesAndDefaults) {
  ShapeParameters p;
  p.numbers["n"] = 2;
  p.numbers["inf"] = std::numeric_limits<double>::infinity();
  p.lists["l"] = {1, 2};
  p.point_lists["pts"] = {{1, 2}};
  p.spot = SourceSpot{"s.yaml", 3, 5, "particles[2]"};
  const ParameterReader r(p);
  EXPECT_EQ(r.number("n", "n"), 2);
  EXPECT_EQ(r.number_or("missing", 7), 7);
  EXPECT_EQ(r.list("n", "n"), std::vector<double>{2});  // a number is a list of one
  EXPECT_EQ(r.number_in("n", "n", 2, 3, true), 2);
  EXPECT_TRUE(r.has("pts"));
  EXPECT_FALSE(r.has("nope"));
  auto message = [&](auto&& f) {
    try {
      f();
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message([&] { r.number_in("n", "n", 2, 3); }), "s.yaml:3:5: key 'particles[2].n': must be in (2, 3] (n; got 2)");
  EXPECT_EQ(message([&] { r.number("l", "a size"); }), "s.yaml:3:5: key 'particles[2].l': expected a number (a size), got a list");
  EXPECT_EQ(message([&] { r.number("inf", "a size"); }), "s.yaml:3:5: key 'particles[2].inf': must be a finite number (a size)");
  EXPECT_EQ(message([&] { r.check_known({"n", "l", "pts"}, "x"); }),
            "s.yaml:3:5: key 'particles[2].inf': unknown parameter 'inf' of shape 'x' (known: n, l, pts)");
  EXPECT_EQ(message([&] { r.points("pts", "p", 2); }), "");
  EXPECT_NE(message([&] { r.points("l", "p", 2); }).find("expected a list of 2D points"), std::string::npos);
}

}  // namespace
}  // namespace fp

namespace fp {
namespace {

// `preset:` names a Platonic solid; an unknown name is an error naming the key.
TEST(ShapeFamilies, PolyhedronPresets) {
  for (const auto& [name, vertices] : std::vector<std::pair<std::string, std::size_t>>{
           {"tetrahedron", 4}, {"cube", 8}, {"octahedron", 6}, {"dodecahedron", 20}, {"icosahedron", 12}}) {
    ParticleTemplateSpec spec;
    spec.family = "polyhedron";
    spec.parameters.strings["preset"] = name;
    const ShapePrototype<3> p = ShapeFamilies::builtin().prototype<3>(spec);
    EXPECT_NEAR(p.shape->bounding_radius(), 1.0, 1e-12) << name;
    EXPECT_EQ(p.shape->hull_balls().size(), vertices) << name;
  }
  ParticleTemplateSpec bad;
  bad.family = "polyhedron";
  bad.parameters.strings["preset"] = "cubic";
  bad.parameters.spots["preset"] = SourceSpot{"s.yaml", 7, 13, "particles[0].preset"};
  try {
    ShapeFamilies::builtin().prototype<3>(bad);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.yaml:7:13: key 'particles[0].preset': unknown preset 'cubic'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fp
