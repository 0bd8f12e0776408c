// analyze_shape_packing: spheres given as shapes get the analysis of the same spheres given as a
// sphere packing (one analysis): the same contacts, coordination, z(xi), fabric, projections,
// homogeneity and g(r) (the contact normals of spheres are their centre lines), the same VF of the
// container, and the core VF of the sphere analysis' closed form within the QMC error.
#include "contact/shape_analysis.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/geometry/box_container.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {
namespace {

// Spheres of radius U[0.4, 0.5] on a jittered lattice of spacing 1 in a box of side 12; some
// pairs of neighbours pushed together until they touch.
struct Sample {
  ShapePacking<3> shapes;
  Packing<3> balls;
};

Sample sample() {
  Sample s;
  Rng rng(5);
  const UniformRadius law(0.4, 0.5);
  for (int k = 0; k < 1000; ++k) {
    const double r = law.sample(rng);
    Vec3 c(1.0 + k % 10, 1.0 + (k / 10) % 10, 1.0 + k / 100);
    if (k % 10 != 0 && k % 3 == 0) {  // touch the left neighbour
      const double left = s.balls.radii.back();
      c.x() = s.balls.centers.back().x() + left + r;
    }
    s.balls.add(c, r);
    Particle<3> p;
    p.shape = std::make_shared<SphereShape<3>>(r);
    p.pose.position = c;
    p.size = r;
    s.shapes.particles.push_back(p);
  }
  s.shapes.template_names = {"sphere"};
  return s;
}

TEST(ShapeAnalysis, SpheresAsShapesGetTheAnalysisOfSpheres) {
  const Sample s = sample();
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(12.0));
  const UniformRadius law(0.4, 0.5);
  AnalysisOptions o;
  o.contact_tolerance = 1e-9;
  const PackingAnalysis b = analyze_packing<3>(s.balls, &box, &law, o);
  const PackingAnalysis a = analyze_shape_packing<3>(s.shapes, box, {{&law, 1.0}}, {"sphere"}, o);

  EXPECT_EQ(a.radius_name, "r_eq");
  EXPECT_NEAR(a.r_min, b.r_min, 1e-14);
  EXPECT_NEAR(a.r_max, b.r_max, 1e-14);
  ASSERT_TRUE(a.validation && b.validation);
  EXPECT_TRUE(a.validation->ok) << a.validation->summary();
  EXPECT_EQ(a.coordination.contacts, b.coordination.contacts);
  EXPECT_GT(a.coordination.contacts, 200u);
  EXPECT_EQ(a.coordination.wall_contacts, b.coordination.wall_contacts);
  EXPECT_EQ(a.coordination.rattlers, b.coordination.rattlers);
  EXPECT_EQ(a.coordination.histogram, b.coordination.histogram);
  EXPECT_EQ(a.partial_coordination.contacts, b.partial_coordination.contacts);
  EXPECT_EQ(a.partial_coordination.particles, b.partial_coordination.particles);
  for (std::size_t k = 0; k < b.fabric.per_contact.tensor.size(); ++k) {
    EXPECT_NEAR(a.fabric.per_contact.tensor[k], b.fabric.per_contact.tensor[k], 1e-12);
    EXPECT_NEAR(a.fabric.per_particle.tensor[k], b.fabric.per_particle.tensor[k], 1e-12);
  }
  ASSERT_EQ(a.projections.ks.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(a.projections.histogram[k], b.projections.histogram[k]);
    EXPECT_NEAR(a.homogeneity.axis[k].d, b.homogeneity.axis[k].d, 1e-15);
  }
  EXPECT_NEAR(a.radii_fit.statistic, b.radii_fit.statistic, 1e-15);
  EXPECT_EQ(a.rdf.reference_particles, b.rdf.reference_particles);
  ASSERT_EQ(a.rdf.g.size(), b.rdf.g.size());
  for (std::size_t k = 0; k < a.rdf.g.size(); ++k) EXPECT_NEAR(a.rdf.g[k], b.rdf.g[k], 1e-9) << k;

  EXPECT_TRUE(a.vf_container.exact);
  EXPECT_NEAR(a.vf_container.vf.value, b.vf_container.vf.value, 1e-13);
  // The core: whole spheres by their measure, the cut ones by QMC (the sphere analysis: caps in
  // closed form).
  EXPECT_FALSE(a.vf_core.exact);
  EXPECT_GT(a.vf_core.balls_sampled, 0u);
  EXPECT_NEAR(a.vf_core.vf.value, b.vf_core.vf.value, 4 * a.vf_core.vf.std_error + 1e-3);
  EXPECT_NEAR(a.vf_reference, b.vf_reference, 5e-3);
}

// Capsules in one orientation: nematic order 1, and an equivalent radius from their volume.
TEST(ShapeAnalysis, OrientationAndEquivalentRadius) {
  ShapePacking<3> p;
  for (int k = 0; k < 20; ++k) {
    Particle<3> q;
    q.shape = std::make_shared<SpherocylinderShape<3>>(0.25, 0.2);
    q.pose.position = Vec3(1.0 + k % 5, 1.0 + k / 5, 2.0);
    p.particles.push_back(q);
  }
  p.template_names = {"spherocylinder"};
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(6.0));
  const PackingAnalysis a = analyze_shape_packing<3>(p, box, {}, {"spherocylinder"});
  ASSERT_TRUE(a.orientation.has_value());
  EXPECT_NEAR(a.orientation_order, 1.0, 1e-12);
  const double volume = p.particles[0].shape->measure();
  EXPECT_NEAR(4.0 / 3.0 * std::numbers::pi * std::pow(a.r_max, 3), volume, 1e-12 * volume);
  ASSERT_EQ(a.templates.size(), 1u);
  EXPECT_EQ(a.templates[0].second, 20u);
}

// The radial order: capsules pointing at the box's centre give 1, capsules across the radius
// (axes along z, in the plane z = centre) -1/2, and the marginal order cannot tell the second
// from a random set. The radial axes order sees every body axis: a body axis along the radius
// gives 1 - 3/5, the radius in a body plane at every angle <cos^4 + sin^4> - 3/5 = 3/20, a body
// diagonal along it 1/3 - 3/5 (a cube's corner outwards).
TEST(ShapeAnalysis, RadialOrderSeesAnOnion) {
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(20.0));
  const Vec3 centre = box.interior_point();
  auto ring = [&](bool radial, bool diagonal = false) {
    ShapePacking<3> p;
    p.template_names = {"spherocylinder"};
    for (int k = 0; k < 24; ++k) {
      const double phi = 2 * std::numbers::pi * k / 24;
      const Vec3 u(std::cos(phi), std::sin(phi), 0.0);
      Particle<3> q;
      q.shape = std::make_shared<SpherocylinderShape<3>>(0.25, 0.2);
      q.pose.position = centre + 6.0 * u;
      // Body x along u (radial) or along z (tangential: across the radius).
      q.pose.rotation = diagonal ? Eigen::Matrix3d(Eigen::Quaterniond::FromTwoVectors(Vec3::Ones(), u))
                        : radial ? Eigen::Matrix3d(Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), u))
                                 : Eigen::Matrix3d(Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), Vec3::UnitZ()));
      p.particles.push_back(q);
    }
    return analyze_shape_packing<3>(p, box, {}, {"spherocylinder"});
  };
  const PackingAnalysis out = ring(true), across = ring(false);
  EXPECT_NEAR(out.radial_order, 1.0, 1e-12);
  EXPECT_NEAR(across.radial_order, -0.5, 1e-12);
  EXPECT_NEAR(out.radial_order_noise, std::sqrt(0.2 / 24), 1e-12);
  EXPECT_NEAR(out.radial_axes_order, 0.4, 1e-12);
  EXPECT_NEAR(across.radial_axes_order, 0.15, 1e-12);
  EXPECT_NEAR(ring(true, true).radial_axes_order, 1.0 / 3 - 0.6, 1e-12);
  EXPECT_NEAR(out.radial_axes_order_noise, std::sqrt(16.0 / 525 / 24), 1e-12);
}

}  // namespace
}  // namespace fp
