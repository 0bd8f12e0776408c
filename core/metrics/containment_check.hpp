#pragma once
// The validator's containment check, independent of the container code: it reads each
// container's raw geometry through const accessors (corners, centre and radius, base, axis,
// vertices, triangles) and computes its own signed distances, so that a rounding or a bug in the
// packer's container code cannot pass its own check. Box/rectangle, ball/disk, cylinder,
// polygon (simple, possibly non-convex: crossing number + point-segment distances) and closed
// triangle meshes (mesh_distance.hpp). An unknown container kind is an error, never a pass.
// Coordinates are those of the accessors, which are the packing's frame.
#include <limits>
#include <memory>

#include "core/geometry/container.hpp"

namespace fp {

template <int D>
class ContainmentCheck {
 public:
  /// Throws std::invalid_argument, naming the container by its description, for a kind this
  /// check does not know.
  explicit ContainmentCheck(const Container<D>& container);
  ~ContainmentCheck();
  ContainmentCheck(ContainmentCheck&&) noexcept;
  ContainmentCheck& operator=(ContainmentCheck&&) noexcept;

  /// Signed distance from p to the boundary, < 0 inside. Exact to rounding when p is outside or
  /// within `reach` of the boundary; an inside point farther than `reach` may get any value
  /// <= -reach (meshes stop their search there).
  double signed_distance(const Vec<D>& p, double reach = std::numeric_limits<double>::infinity()) const;
  /// (signed_distance(c) + r) / r for r > 0: the ball (c, r) is inside with tolerance tol when
  /// this is <= tol (centre inside and distance to the boundary >= r - tol r). Values below 0
  /// are exact down to -1 (the mesh search reaches 2 r).
  double protrusion(const Vec<D>& c, double r) const { return (signed_distance(c, 2 * r) + r) / r; }

  struct Kind;  // one per container kind (containment_check.cpp)

 private:
  std::unique_ptr<const Kind> kind_;
};

extern template class ContainmentCheck<2>;
extern template class ContainmentCheck<3>;

}  // namespace fp
