// Fuzz harness of the scene file: fp::parse_scene (core/io/scene_yaml.hpp), then, as
// `frontpack pack` does next, the prototype of every particle template (shapes/shape_registry.hpp).
// Property: the scene is read, or refused with a fp::SceneError that names the scene file and says
// what is wrong without C++ internals. A read scene is usable: finite, positive sizes, a container
// of finite positive measure whose interior point is inside it, outputs with a path and a format.
// The scene is named <scratch folder>/scene.yaml, so `container: {type: mesh, file: cube.stl}`
// reaches the mesh readers and the mesh container (fuzz_support.cpp copies small meshes there).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/io/scene_yaml.hpp"
#include "fuzz_support.hpp"
#include "shapes/shape_registry.hpp"

namespace {

using fp::fuzz::require;

template <int D>
void check_container(const fp::Scene& scene) {
  const fp::Container<D>* c = scene.container<D>();
  require(c != nullptr, "a " + std::to_string(D) + "D scene without its container");
  require(std::isfinite(c->measure()) && c->measure() > 0, "container measure " + std::to_string(c->measure()));
  const fp::Aabb<D> box = c->bounds();
  require(box.lo.allFinite() && box.hi.allFinite() && (box.lo.array() <= box.hi.array()).all(),
          "container bounds not finite or inverted: " + c->describe());
  require(c->origin().allFinite(), "container origin not finite: " + c->describe());
  const fp::Vec<D> deep = c->interior_point();
  require(deep.allFinite() && c->inside(deep), "the container's interior point is not inside it: " + c->describe());
}

void check_distribution(const fp::RadiusDistribution& d, const std::string& what) {
  require(std::isfinite(d.r_min()) && std::isfinite(d.r_max()) && d.r_min() > 0 && d.r_min() <= d.r_max(),
          what + " bounds [" + std::to_string(d.r_min()) + ", " + std::to_string(d.r_max()) + "]");
}

template <int D>
void check_templates(const fp::Scene& scene, std::string_view input) {
  for (const auto& t : scene.particle_templates) {
    require(t.size != nullptr, "a particle template without a size distribution");
    check_distribution(*t.size, "template size");
    require(std::isfinite(t.fraction) && t.fraction > 0, "template fraction " + std::to_string(t.fraction));
    try {
      const fp::ShapePrototype<D> proto = fp::ShapeFamilies::builtin().prototype<D>(t);
      require(proto.shape != nullptr, "a prototype without its shape");
      const double volume = proto.shape->measure(), radius = proto.shape->bounding_radius();
      require(std::isfinite(volume) && volume > 0, "prototype of '" + t.family + "' has measure " + std::to_string(volume));
      require(std::abs(radius - 1.0) <= 1e-9, "prototype of '" + t.family + "' has circumscribed radius " + std::to_string(radius));
    } catch (const fp::SceneError& e) {
      fp::fuzz::check_error_message(e.what(), input, "shape prototype");
    } catch (...) {
      fp::fuzz::unexpected_exception("shape prototype of '" + t.family + "'");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > fp::fuzz::kMaxInputBytes) size = fp::fuzz::kMaxInputBytes;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string name = fp::fuzz::scratch_folder() + "/scene.yaml";
  fp::Scene scene;
  try {
    scene = fp::parse_scene(text, name);
  } catch (const fp::SceneError& e) {
    fp::fuzz::check_error_message(e.message(), text, "parse_scene");
    require(e.file() == name, "the error names '" + e.file() + "', not the scene file");
    require(e.line() >= 0 && e.column() >= 0, "negative line or column in: " + std::string(e.what()));
    return 0;
  } catch (...) {
    fp::fuzz::unexpected_exception("parse_scene");
  }
  require(scene.dimension == 2 || scene.dimension == 3, "dimension " + std::to_string(scene.dimension));
  require((scene.radii != nullptr) != !scene.particle_templates.empty(), "a scene needs radii or templates, not both");
  if (scene.radii) check_distribution(*scene.radii, "radius distribution");
  if (scene.dimension == 3) {
    require(scene.container2 == nullptr, "a 3D scene with a 2D container");
    check_container<3>(scene);
    check_templates<3>(scene, text);
  } else {
    require(scene.container3 == nullptr, "a 2D scene with a 3D container");
    check_container<2>(scene);
    check_templates<2>(scene, text);
  }
  for (const auto& out : scene.outputs) require(!out.path.empty() && !out.format.empty(), "an output without path or format");
  if (scene.stop.target_volume_fraction)
    require(*scene.stop.target_volume_fraction > 0 && *scene.stop.target_volume_fraction < 1, "stop.volume_fraction out of (0, 1)");
  if (scene.stop.time_limit_seconds)
    require(std::isfinite(*scene.stop.time_limit_seconds) && *scene.stop.time_limit_seconds > 0, "stop.time not positive");
  require(scene.packer.radius_pool >= 1, "radius_pool < 1");
  return 0;
}
