#include "cli/scene_regions.hpp"

namespace fp {

SceneRegions::SceneRegions(const Scene& scene)
    : scene_(scene), locator_(*scene.tet_mesh), of_tet_(scene.tet_mesh->tets.size(), 0), volume_(scene.regions.size() + 1, 0.0) {
  const TetMesh& mesh = *scene.tet_mesh;
  for (std::size_t k = 0; k < mesh.tets.size(); ++k) {
    for (std::size_t g = 0; g < scene.regions.size(); ++g)
      if (mesh.tet_group[k] == scene.regions[g].tag) of_tet_[k] = static_cast<int>(g + 1);
    volume_[static_cast<std::size_t>(of_tet_[k])] += tet_volume(mesh, k);
  }
}

std::size_t SceneRegions::at(const Vec3& x) const {
  const int k = locator_.tet_at(x);
  return k < 0 ? 0 : static_cast<std::size_t>(of_tet_[static_cast<std::size_t>(k)]);
}

std::optional<double> SceneRegions::target(std::size_t g) const {
  if (g > 0 && scene_.regions[g - 1].target_volume_fraction) return scene_.regions[g - 1].target_volume_fraction;
  return scene_.stop.target_volume_fraction;
}

}  // namespace fp
