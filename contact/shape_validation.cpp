#include "contact/shape_validation.hpp"

#include <algorithm>
#include <cstdio>

#include "contact/narrow_phase.hpp"
#include "contact/shape_containment.hpp"
#include "core/geometry/neighbour_grid.hpp"

namespace fp {

std::string ShapeValidation::summary() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: %llu pairs checked, %llu overlapping (max overlap %.3g of the smaller circumscribed radius, pair %d-%d), "
                "%llu outside the container (max %.3g r), tolerance %.3g",
                ok ? "ok" : "FAILED", static_cast<unsigned long long>(pairs_checked),
                static_cast<unsigned long long>(overlaps), max_overlap_rel, worst_a, worst_b,
                static_cast<unsigned long long>(outside), max_outside_rel, tolerance);
  return buf;
}

template <int D>
ShapeValidation validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance) {
  ShapeValidation v;
  v.tolerance = tolerance;
  const auto& P = packing.particles;
  if (P.empty()) return v;
  double r_min = P[0].bounding_radius(), r_max = r_min;
  Aabb<D> box;
  for (const auto& p : P) {
    r_min = std::min(r_min, p.bounding_radius());
    r_max = std::max(r_max, p.bounding_radius());
    box.extend(p.pose.position);
  }
  box.lo.array() -= r_max;
  box.hi.array() += r_max;
  NeighbourGrid<D> grid(box, r_min, r_max);
  NarrowPhase<D> np;
  const ShapeContainment<D> containment(container, np);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Particle<D>& p = P[i];
    const double r = p.bounding_radius();
    grid.for_each_within(p.pose.position, r, [&](int j, const Vec<D>&, double rj, double) {
      ++v.pairs_checked;
      const double g = np.gap(P[static_cast<std::size_t>(j)], p).value;
      const double scale = std::min(r, rj);
      if (std::abs(g) <= tolerance * scale) ++v.contacts;
      if (-g / scale > v.max_overlap_rel) {
        v.max_overlap_rel = -g / scale;
        v.worst_a = j;
        v.worst_b = static_cast<int>(i);
      }
      if (g < -tolerance * scale) ++v.overlaps;
    });
    grid.insert(static_cast<int>(i), p.pose.position, r);
    const double beyond = containment.protrusion(p);
    if (beyond / r > v.max_outside_rel) v.max_outside_rel = beyond / r;
    if (beyond > tolerance * r) ++v.outside;
    if (std::abs(beyond) <= tolerance * r) ++v.wall_contacts;
  }
  v.mean_coordination = 2.0 * static_cast<double>(v.contacts) / static_cast<double>(P.size());
  v.ok = v.overlaps == 0 && v.outside == 0;
  return v;
}

template ShapeValidation validate_shapes<2>(const ShapePacking<2>&, const Container<2>&, double);
template ShapeValidation validate_shapes<3>(const ShapePacking<3>&, const Container<3>&, double);

}  // namespace fp
