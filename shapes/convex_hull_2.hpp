#pragma once
// Convex hull of planar points (Andrew's monotone chain): the polygon's extreme vertices,
// counter-clockwise, without duplicates or points on edges.
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// Throws std::invalid_argument when the points span no area (fewer than 3, coincident or
/// collinear up to 1e-12 of their extent).
std::vector<Vec2> convex_hull_2(std::vector<Vec2> points);

}  // namespace fp
