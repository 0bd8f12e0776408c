// The built-in shape families: name, 2D factory, 3D factory (nullptr = the family does not exist
// in that dimension) and what a user writes for it (the parameters the registry accepts, the
// dimensions a size may be drawn on; tests/shapes/shape_registry_test.cpp checks them against
// the factories). A new shape adds its own files and its entry here.
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/round_families.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

void register_builtin_shapes(ShapeFamilies& families) {
  families.add("sphere", sphere_prototype<2>, sphere_prototype<3>,
               {"a disk (2D) or a sphere (3D) through the general front (radii: the sphere fast path)", {},
                {"circumscribed_radius", "diameter", "equivalent_radius", "radius"}});
  families.add("spherocylinder", spherocylinder_prototype<2>, spherocylinder_prototype<3>,
               {"a stadium (2D) or a capsule (3D): a cylinder with hemispherical caps",
                {{"elongation", "total length / width, >= 1 (1: a sphere; L/D + 1 for a shaft L, diameter D)"},
                 {"aspect_ratio", "instead, the older key: width / total length, in (0, 1]"}},
                {"circumscribed_radius", "cylinder_length", "equivalent_radius", "length", "radius", "width"}});
  families.add("cluster", cluster_prototype<2>, cluster_prototype<3>,
               {"a clump of overlapping disks (2D) or spheres (3D), rigid",
                {{"centers", "the members' centres, [[x, y(, z)], ...] (rescaled: circumscribed radius 1)"},
                 {"radii", "the members' radii, one per centre"},
                 {"preset", "instead of centers and radii: dimer | trimer (equal members touching; the same clump in 2D and 3D)"}},
                {"circumscribed_radius", "equivalent_radius"}});
  families.add("polygon", convex_polytope_prototype<2>, nullptr,
               {"a convex polygon",
                {{"vertices", "[[x, y], ...] (the convex hull is taken)"}, {"sides", "instead: a regular polygon of N >= 3 sides"}},
                {"circumscribed_radius", "equivalent_radius", "inscribed_radius"}});
  families.add("polyhedron", nullptr, convex_polytope_prototype<3>,
               {"a convex polyhedron",
                {{"vertices", "[[x, y, z], ...] (the convex hull is taken)"},
                 {"preset", "instead: tetrahedron | cube | octahedron | dodecahedron | icosahedron"},
                 {"platonic", "instead: a Platonic solid by its number of faces, 4 | 6 | 8 | 12 | 20"}},
                {"circumscribed_radius", "equivalent_radius", "inscribed_radius"}});
  families.add("ellipse", ellipsoid_prototype<2>, nullptr,
               {"an ellipse", {{"axes", "[a, b]: the semi-axes' ratios"}},
                {"circumscribed_radius", "equivalent_radius", "semi_axis_a", "semi_axis_b"}});
  families.add("ellipsoid", nullptr, ellipsoid_prototype<3>,
               {"an ellipsoid", {{"axes", "[a, b, c]: the semi-axes' ratios"}},
                {"circumscribed_radius", "equivalent_radius", "semi_axis_a", "semi_axis_b", "semi_axis_c"}});
  families.add("cylinder", nullptr, cylinder_prototype,
               {"a circular cylinder with flat ends",
                {{"elongation", "height / diameter, > 0 (above 1 a rod, below 1 a disc)"},
                 {"aspect_ratio", "instead, the older key: diameter / height, > 0"}},
                {"circumscribed_radius", "diameter", "equivalent_radius", "height", "radius"}});
}

}  // namespace fp
