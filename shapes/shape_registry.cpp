#include "shapes/shape_registry.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "shapes/shape_parameters.hpp"

namespace fp {

const ShapeFamilies& ShapeFamilies::builtin() {
  static const ShapeFamilies families = [] {
    ShapeFamilies f;
    register_builtin_shapes(f);
    return f;
  }();
  return families;
}

void ShapeFamilies::add(const std::string& name, ShapeFamilyFactory<2> in_2d, ShapeFamilyFactory<3> in_3d, ShapeFamilyInfo info) {
  if (!in_2d && !in_3d) throw std::logic_error("shape family '" + name + "' has no factory in 2D nor in 3D");
  if (!families_.emplace(name, Family{std::move(in_2d), std::move(in_3d), std::move(info)}).second)
    throw std::logic_error("shape family '" + name + "' registered twice");
}

std::vector<std::string> ShapeFamilies::names() const {
  std::vector<std::string> out;
  for (const auto& [name, f] : families_) out.push_back(name);
  return out;
}

bool ShapeFamilies::in_dimension(const std::string& name, int dimension) const {
  const auto f = families_.find(name);
  if (f == families_.end()) return false;
  return dimension == 2 ? static_cast<bool>(f->second.in_2d) : dimension == 3 && static_cast<bool>(f->second.in_3d);
}

template <int D>
ShapePrototype<D> ShapeFamilies::prototype(const ParticleTemplateSpec& spec) const {
  const ParameterReader reader(spec.parameters);
  auto listed = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  };
  auto factory_of = [](const Family& f) -> const ShapeFamilyFactory<D>& {
    if constexpr (D == 2) return f.in_2d;
    else return f.in_3d;
  };
  std::vector<std::string> in_d;  // the families that exist in this dimension, for the messages
  for (const auto& [name, f] : families_)
    if (factory_of(f)) in_d.push_back(name);

  auto it = families_.find(spec.family);
  if (it == families_.end())
    reader.fail("shape", "unknown shape '" + spec.family + "' (known in " + std::to_string(D) + "D: " + listed(in_d) + ")");
  const ShapeFamilyFactory<D>& make = factory_of(it->second);
  if (!make)
    reader.fail("shape", "shape '" + spec.family + "' does not exist in " + std::to_string(D) + "D (known in " +
                             std::to_string(D) + "D: " + listed(in_d) + ")");

  std::vector<std::string> known;
  for (const auto& [name, meaning] : it->second.info.parameters) known.push_back(name);
  reader.check_known(known, spec.family);
  ShapePrototype<D> proto = make(spec.parameters);
  if (!proto.shape || proto.dimensions.count("circumscribed_radius") == 0)
    throw std::logic_error("shape family '" + spec.family + "' returned an incomplete prototype");

  if (proto.dimensions.count(spec.size_on) == 0) {
    std::vector<std::string> dims;
    for (const auto& [name, value] : proto.dimensions) dims.push_back(name);
    reader.fail("size_on", "shape '" + spec.family + "' has no dimension '" + spec.size_on + "' (its dimensions: " +
                               listed(dims) + ")");
  }
  // Proportions beyond what a double resolves (axes: [1e228, 0.5, 0.25]) leave a shape of no
  // measure, or a dimension of 0, at circumscribed radius 1: nothing could be sized or packed.
  const double measure = proto.shape->measure(), dimension = proto.dimensions.at(spec.size_on);
  if (!(measure > 0) || !std::isfinite(measure) || !(dimension > 0) || !std::isfinite(dimension)) {
    std::ostringstream os;
    os.precision(6);
    os << "shape '" << spec.family << "' is degenerate with these parameters (at circumscribed radius 1 its "
       << (D == 3 ? "volume" : "area") << " is " << measure << " and its " << spec.size_on << " " << dimension
       << "): its proportions are too extreme";
    reader.fail("shape", os.str());
  }
  return proto;
}

template ShapePrototype<2> ShapeFamilies::prototype<2>(const ParticleTemplateSpec&) const;
template ShapePrototype<3> ShapeFamilies::prototype<3>(const ParticleTemplateSpec&) const;

}  // namespace fp
