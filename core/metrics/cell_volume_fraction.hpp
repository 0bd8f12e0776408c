#pragma once
// Uniformity of a packing: the solid fraction in cubic (square) cells of a few mean diameters,
// away from the walls (a target solid fraction is only a target if every part of the
// container has it; a stop criterion alone leaves a dense core and an empty rim).
//
// Cells tile space from the container's low corner with edge `edge`; a cell is counted when it
// lies wholly inside the container at least `margin` from the boundary (signed distance of its
// centre <= -(half its diagonal + margin): the signed distance is 1-Lipschitz), so its measure
// is edge^D exactly. Each ball adds its measure inside the cell (ball_box.hpp); balls are assumed
// not to overlap, as validate checks. The figures: the cells' mean, standard deviation
// (population), extremes and the cell farthest from the mean.
#include <cstdint>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"

namespace fp {

struct CellVolumeFraction {
  double edge = 0.0;          ///< the cells' edge
  double diameters = 0.0;     ///< edge / mean diameter
  double margin = 0.0;        ///< the cells' distance to the boundary, at least
  std::uint64_t cells = 0;    ///< cells counted; 0: none fits (figures NaN)
  double mean = 0.0, std_dev = 0.0, min = 0.0, max = 0.0;
  double worst = 0.0;         ///< the VF of the cell farthest from the mean
  std::vector<double> worst_centre;  ///< its centre, absolute coordinates
  bool computed() const { return cells > 0; }
};

/// The per-cell VF with cells of `edge` at least `margin` inside. Throws std::invalid_argument
/// for a non-positive or non-finite edge, a negative margin, or more than 2^26 cells in the
/// container's bounds. O(N) plus the cells.
template <int D>
CellVolumeFraction cell_volume_fraction(const Packing<D>& packing, const Container<D>& container, double edge,
                                        double margin);

/// The analysis' choice: cells of `diameters` mean diameters (2 r_mean), halved down to 2 mean
/// diameters until at least `min_cells` are counted; margin 2 r_max (the core's). Not computed
/// (cells = 0) when the packing is empty or no cell fits at 2 diameters.
template <int D>
CellVolumeFraction cell_volume_fraction_auto(const Packing<D>& packing, const Container<D>& container, double r_mean,
                                             double r_max, double diameters = 8.0, std::uint64_t min_cells = 8);

}  // namespace fp
