#include "core/io/scene_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/bed_region.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/local_frame.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/geometry/tet_mesh_check.hpp"
#include "core/geometry/tet_mesh_container.hpp"
#ifdef FRONTPACK_TET_MESHER
#include "core/geometry/tet_mesher_cgal.hpp"
#endif
#include "core/io/document_file.hpp"
#include "core/io/input_file.hpp"
#include "core/io/output_format.hpp"
#include "core/io/yaml_document.hpp"
#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/split_radius.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {
namespace {

using namespace yaml_document;


/// A constructor's message without the C++ class it starts with ("LognormalRadius: [min, max]
/// = ..." -> "[min, max] = ..."): the error names the key instead.
std::string without_class_name(const std::string& what) {
  std::size_t i = 0;
  while (i < what.size() && std::isalnum(static_cast<unsigned char>(what[i]))) ++i;
  const bool class_name = i > 0 && std::isupper(static_cast<unsigned char>(what[0])) &&
                          std::any_of(what.begin() + 1, what.begin() + static_cast<std::ptrdiff_t>(i),
                                      [](unsigned char c) { return std::isupper(c); });
  return class_name && what.compare(i, 2, ": ") == 0 ? what.substr(i + 2) : what;
}

// Runs a constructor; its std::invalid_argument (or any std::exception) becomes a SceneError
// at `where`.
template <typename F>
auto construct(const Map& where, F&& f, const std::string& doing = "building it") -> decltype(f()) {
  try {
    return f();
  } catch (const SceneError&) {
    throw;
  } catch (const std::bad_alloc&) {  // what() would only say "std::bad_alloc"
    where.fail("out of memory while " + doing);
  } catch (const std::exception& e) {
    where.fail(without_class_name(e.what()));
  }
}

std::string dim_text(int d) { return std::to_string(d) + "D, from 'dimension'"; }

// --- containers ------------------------------------------------------------------------

/// Containers wider than this many smallest radii get their frame at the seed point (parse_body).
constexpr double kFarFrameExtent = 524288.0;  // 2^19: then |local| <= 2^18 r_min keeps 1e-10 r_min

const Keys kContainerKeys = {"type", "min", "max", "center", "radius", "base", "axis", "height", "vertices", "file", "scale", "bed"};
const Keys kContainerTypes3 = {"box", "sphere", "cylinder", "mesh"};
const Keys kContainerTypes2 = {"rectangle", "disk", "polygon"};

Keys container_keys(const std::string& type) {
  if (type == "box" || type == "rectangle") return {"type", "min", "max", "bed"};
  if (type == "sphere" || type == "disk") return {"type", "center", "radius", "bed"};
  if (type == "cylinder") return {"type", "base", "axis", "radius", "height", "bed"};
  if (type == "polygon") return {"type", "vertices", "bed"};
  return {"type", "file", "scale", "bed"};  // mesh
}

/// container.bed: the container filled from its floor up to a height (core/geometry/bed_region.hpp).
template <int D>
ContainerPtr<D> parse_bed(const Value& v, ContainerPtr<D> container) {
  const Map m = v.map();
  m.check_known({"height", "up", "surface"});
  const double height = m.get("height", "the fill height above the container's lowest point along 'up'").positive();
  Vec<D> up = Vec<D>::Zero();
  up[D - 1] = 1.0;
  if (auto u = m.find("up")) {
    up = u->vec<D>(dim_text(D));
    if (!up.allFinite() || up.norm() == 0.0) u->fail("must be a non-zero vector (the direction from the floor to the surface)");
  }
  BedSurface surface = BedSurface::Free;
  if (auto s = m.find("surface"))
    surface = s->choice({"free", "flat"}) == "flat" ? BedSurface::Flat : BedSurface::Free;
  return construct(m, [&] { return std::make_shared<const BedRegion<D>>(std::move(container), up, height, surface); });
}

template <int D>
ContainerPtr<D> parse_box(const Map& m, const std::optional<Vec<D>>& origin) {
  const Vec<D> lo = m.get("min").vec<D>(dim_text(D));
  const Value max = m.get("max");
  const Vec<D> hi = max.vec<D>(dim_text(D));
  const char* axis = "xyz";
  for (int k = 0; k < D; ++k)
    if (!(lo[k] < hi[k]))
      max.fail(std::string("must be greater than container.min on every axis; on ") + axis[k] + " min is " +
               std::to_string(lo[k]) + " and max is " + std::to_string(hi[k]));
  Aabb<D> box;
  box.extend(lo);
  box.extend(hi);
  return construct(m, [&] { return std::make_shared<const BoxContainer<D>>(lo, hi, origin.value_or(frame_origin<D>(box))); });
}

template <int D>
ContainerPtr<D> parse_ball(const Map& m, const std::optional<Vec<D>>& origin) {
  const Vec<D> c = m.get("center").vec<D>(dim_text(D));
  const double r = m.get("radius").positive();
  Aabb<D> box;
  box.extend(c.array() - r);
  box.extend(c.array() + r);
  return construct(m, [&] { return std::make_shared<const BallContainer<D>>(c, r, origin.value_or(frame_origin<D>(box))); });
}

ContainerPtr<3> parse_cylinder(const Map& m, const std::optional<Vec3>& origin) {
  const Vec3 base = m.get("base", "centre of the bottom cap").vec<3>(dim_text(3));
  Vec3 axis(0, 0, 1);
  if (auto a = m.find("axis")) {
    axis = a->vec<3>(dim_text(3));
    if (axis.norm() == 0.0) a->fail("must be a non-zero vector");
  }
  const double r = m.get("radius").positive();
  const double h = m.get("height").positive();
  // The frame from a box around both caps (it need not be tight).
  Aabb<3> box;
  const Vec3 top = base + h * axis.normalized();
  for (const Vec3& end : {base, top}) {
    box.extend(end.array() - r);
    box.extend(end.array() + r);
  }
  return construct(m, [&] { return std::make_shared<const CylinderContainer>(base, axis, r, h, origin.value_or(frame_origin<3>(box))); });
}

ContainerPtr<2> parse_polygon(const Map& m, const std::optional<Vec2>& origin) {
  const Value v = m.get("vertices", "[[x, y], ...] in order around the polygon");
  std::vector<Vec2> vertices;
  for (const auto& item : v.list()) vertices.push_back(item.vec<2>("a 2D point"));
  if (vertices.size() < 3) v.fail("a polygon needs at least 3 vertices, got " + std::to_string(vertices.size()));
  Aabb<2> box;
  for (const Vec2& p : vertices) box.extend(p);
  return construct(m, [&] { return std::make_shared<const PolygonContainer>(vertices, origin.value_or(frame_origin<2>(box))); });
}

ContainerPtr<3> parse_mesh(const Map& m, const Context& ctx, const std::optional<Vec3>& origin) {
  const Value file = m.get("file", "an STL, OFF or OBJ surface or a Gmsh .msh tetrahedral mesh, relative to the scene file's folder");
  const std::string name = file.string();
  if (name.empty()) file.fail("must name a file");
  if (name.find('\0') != std::string::npos) file.fail("the file name contains a NUL byte");
  const std::string resolved = ctx.relative(name);
  if (const std::string problem = input_file_problem(resolved); !problem.empty())
    file.fail("mesh file '" + resolved + "' " + problem);
  {
    std::ifstream probe(resolved, std::ios::binary);
    if (!probe || std::filesystem::is_directory(resolved)) {
      const int err = errno;
      std::error_code ec;
      const std::string shown_path = std::filesystem::absolute(resolved, ec).lexically_normal().string();
      file.fail("cannot read mesh file '" + (ec ? resolved : shown_path) + "'" +
                (err ? std::string(": ") + std::strerror(err) : ""));
    }
  }
  double scale = 1.0;
  if (auto s = m.find("scale")) scale = s->positive();
  if (ctx.read_files) ctx.read_files->push_back(resolved);
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".msh")  // a tetrahedral mesh: its boundary is the container, its tetrahedra stay with the scene
    return construct(m, [&]() -> ContainerPtr<3> {
      TetMeshContainer read = read_tet_mesh_container(resolved, scale, origin);
      if (ctx.tet_mesh) *ctx.tet_mesh = read.mesh;
      return read.container;
    }, "reading mesh '" + resolved + "'");
  return construct(m, [&]() -> ContainerPtr<3> { return MeshContainer::from_file(resolved, scale, FrameChoice::Local, origin); },
                   "reading mesh '" + resolved + "'");
}

template <int D>
ContainerPtr<D> parse_container_of_its_type(const Value& v, const Context& ctx, const std::optional<Vec<D>>& origin) {
  const Map m = v.map();
  m.check_known(kContainerKeys);
  const Keys& mine = D == 3 ? kContainerTypes3 : kContainerTypes2;
  const Keys& other = D == 3 ? kContainerTypes2 : kContainerTypes3;
  const Value t = m.get("type", "one of " + join(mine));
  const std::string type = t.string();
  if (contains(other, type))
    t.fail("'" + type + "' is a " + std::to_string(5 - D) + "D container but the scene has dimension: " + std::to_string(D) +
           "; allowed in " + std::to_string(D) + "D: " + join(mine));
  t.choice(mine);
  m.check_used(container_keys(type), "a '" + type + "' container");
  if constexpr (D == 3) {
    if (type == "box") return parse_box<3>(m, origin);
    if (type == "sphere") return parse_ball<3>(m, origin);
    if (type == "cylinder") return parse_cylinder(m, origin);
    return parse_mesh(m, ctx, origin);
  } else {
    (void)ctx;
    if (type == "rectangle") return parse_box<2>(m, origin);
    if (type == "disk") return parse_ball<2>(m, origin);
    return parse_polygon(m, origin);
  }
}

/// Lengths whose D-th powers (areas, volumes: the measures every figure is made of) are ordinary
/// doubles, with room for the sums and ratios of the metrics: 1e-100 <= L <= 1e100. Packings are
/// exact under scaling by a power of two (tests/front/test_front_far_and_scaled.cpp), so a scene
/// beyond these bounds loses nothing by being stated in other units.
void check_length(const Value& where, const std::string& what, double length, int dimension) {
  if (length >= kMinLength && length <= kMaxLength) return;
  std::ostringstream os;
  os.precision(6);
  os << what << " (" << length << ") is outside [" << kMinLength << ", " << kMaxLength << "]: " << (dimension == 3 ? "volumes" : "areas")
     << " (its " << (dimension == 3 ? "cube" : "square") << ") would not be ordinary doubles; state the scene in other units "
     << "(the packing is the same at any scale)";
  where.fail(os.str());
}

/// The container; in the frame of `origin` when given, else in its own (local_frame.hpp).
template <int D>
ContainerPtr<D> parse_container(const Value& v, const Context& ctx, const std::optional<Vec<D>>& origin = std::nullopt) {
  ContainerPtr<D> container = parse_container_of_its_type<D>(v, ctx, origin);
  if (auto bed = v.map().find("bed")) container = parse_bed<D>(*bed, std::move(container));
  check_length(v, "the container's extent", container->bounds().size().maxCoeff(), D);
  // Within the length bounds the volume is finite; this guards a container whose measure is
  // computed otherwise (a mesh's signed volume): every volume fraction would be 0 and a
  // volume_fraction stop never reached.
  if (!std::isfinite(container->measure()))
    v.fail(std::string("the container is too large: its ") + (D == 3 ? "volume" : "area") + " is beyond the largest double (" +
           container->describe() + ")");
  return container;
}

// --- radius distributions ----------------------------------------------------------------

const Keys kDistributionKeys = {"distribution", "value", "min", "max", "mean", "std", "median", "mu",
                                "sigma", "values", "edges", "weights", "curve", "basis"};
/// The narrowest spread of a normal or lognormal law, relative to its radii: below it every draw
/// rounds to the same radius.
constexpr double kNarrowestLaw = 1e-9;
const Keys kDistributions = {"constant", "uniform", "normal", "lognormal", "discrete", "histogram", "gradation"};

Keys distribution_keys(const std::string& kind) {
  if (kind == "constant") return {"distribution", "value"};
  if (kind == "uniform") return {"distribution", "min", "max"};
  if (kind == "normal") return {"distribution", "mean", "std", "min", "max"};
  if (kind == "lognormal") return {"distribution", "median", "mu", "sigma", "min", "max"};
  if (kind == "discrete") return {"distribution", "values"};
  if (kind == "histogram") return {"distribution", "edges", "weights"};
  return {"distribution", "curve", "basis"};  // gradation
}

// min and max of a bounded distribution: 0 < min < max.
std::pair<double, double> bounds(const Map& m, const std::string& why) {
  const double lo = m.get("min", why).positive();
  const Value max = m.get("max", why);
  const double hi = max.positive();
  if (!(lo < hi)) max.fail("must be greater than min (min " + m.get("min").node().Scalar() + ", max " + excerpt(max.node().Scalar()) + ")");
  return {lo, hi};
}

RadiusDistributionPtr parse_distribution(const Value& v, int dimension) {
  const Map m = v.map();
  m.check_known(kDistributionKeys);
  const std::string kind = m.get("distribution", "one of " + join(kDistributions)).choice(kDistributions);
  m.check_used(distribution_keys(kind), "the '" + kind + "' distribution");
  const std::string truncation = "every distribution is bounded: the radius is truncated to [min, max]";
  if (kind == "constant") {
    const double r = m.get("value", "the radius").positive();
    return construct(m, [&] { return std::make_shared<const ConstantRadius>(r); });
  }
  if (kind == "uniform") {
    const auto [lo, hi] = bounds(m, "uniform on [min, max]");
    return construct(m, [&] { return std::make_shared<const UniformRadius>(lo, hi); });
  }
  if (kind == "normal") {
    const double mean = m.get("mean").number();
    const Value sd_value = m.get("std", "standard deviation of the radius");
    const double sd = sd_value.positive();
    const auto [lo, hi] = bounds(m, truncation);
    // Narrower, the draws all round to the mean and the law's CDF jumps there: the radii test
    // failed a packing of one radius (std 1e-300).
    if (sd < kNarrowestLaw * std::max(std::abs(mean), hi))
      sd_value.fail("is below 1e-9 of the radii (got " + excerpt(sd_value.node().Scalar()) + "): that is one radius; write "
                    "'distribution: constant, value: R'");
    return construct(m, [&] { return std::make_shared<const TruncatedNormalRadius>(mean, sd, lo, hi); });
  }
  if (kind == "lognormal") {
    const auto median = m.find("median");
    const auto mu = m.find("mu");
    if (median && mu) mu->fail("give either median or mu (= ln median), not both");
    if (!median && !mu) m.get("median", "or mu = ln(median)");
    const Value sigma_value = m.get("sigma", "standard deviation of ln r");
    const double sigma = sigma_value.positive();
    if (sigma < kNarrowestLaw)
      sigma_value.fail("is below 1e-9 (got " + excerpt(sigma_value.node().Scalar()) + "): that is one radius; write "
                       "'distribution: constant, value: R'");
    const auto [lo, hi] = bounds(m, truncation);
    if (median) {
      const double med = median->positive();
      return construct(m, [&] { return std::make_shared<const LognormalRadius>(LognormalRadius::from_median(med, sigma, lo, hi)); });
    }
    const double mu_log = mu->number();
    return construct(m, [&] { return std::make_shared<const LognormalRadius>(mu_log, sigma, lo, hi); });
  }
  if (kind == "discrete") {
    const Value values = m.get("values", "[[radius, count weight], ...]");
    auto pairs = values.pairs("[radius, count weight]");
    if (pairs.empty()) values.fail("needs at least one [radius, weight] pair");
    return construct(m, [&] { return std::make_shared<const DiscreteRadius>(pairs); });
  }
  if (kind == "histogram") {
    const Value edges_v = m.get("edges", "radius bin edges, increasing");
    const auto edges = edges_v.numbers();
    const Value weights_v = m.get("weights", "one count weight per bin");
    const auto weights = weights_v.numbers();
    if (edges.size() < 2) edges_v.fail("needs at least 2 edges (one bin), got " + std::to_string(edges.size()));
    if (weights.size() + 1 != edges.size())
      weights_v.fail("needs one weight per bin: " + std::to_string(edges.size() - 1) + " for " + std::to_string(edges.size()) +
                     " edges, got " + std::to_string(weights.size()));
    return construct(m, [&] { return std::make_shared<const HistogramRadius>(edges, weights); });
  }
  // gradation
  const auto curve = m.get("curve", "[[sieve diameter, % passing], ...]").pairs("[sieve diameter, % passing]");
  GradationRadius::Basis basis = GradationRadius::Basis::Mass;
  if (auto b = m.find("basis")) basis = b->choice({"mass", "count"}) == "mass" ? GradationRadius::Basis::Mass : GradationRadius::Basis::Count;
  return construct(m, [&] { return std::make_shared<const GradationRadius>(curve, basis, dimension); });
}

// --- packer, stop, output ------------------------------------------------------------------

const Keys kMinimisationAlgorithms = {"newton", "slsqp", "lbfgs", "nelder-mead", "cobyla", "sbplx"};

/// A count of particles (N0): a positive integer, 1e6 written as a float too.
std::uint64_t particle_count(const Value& x) {
  const std::uint64_t n = x.unsigned_integer(true);
  if (n == 0) x.fail("must be a positive integer (got " + excerpt(x.node().Scalar()) + ")");
  return n;
}

/// A solid fraction (phi0): in (0, 1).
double solid_fraction(const Value& x) {
  const double phi = x.number();
  if (!(phi > 0 && phi < 1)) x.fail("must be in (0, 1) (got " + excerpt(x.node().Scalar()) + ")");
  return phi;
}

/// An overlap allowance epsilon, times r_min: in [0, 1).
double overlap_epsilon(const Value& x) {
  const double e = x.number();
  if (!(e >= 0 && e < 1)) x.fail("must be in [0, 1): the overlap allowed, times r_min (got " + excerpt(x.node().Scalar()) + ")");
  return e;
}

/// The contacts a placed sphere needs (z_min): from 1 to `most` (the dimension + 1).
int contact_count(const Value& x, int most) {
  const std::uint64_t z = x.unsigned_integer();
  if (z < 1 || z > static_cast<std::uint64_t>(most))
    x.fail("must be an integer from 1 to " + std::to_string(most) + " in " + std::to_string(most - 1) + "D (got " +
           excerpt(x.node().Scalar()) + ")");
  return static_cast<int>(z);
}

void parse_minimisation(const Value& v, MinimisationOptions& o) {
  const Map m = v.map();
  m.check_known({"algorithm", "gap_tolerance", "max_evaluations", "polish"});
  if (auto x = m.find("algorithm")) o.algorithm = x->choice(kMinimisationAlgorithms);
  if (auto x = m.find("gap_tolerance")) {
    const double t = x->number();
    if (!(t > 0 && t < 0.1))
      x->fail("must be in (0, 0.1): it is relative to the particle size (got " + excerpt(x->node().Scalar()) + ")");
    o.gap_tolerance = t;
  }
  if (auto x = m.find("max_evaluations")) {
    const std::uint64_t n = x->unsigned_integer(true);
    if (n < 10 || n > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      x->fail("must be an integer from 10 to " + std::to_string(std::numeric_limits<int>::max()) + " (got " + excerpt(x->node().Scalar()) + ")");
    o.max_evaluations = static_cast<int>(n);
  }
  if (auto x = m.find("polish")) o.polish = x->boolean();
}

// `shapes`: the scene has particle templates (the minimisation options are used by them only).
template <int D>
void parse_packer(const Value& v, const Container<D>& container, bool shapes, PackerOptions& p,
                  std::map<std::string, SourceSpot>& spots) {
  const Map m = v.map();
  m.check_known({"method", "front", "candidate", "pair_order", "contact_bodies", "probe_smallest", "walls", "radius_pool", "contact_tolerance",
                 "grid_cell_factor", "hierarchical_grid_ratio", "seed_point", "minimisation", "contact_solver", "threads", "block_edge",
                 "overlap", "z_min", "loose", "fallback_r_min", "mesh_edge", "random_tries", "near_tries",
                 "two_contact_tries", "nuclei", "pairs_per_nucleus", "reshapes", "order", "voids",
                 "random_share", "orientation_trials", "pocket_trials", "roll_steps", "face_to_face", "orientation_frame"});
  if (auto x = m.find("face_to_face")) {
    if (!shapes)
      x->fail("chooses the orientation of particle templates ('particles: [{shape: ..., size: ...}]'); this scene has "
              "spheres ('particles: {radius: ...}'), which have none");
    p.face_to_face = x->boolean();
  }
  if (auto x = m.find("orientation_frame")) {
    if (!shapes)
      x->fail("chooses the orientation of particle templates ('particles: [{shape: ..., size: ...}]'); this scene has "
              "spheres ('particles: {radius: ...}'), which have none");
    p.orientation_frame = x->choice({"radial", "lab"}) == "radial" ? OrientationFrame::Radial : OrientationFrame::Lab;
  }
  if (p.face_to_face && p.orientation_frame == OrientationFrame::Radial)
    m.find("face_to_face")->fail("turns a face of the particle against one of s0's, which the radial orientation frame (the "
                                 "default: orientations relative to the radius from the seed point) does not allow; add "
                                 "'orientation_frame: lab'");
  const std::pair<const char*, int PackerOptions::*> orientation_keys[] = {{"orientation_trials", &PackerOptions::orientation_trials},
                                                                           {"pocket_trials", &PackerOptions::pocket_trials},
                                                                           {"roll_steps", &PackerOptions::roll_steps}};
  for (const auto& [key, member] : orientation_keys)
    if (auto x = m.find(key)) {
      if (!shapes)
        x->fail("chooses the orientation of particle templates ('particles: [{shape: ..., size: ...}]'); this scene has "
                "spheres ('particles: {radius: ...}'), which have none");
      const std::uint64_t n = x->unsigned_integer();
      const std::uint64_t least = std::string(key) == "orientation_trials" ? 1 : 0;
      if (n < least || n > 10000) x->fail("must be an integer from " + std::to_string(least) + " to 10000 (got " + excerpt(x->node().Scalar()) + ")");
      p.*member = static_cast<int>(n);
    }
  if (auto x = m.find("contact_solver")) {
    if (!shapes)
      x->fail("used by particle templates only; this scene has spheres ('particles: {radius: ...}'), whose contacts are "
              "always solved in closed form");
    p.contact_solver = x->choice({"auto", "minimisation"}) == "auto" ? ContactSolverChoice::Auto : ContactSolverChoice::Minimisation;
  }
  if (auto x = m.find("minimisation")) {
    if (!shapes)
      x->fail("used by particle templates only ('particles: [{shape: ..., size: ...}]'); this scene has spheres "
              "('particles: {radius: ...}'), whose contacts are solved in closed form");
    parse_minimisation(*x, p.minimisation);
  }
  if (auto x = m.find("method")) {
    p.method = x->choice({"front", "tet_mesh", "stacking"});
    if (p.method == "tet_mesh" && (D != 3 || shapes))
      x->fail("the tetrahedral-mesh packer (paper 000) packs spheres in 3D: it needs dimension: 3 and 'particles: {radius: ...}'");
    if (p.method == "stacking" && shapes)
      x->fail("the graded stacking (paper 003) packs spheres (disks): it needs 'particles: {radius: ...}'");
    if (p.method != "front" && dynamic_cast<const BedRegion<D>*>(&container))
      x->fail("a bed (container.bed) is filled by the advancing front, 'method: front'; the " + p.method +
              " packer fills a whole container");
  }
  const std::pair<const char*, int StackingParameters::*> stacking_keys[] = {
      {"random_tries", &StackingParameters::random_tries},   {"near_tries", &StackingParameters::near_tries},
      {"two_contact_tries", &StackingParameters::two_contact_tries}, {"nuclei", &StackingParameters::nuclei},
      {"pairs_per_nucleus", &StackingParameters::pairs_per_nucleus}, {"reshapes", &StackingParameters::reshapes}};
  for (const auto& [key, member] : stacking_keys)
    if (auto x = m.find(key)) {
      if (p.method != "stacking") x->fail("a parameter of the graded stacking: needs 'method: stacking'");
      const std::uint64_t n = x->unsigned_integer();
      if (n > 1000000) x->fail("must be an integer from 0 to 1000000 (got " + excerpt(x->node().Scalar()) + ")");
      p.stacking.*member = static_cast<int>(n);
    }
  if (auto x = m.find("order")) {
    if (p.method != "stacking") x->fail("a parameter of the graded stacking: needs 'method: stacking'");
    p.stacking.contacts_first = x->choice({"paper", "contacts_first"}) == "contacts_first";
  }
  if (auto x = m.find("random_share")) {
    if (p.method != "stacking" || !p.stacking.contacts_first)
      x->fail("the share of the list placed in the paper's order before contacts first: needs 'method: stacking, order: contacts_first'");
    const double share = x->number();
    if (!(share >= 0 && share <= 1)) x->fail("must be a number from 0 to 1 (got " + excerpt(x->node().Scalar()) + ")");
    p.stacking.random_share = share;
  }
  if (auto x = m.find("voids")) {
    if (p.method != "stacking") x->fail("a parameter of the graded stacking: needs 'method: stacking'");
    p.stacking.voids = x->boolean();
  }
  for (const char* key : {"overlap", "z_min", "loose", "fallback_r_min", "mesh_edge"})
    if (auto x = m.find(key); x && p.method != "tet_mesh")
      x->fail("a parameter of the tetrahedral-mesh packer: needs 'method: tet_mesh'");
  if (auto x = m.find("overlap")) p.tet_mesh.overlap = overlap_epsilon(*x);
  if (auto x = m.find("z_min")) p.tet_mesh.z_min = contact_count(*x, 4);
  if (auto x = m.find("loose")) p.tet_mesh.loose = x->boolean();
  if (auto x = m.find("fallback_r_min")) p.tet_mesh.fallback_r_min = x->boolean();
  if (auto x = m.find("mesh_edge")) p.tet_mesh.mesh_edge = x->positive();
  if (auto x = m.find("front")) {
    const std::string s = x->choice({"closest", "random", "fifo"});
    p.front_pick = s == "closest" ? FrontPick::ClosestToSeed : s == "random" ? FrontPick::Random : FrontPick::Fifo;
  }
  if (auto x = m.find("candidate"))
    p.candidate = x->choice({"closest", "first"}) == "closest" ? CandidateChoice::ClosestToSeed : CandidateChoice::First;
  if (auto x = m.find("pair_order"))
    p.pair_order = x->choice({"nearest", "index"}) == "nearest" ? PairOrder::NearestFirst : PairOrder::Index;
  if (auto x = m.find("contact_bodies"))
    p.contact_bodies = x->choice({"front", "all"}) == "front" ? ContactBodies::Front : ContactBodies::All;
  if (auto x = m.find("probe_smallest")) {
    if (x->node().IsScalar() && x->node().Scalar() == "auto") p.probe_smallest.reset();
    else p.probe_smallest = x->boolean();
  }
  if (auto x = m.find("walls")) p.walls_as_bodies = x->boolean();
  if (auto x = m.find("radius_pool")) {
    const std::uint64_t n = x->unsigned_integer();
    if (n < 1 || n > kMaxRadiusPool)
      x->fail("must be an integer from 1 to " + std::to_string(kMaxRadiusPool) + " (got " + excerpt(x->node().Scalar()) +
              "): each placement sorts the pool, so its cost grows with it (experiments/extremes)");
    p.radius_pool = static_cast<int>(n);
    spots["packer.radius_pool"] = x->spot();
  }
  if (auto x = m.find("contact_tolerance")) {
    const double t = x->number();
    if (!(t > 0 && t < 1e-3)) x->fail("must be in (0, 1e-3): it is relative to the particle radii (got " + excerpt(x->node().Scalar()) + ")");
    p.contact_tolerance = t;
    // One tolerance for every particle kind: for particle templates it is the minimisation's
    // gap_tolerance (the same setting under the name of the solver that needs it most).
    if (shapes) {
      const auto mini = m.find("minimisation");
      if (mini && mini->map().find("gap_tolerance") && p.minimisation.gap_tolerance != t)
        x->fail("is the tolerance of packer.minimisation.gap_tolerance too, which this scene sets to another value: give one of them");
      p.minimisation.gap_tolerance = t;
    }
  }
  if (auto x = m.find("grid_cell_factor")) {
    const double f = x->number();
    if (!(f >= 1)) x->fail("must be >= 1 (got " + excerpt(x->node().Scalar()) + ")");
    p.grid_cell_factor = f;
  }
  if (auto x = m.find("hierarchical_grid_ratio")) {
    const double f = x->number();
    if (!(f > 1)) x->fail("must be > 1 (got " + excerpt(x->node().Scalar()) + ")");
    p.hierarchical_grid_ratio = f;
  }
  if (auto x = m.find("threads")) {
    const std::uint64_t n = x->unsigned_integer();
    if (n > kMaxThreads) x->fail("must be an integer from 0 (every hardware thread) to " + std::to_string(kMaxThreads) + " (got " + excerpt(x->node().Scalar()) + ")");
    p.threads = static_cast<int>(n);
  }
  if (auto x = m.find("block_edge")) {
    const double e = x->number();
    if (!(e > 0 && std::isfinite(e))) x->fail("must be a positive length (got " + excerpt(x->node().Scalar()) + ")");
    p.block_edge = e;
    spots["packer.block_edge"] = x->spot();
  }
  if (auto x = m.find("seed_point")) {
    const Vec<D> s = x->vec<D>(dim_text(D));
    if (!container.inside(s - container.origin())) x->fail("the point is outside the container (" + container.describe() + ")");
    p.seed_point = std::vector<double>(s.data(), s.data() + D);
  }
}

void parse_stop(const Value& v, StopCriteria& s, std::map<std::string, SourceSpot>& spots) {
  const Map m = v.map();
  m.check_known({"particles", "volume_fraction", "time", "scale_sizes"});
  spots["stop"] = v.spot();
  if (auto x = m.find("particles")) {
    s.max_particles = particle_count(*x);
    spots["stop.particles"] = x->spot();
  }
  if (auto x = m.find("volume_fraction")) {
    s.target_volume_fraction = solid_fraction(*x);
    spots["stop.volume_fraction"] = x->spot();
  }
  if (auto x = m.find("time")) s.time_limit_seconds = x->positive();
  if (auto x = m.find("scale_sizes")) s.scale_sizes = x->boolean();
}

/// `stop.scale_sizes` solves for the scale of the size law at which the front's stop.particles
/// fill the container: it needs that count, and nothing that changes the count or cuts the trial
/// packings short.
void check_scale_sizes(const Map& root, const Scene& scene) {
  const Value v = *root.find("stop")->map().find("scale_sizes");
  std::string why;
  if (!scene.stop.max_particles) why = "give the count: 'stop: {particles: N, scale_sizes: true}'";
  else if (scene.stop.time_limit_seconds) why = "a time stop would cut its trial packings short: drop 'stop.time'";
  else if (scene.stop.target_volume_fraction) why = "the N particles fill the container: drop 'stop.volume_fraction'";
  else if (scene.target_solid_fraction) why = "the thinning to 'target' would change the count: give one of the two";
  else if (scene.densify) why = "the void filling ('densify') would add particles to the N: drop one of the two";
  else if (scene.packer.method != "front") why = "it scales the front's sizes: 'packer.method' must be front";
  else if (!scene.particle_templates.empty()) why = "it scales the radii of spheres (disks) only; a scene of shapes is not scaled";
  if (!why.empty()) v.fail("scale_sizes solves for the scale of the size law at which stop.particles fill the container; " + why);
}

/// `target: {solid_fraction: PHI | porosity: N | void_ratio: E}`: exactly one, as a solid fraction.
double parse_target(const Value& v) {
  const Map m = v.map();
  m.check_known({"solid_fraction", "porosity", "void_ratio"});
  const auto phi = m.find("solid_fraction"), n = m.find("porosity"), e = m.find("void_ratio");
  if ((phi ? 1 : 0) + (n ? 1 : 0) + (e ? 1 : 0) != 1)
    v.fail("give exactly one of solid_fraction (phi), porosity (n = 1 - phi) or void_ratio (e = 1/phi - 1)");
  if (phi) return solid_fraction(*phi);
  if (n) return 1 - solid_fraction(*n);
  const double ratio = e->number();
  if (!(ratio > 0 && std::isfinite(ratio))) e->fail("must be a positive number (got " + excerpt(e->node().Scalar()) + ")");
  return 1 / (1 + ratio);
}

void parse_densify(const Value& v, int dimension, bool shapes, const RadiusDistributionPtr& law, DensifyOptions& d) {
  if (shapes) v.fail("void filling adds spheres: it needs a scene of spheres (disks), not of shapes");
  if (v.node().IsNull()) return;  // `densify:` alone: every default
  const Map m = v.map();
  m.check_known({"radii", "radius_pool", "overlap", "z_min", "rounds", "volume_fraction", "particles", "fallback_r_min", "split"});
  if (auto x = m.find("fallback_r_min")) d.fallback_r_min = x->boolean();
  if (auto x = m.find("radii")) d.radii = x->choice({"distribution", "fit"}) == "fit" ? VoidRadii::Fit : VoidRadii::Distribution;
  if (auto x = m.find("radius_pool")) {
    const std::uint64_t n = x->unsigned_integer();
    if (n > 1000000) x->fail("must be an integer from 0 (half the square root of the packing's count) to 1000000 (got " + excerpt(x->node().Scalar()) + ")");
    d.radius_pool = static_cast<int>(n);
  }
  if (auto x = m.find("overlap")) d.overlap = overlap_epsilon(*x);
  if (auto x = m.find("z_min")) d.z_min = contact_count(*x, dimension + 1);
  if (auto x = m.find("rounds")) {
    const std::uint64_t n = x->unsigned_integer();
    if (n > 1000000) x->fail("must be an integer from 0 (until a round adds nothing) to 1000000 (got " + excerpt(x->node().Scalar()) + ")");
    d.rounds = static_cast<int>(n);
  }
  if (auto x = m.find("volume_fraction")) d.target_volume_fraction = solid_fraction(*x);
  if (auto x = m.find("particles")) d.max_particles = particle_count(*x);
  if (auto x = m.find("split")) {
    if (d.radii != VoidRadii::Distribution) x->fail("splits the law between the packer and the voids: needs 'radii: distribution'");
    const double r_s = x->positive();
    construct(m, [&] { return SplitRadius(law, r_s, SplitRadius::Side::Below); });  // both sides non-empty
    d.split = r_s;
  }
}

/// `least_squares: {radii: fixed | range, evaluations: N, relax_evaluations: N, boundary: BOOL,
/// edge_gap: G, relax_rounds: N, tolerance: T}`.
void parse_least_squares(const Value& v, bool shapes, LeastSquaresOptions& o) {
  if (shapes) v.fail("least-squares densification moves and grows spheres: it needs a scene of spheres (disks), not of shapes");
  if (v.node().IsNull()) return;  // `least_squares:` alone: every default
  const Map m = v.map();
  m.check_known({"radii", "evaluations", "relax_evaluations", "boundary", "edge_gap", "relax_rounds", "tolerance"});
  if (auto x = m.find("radii"))
    o.radii = x->choice({"range", "fixed"}) == "fixed" ? LeastSquaresRadii::Fixed : LeastSquaresRadii::Range;
  const auto count = [](const Value& x, std::uint64_t lo, std::uint64_t hi) {
    const std::uint64_t k = x.unsigned_integer();
    if (k < lo || k > hi)
      x.fail("must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + " (got " + excerpt(x.node().Scalar()) + ")");
    return static_cast<int>(k);
  };
  if (auto x = m.find("evaluations")) o.evaluations = count(*x, 1, 1000000);
  if (auto x = m.find("relax_evaluations")) o.relax_evaluations = count(*x, 1, 1000000);
  if (auto x = m.find("relax_rounds")) o.relax_rounds = count(*x, 0, 1000);
  if (auto x = m.find("boundary")) o.boundary = x->boolean();
  if (auto x = m.find("edge_gap")) {
    const double g = x->number();
    if (!(g >= 0 && std::isfinite(g))) x->fail("must be a number >= 0 (0: every edge; got " + excerpt(x->node().Scalar()) + ")");
    o.edge_gap = g;
  }
  if (auto x = m.find("tolerance")) {
    const double t = x->number();
    if (!(t > 0 && t <= 0.01)) x->fail("must be a number in (0, 0.01] (got " + excerpt(x->node().Scalar()) + ")");
    o.tolerance = t;
  }
}

/// `regions: {NAME: {radius: LAW, volume_fraction: PHI0}, ...}`: physical volumes of the scene's
/// tetrahedral mesh, by name or tag.
void parse_regions(const Value& v, Scene& scene) {
  if (!scene.tet_mesh) v.fail("regions are physical volumes of a tetrahedral mesh: container: {type: mesh, file: NAME.msh}");
  if (scene.packer.method != "tet_mesh") v.fail("regions are filled by the tetrahedral-mesh packer: needs 'packer: {method: tet_mesh}'");
  const Map m = v.map();
  std::vector<std::string> names;
  for (const auto& [key, name] : scene.tet_mesh->group_names)
    if (key.first == 3) names.push_back(name + " (" + std::to_string(key.second) + ")");
  for (const std::string& name : m.keys()) {
    const Value entry = *m.find(name);
    RegionSpec r;
    r.name = name;
    r.tag = -1;
    for (const auto& [key, given] : scene.tet_mesh->group_names)
      if (key.first == 3 && given == name) r.tag = key.second;
    if (r.tag < 0 && !name.empty() && name.find_first_not_of("0123456789") == std::string::npos && name.size() < 10) {
      const int tag = std::stoi(name);
      if (std::find(scene.tet_mesh->tet_group.begin(), scene.tet_mesh->tet_group.end(), tag) != scene.tet_mesh->tet_group.end())
        r.tag = tag;
    }
    if (r.tag < 0)
      entry.fail("no physical volume of that name or tag in the mesh; it has: " + (names.empty() ? std::string("none") : join(names)));
    for (const RegionSpec& other : scene.regions)
      if (other.tag == r.tag) entry.fail("the same physical volume as region '" + other.name + "'");
    const Map e = entry.map();
    e.check_known({"radius", "volume_fraction"});
    if (auto x = e.find("radius")) r.radii = parse_distribution(*x, 3);
    if (auto x = e.find("volume_fraction")) r.target_volume_fraction = solid_fraction(*x);
    scene.regions.push_back(std::move(r));
  }
}

std::vector<OutputSpec> parse_outputs(const Value& v, const Context& ctx, bool shapes) {
  if (!v.node().IsSequence()) v.fail("expected a list of {format, path} entries, got " + shown(v.node()));
  std::vector<OutputSpec> out;
  for (const auto& item : v.list()) {
    const Map m = item.map();
    m.check_known({"format", "path", "surfaces"});
    const Value path = m.get("path", "the file to write");
    OutputSpec spec;
    spec.path = path.string();
    if (spec.path.empty()) path.fail("must not be empty");
    if (spec.path.find('\0') != std::string::npos) path.fail("the path contains a NUL byte");
    spec.path = ctx.relative(spec.path);
    spec.spot = path.spot();
    if (auto f = m.find("format")) {
      const std::string name = f->string();
      try {
        spec.format = output_format_name(parse_output_format(name));
      } catch (const std::invalid_argument&) {
        f->choice({"vtu", "yade", "lammps", "csv", "json"});  // fails with the list
      }
    } else {
      try {
        spec.format = output_format_name(format_from_extension(spec.path));
      } catch (const std::invalid_argument& e) {
        path.fail(std::string(e.what()) + "; or give 'format'");
      }
    }
    if (auto s = m.find("surfaces")) {
      spec.surfaces = parse_surface_detail(s->choice({"fine", "coarse", "none"}));
      if (spec.format != "vtu") s->fail("the surfaces side file is written beside a vtu output only (this one is " + spec.format + ")");
      if (!shapes) s->fail("spheres have no surfaces side file (it draws particles of other shapes)");
    }
    out.push_back(spec);
  }
  return out;
}

template <int D>
void check_sizes_fit(const Value& radius, const Container<D>& container, const RadiusDistribution& radii) {
  // Necessary condition only: a ball of radius r needs 2r of room on every axis.
  const Vec<D> extent = container.bounds().size();
  const double room = extent.minCoeff();
  if (2 * radii.r_min() > room) {
    std::ostringstream os;
    os.precision(6);
    os << "the smallest particle (radius " << radii.r_min() << ") does not fit in the container ("
       << container.describe() << ", narrowest extent " << room << ")";
    radius.fail(os.str());
  }
  // The bounding box is not enough for a sliver or a mesh with thin parts: the deepest point the
  // container knows must hold the largest particle, or the requested distribution cannot be
  // packed (radii that fit nowhere would pile up unplaced).
  const Vec<D> deep = container.interior_point();
  const double clearance = -container.signed_distance(deep);
  if (radii.r_max() > clearance) {
    std::ostringstream os;
    os.precision(6);
    os << (radii.r_min() > clearance ? "no particle" : "the largest particles") << " (radius up to " << radii.r_max()
       << ") fit nowhere in the container (" << container.describe() << "): its deepest point found, ("
       << (deep + container.origin()).transpose() << "), is only " << clearance << " from the boundary";
    radius.fail(os.str());
  }
}

// --- particle templates ---------------------------------------------------------------------

// The keys every template has; any other key is a parameter of its shape family.
const Keys kTemplateKeys = {"shape", "size", "size_on", "orientation", "fraction"};
const std::string kParticleForms =
    "'{radius: {distribution: ...}}' for spheres, or a list of particle templates "
    "'[{shape: <family>, size: {distribution: ...}, ...}, ...]'";

// A plain scalar that reads as a number (possibly out of range: number() then says so).
bool looks_numeric(const YAML::Node& n) {
  if (!n.IsScalar() || n.Tag() == "!") return false;
  std::string_view s = n.Scalar();
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && res.ptr == s.data() + s.size() && (res.ec == std::errc() || res.ec == std::errc::result_out_of_range);
}

// One family parameter: a number, a word (preset: cube), a list of numbers or a list of points.
void parse_shape_parameter(const Value& v, const std::string& name, ShapeParameters& out) {
  const std::string what = "a shape parameter is a number, a word, a list of numbers or a list of points";
  const std::string hint = suggestion(name, kTemplateKeys);
  const YAML::Node& n = v.node();
  if (n.IsScalar() && !looks_numeric(n)) {
    out.strings[name] = n.Scalar();
    out.spots[name] = v.spot();
    return;
  }
  if (n.IsScalar()) {
    out.numbers[name] = v.number();
  } else if (n.IsSequence()) {
    const auto items = v.list();
    if (!items.empty() && items.front().node().IsSequence()) {
      std::vector<std::vector<double>> points;
      for (const auto& item : items) {
        if (!item.node().IsSequence())
          item.fail("expected a point [x, y(, z)] like the first item of the list, got " + shown(item.node()));
        points.push_back(item.numbers());
      }
      out.point_lists[name] = std::move(points);
    } else {
      std::vector<double> numbers;
      for (const auto& item : items) numbers.push_back(item.number());
      out.lists[name] = std::move(numbers);
    }
  } else if (n.IsMap()) {
    v.fail(what + ", got a mapping" + (hint.empty() ? "; a size distribution goes in 'size'" : hint));
  } else {
    v.fail(what + ", got " + shown(n) + hint);
  }
  out.spots[name] = v.spot();
}

template <int D>
OrientationSpec parse_orientation(const Value& v) {
  const std::string forms = std::string("'random' (isotropic), ") +
                            (D == 2 ? "{fixed: <angle in degrees>}" : "{fixed: [w, x, y, z]} (a unit quaternion)") +
                            ", or {law: watson | fisher, axis: " + (D == 2 ? "[x, y]" : "[x, y, z]") +
                            ", kappa: K} (or order: S instead of kappa)";
  OrientationSpec o;
  const YAML::Node& n = v.node();
  if (n.IsScalar() && n.Tag() != "!") {
    const std::string s = n.Scalar();
    if (s != "random" && s != "isotropic")
      v.fail("unknown orientation '" + s + "'" + suggestion(s, {"random", "isotropic"}) + "; expected " + forms);
    return o;
  }
  if (!n.IsMap()) v.fail("expected " + forms + ", got " + shown(n));
  const Map m = v.map();
  m.check_known({"fixed", "law", "axis", "kappa", "order"});
  if (auto law = m.find("law")) {
    if (m.has("fixed")) law->fail("give either a fixed orientation or a law, not both");
    const std::string name = law->choice({"watson", "fisher", "isotropic"});
    if (name == "isotropic") {
      for (const char* key : {"axis", "kappa", "order"})
        if (auto x = m.find(key)) x->fail("the isotropic law has no parameters");
      return o;
    }
    o.kind = name == "watson" ? OrientationKind::Watson : OrientationKind::Fisher;
    const Value axis = m.get("axis", std::string("the law's axis, ") + (D == 2 ? "[x, y]" : "[x, y, z]"));
    const Vec<D> a = axis.vec<D>(dim_text(D));
    if (!(a.norm() > 0)) axis.fail("the axis must be a non-zero vector");
    const Vec<D> unit = a.normalized();
    o.axis.assign(unit.data(), unit.data() + D);
    const auto kappa = m.find("kappa"), order = m.find("order");
    if (kappa && order) order->fail("give either kappa or order, not both");
    if (!kappa && !order) m.fail("the " + name + " law needs its concentration: kappa: K, or the nematic order it is to have: order: S");
    if (kappa) {
      o.kappa = kappa->number();
      if (!(std::abs(o.kappa) <= kMaxConcentration))
        kappa->fail("must be within [-1000, 1000] (got " + excerpt(kappa->node().Scalar()) + "); for all particles alike, give a fixed orientation");
      if (o.kind == OrientationKind::Fisher && o.kappa < 0)
        kappa->fail("fisher's kappa must be >= 0 (the law points the axis along 'axis'; reverse the axis instead)");
    } else {
      try {
        o.kappa = OrientationLaw<D>::concentration_for_order(o.kind, order->number());
      } catch (const std::invalid_argument& e) {
        order->fail(e.what());
      }
    }
    return o;
  }
  for (const char* key : {"axis", "kappa", "order"})
    if (auto x = m.find(key)) x->fail("a parameter of a law about an axis: needs 'law: watson' or 'law: fisher'");
  const Value f = m.get("fixed", forms);
  o.kind = OrientationKind::Fixed;
  if constexpr (D == 2) {
    if (!f.node().IsScalar())
      f.fail("in 2D the fixed orientation is one angle in degrees, e.g. {fixed: 30}, got " + shown(f.node()));
    o.fixed = {f.number()};
  } else {
    if (!f.node().IsSequence())
      f.fail("in 3D the fixed orientation is a unit quaternion [w, x, y, z], e.g. {fixed: [1, 0, 0, 0]}, got " + shown(f.node()));
    std::vector<double> q = f.numbers();
    if (q.size() != 4) f.fail("a quaternion [w, x, y, z] has 4 components, got " + std::to_string(q.size()));
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(std::abs(norm - 1.0) <= 1e-6)) {
      std::ostringstream os;
      os.precision(9);
      os << "must be a unit quaternion [w, x, y, z] (norm 1 within 1e-6), got norm " << norm;
      f.fail(os.str());
    }
    for (double& c : q) c /= norm;
    o.fixed = std::move(q);
  }
  return o;
}

template <int D>
ParticleTemplateSpec parse_template(const Value& v) {
  const Map m = v.map();
  ParticleTemplateSpec t;
  t.parameters.spot = v.spot();
  const Value shape = m.get("shape", "the shape family, e.g. sphere, spherocylinder, polygon, polyhedron, ellipsoid, cluster");
  t.family = shape.string();
  if (t.family.empty()) shape.fail("must name a shape family");
  // Parameters before `size`: a misplaced distribution (`radius: {distribution: ...}`) is named as such.
  // Every key written gets a spot, the common ones too: shapes/ reports an unknown `shape` or
  // `size_on` at its own line.
  for (const auto& name : m.keys()) {
    if (contains(kTemplateKeys, name)) t.parameters.spots[name] = m.find(name)->spot();
    else parse_shape_parameter(*m.find(name), name, t.parameters);
  }
  const Value size = m.get("size", "the size distribution, e.g. {distribution: uniform, min: 1, max: 2}, "
                                   "drawn on 'size_on' (default circumscribed_radius)");
  t.size = parse_distribution(size, D);
  if (!(t.size->r_min() > 0)) size.fail("sizes must be positive (the distribution starts at " + std::to_string(t.size->r_min()) + ")");
  if (auto x = m.find("size_on")) {
    t.size_on = x->string();
    if (t.size_on.empty()) x->fail("must name a dimension of the shape, e.g. circumscribed_radius");
  }
  if (auto x = m.find("orientation")) t.orientation = parse_orientation<D>(*x);
  if (auto x = m.find("fraction")) {
    if (x->node().IsMap()) {  // {number | volume | mass: share}
      const Map f = x->map();
      f.check_known({"number", "volume", "mass"});
      if (f.keys().size() != 1) x->fail("give one of number, volume or mass, e.g. {volume: 0.3}");
      const std::string basis = f.keys().front();
      t.fraction = f.find(basis)->positive();
      t.fraction_basis = basis == "number" ? FractionBasis::Number : FractionBasis::Volume;
    } else {
      t.fraction = x->positive();
    }
  }
  return t;
}

// The `particles` section: spheres (`{radius: ...}` -> scene.radii, the sphere fast path) or
// particle templates (a list, or one mapping with `shape`). Returns true for templates.
template <int D>
bool parse_particles(const Value& v, const Container<D>& container, Scene& scene) {
  if (v.node().IsSequence()) {
    const auto items = v.list();
    if (items.empty()) v.fail("needs at least one particle template (" + kParticleForms + ")");
    for (const auto& item : items) {
      if (!item.node().IsMap()) item.fail("expected a particle template {shape: ..., size: ...}, got " + shown(item.node()));
      scene.particle_templates.push_back(parse_template<D>(item));
      // Shares are of one whole: every `fraction` on the first template's basis.
      const ParticleTemplateSpec& first = scene.particle_templates.front();
      ParticleTemplateSpec& last = scene.particle_templates.back();
      if (!item.map().has("fraction")) last.fraction_basis = first.fraction_basis;  // the default share, 1, on it
      if (last.fraction_basis != first.fraction_basis)
        item.map().find("fraction")->fail("every template's fraction must be on the same basis (number, or volume = mass), "
                                          "as the first template's");
    }
    return true;
  }
  if (!v.node().IsMap()) v.fail("expected " + kParticleForms + ", got " + shown(v.node()));
  const Map m = v.map();
  bool is_template = m.has("shape");
  if (!m.has("radius"))
    for (const auto& k : m.keys()) is_template = is_template || contains(kTemplateKeys, k);
  if (is_template) {
    scene.particle_templates.push_back(parse_template<D>(v));
    return true;
  }
  m.check_known({"radius"});
  const Value radius = m.get("radius", "the radius distribution, e.g. {distribution: uniform, min: 1, max: 2}; "
                                       "or particle templates with 'shape'");
  scene.radii = parse_distribution(radius, D);
  check_sizes_fit<D>(radius, container, *scene.radii);
  return false;
}

/// Packer method tet_mesh in a container that is a surface (STL/OFF/OBJ): its inside meshed into
/// tetrahedra of the packer's mesh_edge, by default the paper's 8 mean radii.
void mesh_surface(Scene& scene, const Container<3>& container, const Map& root) {
  const Value method = *root.find("packer")->map().find("method");
  const auto* surface = dynamic_cast<const MeshContainer*>(&container);
  if (!surface)
    method.fail("the tetrahedral-mesh packer needs a tetrahedral mesh (container: {type: mesh, file: NAME.msh}, Gmsh 2.2 or "
                "4.1) or a surface to mesh (container: {type: mesh, file: NAME.stl, .off or .obj})");
  const double edge = scene.packer.tet_mesh.mesh_edge.value_or(8.0 * scene.radii->mean());
#ifdef FRONTPACK_TET_MESHER
  // Tetrahedra of edge h: about 8.5 per h^3 of volume; past the tetrahedra a mesh of the scene's
  // own limits could hold, refuse before meshing.
  const double tets = 8.5 * container.measure() / (edge * edge * edge);
  if (tets > 5e7) {
    std::ostringstream os;
    os << "meshing the container with edges of " << edge << " would make about " << tets
       << " tetrahedra (more than 5e7); give packer.mesh_edge or larger particles";
    method.fail(os.str());
  }
  scene.tet_mesh = construct(root.find("packer")->map(), [&] {
    return std::make_shared<const TetMesh>(mesh_tetrahedra(surface->vertices(), surface->triangles(), edge));
  }, "meshing the container into tetrahedra");
  if (const std::string problem = tet_mesh_problem(*scene.tet_mesh, /*boundary_closes=*/false); !problem.empty())
    method.fail("the tetrahedra meshed from the container are unfit: " + problem);
#else
  (void)edge;
  method.fail("this frontpack was built without the tetrahedral mesher (configure with -DFRONTPACK_TET_MESHER=ON), so "
              "the tetrahedral-mesh packer needs a .msh container (Gmsh 2.2 or 4.1)");
#endif
}

template <int D>
void parse_body(const Map& root, Scene& scene, const Context& ctx) {
  const Value container_value = root.get("container", "the region to fill");
  scene.spots["container"] = container_value.spot();
  ContainerPtr<D> container = parse_container<D>(container_value, ctx);
  const Value particles_value = root.get("particles", kParticleForms);
  scene.spots["particles"] = particles_value.spot();
  const bool shapes = parse_particles<D>(particles_value, *container, scene);
  if (auto p = root.find("packer")) parse_packer<D>(*p, *container, shapes, scene.packer, scene.spots);
  if constexpr (D == 3) {
    if (scene.packer.method == "tet_mesh" && !scene.tet_mesh) mesh_surface(scene, *container, root);
  }
  // A container more than kFarFrameExtent smallest particles across can never be filled (some
  // 10^16 particles): it is packed only around where growth starts, and there its own frame (its
  // centre) would leave coordinates of up to half its extent, too coarse for the contact
  // tolerance. Its frame moves to the seed point (local_frame.hpp: seed_frame_origin).
  double r_min = std::numeric_limits<double>::infinity(), r_max = 0;
  if (scene.radii) r_min = scene.radii->r_min(), r_max = scene.radii->r_max();
  for (const auto& t : scene.particle_templates) r_min = std::min(r_min, t.size->r_min()), r_max = std::max(r_max, t.size->r_max());
  check_length(particles_value, "the smallest particle size", r_min, D);
  check_length(particles_value, "the largest particle size", r_max, D);
  if (scene.packer.block_edge && *scene.packer.block_edge < kMinBlockEdge * r_max) {
    std::ostringstream os;
    os << "must be at least " << kMinBlockEdge << " x the largest particle size " << r_max << " = " << kMinBlockEdge * r_max
       << ": two blocks growing at once must be out of each other's reach";
    root.find("packer")->map().find("block_edge")->fail(os.str());
  }
  if (scene.packer.block_edge) {
    double blocks = 1;
    for (int a = 0; a < D; ++a) blocks *= blocks_along(container->bounds().size()[a], r_max, *scene.packer.block_edge);
    if (blocks > kMaxBlocks) {
      std::ostringstream os;
      os << "cuts the container into " << blocks << " blocks, more than the " << kMaxBlocks << " a packing may have; use a larger edge";
      root.find("packer")->map().find("block_edge")->fail(os.str());
    }
  }
  if (container->bounds().size().maxCoeff() > kFarFrameExtent * r_min) {
    Vec<D> seed = container->interior_point() + container->origin();
    if (scene.packer.seed_point)
      for (int a = 0; a < D; ++a) seed[a] = (*scene.packer.seed_point)[a];
    container = parse_container<D>(container_value, ctx, seed_frame_origin<D>(seed, r_max));
  }
  // Every query of the packing, its check and its analysis is about distances up to about the
  // largest particle: a mesh indexes its cells for that scale.
  container->prepare_queries(r_max);
  if constexpr (D == 3) scene.container3 = std::move(container);
  else scene.container2 = std::move(container);
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source_name, const std::vector<SceneOverride>& overrides) {
  Context ctx;
  ctx.file = source_name;
  ctx.folder = std::filesystem::path(source_name).parent_path();

  YAML::Node doc = load_document(ctx, text, "scene", "required keys: dimension, container, particles");
  apply_overrides(doc, overrides);
  ctx.overrides = &overrides;

  Scene scene;
  scene.source_path = source_name;
  scene.source_text = text;
  for (const auto& o : overrides) scene.overrides.push_back(o.key + "=" + o.value);
  ctx.read_files = &scene.read_files;
  ctx.tet_mesh = &scene.tet_mesh;
  try {
    const Map root = document_root(ctx, doc);
    root.check_known(
        {"dimension", "seed", "container", "particles", "packer", "stop", "target", "densify", "least_squares", "regions",
         "material", "output"});
    const Value dim = root.get("dimension", "2 or 3");
    const std::uint64_t d = dim.unsigned_integer();
    if (d != 2 && d != 3) dim.fail("must be 2 or 3 (got " + excerpt(dim.node().Scalar()) + ")");
    scene.dimension = static_cast<int>(d);
    if (auto s = root.find("seed")) scene.seed = s->unsigned_integer();
    if (scene.dimension == 3) parse_body<3>(root, scene, ctx);
    else parse_body<2>(root, scene, ctx);
    if (auto s = root.find("stop")) parse_stop(*s, scene.stop, scene.spots);
    if (auto d = root.find("densify"))
      parse_densify(*d, scene.dimension, !scene.particle_templates.empty(), scene.radii, scene.densify.emplace());
    if (auto l = root.find("least_squares"))
      parse_least_squares(*l, !scene.particle_templates.empty(), scene.least_squares.emplace());
    if (auto r = root.find("regions")) parse_regions(*r, scene);
    if (auto t = root.find("target")) {
      if (scene.stop.target_volume_fraction)
        t->fail("give one of 'target' (the whole container at that solid fraction) and 'stop.volume_fraction' (growth "
                "stopped there: a dense part and an empty one)");
      if (scene.densify && scene.densify->target_volume_fraction)
        t->fail("the void filling stops at the target: drop 'densify.volume_fraction'");
      scene.target_solid_fraction = parse_target(*t);
      scene.spots["target"] = t->spot();
    }
    if (scene.stop.scale_sizes) check_scale_sizes(root, scene);
    if (scene.packer.method == "stacking" && !scene.target_solid_fraction && !scene.stop.max_particles)
      root.find("packer")->map().find("method")->fail(
          "the graded stacking (paper 003) places a list of particles made from the gradation and a target: give "
          "'target: {solid_fraction | porosity | void_ratio: ...}' (the list's solid) or 'stop: {particles: N}'");
    if (auto m = root.find("material")) {
      const Map material = m->map();
      material.check_known({"density"});
      const Value rho = material.get("density", "the particles' material density (mass per unit volume)");
      scene.density = rho.number();
      if (!(scene.density > 0) || !std::isfinite(scene.density))
        rho.fail("must be a positive number: mass per unit volume of the scene's length unit (got " + excerpt(rho.node().Scalar()) + ")");
    }
    if (auto o = root.find("output")) scene.outputs = parse_outputs(*o, ctx, !scene.particle_templates.empty());
  } catch (const YAML::Exception& e) {  // not expected: every access is checked first
    ctx.fail(e.mark, "", e.msg);
  }
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  const std::string text = read_document_file(path, "scene", "scenes/demo.yaml", kMaxSceneBytes);
  Scene scene = parse_scene(text, path, overrides);
  scene.read_files.insert(scene.read_files.begin(), path);
  return scene;
}

}  // namespace fp
