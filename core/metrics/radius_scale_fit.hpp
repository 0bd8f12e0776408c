#pragma once
// The scale of a packing's radii against a law (`stop: {particles: N, scale_sizes: true}` scales
// the law so that N particles fill the container): fitted from the radii, so that `pack` and
// `validate` test the law's shape with the same scale, from the packing alone. The K-S test with a
// fitted scale is conservative (its p-values are too large, never too small).
#include <span>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// The factor s that makes `radii` (finite, positive) a sample of `law` scaled by s:
///   discrete law: the most common radius over the value that puts the most radii on the law's
///     values (within kRadiusSlack; ties: the ratio nearest the ratio of the means);
///   continuous law: the mean radius over the law's mean, moved into the scales that keep every
///     radius within the law's range ([max r / r_max, min r / r_min]) when there are such scales.
/// 1 for an empty sample.
double fit_radius_scale(std::span<const double> radii, const RadiusDistribution& law);

}  // namespace fp
