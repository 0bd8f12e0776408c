#pragma once
// Shared by the shapes tests: scene-like template specs, a catalogue of prototypes of every
// family (several parameter sets, 2D and 3D), seeded sampling and world-frame support functions.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "shapes/pose.hpp"
#include "shapes/shape_registry.hpp"

namespace fp::test {

/// A template as the scene reader would hand it over: written at scene.yaml line 7, column 3.
inline ParticleTemplateSpec make_spec(const std::string& family, ShapeParameters p = {}) {
  ParticleTemplateSpec s;
  s.family = family;
  p.spot = SourceSpot{"scene.yaml", 7, 3, "particles[0]"};
  s.parameters = std::move(p);
  return s;
}

inline ShapeParameters numbers(std::map<std::string, double> n) {
  ShapeParameters p;
  p.numbers = std::move(n);
  return p;
}

template <int D>
ShapePrototype<D> prototype(const std::string& family, ShapeParameters p = {}) {
  return ShapeFamilies::builtin().prototype<D>(make_spec(family, std::move(p)));
}

struct Named {
  std::string name;    ///< for SCOPED_TRACE
  std::string family;
  ShapeParameters parameters;
};

/// Every family with a few parameter sets (clusters overlapping, apart and nested).
template <int D>
std::vector<Named> catalogue() {
  std::vector<Named> c;
  auto add = [&](std::string name, std::string family, ShapeParameters p) {
    c.push_back({std::move(name), std::move(family), std::move(p)});
  };
  add("sphere", "sphere", {});
  add("spherocylinder 0.3", "spherocylinder", numbers({{"aspect_ratio", 0.3}}));
  add("spherocylinder 1", "spherocylinder", numbers({{"aspect_ratio", 1.0}}));
  ShapeParameters overlap, apart, nested;
  if constexpr (D == 2) {
    overlap.point_lists["centers"] = {{0, 0}, {1.2, 0.3}, {0.4, -1.1}};
    overlap.lists["radii"] = {1.0, 0.6, 0.8};
    apart.point_lists["centers"] = {{-2, 0}, {2, 1}};
    nested.point_lists["centers"] = {{0, 0}, {0.2, 0.1}, {1.5, 0}};
  } else {
    overlap.point_lists["centers"] = {{0, 0, 0}, {1.2, 0.3, 0}, {0.4, -1.1, 0.3}, {0, 0.2, 0.9}};
    overlap.lists["radii"] = {1.0, 0.6, 0.8, 0.5};
    apart.point_lists["centers"] = {{-2, 0, 0}, {2, 1, 0.5}};
    nested.point_lists["centers"] = {{0, 0, 0}, {0.2, 0.1, 0}, {1.5, 0, 0}};
  }
  apart.lists["radii"] = {1.0, 0.9};  // the reference point (r^D-weighted) falls between them
  nested.lists["radii"] = {1.0, 0.3, 0.7};
  add("cluster overlapping", "cluster", overlap);
  add("cluster apart", "cluster", apart);
  add("cluster nested", "cluster", nested);
  if constexpr (D == 2) {
    add("triangle", "polygon", numbers({{"sides", 3}}));
    add("heptagon", "polygon", numbers({{"sides", 7}}));
    ShapeParameters irregular;
    irregular.point_lists["vertices"] = {{0, 0}, {3, 0.5}, {2.5, 2}, {0.5, 1.5}, {1, 1}, {3, 0.5}};
    add("irregular polygon", "polygon", irregular);
    ShapeParameters e, round;
    e.lists["axes"] = {1.0, 0.3};
    round.lists["axes"] = {2.0, 2.0};
    add("ellipse", "ellipse", e);
    add("circle as ellipse", "ellipse", round);
  } else {
    for (int f : {4, 6, 8, 12, 20}) add("platonic " + std::to_string(f), "polyhedron", numbers({{"platonic", f}}));
    ShapeParameters irregular;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 30; ++i) irregular.point_lists["vertices"].push_back({2 * u(rng), u(rng), 0.5 * u(rng)});
    add("irregular polyhedron", "polyhedron", irregular);
    ShapeParameters e;
    e.lists["axes"] = {1.0, 0.5, 0.25};
    add("ellipsoid", "ellipsoid", e);
    add("cylinder flat", "cylinder", numbers({{"aspect_ratio", 3.0}}));
    add("cylinder long", "cylinder", numbers({{"aspect_ratio", 0.4}}));
  }
  return c;
}

/// Directions: evenly spread (2D angles, 3D Fibonacci sphere).
template <int D>
std::vector<Vec<D>> directions(int n) {
  std::vector<Vec<D>> out;
  for (int i = 0; i < n; ++i) {
    if constexpr (D == 2) {
      const double t = 2 * kPi * (i + 0.5) / n;
      out.emplace_back(std::cos(t), std::sin(t));
    } else {
      const double z = 1 - 2 * (i + 0.5) / n, rho = std::sqrt(1 - z * z);
      const double t = kPi * (3 - std::sqrt(5.0)) * i;
      out.emplace_back(rho * std::cos(t), rho * std::sin(t), z);
    }
  }
  return out;
}

/// Uniform point in [-h, h]^D.
template <int D>
Vec<D> uniform_box(std::mt19937_64& rng, double h) {
  std::uniform_real_distribution<double> u(-h, h);
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = u(rng);
  return x;
}

/// Uniform random rotation (2D angle; 3D normalised Gaussian quaternion).
template <int D>
Mat<D> random_rotation(std::mt19937_64& rng) {
  if constexpr (D == 2) {
    return rotation_2d(std::uniform_real_distribution<double>(0, 2 * kPi)(rng));
  } else {
    std::normal_distribution<double> g;
    return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  }
}

template <int D>
Vec<D> random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = g(rng);
  return x.normalized();
}

}  // namespace fp::test
