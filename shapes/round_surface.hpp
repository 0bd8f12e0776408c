#pragma once
// Display surfaces of round shapes: a ball of radius r swept along [-a e_x, a e_x] (a = 0 gives
// a circle / sphere; an ellipsoid scales the unit sphere's vertices per axis).
#include "shapes/shape.hpp"

namespace fp {

/// 2D: closed outline with `resolution` segments per full turn; 3D: triangles of a capsule
/// (resolution around the axis, resolution / 2 from pole to pole).
template <int D>
SurfaceMesh<D> capsule_surface(double a, double r, int resolution);

}  // namespace fp
