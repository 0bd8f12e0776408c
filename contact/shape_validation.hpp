#pragma once
// Checks a packing of general particles from the particles alone: every pair whose circumscribed
// spheres meet (found with a grid, then the narrow phase), every particle against the container
// (its hull balls: exact for convex containers). The figures the packer reports are the ones
// this finds. Also counts contacts (|gap| <= tolerance) for the coordination number.
#include <cstdint>
#include <string>

#include "core/geometry/container.hpp"
#include "shapes/particle.hpp"

namespace fp {

struct ShapeValidation {
  bool ok = true;
  double tolerance = 0;            ///< relative to the smaller circumscribed radius of a pair
  std::uint64_t pairs_checked = 0; ///< pairs given to the narrow phase
  std::uint64_t overlaps = 0;      ///< pairs overlapping beyond the tolerance
  double max_overlap_rel = 0;      ///< largest overlap depth / smaller circumscribed radius
  int worst_a = -1, worst_b = -1;
  std::uint64_t outside = 0;       ///< particles reaching beyond the container by more than the tolerance
  double max_outside_rel = 0;      ///< largest protrusion / circumscribed radius
  std::uint64_t contacts = 0;      ///< particle pairs with |gap| <= tolerance
  std::uint64_t wall_contacts = 0; ///< particles within the tolerance of the boundary
  double mean_coordination = 0;    ///< 2 contacts / N

  std::string summary() const;
};

template <int D>
ShapeValidation validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance);

}  // namespace fp
