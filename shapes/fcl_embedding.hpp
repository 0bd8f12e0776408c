#pragma once
// FCL is 3D only: how our 2D shapes and poses enter it (the plane z = 0), and the FCL convex
// geometries built from our vertex lists (FCL itself stays in fcl_embedding.cpp).
//
// A body symmetric about z = 0 has the same distance to another such body in 3D as their z = 0
// sections have in 2D (reflect a nearest pair and take midpoints). Penetration depth stays in the
// plane only if the bodies are deep enough in z: the depth along z is the sum of their
// half-heights, and the in-plane depth of two overlapping bodies is at most the sum of their
// circumscribed radii; prisms and ellipse stand-ins extend kEmbeddingDepth circumscribed radii
// each way, so z never wins.
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "shapes/pose.hpp"
#include "shapes/shape.hpp"

namespace fp {

/// Half-height of a 2D shape's stand-in along z, in circumscribed radii.
inline constexpr double kEmbeddingDepth = 10.0;

template <int D>
Eigen::Vector3d fcl_point(const Vec<D>& x) {
  if constexpr (D == 2) return {x.x(), x.y(), 0.0};
  else return x;
}

template <int D>
Eigen::Matrix3d fcl_rotation(const Mat<D>& R) {
  if constexpr (D == 2) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    m.topLeftCorner<2, 2>() = R;
    return m;
  } else {
    return R;
  }
}

/// World transform of an FCL part of a particle at `pose` (fcl::Transform3d is this type).
template <int D>
Eigen::Isometry3d fcl_part_transform(const Pose<D>& pose, const FclPart<D>& part) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const Eigen::Matrix3d R = fcl_rotation<D>(pose.rotation);
  t.linear() = R * part.rotation;
  t.translation() = fcl_point<D>(pose.position) + R * fcl_point<D>(part.offset);
  return t;
}

/// fcl::Convexd of a closed convex polytope; faces are vertex index lists, counter-clockwise
/// seen from outside.
std::shared_ptr<fcl::CollisionGeometry<double>> make_fcl_convex(const std::vector<Eigen::Vector3d>& vertices,
                                                                const std::vector<std::vector<int>>& faces);

/// The prism polygon × [-half_height, half_height] (polygon counter-clockwise) as fcl::Convexd.
std::shared_ptr<fcl::CollisionGeometry<double>> make_fcl_prism(const std::vector<Vec2>& polygon, double half_height);

}  // namespace fp
