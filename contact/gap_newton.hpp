#pragma once
// Newton's method on the contact equations ω_i(x) = 0, i = 1..D (paper 004, Eq. 3: ω is the
// signed gap of fixed body i and the mobile at x, in distance form, so |∇ω_i| = 1 and the
// Jacobian's rows are the contact normals), and the equivalent-sphere positions it starts from.
// Shared by the minimisation solver (its polish, and its Newton-first mode) and the gap Newton
// solver (Newton alone).
#include <array>
#include <cmath>
#include <span>

#include "contact/body.hpp"
#include "contact/contact_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "contact/sphere_contact_solver.hpp"

namespace fp::gap_newton {

/// dx with J dx = rhs for the D x D matrix of rows `rows` (unit normals), by Cramer's rule; false
/// when the rows are nearly dependent (|det| <= 1e-12: two contact normals nearly parallel,
/// where Newton's step is meaningless).
template <int D>
bool solve_rows(const std::array<Gap<D>, D>& rows, const Vec<D>& rhs, Vec<D>& dx) {
  if constexpr (D == 2) {
    const Vec2& a = rows[0].normal;
    const Vec2& b = rows[1].normal;
    const double det = a.x() * b.y() - a.y() * b.x();
    if (!(std::abs(det) > 1e-12)) return false;
    dx = Vec2(rhs[0] * b.y() - rhs[1] * a.y(), a.x() * rhs[1] - b.x() * rhs[0]) / det;
  } else {
    const Vec3 c12 = rows[1].normal.cross(rows[2].normal);
    const double det = rows[0].normal.dot(c12);
    if (!(std::abs(det) > 1e-12)) return false;
    dx = (rhs[0] * c12 + rhs[1] * rows[2].normal.cross(rows[0].normal) + rhs[2] * rows[0].normal.cross(rows[1].normal)) / det;
  }
  return std::isfinite(dx.squaredNorm());
}

/// Newton steps from x (gaps g at x) until `converged(g)`, at most `iterations`; a step is kept
/// only if it reduces the largest |ω_i| (quadratic convergence near a solution), is at most
/// `max_step` long, and is halved up to `halvings` times until it does (damped Newton: far from
/// a solution the full step overshoots); a step that gains nothing even then ends it.
/// `gaps(x, g)` evaluates the gaps. On return x and g are the last kept point and its gaps.
template <int D, class Gaps, class Converged>
void newton(Gaps&& gaps, Converged&& converged, Vec<D>& x, std::array<Gap<D>, D>& g, double max_step, int iterations,
            int halvings = 0) {
  const auto largest = [](const std::array<Gap<D>, D>& v) {
    double m = 0;
    for (const Gap<D>& gi : v) m = std::max(m, std::abs(gi.value));
    return m;
  };
  for (int it = 0; it < iterations && !converged(g); ++it) {
    Vec<D> rhs;
    for (int i = 0; i < D; ++i) rhs[i] = -g[static_cast<std::size_t>(i)].value;
    Vec<D> dx;
    if (!solve_rows<D>(g, rhs, dx)) return;
    const double len = dx.norm();
    if (len > max_step) dx *= max_step / len;
    std::array<Gap<D>, D> g_new;
    const double before = largest(g);
    for (int h = 0;; ++h) {
      if (h > 0) {
        if (h > halvings) return;
        dx *= 0.5;
      }
      gaps(x + dx, g_new);
      if (largest(g_new) < before) break;
    }
    x += dx;
    g = g_new;
  }
}

/// The analytic positions of the problem's spheres of radius ri + blend (rb - ri) for each shape
/// (ri, rb: inscribed and circumscribed radii) at its reference point. A fixed body without a
/// shape is a sphere of its radius. Returns how many (at most out.size()).
template <int D>
int sphere_starts(std::span<const Body<D>> fixed, const Shape<D>& mobile, double blend, std::span<Placement<D>> out) {
  auto equivalent = [&](const Shape<D>& sh) {
    const double ri = sh.inscribed_radius(), rb = sh.bounding_radius();
    return ri + blend * (rb - ri);
  };
  std::array<Body<D>, D> eq;
  for (int i = 0; i < D; ++i) {
    eq[static_cast<std::size_t>(i)] = fixed[i];
    if (fixed[i].shaped) eq[static_cast<std::size_t>(i)].radius = equivalent(*fixed[i].shaped->shape);
  }
  Mobile<D> eq_mobile;
  eq_mobile.radius = equivalent(mobile);
  return SphereContactSolver<D>{}.solve(std::span<const Body<D>>(eq.data(), D), eq_mobile, out);
}

/// The starting points: the positions of equivalent spheres (radius halfway between inscribed and
/// circumscribed; if none, circumscribed; then inscribed), as the paper starts its minimisations.
template <int D>
int equivalent_sphere_starts(std::span<const Body<D>> fixed, const Shape<D>& mobile, std::span<Placement<D>> out) {
  for (const double blend : {0.5, 1.0, 0.0})
    if (const int n = sphere_starts<D>(fixed, mobile, blend, out); n > 0) return n;
  return 0;
}

}  // namespace fp::gap_newton
