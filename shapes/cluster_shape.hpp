#pragma once
// Cluster (clump): the union of member balls (disks in 2D), any number, any radii, overlapping
// or not. The member balls are their own hull balls and their own FCL parts, so containment and
// overlap tests are exact. The measure counts overlaps once (ball_union.hpp: exact in 2D,
// ~1e-12 relative in 3D).
#include <vector>

#include "shapes/shape.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

template <int D>
class ClusterShape final : public Shape<D> {
 public:
  /// Members in the body frame (the reference point is the origin); computes the union's measure.
  explicit ClusterShape(std::vector<Ball<D>> members);
  /// Same, with the union's measure already known (scaled copies).
  ClusterShape(std::vector<Ball<D>> members, double measure);
  static constexpr const char* kKind = "cluster";
  /// A particle template's largest number of members. The exact volume of the union grows as
  /// about members^2.5 (members overlapping at random in a cube of 2 radii: 100 in 2.5 s, 200 in
  /// 10 s; 1,000 not done in 5 min) and each contact problem of the ball wrapper faster still (5
  /// members: 70 particles/s, 20: 0.7/s; experiments/extremes/RESULTS.md). Clumps of DEM practice
  /// have from 2 to a few tens.
  static constexpr int kMaxMembers = 200;
  const std::vector<Ball<D>>& members() const { return members_; }

  const char* kind() const override { return kKind; }
  double measure() const override { return measure_; }
  double bounding_radius() const override { return bounding_; }
  /// The largest origin-centred ball inside one member; 0 when the origin is in none (e.g. two
  /// members apart), which is a valid lower bound.
  double inscribed_radius() const override { return inscribed_; }
  Vec<D> support(const Vec<D>& u) const override;
  bool contains(const Vec<D>& x) const override;
  std::vector<Ball<D>> hull_balls() const override { return members_; }
  void rounded_cores(std::vector<RoundedCore<D>>& out) const override {
    out.resize(members_.size());
    for (std::size_t i = 0; i < members_.size(); ++i) out[i].points.assign(1, members_[i].center), out[i].radius = members_[i].radius;
  }
  /// 2D: the union's outline (exposed arcs only); 3D: every member sphere (overlapping meshes).
  SurfaceMesh<D> surface(int resolution) const override;
  std::vector<FclPart<D>> fcl_parts() const override;
  ShapePtr<D> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  std::vector<Ball<D>> members_;
  double measure_;
  double bounding_ = 0.0;
  double inscribed_ = 0.0;
};

/// "cluster": `centers` (D-points) and `radii` (same count, positive). The reference point is the
/// centroid of the members weighted by their own measures r^D, overlaps ignored (so it is easy to
/// state by hand; it is the true centroid when members do not overlap), and the prototype is
/// scaled so that max |c_i| + r_i = 1. Dimensions: circumscribed_radius, equivalent_radius.
template <int D>
ShapePrototype<D> cluster_prototype(const ShapeParameters& p);

}  // namespace fp
