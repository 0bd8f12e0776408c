#pragma once
// Homogeneity of a packing (paper 002 Sect. 1 and 4): a one-sample Kolmogorov-Smirnov test of
// each centre coordinate against the uniform law. The paper packs cubes and does not state the
// interval. Here the test takes the centres in the container's core (the container less a margin;
// the analysis passes 2 r_max, the core of `VF core`): the wall layers are ordered by the walls in
// every dense packing, so no uniform law fits them. The reference is the coordinate's law for a
// point uniform in that core: exact where the container fills its bounding box (a box or a
// rectangle: uniform on the shrunk interval), else from quasi-random points of the bounding box
// kept in the core (a cylinder's, a sphere's, a mesh's marginal is not uniform).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/ks_result.hpp"

namespace fp {

struct CentreHomogeneity {
  double margin = 0.0;
  std::vector<double> lo, hi;  ///< the core's range per axis
  std::vector<KsResult> axis;  ///< x, y (, z); NaN figures for an axis whose core is empty
  std::uint64_t reference_points = 0;  ///< quasi-random points of the core the reference law is taken from (0: exact)
};

/// The box `bounds` less `margin` on every side as the core: the centres within it, each
/// coordinate against the uniform law on the core's interval. O(N log N). Balls with a
/// non-finite centre or radius are left out.
template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Aabb<D>& bounds, double margin);

/// `container` less `margin` as the core: for a container that fills its bounding box the
/// overload above; else the centres within the core (signed distance at most -margin), each
/// coordinate against the law of that coordinate over `points` Halton points of the bounding box
/// kept in the core. O(N log N + points) distance queries.
template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Container<D>& container, double margin,
                                     std::size_t points = std::size_t{1} << 17);

}  // namespace fp
