#pragma once
// Exact measure of the intersection of two balls (paper 002, Sect. 5, Eq. 2): the building
// block of the reference-sphere volume fraction.
#include "core/geometry/vec.hpp"

namespace fp {

/// Volume of the intersection of two spheres of radii r1, r2 >= 0 whose centres are d >= 0 apart
/// (paper 002, Eq. 2). Disjoint or tangent: 0. One inside the other (d <= |r1 - r2|, which
/// includes d = 0): the volume of the smaller sphere. Otherwise the lens formula, which is
/// continuous at both transitions.
double lens_volume(double r1, double r2, double d);

/// Area of the intersection of two disks (same cases as lens_volume): the sum of the two
/// circular segments cut by the common chord.
double lens_area(double r1, double r2, double d);

/// lens_area in 2D, lens_volume in 3D.
template <int D>
double ball_intersection_measure(double r1, double r2, double d) {
  if constexpr (D == 2) return lens_area(r1, r2, d);
  else return lens_volume(r1, r2, d);
}

}  // namespace fp
