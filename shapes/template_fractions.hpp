#pragma once
// The share of each particle template by number, from the scene's `fraction`s: given by number
// (the default), or by volume or mass (what a sieve analysis or a mix design gives). By volume,
// template k's number share is proportional to f_k / E[V_k], E[V_k] its mean particle volume
// (area in 2D): the prototype's measure times E[(size x scale)^D] of its size law. One material
// for every template, so mass and volume shares are the same.
#include <vector>

#include "core/io/scene.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

/// The mean measure of one particle of a template: `prototype` (circumscribed radius 1) scaled
/// by `scale_per_size` times the size drawn from `size`.
template <int D>
double mean_particle_measure(const ShapePrototype<D>& prototype, double scale_per_size, const RadiusDistribution& size);

/// The number share of each of the scene's templates (summing to 1), in the scene's order, from
/// each template's mean particle measure (`measures`, used for fractions by volume).
std::vector<double> number_fractions(const Scene& scene, const std::vector<double>& measures);

/// The same, each template's prototype made from the scene. Throws SceneError as
/// ShapeFamilies::prototype does for a template it cannot make.
template <int D>
std::vector<double> number_fractions(const Scene& scene);

}  // namespace fp
