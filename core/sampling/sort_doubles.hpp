#pragma once
// Ascending sort of doubles in linear time (LSD radix sort on their bit patterns, 16 bits a
// pass): the goodness-of-fit tests and the analysis sort millions of radii, coordinates and
// contact projections, where std::sort's comparisons were a quarter of `frontpack analyze`.
// The result is std::sort's (values in ascending order); -0.0 comes before +0.0 and NaNs go to
// the ends (negative ones first, positive ones last).
#include <vector>

namespace fp {

void sort_doubles(std::vector<double>& values);

}  // namespace fp
