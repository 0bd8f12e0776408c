#include "contact/gap_newton_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "contact/gap_newton.hpp"
#include "contact/swept_ball.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {

template <int D>
GapNewtonSolver<D>::GapNewtonSolver(const NarrowPhase<D>& narrow_phase, double gap_tolerance)
    : np_(narrow_phase), tol_(gap_tolerance) {
  if (!(tol_ > 0)) throw std::invalid_argument("gap_tolerance must be positive");
}

namespace {
/// A sphere particle of radius r (a body or mobile given as a plain sphere), reused while r is.
template <int D>
void as_sphere(double r, Particle<D>& p) {
  if (!p.shape || p.shape->bounding_radius() != r) p.shape = std::make_shared<SphereShape<D>>(r);
}
}  // namespace

template <int D>
int GapNewtonSolver<D>::solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const {
  if (fixed.size() != static_cast<std::size_t>(D) || out.empty()) return 0;
  thread_local std::array<Particle<D>, D> spheres;  // fixed bodies without a particle
  thread_local Particle<D> mob;
  std::array<const Particle<D>*, D> particle{};
  for (int i = 0; i < D; ++i) {
    const Body<D>& b = fixed[static_cast<std::size_t>(i)];
    if (b.is_wall()) continue;
    if (b.shaped) {
      particle[static_cast<std::size_t>(i)] = b.shaped;
      continue;
    }
    Particle<D>& s = spheres[static_cast<std::size_t>(i)];
    as_sphere<D>(b.radius, s);
    s.pose.position = b.center;
    particle[static_cast<std::size_t>(i)] = &s;
  }
  if (mobile.shape) mob.shape = mobile.shape;
  else as_sphere<D>(mobile.radius, mob);
  mob.pose.rotation = mobile.rotation;
  const double r_mob = mob.shape->bounding_radius();

  // The minimisation solver's tolerance: per body, of the smaller circumscribed radius.
  // A step may cross the smallest body: the mobile's size alone would hold a tiny mobile back
  // from a start far off on a big body's surface.
  std::array<double, D> limit;
  double smallest_fixed = 0;
  for (int i = 0; i < D; ++i) {
    const Body<D>& b = fixed[static_cast<std::size_t>(i)];
    limit[static_cast<std::size_t>(i)] = tol_ * (b.is_wall() ? r_mob : std::min(r_mob, b.radius));
    if (!b.is_wall()) smallest_fixed = smallest_fixed > 0 ? std::min(smallest_fixed, b.radius) : b.radius;
  }
  const double max_step = 0.5 * std::max(r_mob, smallest_fixed);

  // Swept balls against a swept-ball mobile (spheres, capsules): the narrow phase's gap (paper 004
  // Eq. 6, segment distance) with the segments' directions prepared once for the ~30 gap
  // evaluations of a solve (measured: a third of the packing time of capsules went to recomputing
  // them and to the narrow phase's dispatch). Other bodies (walls): the narrow phase.
  const std::optional<SweptBall<D>> moving = swept_ball<D>(*mob.shape, mob.pose.rotation, Vec<D>::Zero());
  std::array<std::optional<SweptBall<D>>, D> swept;
  std::array<std::optional<SegmentPair<D>>, D> pair;
  for (int i = 0; i < D; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!moving || !particle[k]) continue;
    swept[k] = swept_ball<D>(*particle[k]->shape, particle[k]->pose.rotation, particle[k]->pose.position);
    if (swept[k]) pair[k].emplace(swept[k]->along, moving->along);
  }
  const auto gaps = [&](const Vec<D>& x, std::array<Gap<D>, D>& g) {
    mob.pose.position = x;
    for (int i = 0; i < D; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Body<D>& b = fixed[k];
      if (pair[k])
        g[k] = swept_ball_gap<D>(pair[k]->closest(swept[k]->from, x + moving->from), swept[k]->radius, moving->radius,
                                 x - particle[k]->pose.position);
      else
        g[k] = b.is_wall() ? np_.gap(*b.wall, mob) : np_.gap(*particle[k], mob);
    }
  };
  const auto within = [&](const std::array<Gap<D>, D>& g, double slack) {
    for (int i = 0; i < D; ++i)
      if (!(std::abs(g[static_cast<std::size_t>(i)].value) <= slack * limit[static_cast<std::size_t>(i)])) return false;
    return true;
  };

  // Needles (a body or the mobile): their equivalent spheres are far from most of their surface,
  // and the full Newton step from there overshoots; damped steps, and where the equivalent
  // spheres' starts found fewer than two positions, the inscribed spheres' starts (near the
  // middle of the needles), then the circumscribed ones', too. Elsewhere damping costs more than
  // it finds (measured: 3D capsules of aspect 0.5 pack 25 % slower with one halving).
  const auto elongated = [](const Shape<D>& sh) { return sh.inscribed_radius() < kElongated * sh.bounding_radius(); };
  bool needles = elongated(*mob.shape);
  for (const Body<D>& b : fixed) needles = needles || (b.shaped && elongated(*b.shaped->shape));
  const int halvings = needles ? kHalvings : 0;

  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> starts;
  int found = 0;
  std::array<Gap<D>, D> g;
  const auto newton_from = [&](int n_starts) {
    for (int k = 0; k < n_starts && found < static_cast<int>(out.size()); ++k) {
      Vec<D> x = starts[static_cast<std::size_t>(k)].position;
      gaps(x, g);
      gap_newton::newton<D>(gaps, [&](const std::array<Gap<D>, D>& v) { return within(v, kAcceptance); }, x, g, max_step,
                            kIterations, halvings);
      if (!within(g, kAcceptance)) continue;
      bool is_new = true;
      for (int q = 0; q < found && is_new; ++q) is_new = (out[static_cast<std::size_t>(q)].position - x).norm() > 1e-6 * r_mob;
      if (is_new) out[static_cast<std::size_t>(found++)].position = x;
    }
  };
  newton_from(gap_newton::equivalent_sphere_starts<D>(fixed, *mob.shape, starts));
  for (const double blend : {0.0, 1.0})
    if (found < 2 && needles) newton_from(gap_newton::sphere_starts<D>(fixed, *mob.shape, blend, starts));
  return found;
}

template class GapNewtonSolver<2>;
template class GapNewtonSolver<3>;

}  // namespace fp
