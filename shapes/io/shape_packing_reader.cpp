#include "shapes/io/shape_packing_reader.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/exact_decimal.hpp"
#include "core/io/run_record.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/pose.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {
namespace {

using Json = nlohmann::json;

struct Reader {
  const std::string& source;

  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    throw std::runtime_error(source + ": " + where + ": " + why);
  }
  double number(const Json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(where, "not a finite number");
    return v;
  }
  double positive(const Json& j, const std::string& where) const {
    const double v = number(j, where);
    if (!(v > 0)) fail(where, "must be positive");
    return v;
  }
  const Json& member(const Json& j, const char* key, const std::string& where) const {
    if (!j.is_object() || !j.contains(key)) fail(where, std::string("missing key '") + key + "'");
    return j[key];
  }
  const Json& list(const Json& j, const std::string& where, std::size_t n = 0) const {
    if (!j.is_array() || (n && j.size() != n))
      fail(where, n ? "expected a list of " + std::to_string(n) + " numbers" : std::string("expected a list"));
    return j;
  }
  /// A shape of finite, positive circumscribed radius and measure (huge numbers overflow).
  template <int D>
  void finite_shape(const Shape<D>& s, const std::string& where) const {
    const double r = s.bounding_radius(), m = s.measure();
    if (!(std::isfinite(r) && r > 0 && std::isfinite(m) && m > 0))
      fail(where, "gives a shape of circumscribed radius " + std::to_string(r) + " and measure " + std::to_string(m));
  }
  template <int K>
  Eigen::Matrix<double, K, 1> point(const Json& j, const std::string& where) const {
    list(j, where, K);
    Eigen::Matrix<double, K, 1> p;
    for (int k = 0; k < K; ++k) p[k] = number(j[static_cast<std::size_t>(k)], where + "[" + std::to_string(k) + "]");
    return p;
  }

  /// The shape a template's definition (shape_packing_writers: each kind's definition_json()) describes.
  template <int D>
  ShapePtr<D> shape(const Json& def, const std::string& where) const {
    const Json& kind_json = member(def, "kind", where);
    if (!kind_json.is_string()) fail(where + ".kind", "expected a string");
    const std::string kind = kind_json.get<std::string>();
    if (kind == SphereShape<D>::kKind) return std::make_shared<SphereShape<D>>(positive(member(def, "radius", where), where + ".radius"));
    if (kind == SpherocylinderShape<D>::kKind) {
      const double a = number(member(def, "segment_half_length", where), where + ".segment_half_length");
      if (!(a >= 0)) fail(where + ".segment_half_length", "must not be negative");
      return std::make_shared<SpherocylinderShape<D>>(a, positive(member(def, "radius", where), where + ".radius"));
    }
    if (kind == EllipsoidShape<D>::kKind) {
      const Vec<D> axes = point<D>(member(def, "semi_axes", where), where + ".semi_axes");
      if (!(axes.array() > 0).all()) fail(where + ".semi_axes", "must be positive");
      return std::make_shared<EllipsoidShape<D>>(axes);
    }
    if (kind == ClusterShape<D>::kKind) {
      const Json& centers = list(member(def, "centers", where), where + ".centers");
      const Json& radii = list(member(def, "radii", where), where + ".radii", centers.size());
      if (centers.empty()) fail(where + ".centers", "no member");
      std::vector<Ball<D>> members;
      for (std::size_t k = 0; k < centers.size(); ++k) {
        const std::string at = "[" + std::to_string(k) + "]";
        members.push_back({point<D>(centers[k], where + ".centers" + at), positive(radii[k], where + ".radii" + at)});
      }
      return std::make_shared<ClusterShape<D>>(std::move(members));
    }
    if (kind == ConvexPolytopeShape<D>::kKind) {
      const Json& vj = list(member(def, "vertices", where), where + ".vertices");
      const Json& fj = list(member(def, "facets", where), where + ".facets");
      if (vj.size() < static_cast<std::size_t>(D + 1) || fj.size() < static_cast<std::size_t>(D + 1))
        fail(where, "a polytope needs at least " + std::to_string(D + 1) + " vertices and facets");
      std::vector<Vec<D>> vertices;
      for (std::size_t k = 0; k < vj.size(); ++k) vertices.push_back(point<D>(vj[k], where + ".vertices[" + std::to_string(k) + "]"));
      std::vector<std::array<int, D>> facets;
      for (std::size_t k = 0; k < fj.size(); ++k) {
        const std::string at = where + ".facets[" + std::to_string(k) + "]";
        const auto f = point<D>(fj[k], at);
        std::array<int, D> ids;
        for (int c = 0; c < D; ++c) {
          if (!(f[c] >= 0 && f[c] < static_cast<double>(vertices.size()) && f[c] == std::floor(f[c]))) fail(at, "not a vertex index");
          ids[static_cast<std::size_t>(c)] = static_cast<int>(f[c]);
        }
        facets.push_back(ids);
      }
      return std::make_shared<ConvexPolytopeShape<D>>(std::move(vertices), std::move(facets));
    }
    if constexpr (D == 3)
      if (kind == CylinderShape::kKind)
        return std::make_shared<CylinderShape>(positive(member(def, "radius", where), where + ".radius"),
                                               0.5 * positive(member(def, "height", where), where + ".height"));
    fail(where + ".kind", "unknown shape kind '" + kind + "' for a " + std::to_string(D) + "D packing");
  }
};

}  // namespace

bool is_shape_packing_json(const std::string& text) {
  const Json j = Json::parse(text, nullptr, false);
  return j.is_object() && j.contains("shapes");
}

template <int D>
ShapePacking<D> read_shape_packing_json(const std::string& text, const std::string& source_name, const Vec<D>& origin) {
  const Reader r{source_name};
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::exception& e) {
    throw std::runtime_error(source_name + ": invalid JSON: " + json_error_text(e.what()));
  }
  const Json& dim = r.member(j, "dimension", "top level");
  if (!dim.is_number_integer() || dim.get<int>() != D)
    r.fail("dimension", "the file is not a " + std::to_string(D) + "D packing");

  ShapePacking<D> out;
  out.origin = origin;
  struct Template {
    ShapePtr<D> shape;  // at the representative size
    double size = 0;
  };
  std::vector<Template> templates;
  const Json& shapes = r.list(r.member(j, "shapes", "top level"), "shapes");
  for (std::size_t t = 0; t < shapes.size(); ++t) {
    const std::string where = "shapes[" + std::to_string(t) + "]";
    const Json& s = shapes[t];
    const Json& name = r.member(s, "name", where);
    out.template_names.push_back(name.is_string() ? name.get<std::string>() : std::string());
    const Json& def = r.member(s, "definition", where);
    if (def.is_null()) {  // a template that placed nothing
      templates.push_back({});
      continue;
    }
    Template made{r.shape<D>(def, where + ".definition"),
                  r.positive(r.member(s, "representative_size", where), where + ".representative_size")};
    r.finite_shape(*made.shape, where + ".definition");
    templates.push_back(std::move(made));
  }

  const Json& particles = r.list(r.member(j, "particles", "top level"), "particles");
  std::vector<std::string> position_text;
  if (!origin.isZero()) {  // far from the origin a double lost digits: subtract it from the text
    position_text = std::move(json_number_texts(text, 1, [](const std::vector<std::string>& path) {
      return path == std::vector<std::string>{"particles", "[]", "position"} ? 0 : -1;
    })[0]);
    if (position_text.size() != 3 * particles.size()) r.fail("particles", "cannot re-read the positions");
  }
  const auto axes = offset_axes(origin.data(), D);
  out.particles.reserve(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const std::string where = "particles[" + std::to_string(i) + "]";
    const Json& p = particles[i];
    const Json& id = r.member(p, "shape_id", where);
    if (!id.is_number_integer() || id.get<std::int64_t>() < 0 || id.get<std::uint64_t>() >= templates.size())
      r.fail(where + ".shape_id", "not the index of an entry of 'shapes'");
    const Template& t = templates[id.get<std::size_t>()];
    if (!t.shape) r.fail(where + ".shape_id", "its entry of 'shapes' has no definition");
    const Vec3 x = r.point<3>(r.member(p, "position", where), where + ".position");
    const Eigen::Vector4d q = r.point<4>(r.member(p, "quaternion", where), where + ".quaternion");
    if (!(std::abs(q.norm() - 1) <= 1e-6)) r.fail(where + ".quaternion", "not a unit quaternion");
    const double size = r.positive(r.member(p, "size", where), where + ".size");
    if constexpr (D == 2)
      if (x.z() != 0 || q[1] != 0 || q[2] != 0) r.fail(where, "a 2D particle has z = 0 and a rotation about z");
    Particle<D> particle;
    particle.shape = size == t.size ? t.shape : t.shape->scaled(size / t.size);
    r.finite_shape(*particle.shape, where + ".size");
    particle.template_id = id.get<int>();
    particle.size = size;
    particle.pose.rotation = rotation_of<D>(q);
    for (int k = 0; k < D; ++k) {
      if (axes[static_cast<std::size_t>(k)].zero()) {
        particle.pose.position[k] = x[k];
        continue;
      }
      const auto v = axes[static_cast<std::size_t>(k)].local_from_text(position_text[3 * i + static_cast<std::size_t>(k)]);
      if (!v) r.fail(where + ".position", "not a plain decimal number");
      particle.pose.position[k] = *v;
    }
    out.particles.push_back(std::move(particle));
  }
  return out;
}

template ShapePacking<2> read_shape_packing_json<2>(const std::string&, const std::string&, const Vec2&);
template ShapePacking<3> read_shape_packing_json<3>(const std::string&, const std::string&, const Vec3&);

}  // namespace fp
