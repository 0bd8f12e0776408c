#pragma once
// Which contact solver places a mobile particle against given fixed bodies. Solvers are
// registered for shape-kind pairs (fixed kind, mobile kind); a wall's kind is that of its
// surface (kPlaneWall, ...), so a solver can take plane walls and leave curved ones.
// A problem goes to the most recently registered solver that is registered for EVERY (fixed,
// mobile) pair of the problem, else to the default, minimisation. The gap Newton solver is
// registered first, for every pair of kinds and every wall: what no closed form covers (mixes,
// polyhedra with spheres or curved walls, cylinders) goes to it, not to minimisation. Then in 2D
// the polygon wrapper covers disks, stadiums, polygons, clusters and walls; in 3D the polytope
// wrapper polyhedra and plane walls; the ellipsoid solver, registered after them, takes
// ellipsoids (ellipses), spheres and plane walls; the ball wrapper spheres (disks) and clusters
// with walls; the analytic sphere solver, registered last, spheres and walls alone. Minimisation
// is left for kinds registered by no one (a new family until it says otherwise) and for
// `contact_solver: minimisation`.
#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "core/io/scene.hpp"

namespace fp {

/// The registry kinds of the container walls (core/geometry/wall.hpp).
inline constexpr const char* kPlaneWall = "wall:plane";
inline constexpr const char* kSphereWall = "wall:sphere";
inline constexpr const char* kCylinderWall = "wall:cylinder";
inline constexpr const char* kCornerWall = "wall:corner";  ///< a reflex corner (WallKind::Vertex)
inline constexpr const char* kWallKinds[] = {kPlaneWall, kSphereWall, kCylinderWall, kCornerWall};

template <int D>
class SolverRegistry {
 public:
  /// The default registry: the gap Newton solver for every pair of built-in kinds; in 2D the
  /// polygon wrapper for rounded convex cores, in 3D the polytope wrapper for polyhedra; the
  /// ellipsoid solver for ellipsoids, spheres and plane walls; the ball wrapper for spheres,
  /// clusters and walls; the analytic sphere solver for spheres and walls; minimisation elsewhere.
  /// With `closed_form` false, minimisation for every problem (no solver registered).
  SolverRegistry(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options, bool closed_form = true);

  void set_default(std::shared_ptr<const ContactSolver<D>> solver) {
    default_ = std::move(solver);
    picked_.clear();
  }
  /// Registers `solver` for (fixed_kind, mobile_kind); it takes precedence over those registered
  /// before it wherever it covers every pair of a problem.
  void add_pair(const std::string& fixed_kind, const std::string& mobile_kind, std::shared_ptr<const ContactSolver<D>> solver);
  /// add_pair for every kind of wall.
  void add_walls(const std::string& mobile_kind, const std::shared_ptr<const ContactSolver<D>>& solver);

  /// Passes the placement's other particles to every solver (ContactSolver::set_obstacles).
  void set_obstacles(std::span<const Particle<D>* const> obstacles, double tol) const {
    default_->set_obstacles(obstacles, tol);
    for (const ContactSolver<D>* s : registered_) s->set_obstacles(obstacles, tol);
  }
  /// The solver for this problem (never null).
  const ContactSolver<D>& pick(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const;
  /// Its name for reports: "analytic sphere" or "minimisation" (or the class of an override).
  const ContactSolver<D>& default_solver() const { return *default_; }

 private:
  struct PickKey {
    std::array<const char*, D> fixed{};  ///< the kinds' names (static strings: compared by address)
    const char* mobile = nullptr;
    bool operator==(const PickKey&) const = default;
  };
  static constexpr std::size_t kPickedKept = 64;
  const ContactSolver<D>& pick_by_name(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const;

  std::shared_ptr<const ContactSolver<D>> default_;
  /// Answers of pick() by kind combination. A registry serves one packer (one thread); add_pair
  /// and set_default clear it.
  mutable std::vector<std::pair<PickKey, const ContactSolver<D>*>> picked_;
  /// Per pair, its solvers in registration order (the last one first in precedence).
  std::map<std::pair<std::string, std::string>, std::vector<std::shared_ptr<const ContactSolver<D>>>> pairs_;
  /// Every solver of pairs_, once.
  std::vector<const ContactSolver<D>*> registered_;
};

}  // namespace fp
