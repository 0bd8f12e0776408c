#pragma once
// The simulation box of a LAMMPS / LIGGGHTS data file, shared by the sphere and shape writers:
// the container bounds (run record), grown if needed so that every atom centre is inside
// (LAMMPS drops atoms outside the box); without bounds, the atoms' bounding box grown by their
// radii. Every axis gets lo < hi; a 2D packing sits at z = 0 inside a thin slab.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/vec.hpp"
#include "core/io/run_record.hpp"

namespace fp {

template <int D>
class LammpsBox {
 public:
  explicit LammpsBox(const RunRecord& rec) : rec_(rec) {}

  void add_atom(const Vec<D>& c, double r) {
    r_max_ = std::max(r_max_, r);
    for (int k = 0; k < D; ++k) {
      lo_[k] = std::min(lo_[k], rec_.bounds ? c[k] : c[k] - r);
      hi_[k] = std::max(hi_[k], rec_.bounds ? c[k] : c[k] + r);
    }
  }

  /// The box (call after every atom is added).
  Aabb<3> finish() const {
    Vec3 lo = lo_, hi = hi_;
    if (rec_.bounds) {
      lo = lo.cwiseMin(rec_.bounds->lo);
      hi = hi.cwiseMax(rec_.bounds->hi);
    }
    const double half = r_max_ > 0 ? r_max_ : 0.5;
    for (int k = 0; k < 3; ++k) {
      if (!(lo[k] < hi[k])) {  // empty packing or a flat axis: LAMMPS needs lo < hi
        const double mid = std::isfinite(lo[k]) && std::isfinite(hi[k]) ? 0.5 * (lo[k] + hi[k]) : 0.0;
        lo[k] = mid - half;
        hi[k] = mid + half;
      }
    }
    if constexpr (D == 2) {  // LAMMPS 2D wants the atoms at z = 0 strictly inside a thin z slab
      lo[2] = -half;
      hi[2] = half;
    }
    Aabb<3> box;
    box.lo = lo;
    box.hi = hi;
    return box;
  }

 private:
  const RunRecord& rec_;
  Vec3 lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi_ = Vec3::Constant(-std::numeric_limits<double>::infinity());
  double r_max_ = 0.0;
};

}  // namespace fp
