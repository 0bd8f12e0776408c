#include "cli/packing_input.hpp"

#include <stdexcept>

#include "core/io/output_format.hpp"
#include "core/io/packing_readers.hpp"
#include "core/io/scene_yaml.hpp"
#include "shapes/io/shape_packing_reader.hpp"

namespace fp {

PackingInput read_packing_input(const std::string& packing_path, const std::string& format, const std::string& scene_path,
                                bool shapes_too, const std::vector<SceneOverride>& overrides) {
  PackingInput in;
  if (!scene_path.empty()) in.scene = load_scene(scene_path, overrides);
  const OutputFormat f = format.empty() ? format_from_extension(packing_path) : parse_output_format(format);
  if (in.scene && !in.scene->particle_templates.empty()) {
    if (!shapes_too) throw std::runtime_error(scene_path + " describes non-spherical particles: " + kSpheresAndDisksOnly);
    if (f != OutputFormat::Json)
      throw std::runtime_error(packing_path + ": " + scene_path +
                               " describes non-spherical particles: give the packing's json output, which carries the shapes");
    const std::string text = read_packing_text(packing_path);
    if (!is_shape_packing_json(text))
      throw std::runtime_error(packing_path + ": not the json output of a packing of shapes (no 'shapes' list), which " +
                               scene_path + " describes");
    in.shapes = true;
    in.dimension = in.scene->dimension;
    if (in.dimension == 2) in.shapes2 = read_shape_packing_json<2>(text, packing_path, in.scene->container<2>()->origin());
    else in.shapes3 = read_shape_packing_json<3>(text, packing_path, in.scene->container<3>()->origin());
    const std::size_t templates = in.scene->particle_templates.size();
    const auto check_ids = [&](const auto& particles) {  // the file's shape ids name the scene's templates
      for (std::size_t i = 0; i < particles.size(); ++i)
        if (static_cast<std::size_t>(particles[i].template_id) >= templates)
          throw std::runtime_error(packing_path + ": particles[" + std::to_string(i) + "].shape_id is " +
                                   std::to_string(particles[i].template_id) + " but " + scene_path + " has " +
                                   std::to_string(templates) + " particle templates");
    };
    if (in.dimension == 2) check_ids(in.shapes2.particles);
    else check_ids(in.shapes3.particles);
    return in;
  }
  in.dimension = packing_file_dimension(f, packing_path);
  if (in.scene && in.dimension != in.scene->dimension)
    throw std::runtime_error(packing_path + " holds a " + std::to_string(in.dimension) + "D packing but " + scene_path +
                             " is a " + std::to_string(in.scene->dimension) + "D scene");
  // Read in the container's frame (exact: the packer's own doubles), or without a scene in the
  // frame the particles' bounds give.
  if (in.dimension == 2)
    in.packing2 = in.scene ? read_packing<2>(f, packing_path, in.scene->container<2>()->origin())
                           : read_packing_in_own_frame<2>(f, packing_path);
  else
    in.packing3 = in.scene ? read_packing<3>(f, packing_path, in.scene->container<3>()->origin())
                           : read_packing_in_own_frame<3>(f, packing_path);
  return in;
}

std::vector<NamedPath> scene_reads(const Scene& scene, const std::string& named_by) {
  std::vector<NamedPath> reads;
  for (std::size_t k = 0; k < scene.read_files.size(); ++k) {
    // The scene file comes first when there is one (a scene given as text, a Python dict, has none).
    const bool scene_file = k == 0 && scene.read_files[0] == scene.source_path;
    reads.push_back({scene.read_files[k], scene_file ? named_by : scene.source_path + ": key 'container.file'",
                     scene_file ? "scene file" : "mesh file"});
  }
  return reads;
}

}  // namespace fp
