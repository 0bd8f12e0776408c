#pragma once
// Which contact solver places a mobile particle against given fixed bodies. Keyed by shape-kind
// pairs (fixed kind, mobile kind); walls are the kind "wall". Minimisation is the default for
// every pair; a pair-specific solver (e.g. the analytic sphere solver for sphere-sphere and
// wall-sphere) is used when it is registered for EVERY pair of the problem, so a sphere placed
// against two spheres and a capsule still goes to minimisation.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <utility>

#include "contact/contact_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "core/io/scene.hpp"

namespace fp {

template <int D>
class SolverRegistry {
 public:
  /// The default registry: minimisation everywhere, analytic sphere solver for sphere/wall pairs.
  SolverRegistry(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options);

  void set_default(std::shared_ptr<const ContactSolver<D>> solver) { default_ = std::move(solver); }
  void override_pair(const std::string& fixed_kind, const std::string& mobile_kind,
                     std::shared_ptr<const ContactSolver<D>> solver);

  /// The solver for this problem (never null).
  const ContactSolver<D>& pick(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const;
  /// Its name for reports: "analytic sphere" or "minimisation" (or the class of an override).
  const ContactSolver<D>& default_solver() const { return *default_; }

 private:
  std::shared_ptr<const ContactSolver<D>> default_;
  std::map<std::pair<std::string, std::string>, std::shared_ptr<const ContactSolver<D>>> pairs_;
};

}  // namespace fp
