#pragma once
// A bed: the part of a container below a level, filled from the container's floor up to a fill
// height, as silos, columns, drums and hoppers are. The region is the container cut by the
// plane up . x = level (up a unit vector), and every packer, check and figure sees it as the
// container it fills:
//  * the particles lie wholly below the level;
//  * with a free surface the level is not a wall: no particle is placed against it, so the top
//    layer rests on the particles below it, as a poured bed's does; with a flat surface it is a
//    wall (a lid), and the top layer lies against it as the floor layer lies on the floor.
// The signed distance is the larger of the container's and the plane's: exact inside the region
// (the distance to its boundary is the smaller of the two distances), a lower bound outside.
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"

namespace fp {

enum class BedSurface { Free, Flat };

template <int D>
class BedRegion final : public Container<D> {
 public:
  /// The container `base` up to `height` above its lowest point along `up` (non-zero, any length).
  /// Throws std::invalid_argument for a non-finite or non-positive height, a zero or non-finite
  /// direction, or a height at which nothing of the container lies below the level.
  BedRegion(ContainerPtr<D> base, const Vec<D>& up, double height, BedSurface surface);

  bool inside(const Vec<D>& p) const override { return base_->inside(p) && above(p) <= 0.0; }
  double signed_distance(const Vec<D>& p) const override;
  /// The container's bounds, cut at the level where `up` is an axis direction.
  Aabb<D> bounds() const override { return bounds_; }
  /// Exact: the container's boundary cut at the level, measured by the divergence theorem about
  /// a point of the plane (the cut face adds nothing); closed forms for balls and cylinders.
  double measure() const override { return measure_; }
  /// The container's walls, and with a flat surface the level's plane (id kLidWall).
  void walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const override;
  /// The deepest point found on the line along `up` through the container's interior point.
  Vec<D> interior_point() const override { return interior_; }
  std::string describe() const override;
  void prepare_queries(double reach) const override { base_->prepare_queries(reach); }
  bool contains_ball(const Vec<D>& c, double r, double rel_tol = 1e-9) const override {
    return above(c) <= -r + rel_tol * r && base_->contains_ball(c, r, rel_tol);
  }

  const Container<D>& base() const { return *base_; }
  const Vec<D>& up() const { return up_; }          ///< unit
  double level() const { return level_; }          ///< up . x at the surface, local frame
  double floor_level() const { return floor_; }    ///< up . x at the container's lowest point, local frame
  double height() const { return level_ - floor_; }
  BedSurface surface() const { return surface_; }
  /// The measure of the container up to `h` above the floor (0 at 0, measure() at height()), exact.
  double measure_up_to(double h) const;
  /// The same container filled to `h` instead (the bed's profile cuts it in slabs).
  BedRegion filled_to(double h) const { return BedRegion(base_, up_, h, surface_); }

  /// The lid's wall id: past every id a container uses.
  static constexpr int kLidWall = 1 << 30;

 private:
  double above(const Vec<D>& p) const { return up_.dot(p) - level_; }

  ContainerPtr<D> base_;
  Vec<D> up_;
  double floor_ = 0.0, level_ = 0.0;
  BedSurface surface_;
  Aabb<D> bounds_;
  double measure_ = 0.0;
  Vec<D> interior_;
};

/// The lowest value of up . x over the container (local frame; `up` unit), exact for every kind.
template <int D>
double lowest_along(const Container<D>& container, const Vec<D>& up);

/// The part on the side up . x <= level of a closed polygon (corners in order; a triangle in 3D)
/// or, with closed = false, of a polyline: Sutherland–Hodgman against one plane.
template <int D>
std::vector<Vec<D>> clip_below(const std::vector<Vec<D>>& corners, const Vec<D>& up, double level, bool closed = true);

extern template class BedRegion<2>;
extern template class BedRegion<3>;

}  // namespace fp
