#pragma once
// A fixed body a mobile particle may touch: another particle or a container wall.
// Spheres are described by centre + radius alone (the fast path reads nothing else); a general
// particle also points at its Particle (shape + pose), with centre = its reference point and
// radius = its bounding radius, so that sphere-based pruning works for every shape.
#include "core/geometry/vec.hpp"
#include "core/geometry/wall.hpp"
#include "shapes/particle.hpp"

namespace fp {

template <int D>
struct Body {
  const Wall<D>* wall = nullptr;  ///< non-null for a wall
  Vec<D> center = Vec<D>::Zero(); ///< particle centre (reference point)
  double radius = 0.0;            ///< sphere radius; bounding radius of a general particle
  int particle = -1;              ///< particle id, -1 for a wall
  const Particle<D>* shaped = nullptr;  ///< general particles only

  static Body sphere(const Vec<D>& c, double r, int id = -1) { Body b; b.center = c; b.radius = r; b.particle = id; return b; }
  static Body of_wall(const Wall<D>& w) { Body b; b.wall = &w; return b; }
  static Body of_particle(const Particle<D>& p, int id = -1) {
    Body b;
    b.center = p.pose.position;
    b.radius = p.bounding_radius();
    b.particle = id;
    b.shaped = &p;
    return b;
  }
  bool is_wall() const { return wall != nullptr; }
};

/// The mobile particle: its position is the unknown. Spheres need only the radius; a general
/// particle brings its shape (at its size) and its fixed orientation.
template <int D>
struct Mobile {
  double radius = 0.0;               ///< sphere radius; bounding radius of a general shape
  ShapePtr<D> shape;                 ///< general shapes only
  Mat<D> rotation = Mat<D>::Identity();

  static Mobile of_shape(ShapePtr<D> s, const Mat<D>& R) {
    Mobile m;
    m.radius = s->bounding_radius();
    m.shape = std::move(s);
    m.rotation = R;
    return m;
  }
};

/// A solution of the contact problem.
template <int D>
struct Placement {
  Vec<D> position;
};

}  // namespace fp
