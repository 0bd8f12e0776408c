#pragma once
// Vertices of a polytope that contains the unit disk / ball and stays close to it: the hull balls
// of curved convex shapes are these points mapped onto the shape (ellipsoids scale them per axis,
// cylinders use the 2D set for their rims). Their hull contains the shape, and sticks out by at
// most kUnitBallCoverSlack<D> of the shape's size (the points lie that far outside it).
//   2D: regular 32-gon, vertices at 1 / cos(pi / 32) (slack 0.48 %).
//   3D: geodesic icosphere (icosahedron split 3 times: 642 vertices, 1280 faces), vertices pushed
//       out by 1 / (smallest distance from the centre to a face plane) (slack 0.45 %).
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
const std::vector<Vec<D>>& unit_ball_cover();

/// Largest |vertex| - 1 of unit_ball_cover<D>().
template <int D>
double unit_ball_cover_slack();

}  // namespace fp
