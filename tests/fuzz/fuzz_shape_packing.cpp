// Fuzz harness of the shape packing reader (shapes/io/shape_packing_reader.hpp), as
// `frontpack validate PACKING.json --scene SCENE` calls it for a scene of shapes: every input is
// read in 2D and 3D, in the zero frame and in a far frame (exact decimal subtraction).
// Property: a read succeeds or throws the documented std::runtime_error naming the file, without
// C++ internals in its message. A packing read has every particle with a shape of finite,
// positive circumscribed radius and a template id among the file's shapes, in the frame asked for.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz_support.hpp"
#include "shapes/io/shape_packing_reader.hpp"

namespace {

using fp::fuzz::require;

template <int D>
void read_both(const std::string& text, std::string_view input, const fp::Vec<D>& origin, const std::string& context) {
  const std::string path = "packing.json";
  try {
    const fp::ShapePacking<D> p = fp::read_shape_packing_json<D>(text, path, origin);
    require(p.origin == origin, context + ": not in the frame asked for");
    for (const fp::Particle<D>& q : p.particles) {
      require(q.shape != nullptr, context + ": a particle without a shape");
      const double r = q.shape->bounding_radius();
      require(std::isfinite(r) && r > 0, context + ": a shape of circumscribed radius " + std::to_string(r));
      require(q.template_id >= 0 && static_cast<std::size_t>(q.template_id) < p.template_names.size(),
              context + ": a template id beyond the shapes");
    }
  } catch (const std::runtime_error& e) {
    fp::fuzz::check_error_message(e.what(), input, context);
    require(std::string_view(e.what()).find(path) != std::string_view::npos, context + ": the error does not name the file: " + e.what());
  } catch (...) {
    fp::fuzz::unexpected_exception(context);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > fp::fuzz::kMaxInputBytes) size = fp::fuzz::kMaxInputBytes;
  const std::string text(reinterpret_cast<const char*>(data), size);
  (void)fp::is_shape_packing_json(text);  // never throws
  read_both<2>(text, text, fp::Vec2::Zero(), "2D");
  read_both<3>(text, text, fp::Vec3::Zero(), "3D");
  read_both<2>(text, text, fp::Vec2(1e9, -0x1p40), "2D far");
  read_both<3>(text, text, fp::Vec3(1e9, -0x1p40, 0.5), "3D far");
  return 0;
}
