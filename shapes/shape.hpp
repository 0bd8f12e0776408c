#pragma once
// A particle shape, in its body frame (reference point at the origin). Everything the packer,
// the contact solvers, the narrow phase and the writers need from a shape is here; a new shape
// implements this class and registers its family (shapes/builtin_shapes.cpp).
//
// 2D shapes live in the z = 0 plane when they are handed to FCL (which is 3D only): disks become
// spheres, stadiums capsules, polygons tall prisms, ellipses ellipsoids. Two such bodies are at
// the same distance in 3D as in 2D, because both are symmetric about z = 0 and (prisms) extend
// far enough in z that the least-penetration direction stays in the plane.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/vec.hpp"

namespace fcl {
template <typename S>
class CollisionGeometry;
}

namespace fp {

/// A ball in the body frame (cluster members, hull generators).
template <int D>
struct Ball {
  Vec<D> center = Vec<D>::Zero();
  double radius = 0.0;
};

/// A convex core thickened by a radius: the points' convex hull plus a ball of `radius` (a ball:
/// one point; a spherocylinder: its axis segment; a convex polytope: its vertices and radius 0).
template <int D>
struct RoundedCore {
  std::vector<Vec<D>> points;
  double radius = 0.0;
};

/// A closed surface for display: triangles in 3D, the outline's segments in 2D (body frame).
template <int D>
struct SurfaceMesh {
  std::vector<Vec<D>> vertices;
  std::vector<std::array<int, D>> facets;
};

/// One convex piece handed to FCL, placed at `offset` and turned by `rotation` in the body frame
/// (clusters have several pieces; a 2D stadium is an FCL capsule turned from z onto x).
template <int D>
struct FclPart {
  Vec<D> offset = Vec<D>::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< FCL geometry frame -> body frame (embedded in 3D)
  std::shared_ptr<fcl::CollisionGeometry<double>> geometry;  ///< 3D (2D shapes embedded in z = 0)
};

template <int D>
class Shape {
 public:
  virtual ~Shape() = default;

  /// The family name, also the key of the solver and narrow-phase registries ("sphere", ...).
  virtual const char* kind() const = 0;
  /// Volume (3D) or area (2D).
  virtual double measure() const = 0;
  /// Largest distance from the origin to a point of the shape (circumscribed radius).
  virtual double bounding_radius() const = 0;
  /// Radius of a ball centred at the origin inside the shape (a lower bound is fine).
  virtual double inscribed_radius() const = 0;
  /// A point of the shape farthest along u (u need not be unit): the support function's argmax.
  virtual Vec<D> support(const Vec<D>& u) const = 0;
  /// True if the body-frame point x is in the closed shape.
  virtual bool contains(const Vec<D>& x) const = 0;
  /// Balls whose convex hull contains the shape and whose extreme points are points of the shape
  /// (or of a slightly larger shape, stated per family). A convex function of position (distance
  /// to a point or an axis, a linear form) reaches its maximum over the shape on these balls:
  /// that makes containment in convex containers and wall gaps exact for balls, capsules,
  /// clusters and polytopes.
  virtual std::vector<Ball<D>> hull_balls() const = 0;
  /// The shape as a union of rounded convex cores (body frame): what the wrapper contact solvers
  /// need (contact/ball_wrapper_solver.hpp, contact/polygon_wrapper_solver.hpp). A ball, a
  /// spherocylinder and a convex polytope are one core; a cluster is one per member. Empty (the
  /// default) for a shape that is no such union (ellipsoids, cylinders): it is placed by
  /// minimisation. Written into `out`, whose storage is reused: the 2D wrapper asks once per
  /// contact problem, where allocating cost 4 % of a polygon packing.
  virtual void rounded_cores(std::vector<RoundedCore<D>>& out) const { out.clear(); }
  /// Closed surface for display; `resolution` = segments per full turn of curved parts.
  virtual SurfaceMesh<D> surface(int resolution) const = 0;
  /// The convex pieces for FCL (built on each call: cache the result).
  virtual std::vector<FclPart<D>> fcl_parts() const = 0;
  /// The same shape scaled by s about the origin.
  virtual std::shared_ptr<const Shape<D>> scaled(double s) const = 0;
  /// The definition as a JSON object's text ({"kind": ..., parameters...}), for the outputs.
  virtual std::string definition_json() const = 0;
};

template <int D>
using ShapePtr = std::shared_ptr<const Shape<D>>;

}  // namespace fp
