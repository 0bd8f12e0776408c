#pragma once
// Volume fraction (area fraction in 2D) of a packing, paper 002 Sect. 5: in a reference ball,
// with the exact intersection of every particle with it (Eq. 2), and over the whole container.
#include <utility>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/geometry/vec.hpp"

namespace fp {

/// Sum over the particles of |ball_i intersect ball(center, r_ref)|, divided by |ball(center, r_ref)|.
/// O(N). Throws std::invalid_argument unless r_ref > 0 and finite. Exact up to rounding; it is
/// the VF of the packing only while the particles do not overlap one another.
template <int D>
double vf_reference_sphere(const Packing<D>& packing, const Vec<D>& center, double r_ref);

/// (r_ref, VF) at `count` equispaced radii from r_from to r_to inclusive (paper 002 uses 31 radii
/// in [r_max, a], a the half side of the cube). count == 1 gives r_from only. O(N * count).
template <int D>
std::vector<std::pair<double, double>> vf_reference_curve(const Packing<D>& packing, const Vec<D>& center,
                                                          double r_from, double r_to, int count = 31);

/// Sum of particle volumes / container_measure, with compensated summation. Exact when every
/// particle lies inside the container (validate_packing checks that) and none overlap.
template <int D>
double vf_container(const Packing<D>& packing, double container_measure);

}  // namespace fp
