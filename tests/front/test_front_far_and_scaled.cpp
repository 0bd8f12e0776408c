// A scene shifted far from the origin or scaled by a power of two packs the same packing
// as at the origin and scale 1. Every container kind, offsets 1e3, 2^20, 1e6 and 1e9, scales
// 2^-60 .. 2^60. The shifted scenes use sizes that are exact at every offset (dyadic: 0.5, 0.625),
// so the packing in the container's local frame must be bit for bit the reference's (and the
// scaled one the reference times the scale); each is also checked by the independent brute-force
// code of front_test_util.hpp in its own frame: no overlap beyond 1e-9 r_min, every particle inside.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>

#include "front_checks.hpp"

namespace fptest {
namespace {

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string vec(std::initializer_list<double> xs) {
  std::string s = "[";
  for (const double x : xs) s += (s.size() > 1 ? ", " : "") + num(x);
  return s + "]";
}

/// One container kind, as a scene text and an independent distance, at offset o and scale s.
template <int D>
struct Kind {
  std::string name;
  std::function<std::string(double o, double s)> container;
  std::function<SignedDistance<D>(double o, double s)> distance;
  double r_min, r_max;  // at scale 1
  std::function<std::string(double s)> law = {};  // the radius law at scale s (none: uniform [r_min, r_max])
};

template <int D>
std::string scene_text(const Kind<D>& k, double o, double s) {
  const std::string law = k.law ? k.law(s)
                                : "{distribution: uniform, min: " + num(k.r_min * s) + ", max: " + num(k.r_max * s) + "}";
  return "dimension: " + std::to_string(D) + "\nseed: 42\ncontainer: " + k.container(o, s) + "\nparticles: {radius: " +
         law + "}\n";
}

template <int D>
fp::PackResult<D> pack_checked(const Kind<D>& k, double o, double s, const std::string& what) {
  const fp::Scene scene = scene_from_yaml(scene_text(k, o, s));
  fp::PackResult<D> res = fp::pack<D>(scene);
  SCOPED_TRACE(what + ": " + std::to_string(res.packing.size()) + " particles");
  expect_valid<D>(res.packing, k.distance(o, s), k.r_min * s, k.r_max * s, what);
  return res;
}

template <int D>
void expect_same_as_reference(const Kind<D>& k) {
  const fp::PackResult<D> ref = pack_checked(k, 0.0, 1.0, k.name + " at the origin");
  ASSERT_GT(ref.packing.size(), 200u);
  for (const double o : {1e3, 1048576.0, 1e6, 1e9}) {
    const std::string what = k.name + " offset " + num(o);
    const fp::PackResult<D> far = pack_checked(k, o, 1.0, what);
    EXPECT_TRUE(bitwise_equal<D>(far.packing, ref.packing)) << what << ": " << far.packing.size() << " vs "
                                                            << ref.packing.size() << " particles";
  }
  for (const int e : {-60, -30, 30, 60}) {
    const double s = std::ldexp(1.0, e);
    const std::string what = k.name + " scale 2^" + std::to_string(e);
    fp::PackResult<D> scaled = pack_checked(k, 0.0, s, what);
    for (auto& c : scaled.packing.centers) c /= s;
    for (double& r : scaled.packing.radii) r /= s;
    EXPECT_TRUE(bitwise_equal<D>(scaled.packing, ref.packing)) << what;
  }
}

/// A cube of side 0.5 s at (o, o, o).
Kind<3> cube(const std::string& name, double r_min, double r_max, std::function<std::string(double s)> law = {}) {
  return {name,
          [](double o, double s) {
            return "{type: box, min: " + vec({o, o, o}) + ", max: " + vec({o + 0.5 * s, o + 0.5 * s, o + 0.5 * s}) + "}";
          },
          [](double o, double s) { return box_distance<3>(Vec3::Constant(o), Vec3::Constant(o + 0.5 * s)); },
          r_min, r_max, std::move(law)};
}

TEST(FarAndScaled, Box3D) { expect_same_as_reference<3>(cube("box", 0.01, 0.02)); }

// A rare large class (radii 4 times apart at 100 : 1) is placed ahead of the front on a lattice
// of the container's local frame: the same packing far away and at every scale too.
TEST(FarAndScaled, RareLargeClass3D) {
  expect_same_as_reference<3>(cube("box, rare large class", 0.015625, 0.0625, [](double s) {
    return "{distribution: discrete, values: [[" + num(0.015625 * s) + ", 100], [" + num(0.0625 * s) + ", 1]]}";
  }));
}

// Gravel holding nearly all of the volume (radii 64 times apart at 100 : 1) is packed first as a
// skeleton and the sand put on it at random points of its grains: the same packing far away and
// at every scale too.
TEST(FarAndScaled, SkeletonAndFines3D) {
  expect_same_as_reference<3>(cube("box, skeleton and fines", 0.0009765625, 0.0625, [](double s) {
    return "{distribution: discrete, values: [[" + num(0.0009765625 * s) + ", 100], [" + num(0.0625 * s) + ", 1]]}";
  }));
}

TEST(FarAndScaled, Cylinder3D) {
  expect_same_as_reference<3>({"cylinder",
                               [](double o, double s) {
                                 return "{type: cylinder, base: " + vec({o, o, o}) + ", axis: [0, 0, 1], radius: " +
                                        num(0.25 * s) + ", height: " + num(0.5 * s) + "}";
                               },
                               [](double o, double s) {
                                 return cylinder_distance(Vec3::Constant(o), Vec3::UnitZ(), 0.25 * s, 0.5 * s);
                               },
                               0.01, 0.02});
}

TEST(FarAndScaled, Sphere3D) {
  expect_same_as_reference<3>({"sphere",
                               [](double o, double s) {
                                 return "{type: sphere, center: " + vec({o, 0.0 - o, o}) + ", radius: " + num(0.25 * s) + "}";
                               },
                               [](double o, double s) { return ball_distance<3>(Vec3(o, 0.0 - o, o), 0.25 * s); },
                               0.01, 0.02});
}

TEST(FarAndScaled, Rectangle2D) {
  expect_same_as_reference<2>({"rectangle",
                               [](double o, double s) {
                                 return "{type: rectangle, min: " + vec({o, o}) + ", max: " +
                                        vec({o + 0.5 * s, o + 0.625 * s}) + "}";
                               },
                               [](double o, double s) {
                                 return box_distance<2>(Vec2::Constant(o), Vec2(o + 0.5 * s, o + 0.625 * s));
                               },
                               0.004, 0.008});
}

TEST(FarAndScaled, Disk2D) {
  expect_same_as_reference<2>({"disk",
                               [](double o, double s) {
                                 return "{type: disk, center: " + vec({0.0 - o, o}) + ", radius: " + num(0.375 * s) + "}";
                               },
                               [](double o, double s) { return ball_distance<2>(Vec2(0.0 - o, o), 0.375 * s); },
                               0.004, 0.008});
}

std::vector<Vec2> l_shape(double o, double s) {
  std::vector<Vec2> v;
  for (const auto& [x, y] : std::initializer_list<std::pair<double, double>>{
           {0, 0}, {0.5, 0}, {0.5, 0.25}, {0.25, 0.25}, {0.25, 0.5}, {0, 0.5}})
    v.emplace_back(o + s * x, o + s * y);
  return v;
}

TEST(FarAndScaled, Polygon2D) {
  expect_same_as_reference<2>({"polygon",
                               [](double o, double s) {
                                 std::string t = "{type: polygon, vertices: [";
                                 for (const Vec2& p : l_shape(o, s)) t += (t.back() == '[' ? "" : ", ") + vec({p.x(), p.y()});
                                 return t + "]}";
                               },
                               [](double o, double s) { return polygon_distance(l_shape(o, s)); }, 0.004, 0.008});
}

/// An L-shaped prism (a non-convex mesh) with dyadic vertices, written as OFF at offset o.
struct LPrism {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  LPrism(double o, double s) {
    const double xy[6][2] = {{0, 0}, {0.5, 0}, {0.5, 0.25}, {0.25, 0.25}, {0.25, 0.5}, {0, 0.5}};
    for (const double z : {0.0, 0.25})
      for (const auto& p : xy) v.emplace_back(o + s * p[0], o + s * p[1], o + s * z);
    // Bottom (z = 0) and top caps as fans from the reflex-free corners, then the six walls.
    const int cap[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
    for (const auto& c : cap) {
      t.push_back({c[0], c[2], c[1]});
      t.push_back({6 + c[0], 6 + c[1], 6 + c[2]});
    }
    for (int i = 0; i < 6; ++i) {
      const int j = (i + 1) % 6;
      t.push_back({i, j, 6 + j});
      t.push_back({i, 6 + j, 6 + i});
    }
  }
  void write(const std::string& path) const {
    std::ofstream out(path);
    out.precision(17);
    out << "OFF\n" << v.size() << " " << t.size() << " 0\n";
    for (const Vec3& p : v) out << p.x() << " " << p.y() << " " << p.z() << "\n";
    for (const auto& f : t) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
};

TEST(FarAndScaled, Mesh3D) {
  const std::string dir = testing::TempDir();
  Kind<3> k{"mesh",
            [dir](double o, double s) {
              const std::string file = dir + "/l_prism_" + num(o) + "_" + num(s) + ".off";
              LPrism(o, s).write(file);
              return "{type: mesh, file: " + file + "}";
            },
            [](double o, double s) {
              const LPrism m(o, s);
              return mesh_distance(m.v, m.t);
            },
            0.01, 0.02};
  expect_same_as_reference<3>(k);
}

}  // namespace
}  // namespace fptest
