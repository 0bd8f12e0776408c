#include "contact/solver_registry.hpp"

#include <algorithm>

#include "contact/ball_wrapper_solver.hpp"
#include "contact/ellipsoid_contact_solver.hpp"
#include "contact/gap_newton_solver.hpp"
#include "contact/minimisation_solver.hpp"
#include "contact/polygon_wrapper_solver.hpp"
#include "contact/polytope_wrapper_solver.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {

template <int D>
SolverRegistry<D>::SolverRegistry(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options, bool closed_form)
    : default_(std::make_shared<MinimisationSolver<D>>(narrow_phase, options)) {
  if (!closed_form) return;
  {  // every kind with every kind and wall: Newton on the narrow phase's gaps, below the closed forms
    auto solver = std::make_shared<GapNewtonSolver<D>>(narrow_phase, options.gap_tolerance);
    const char* kinds[] = {SphereShape<D>::kKind,          SpherocylinderShape<D>::kKind, ClusterShape<D>::kKind,
                           ConvexPolytopeShape<D>::kKind,  EllipsoidShape<D>::kKind,      CylinderShape::kKind};
    for (const char* mobile : kinds) {
      if (D == 2 && mobile == CylinderShape::kKind) continue;
      add_walls(mobile, solver);
      for (const char* fixed : kinds) add_pair(fixed, mobile, solver);
    }
  }
  if constexpr (D == 2) {  // rounded convex cores: disks, stadiums, polygons, clusters
    const char* cores[] = {SphereShape<2>::kKind, SpherocylinderShape<2>::kKind, ConvexPolytopeShape<2>::kKind, ClusterShape<2>::kKind};
    auto wrapper = std::make_shared<PolygonWrapperSolver>();
    for (const char* mobile : cores) {
      add_walls(mobile, wrapper);
      for (const char* fixed : cores) add_pair(fixed, mobile, wrapper);
    }
  }
  if constexpr (D == 3) {  // polyhedra against polyhedra and plane walls (other walls: not taken)
    auto wrapper = std::make_shared<PolytopeWrapperSolver>();
    add_pair(ConvexPolytopeShape<3>::kKind, ConvexPolytopeShape<3>::kKind, wrapper);
    add_pair(kPlaneWall, ConvexPolytopeShape<3>::kKind, wrapper);
    add_pair(kCornerWall, ConvexPolytopeShape<3>::kKind, wrapper);
  }
  {  // ellipsoids (ellipses) with spheres (disks) and plane walls: Newton on the wrappers
    const char* smooth[] = {EllipsoidShape<D>::kKind, SphereShape<D>::kKind};
    auto solver = std::make_shared<EllipsoidContactSolver<D>>();
    for (const char* mobile : smooth) {
      add_pair(kPlaneWall, mobile, solver);
      for (const char* fixed : smooth) add_pair(fixed, mobile, solver);
    }
  }
  const char* balls[] = {SphereShape<D>::kKind, ClusterShape<D>::kKind};
  auto wrapper = std::make_shared<BallWrapperSolver<D>>();
  for (const char* mobile : balls) {
    add_walls(mobile, wrapper);
    for (const char* fixed : balls) add_pair(fixed, mobile, wrapper);
  }
  auto analytic = std::make_shared<SphereContactSolver<D>>();
  add_pair(SphereShape<D>::kKind, SphereShape<D>::kKind, analytic);
  add_walls(SphereShape<D>::kKind, analytic);
}

template <int D>
void SolverRegistry<D>::add_pair(const std::string& fixed_kind, const std::string& mobile_kind,
                                 std::shared_ptr<const ContactSolver<D>> solver) {
  if (std::find(registered_.begin(), registered_.end(), solver.get()) == registered_.end()) registered_.push_back(solver.get());
  pairs_[{fixed_kind, mobile_kind}].push_back(std::move(solver));
  picked_.clear();
}

template <int D>
void SolverRegistry<D>::add_walls(const std::string& mobile_kind, const std::shared_ptr<const ContactSolver<D>>& solver) {
  for (const char* wall : kWallKinds) add_pair(wall, mobile_kind, solver);
}

namespace {
template <int D>
const char* wall_kind(const Wall<D>& w) {
  switch (w.kind) {
    case WallKind::Plane: return kPlaneWall;
    case WallKind::Sphere: return kSphereWall;
    case WallKind::Cylinder: return kCylinderWall;
    case WallKind::Vertex: return kCornerWall;
  }
  return kPlaneWall;
}
/// A body's registry kind: its wall's, its shape's, or a sphere's (a body without a particle).
template <int D>
const char* kind_of(const Body<D>& b) {
  return b.is_wall() ? wall_kind(*b.wall) : b.shaped ? b.shaped->shape->kind() : SphereShape<D>::kKind;
}
}  // namespace

template <int D>
const ContactSolver<D>& SolverRegistry<D>::pick(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const {
  if (pairs_.empty() || fixed.empty()) return *default_;
  // A front asks for the same few kind combinations millions of times: their answers are kept by
  // the kinds' name pointers (a miss, or the same name at another address, takes the full path).
  PickKey key;
  key.mobile = mobile.shape ? mobile.shape->kind() : SphereShape<D>::kKind;
  for (std::size_t i = 0; i < fixed.size() && i < key.fixed.size(); ++i) key.fixed[i] = kind_of(fixed[i]);
  if (fixed.size() == key.fixed.size())
    for (const auto& [k, solver] : picked_)
      if (k == key) return *solver;
  const ContactSolver<D>& solver = pick_by_name(fixed, mobile);
  if (fixed.size() == key.fixed.size() && picked_.size() < kPickedKept) picked_.push_back({key, &solver});
  return solver;
}

template <int D>
const ContactSolver<D>& SolverRegistry<D>::pick_by_name(std::span<const Body<D>> fixed, const Mobile<D>& mobile) const {
  // A mobile without a shape is a sphere of its radius (the sphere fast path's form), as a fixed
  // body without a particle is: the minimisation solver cannot solve it (it needs the shape).
  const std::string mobile_kind = mobile.shape ? mobile.shape->kind() : SphereShape<D>::kKind;
  const auto solvers_of = [&](const Body<D>& b) -> const std::vector<std::shared_ptr<const ContactSolver<D>>>* {
    const auto it = pairs_.find({kind_of(b), mobile_kind});
    return it == pairs_.end() ? nullptr : &it->second;
  };
  const auto* first = solvers_of(fixed[0]);
  if (!first) return *default_;
  for (auto candidate = first->rbegin(); candidate != first->rend(); ++candidate) {
    bool everywhere = true;
    for (std::size_t i = 1; i < fixed.size() && everywhere; ++i) {
      const auto* list = solvers_of(fixed[i]);
      everywhere = list && std::find(list->begin(), list->end(), *candidate) != list->end();
    }
    if (everywhere) return **candidate;
  }
  return *default_;
}

template class SolverRegistry<2>;
template class SolverRegistry<3>;

}  // namespace fp
