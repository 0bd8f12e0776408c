#pragma once
// The container interface: every packer and metric sees containers only through this.
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"
#include "core/geometry/wall.hpp"

namespace fp {

/// Every position a container takes or returns is in its local frame: relative to origin()
/// (core/geometry/local_frame.hpp), so that far-off scenes keep their digits. Absolute =
/// origin() + local; only scene input and packing files see absolute coordinates.
template <int D>
class Container {
 public:
  virtual ~Container() = default;

  /// The absolute position of the local frame's origin (zero for a container near the origin).
  const Vec<D>& origin() const { return origin_; }

  /// True if p is in the closed container.
  virtual bool inside(const Vec<D>& p) const = 0;
  /// Euclidean signed distance to the boundary: < 0 inside, > 0 outside.
  virtual double signed_distance(const Vec<D>& p) const = 0;
  virtual Aabb<D> bounds() const = 0;
  /// Volume (3D) or area (2D).
  virtual double measure() const = 0;
  /// Appends the walls (as bodies) whose distance to p is at most `reach`.
  virtual void walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const = 0;
  /// A point deep inside, where packing starts (the centre for convex containers).
  virtual Vec<D> interior_point() const = 0;
  /// One-line human description in absolute coordinates, e.g. "box [0,0,0]-[0.9,0.9,0.9]".
  virtual std::string describe() const = 0;

  /// A hint: queries will be about distances up to `reach` (the largest particle). A container
  /// whose queries are costly (a mesh) builds what makes them cheap at that scale; the answers
  /// never change. Not to be called while queries run on other threads.
  virtual void prepare_queries(double /*reach*/) const {}

  /// True if the ball (c, r) lies inside, allowing a contact tolerance of rel_tol*r
  /// so that particles tangent to a wall are accepted.
  virtual bool contains_ball(const Vec<D>& c, double r, double rel_tol = 1e-9) const {
    return signed_distance(c) <= -r + rel_tol * r;
  }

 protected:
  explicit Container(const Vec<D>& origin = Vec<D>::Zero()) : origin_(origin) {}

 private:
  Vec<D> origin_;
};

template <int D>
using ContainerPtr = std::shared_ptr<const Container<D>>;

}  // namespace fp
