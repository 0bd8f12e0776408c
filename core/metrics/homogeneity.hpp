#pragma once
// Homogeneity of a packing (paper 002 Sect. 1 and 4): a one-sample Kolmogorov-Smirnov test of
// each centre coordinate against the uniform distribution. The paper packs cubes and does not
// state the interval; here it is the container's bounding range shrunk by `margin` at each end
// (the analysis passes r_max: the range the centres of the largest particles can reach). For a
// box this is the natural reference; for other shapes the marginal of a homogeneous packing is
// not uniform, so the figures there say how far from a box-like spread the centres are.
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/metrics/ks_result.hpp"

namespace fp {

struct CentreHomogeneity {
  double margin = 0.0;
  std::vector<double> lo, hi;  ///< reference interval per axis
  std::vector<KsResult> axis;  ///< x, y (, z); NaN figures for an axis whose interval is empty
};

/// O(N log N). Balls with a non-finite centre or radius are left out.
template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Aabb<D>& bounds, double margin);

}  // namespace fp
