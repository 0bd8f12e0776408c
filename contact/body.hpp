#pragma once
// A fixed body a mobile particle may touch: another particle (for spheres: centre + radius)
// or a container wall. General shapes (a later issue) add a shape + orientation here.
#include "core/geometry/vec.hpp"
#include "core/geometry/wall.hpp"

namespace fp {

template <int D>
struct Body {
  const Wall<D>* wall = nullptr;  ///< non-null for a wall
  Vec<D> center = Vec<D>::Zero(); ///< particle centre
  double radius = 0.0;            ///< particle radius
  int particle = -1;              ///< particle id, -1 for a wall

  static Body sphere(const Vec<D>& c, double r, int id = -1) { Body b; b.center = c; b.radius = r; b.particle = id; return b; }
  static Body of_wall(const Wall<D>& w) { Body b; b.wall = &w; return b; }
  bool is_wall() const { return wall != nullptr; }
};

/// The mobile particle: for spheres/disks only its radius (position is the unknown).
template <int D>
struct Mobile {
  double radius = 0.0;
};

/// A solution of the contact problem.
template <int D>
struct Placement {
  Vec<D> position;
};

}  // namespace fp
