#pragma once
// contains() of the families with planar or quadric faces accepts points up to this fraction of
// the bounding radius outside, so that the shape's own support points and vertices, computed with
// rounding, test inside (a closed shape must contain its boundary).
namespace fp {

inline constexpr double kContainsSlack = 1e-12;

}  // namespace fp
