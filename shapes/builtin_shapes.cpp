// The built-in shape families, one line each: name, 2D factory, 3D factory (nullptr = the family
// does not exist in that dimension). A new shape adds its own files and one line here.
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/round_families.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

void register_builtin_shapes(ShapeFamilies& families) {
  families.add("sphere", sphere_prototype<2>, sphere_prototype<3>);
  families.add("spherocylinder", spherocylinder_prototype<2>, spherocylinder_prototype<3>);
  families.add("cluster", cluster_prototype<2>, cluster_prototype<3>);
  families.add("polygon", convex_polytope_prototype<2>, nullptr);
  families.add("polyhedron", nullptr, convex_polytope_prototype<3>);
  families.add("ellipse", ellipsoid_prototype<2>, nullptr);
  families.add("ellipsoid", nullptr, ellipsoid_prototype<3>);
  families.add("cylinder", nullptr, cylinder_prototype);
}

}  // namespace fp
