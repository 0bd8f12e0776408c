#include "contact/solver_registry.hpp"

#include "contact/minimisation_solver.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {

template <int D>
SolverRegistry<D>::SolverRegistry(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options)
    : default_(std::make_shared<MinimisationSolver<D>>(narrow_phase, options)) {
  auto analytic = std::make_shared<SphereContactSolver<D>>();
  override_pair(SphereShape<D>::kKind, SphereShape<D>::kKind, analytic);
  override_pair("wall", SphereShape<D>::kKind, analytic);
}

template <int D>
void SolverRegistry<D>::override_pair(const std::string& fixed_kind, const std::string& mobile_kind,
                                      std::shared_ptr<const ContactSolver<D>> solver) {
  pairs_[{fixed_kind, mobile_kind}] = std::move(solver);
}

template <int D>
const ContactSolver<D>& SolverRegistry<D>::pick(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const {
  if (pairs_.empty()) return *default_;
  // A mobile without a shape is a sphere of its radius (the sphere fast path's form), as a fixed
  // body without a particle is: the minimisation solver cannot solve it (it needs the shape).
  const std::string mobile_kind = mobile.shape ? mobile.shape->kind() : SphereShape<D>::kKind;
  const ContactSolver<D>* common = nullptr;
  for (const Body<D>& b : fixed) {
    const std::string fixed_kind = b.is_wall() ? "wall" : b.shaped ? b.shaped->shape->kind() : SphereShape<D>::kKind;
    const auto it = pairs_.find({fixed_kind, mobile_kind});
    if (it == pairs_.end()) return *default_;
    if (common && common != it->second.get()) return *default_;
    common = it->second.get();
  }
  return common ? *common : *default_;
}

template class SolverRegistry<2>;
template class SolverRegistry<3>;

}  // namespace fp
