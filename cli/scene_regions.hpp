#pragma once
// The regions of a scene's tetrahedral mesh (`regions:`) as the tetrahedral-mesh packer and its
// report use them: region 0 holds the tetrahedra of no named region (the scene's law and stop),
// then one region per RegionSpec, in the scene's order. A point is in the region of the
// tetrahedron holding it (core/geometry/tet_locator.hpp).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/tet_locator.hpp"
#include "core/io/scene.hpp"

namespace fp {

class SceneRegions {
 public:
  /// Needs scene.tet_mesh.
  explicit SceneRegions(const Scene& scene);

  std::size_t count() const { return volume_.size(); }
  /// Per tetrahedron, its region.
  const std::vector<int>& of_tet() const { return of_tet_; }
  double volume(std::size_t g) const { return volume_[g]; }
  /// The region of the tetrahedron holding x; 0 outside the mesh.
  std::size_t at(const Vec3& x) const;
  std::string name(std::size_t g) const { return g == 0 ? "(no region)" : scene_.regions[g - 1].name; }
  /// Its radius law (null: the scene's).
  const RadiusDistribution* law(std::size_t g) const { return g == 0 ? nullptr : scene_.regions[g - 1].radii.get(); }
  /// Its phi0: its own, else the scene's stop.
  std::optional<double> target(std::size_t g) const;

 private:
  const Scene& scene_;
  TetLocator locator_;
  std::vector<int> of_tet_;
  std::vector<double> volume_;
};

}  // namespace fp
