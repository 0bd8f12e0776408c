#pragma once
// Positions of a ball of radius r touching TWO bodies in 3D: a particle s0 and one more body (a
// particle or a wall). Three contacts fix a position (sphere_contact_solver.hpp); two leave a
// curve of positions, of which this returns evenly spaced samples.
//
// Why: the front places each particle against s0 and two more bodies (paper 002). In a
// container barely wider than a particle (a needle cylinder, a capillary, a thin tube of a mesh)
// no position touches three bodies, so the front would stop after the first particle. There the
// front falls back to these positions (front/advancing_front.hpp), which grow a chain along the
// wall.
//
// The curve is the centre locus of s0 (the sphere |x - c0| = r0 + r) cut by the body's locus
// (sphere_contact_solver.hpp): a circle for a particle, a plane wall, a concave sphere wall or a
// vertex; for a cylinder wall of radius R, the points at distance R - r from its axis, sampled
// by the angle around the axis (two points per angle). Computed relative to c0 so far-off
// coordinates keep their digits; each sample is exact to rounding on both loci.
#include <cmath>
#include <vector>

#include "contact/body.hpp"

namespace fp {

/// Appends up to `samples` (2 x samples for a cylinder wall) positions touching the particle
/// (c0, r0) and `body`; nothing when the two loci do not meet.
inline void two_contact_positions(const Vec3& c0, double r0, const Body<3>& body, double r, int samples,
                                  std::vector<Vec3>& out) {
  const double rho0 = r0 + r;  // s0's locus: |x - c0| = rho0
  // A unit vector orthogonal to k, and the third of the frame.
  auto frame = [](const Vec3& k, Vec3& e1, Vec3& e2) {
    e1 = (std::abs(k.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(k).normalized();
    e2 = k.cross(e1);
  };
  // Circle of s0's locus cut by the plane k.y = h (k unit, y = x - c0).
  auto circle = [&](const Vec3& k, double h) {
    const double rc2 = (rho0 - h) * (rho0 + h);
    if (!(rc2 > 0.0)) return;
    const double rc = std::sqrt(rc2);
    Vec3 e1, e2;
    frame(k, e1, e2);
    for (int s = 0; s < samples; ++s) {
      const double phi = 2.0 * kPi * (s + 0.5) / samples;
      out.push_back(c0 + h * k + rc * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  };
  // s0's locus against a sphere |x - p| = rho: their radical plane.
  auto against_sphere = [&](const Vec3& p, double rho) {
    const Vec3 q = p - c0;
    const double d = q.norm();
    if (!(d > 0.0) || !(rho > 0.0)) return;
    circle(q / d, 0.5 * ((d - rho) * (d + rho) + rho0 * rho0) / d);
  };
  if (!body.is_wall()) {
    against_sphere(body.center, body.radius + r);
    return;
  }
  const Wall<3>& w = *body.wall;
  switch (w.kind) {
    case WallKind::Plane:
      circle(w.normal, r + w.normal.dot(w.point - c0));
      return;
    case WallKind::Sphere:
      against_sphere(w.point, w.radius - r);
      return;
    case WallKind::Vertex:
      against_sphere(w.point, r);
      return;
    case WallKind::Cylinder: {
      const double rho = w.radius - r;  // distance of the centre from the axis
      if (!(rho > 0.0)) return;
      const Vec3& a = w.axis;
      const Vec3 d = c0 - w.point;
      const double t0 = a.dot(d);
      const Vec3 q0 = d - t0 * a;  // s0's offset from the axis
      Vec3 e1, e2;
      frame(a, e1, e2);
      for (int s = 0; s < samples; ++s) {
        const double psi = 2.0 * kPi * (s + 0.5) / samples;
        const Vec3 radial = rho * (std::cos(psi) * e1 + std::sin(psi) * e2);
        // |x - c0|^2 = (t - t0)^2 + |radial - q0|^2 = rho0^2 for x = axis point at t + radial.
        const double g = (radial - q0).norm();
        const double dt2 = (rho0 - g) * (rho0 + g);
        if (!(dt2 >= 0.0)) continue;
        const double dt = std::sqrt(dt2);
        const Vec3 base = c0 - q0 + radial;  // the point at t = t0 on that line
        out.push_back(base + dt * a);
        if (dt > 0.0) out.push_back(base - dt * a);
      }
      return;
    }
  }
}

}  // namespace fp
