#pragma once
// Family factories of the two shapes defined by the shape interface itself (sphere_shape.hpp,
// spherocylinder_shape.hpp); every other family declares its factory in its own header.
#include "shapes/shape_registry.hpp"

namespace fp {

/// "sphere": no parameters. Dimensions: circumscribed_radius = radius = 1, diameter = 2.
template <int D>
ShapePrototype<D> sphere_prototype(const ShapeParameters& p);

/// "spherocylinder": elongation = total length / width >= 1 (or aspect_ratio, its inverse, in
/// (0, 1]). At circumscribed radius 1 the radius is r = 1 / elongation and the segment
/// half-length 1 - r. Dimensions: radius (r), length (2), width (2r), cylinder_length (2(1 - r)).
template <int D>
ShapePrototype<D> spherocylinder_prototype(const ShapeParameters& p);

/// Radius of the ball (disk) of the same measure: the size most DEM size curves are stated on.
template <int D>
double equivalent_radius(double measure);

}  // namespace fp
