#pragma once
// Shape families by name: the scene's `shape: <family>` resolves here. A family is a factory
// from the template's parameters to a prototype (the shape at circumscribed radius 1) plus its
// named dimensions at that scale, on which a size distribution may be stated ("radius",
// "length", ...). Adding a shape = its own files + its entry in shapes/builtin_shapes.cpp.
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/io/scene.hpp"
#include "shapes/shape.hpp"

namespace fp {

template <int D>
struct ShapePrototype {
  ShapePtr<D> shape;                          ///< circumscribed radius 1
  std::map<std::string, double> dimensions;   ///< named dimensions at that scale; always has "circumscribed_radius" = 1
};

template <int D>
using ShapeFamilyFactory = std::function<ShapePrototype<D>(const ShapeParameters&)>;

/// What a user needs to write a template of a family: the registry checks a template's keys
/// against `parameters` (an unknown one is an error naming the known ones), and lists all of it
/// (frontpack.shape_families() in Python; the README's table says the same).
struct ShapeFamilyInfo {
  std::string summary;                                          ///< one line: what the shape is
  std::vector<std::pair<std::string, std::string>> parameters;  ///< name, what it means (and its range)
  std::vector<std::string> size_on;  ///< the named dimensions a size may be drawn on, circumscribed_radius first
};

class ShapeFamilies {
 public:
  /// Every built-in family (registered in shapes/builtin_shapes.cpp).
  static const ShapeFamilies& builtin();

  /// Registers a family; a null factory means the family does not exist in that dimension.
  void add(const std::string& name, ShapeFamilyFactory<2> in_2d, ShapeFamilyFactory<3> in_3d, ShapeFamilyInfo info = {});
  /// Its parameters and dimensions (throws std::out_of_range for an unknown family).
  const ShapeFamilyInfo& info(const std::string& name) const { return families_.at(name).info; }

  bool has(const std::string& name) const { return families_.count(name) != 0; }
  std::vector<std::string> names() const;
  /// Whether family `name` exists in dimension `dimension` (2 or 3).
  bool in_dimension(const std::string& name, int dimension) const;

  /// The prototype of a template; throws SceneError (file, line, key) on an unknown family, a
  /// family missing in dimension D, a bad parameter or a size stated on an unknown dimension.
  template <int D>
  ShapePrototype<D> prototype(const ParticleTemplateSpec& spec) const;

 private:
  struct Family {
    ShapeFamilyFactory<2> in_2d;
    ShapeFamilyFactory<3> in_3d;
    ShapeFamilyInfo info;
  };
  std::map<std::string, Family> families_;
};

/// The one place that lists the built-in families (one line each).
void register_builtin_shapes(ShapeFamilies& families);

}  // namespace fp
