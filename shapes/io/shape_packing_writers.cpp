#include "shapes/io/shape_packing_writers.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "core/io/atomic_file.hpp"
#include "core/io/lammps_box.hpp"
#include "core/io/text_buffer.hpp"
#include "core/io/vtu_frame_field.hpp"
#include "core/io/vtu_appended.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {
namespace {

// ---- text ------------------------------------------------------------------------------


std::string producer(const RunRecord& rec) { return rec.version.empty() ? "frontpack" : "frontpack " + rec.version; }

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write '" + path + "': " + why);
}

template <int D>
Vec3 embed(const Vec<D>& v) {
  if constexpr (D == 3) return v;
  else return Vec3(v[0], v[1], 0.0);
}

/// Body axis k in the world (rotation * e_k), embedded in 3D.
template <int D>
Vec3 world_axis(const Pose<D>& pose, int k) {
  if (k >= D) return Vec3(0, 0, 1);  // 2D: the body z axis is the world z axis
  return embed<D>(Vec<D>(pose.rotation.col(k)));
}

std::size_t template_count(const std::vector<std::string>& names, int max_id) {
  return std::max(names.size(), static_cast<std::size_t>(max_id + 1));
}

// ---- format support -------------------------------------------------------------------

bool is_ball_family(const std::string& f) { return f == "sphere" || f == "disk" || f == "cluster"; }

bool format_writes_balls_only(OutputFormat f) { return f == OutputFormat::Yade || f == OutputFormat::Lammps; }

// ---- VTU (core/io/vtu_appended.hpp) ---------------------------------------------------

template <int D>
void write_centres_vtu(std::ostream& out, const std::string& path, const ShapePacking<D>& p) {
  const auto& ps = p.particles;
  const std::uint64_t n = ps.size();
  std::vector<VtuArray> a;
  using S = VtuArray;
  auto f64 = [&](const char* name, auto value) {
    a.push_back({S::PointData, "Float64", name, 1, n, 8, [&ps, value](VtuRawOut& o) {
                   for (const auto& q : ps) o.put<double>(value(q));
                 }});
  };
  a.push_back({S::PointData, "Int64", "id", 1, n, 8, [n](VtuRawOut& o) {
                 for (std::uint64_t i = 0; i < n; ++i) o.put<std::int64_t>(static_cast<std::int64_t>(i));
               }});
  a.push_back({S::PointData, "Int64", "shape_id", 1, n, 8, [&ps](VtuRawOut& o) {
                 for (const auto& q : ps) o.put<std::int64_t>(q.template_id);
               }});
  f64("size", [](const Particle<D>& q) { return q.size; });
  f64("bounding_radius", [](const Particle<D>& q) { return q.shape->bounding_radius(); });
  f64("measure", [](const Particle<D>& q) { return q.shape->measure(); });
  a.push_back({S::PointData, "Float64", "quaternion", 4, 4 * n, 8, [&ps](VtuRawOut& o) {
                 for (const auto& q : ps) {
                   const Eigen::Vector4d w = quaternion_of<D>(q.pose.rotation);
                   for (int k = 0; k < 4; ++k) o.put<double>(w[k]);
                 }
               }});
  const char* axes[] = {"axis_x", "axis_y", "axis_z"};
  for (int k = 0; k < 3; ++k)
    a.push_back({S::PointData, "Float64", axes[k], 3, 3 * n, 8, [&ps, k](VtuRawOut& o) {
                   for (const auto& q : ps) o.put3(world_axis<D>(q.pose, k));
                 }});
  // Points are absolute (rounded to doubles); away from the origin the exact positions follow as
  // local_position relative to the field frame_origin, as for spheres (core/io/packing_writers.cpp).
  const Vec3 origin = embed<D>(p.origin);
  a.push_back({S::Points, "Float64", "Points", 3, 3 * n, 8, [&ps, origin](VtuRawOut& o) {
                 for (const auto& q : ps) o.put3(origin + embed<D>(q.pose.position));
               }});
  std::string field;
  if (!p.origin.isZero()) {
    a.push_back({S::PointData, "Float64", "local_position", 3, 3 * n, 8, [&ps](VtuRawOut& o) {
                   for (const auto& q : ps) o.put3(embed<D>(q.pose.position));
                 }});
    field = vtu_frame_origin_field(origin.x(), origin.y(), origin.z());
  }
  append_vertex_cells(a, n);
  write_vtu_appended(out, path, n, n, " Scalars=\"bounding_radius\" Vectors=\"axis_x\"", a, field);
}

// One particle's display surface in the world, as VTK cells (local point indices).
struct LocalCells {
  std::vector<Vec3> points;
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> ends;  // end of each cell in `connectivity`
  std::vector<std::uint8_t> types;

  void clear() {
    points.clear();
    connectivity.clear();
    ends.clear();
    types.clear();
  }
  std::size_t bytes() const { return 24 * points.size() + 8 * connectivity.size() + 9 * ends.size() + sizeof(*this); }
};

/// For each point, the index of the first point (in x order) within `tol` of it: points that
/// coincide up to rounding get one index.
std::vector<int> weld(const std::vector<Vec2>& v, double tol) {
  const int n = static_cast<int>(v.size());
  std::vector<int> rep(static_cast<std::size_t>(n)), order(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rep[static_cast<std::size_t>(i)] = order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto &pa = v[static_cast<std::size_t>(a)], &pb = v[static_cast<std::size_t>(b)];
    return pa.x() != pb.x() ? pa.x() < pb.x() : a < b;
  });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int a = order[i];
    if (rep[static_cast<std::size_t>(a)] != a) continue;  // already welded to an earlier point
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const int b = order[j];
      const auto &pa = v[static_cast<std::size_t>(a)], &pb = v[static_cast<std::size_t>(b)];
      if (pb.x() - pa.x() > tol) break;
      if (rep[static_cast<std::size_t>(b)] == b && (pb - pa).norm() <= tol) rep[static_cast<std::size_t>(b)] = a;
    }
  }
  return rep;
}

template <int D>
void particle_cells(const Particle<D>& q, std::size_t index, int resolution, LocalCells& out) {
  out.clear();
  const SurfaceMesh<D> m = q.shape->surface(resolution);
  const int nv = static_cast<int>(m.vertices.size());
  for (const auto& v : m.vertices) out.points.push_back(embed<D>(q.pose.to_world(v)));
  for (const auto& f : m.facets)
    for (const int k : f)
      if (k < 0 || k >= nv)
        throw std::runtime_error("the surface of particle " + std::to_string(index) + " ('" + q.shape->kind() +
                                 "') refers to vertex " + std::to_string(k) + " of " + std::to_string(nv));
  if constexpr (D == 3) {
    for (const auto& f : m.facets) {
      for (const int k : f) out.connectivity.push_back(k);
      out.ends.push_back(static_cast<std::int64_t>(out.connectivity.size()));
      out.types.push_back(kVtkTriangle);
    }
  } else {
    // Chain the outline's segments into loops: each closed loop is a polygon, a chain that
    // does not close a poly line. Outlines drawn as separate arcs (a cluster's exposed arcs, a
    // circle drawn as a capsule of length 0) repeat their junction points under different
    // indices, so points closer than a size-relative tolerance are welded first.
    const std::vector<int> rep = weld(m.vertices, 1e-9 * q.shape->bounding_radius());
    const std::size_t ns = m.facets.size();
    std::vector<std::vector<std::size_t>> incident(static_cast<std::size_t>(nv));
    std::vector<std::array<int, 2>> seg(ns);
    std::vector<char> used(ns, 0);
    for (std::size_t s = 0; s < ns; ++s) {
      seg[s] = {rep[static_cast<std::size_t>(m.facets[s][0])], rep[static_cast<std::size_t>(m.facets[s][1])]};
      if (seg[s][0] == seg[s][1]) {
        used[s] = 1;  // degenerate (welded) segment
        continue;
      }
      incident[static_cast<std::size_t>(seg[s][0])].push_back(s);
      incident[static_cast<std::size_t>(seg[s][1])].push_back(s);
    }
    std::vector<int> chain;
    for (std::size_t s = 0; s < ns; ++s) {
      if (used[s]) continue;
      used[s] = 1;
      const int start = seg[s][0];
      int cur = seg[s][1];
      chain.assign({start, cur});
      bool closed = false;
      while (true) {
        if (cur == start) {
          closed = true;
          chain.pop_back();
          break;
        }
        std::size_t next = ns;
        for (const std::size_t t : incident[static_cast<std::size_t>(cur)])
          if (!used[t]) {
            next = t;
            break;
          }
        if (next == ns) break;
        used[next] = 1;
        cur = seg[next][0] == cur ? seg[next][1] : seg[next][0];
        chain.push_back(cur);
      }
      for (const int k : chain) out.connectivity.push_back(k);
      out.ends.push_back(static_cast<std::int64_t>(out.connectivity.size()));
      out.types.push_back(closed && chain.size() >= 3 ? kVtkPolygon : kVtkPolyLine);
    }
  }
}

// The particles' world surfaces, computed once for the counts and kept in memory up to a budget;
// beyond it they are recomputed for each array of the file (no size limit on the output).
template <int D>
class Surfaces {
 public:
  Surfaces(const ShapePacking<D>& p, int resolution) : p_(p), resolution_(resolution) {
    constexpr std::size_t kBudget = std::size_t{256} << 20;
    std::size_t bytes = 0;
    bool caching = true;
    cells_per_particle_.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      particle_cells(p.particles[i], i, resolution_, scratch_);
      n_points += scratch_.points.size();
      n_cells += scratch_.types.size();
      n_connectivity += scratch_.connectivity.size();
      cells_per_particle_.push_back(scratch_.types.size());
      bytes += scratch_.bytes();
      if (caching && bytes <= kBudget) cache_.push_back(scratch_);
      else caching = false;
    }
  }
  const LocalCells& get(std::size_t i) {
    if (i < cache_.size()) return cache_[i];
    particle_cells(p_.particles[i], i, resolution_, scratch_);
    return scratch_;
  }
  std::size_t cells_of(std::size_t i) const { return cells_per_particle_[i]; }

  std::uint64_t n_points = 0, n_cells = 0, n_connectivity = 0;

 private:
  const ShapePacking<D>& p_;
  int resolution_;
  std::vector<LocalCells> cache_;
  std::vector<std::size_t> cells_per_particle_;
  LocalCells scratch_;
};

template <int D>
void write_surfaces_vtu(std::ostream& out, const std::string& path, const ShapePacking<D>& p, int resolution) {
  Surfaces<D> s(p, resolution);
  const std::size_t n = p.size();
  using S = VtuArray;
  std::vector<VtuArray> a;
  a.push_back({S::CellData, "Int64", "id", 1, s.n_cells, 8, [&s, n](VtuRawOut& o) {
                 for (std::size_t i = 0; i < n; ++i)
                   for (std::size_t c = 0; c < s.cells_of(i); ++c) o.put<std::int64_t>(static_cast<std::int64_t>(i));
               }});
  a.push_back({S::CellData, "Int64", "shape_id", 1, s.n_cells, 8, [&s, &p, n](VtuRawOut& o) {
                 for (std::size_t i = 0; i < n; ++i)
                   for (std::size_t c = 0; c < s.cells_of(i); ++c) o.put<std::int64_t>(p.particles[i].template_id);
               }});
  const Vec3 origin = embed<D>(p.origin);  // display only: absolute, rounded to doubles
  a.push_back({S::Points, "Float64", "Points", 3, 3 * s.n_points, 8, [&s, n, origin](VtuRawOut& o) {
                 for (std::size_t i = 0; i < n; ++i)
                   for (const auto& x : s.get(i).points) o.put3(origin + x);
               }});
  a.push_back({S::Cells, "Int64", "connectivity", 1, s.n_connectivity, 8, [&s, n](VtuRawOut& o) {
                 std::int64_t base = 0;
                 for (std::size_t i = 0; i < n; ++i) {
                   const LocalCells& c = s.get(i);
                   for (const std::int64_t k : c.connectivity) o.put<std::int64_t>(base + k);
                   base += static_cast<std::int64_t>(c.points.size());
                 }
               }});
  a.push_back({S::Cells, "Int64", "offsets", 1, s.n_cells, 8, [&s, n](VtuRawOut& o) {
                 std::int64_t base = 0;
                 for (std::size_t i = 0; i < n; ++i) {
                   const LocalCells& c = s.get(i);
                   for (const std::int64_t e : c.ends) o.put<std::int64_t>(base + e);
                   base += static_cast<std::int64_t>(c.connectivity.size());
                 }
               }});
  a.push_back({S::Cells, "UInt8", "types", 1, s.n_cells, 1, [&s, n](VtuRawOut& o) {
                 for (std::size_t i = 0; i < n; ++i)
                   for (const std::uint8_t t : s.get(i).types) o.put<std::uint8_t>(t);
               }});
  write_vtu_appended(out, path, s.n_points, s.n_cells, "", a);
}

// ---- CSV ------------------------------------------------------------------------------

template <int D>
void write_csv(std::ostream& out, const ShapePacking<D>& p) {
  const auto axes = offset_axes(p.origin.data(), D);
  TextBuffer b(out);
  const auto& ps = p.particles;
  const bool segments = !ps.empty() && std::all_of(ps.begin(), ps.end(), [](const Particle<D>& q) {
    return dynamic_cast<const SpherocylinderShape<D>*>(q.shape.get()) != nullptr;
  });
  if (segments) {
    b.text(D == 3 ? "id,shape_id,ax,ay,az,bx,by,bz,r" : "id,shape_id,ax,ay,bx,by,r").ch('\n');
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const auto& s = static_cast<const SpherocylinderShape<D>&>(*ps[i].shape);
      const Vec<D> a = ps[i].pose.to_world(s.end_a()), e = ps[i].pose.to_world(s.end_b());
      b.integer(static_cast<std::int64_t>(i)).ch(',').integer(ps[i].template_id);
      for (int k = 0; k < D; ++k) b.ch(',').coordinate(a[k], axes[k]);
      for (int k = 0; k < D; ++k) b.ch(',').coordinate(e[k], axes[k]);
      b.ch(',').number(s.radius()).ch('\n');
    }
  } else {
    b.text(D == 3 ? "id,shape_id,kind,x,y,z,qw,qx,qy,qz,size,bounding_radius"
                  : "id,shape_id,kind,x,y,qw,qx,qy,qz,size,bounding_radius")
        .ch('\n');
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const auto& q = ps[i];
      b.integer(static_cast<std::int64_t>(i)).ch(',').integer(q.template_id).ch(',').text(q.shape->kind());
      for (int k = 0; k < D; ++k) b.ch(',').coordinate(q.pose.position[k], axes[k]);
      const Eigen::Vector4d w = quaternion_of<D>(q.pose.rotation);
      for (int k = 0; k < 4; ++k) b.ch(',').number(w[k]);
      b.ch(',').number(q.size).ch(',').number(q.shape->bounding_radius()).ch('\n');
    }
  }
  b.flush();
}

/// A shape's definition_json() with every number reprinted in the shortest form that reads back
/// to the same double (shapes print 17 digits) and non-finite numbers as null, so that the whole
/// file follows one convention and stays valid JSON.
std::string normalised_json(const std::string& in) {
  std::string out;
  out.reserve(in.size());
  bool in_string = false;
  for (std::size_t i = 0; i < in.size();) {
    const char c = in[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < in.size()) out += in[++i];
      else if (c == '"') in_string = false;
      ++i;
      continue;
    }
    if (c == '"') {
      in_string = true;
      out += c;
      ++i;
      continue;
    }
    if (c == '-' || c == '+' || (c >= '0' && c <= '9') || std::isalpha(static_cast<unsigned char>(c))) {
      std::size_t j = i;
      while (j < in.size() && (std::isalnum(static_cast<unsigned char>(in[j])) || in[j] == '-' || in[j] == '+' ||
                               in[j] == '.' || in[j] == '_'))
        ++j;
      const std::string token = in.substr(i, j - i);
      i = j;
      if (token == "true" || token == "false" || token == "null") {
        out += token;
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size()) {
        out += token;  // not a number: leave it to the shape (should not happen)
        continue;
      }
      if (!std::isfinite(v)) {
        out += "null";
        continue;
      }
      char tmp[32];
      const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
      out.append(tmp, res.ptr);
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

// ---- JSON -----------------------------------------------------------------------------

template <int D>
void write_json(std::ostream& out, const ShapePacking<D>& p, const RunRecord& record) {
  const auto& ps = p.particles;
  const auto axes = offset_axes(p.origin.data(), D);
  RunRecord rec = record;
  rec.n = ps.size();
  rec.dimension = D;
  rec.embed_particles = false;
  std::string rec_text = run_record_json(rec);
  while (!rec_text.empty() && (rec_text.back() == '\n' || rec_text.back() == ' ')) rec_text.pop_back();
  // Re-indent the pretty-printed record one level (JSON strings hold no raw newlines).
  std::string indented;
  indented.reserve(rec_text.size() + rec_text.size() / 8);
  for (const char c : rec_text) {
    indented += c;
    if (c == '\n') indented += "  ";
  }

  int max_id = -1;
  for (const auto& q : ps) max_id = std::max(max_id, q.template_id);
  const std::size_t nt = template_count(p.template_names, max_id);
  std::vector<std::size_t> count(nt, 0), representative(nt, ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto t = static_cast<std::size_t>(ps[i].template_id);
    if (count[t]++ == 0) representative[t] = i;
  }

  TextBuffer b(out);
  b.text("{\n  \"frontpack\": ").text(indented).text(",\n  \"dimension\": ").integer(D).text(",\n  \"shapes\": [");
  for (std::size_t t = 0; t < nt; ++t) {
    b.text(t == 0 ? "\n    " : ",\n    ");
    b.text("{\"shape_id\": ").integer(static_cast<std::int64_t>(t)).text(", \"name\": ");
    b.json_string(t < p.template_names.size() ? p.template_names[t] : std::string());
    b.text(", \"count\": ").integer(static_cast<std::int64_t>(count[t]));
    if (count[t] == 0) {
      b.text(", \"kind\": null, \"representative_id\": null, \"representative_size\": null, \"definition\": null}");
      continue;
    }
    const auto& q = ps[representative[t]];
    b.text(", \"kind\": ").json_string(q.shape->kind());
    b.text(", \"representative_id\": ").integer(static_cast<std::int64_t>(representative[t]));
    b.text(", \"representative_size\": ").json_number(q.size);
    b.text(", \"definition\": ").text(normalised_json(q.shape->definition_json())).ch('}');
  }
  b.text(nt == 0 ? "],\n  \"particles\": [" : "\n  ],\n  \"particles\": [");
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto& q = ps[i];
    b.text(i == 0 ? "\n    " : ",\n    ");
    b.text("{\"id\": ").integer(static_cast<std::int64_t>(i)).text(", \"shape_id\": ").integer(q.template_id);
    const Vec3 x = embed<D>(q.pose.position);
    b.text(", \"position\": [");
    for (int k = 0; k < 3; ++k) {
      if (k) b.text(", ");
      if (std::isfinite(x[k])) b.coordinate(x[k], axes[k]);
      else b.json_number(x[k]);
    }
    const Eigen::Vector4d w = quaternion_of<D>(q.pose.rotation);
    b.text("], \"quaternion\": [").json_number(w[0]);
    for (int k = 1; k < 4; ++k) b.text(", ").json_number(w[k]);
    b.text("], \"size\": ").json_number(q.size).ch('}');
  }
  b.text(ps.empty() ? "]\n}\n" : "\n  ]\n}\n");
  b.flush();
}

// ---- clumps: YADE and LAMMPS/LIGGGHTS -------------------------------------------------

template <int D>
void write_yade(std::ostream& out, const ShapePacking<D>& p, const RunRecord& rec) {
  const auto axes = offset_axes(p.origin.data(), D);
  TextBuffer b(out);
  b.text("#format x_y_z_r_clumpId").ch('\n');
  b.text("# ").text(producer(rec)).text(", ").integer(D).text(
      "D: one line per member ball: world centre x y z, radius r, clumpId = particle id (0-based; a sphere is a "
      "clump of one");
  b.text(D == 2 ? "; z = 0" : "").text("); load with yade.ymport.textClumps").ch('\n');
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p.particles[i];
    for (const auto& ball : q.shape->hull_balls()) {
      const Vec3 c = embed<D>(q.pose.to_world(ball.center));
      for (int k = 0; k < 3; ++k) b.coordinate(c[k], axes[k]).ch(' ');
      b.number(ball.radius).ch(' ');
      b.integer(static_cast<std::int64_t>(i)).ch('\n');
    }
  }
  b.flush();
}

template <int D>
void write_lammps(std::ostream& data, std::ostream& clumps, const std::string& path, const ShapePacking<D>& p,
                  const RunRecord& rec) {
  LammpsBox<D> box_of(rec);
  std::int64_t n_balls = 0;
  int max_id = -1;
  for (const auto& q : p.particles) {
    max_id = std::max(max_id, q.template_id);
    for (const auto& ball : q.shape->hull_balls()) {
      ++n_balls;
      box_of.add_atom(q.pose.to_world(ball.center), ball.radius);
    }
  }
  const Aabb<3> box = box_of.finish();
  const Vec3& lo = box.lo;
  const Vec3& hi = box.hi;
  const std::size_t n_types = std::max<std::size_t>(1, template_count(p.template_names, max_id));
  const std::string companion = file_name(multisphere_path(path));
  const auto axes = offset_axes(p.origin.data(), D);

  TextBuffer b(data);
  b.text("LAMMPS data file (atom_style hybrid sphere bond) written by ").text(producer(rec)).text(", ");
  b.text(D == 2 ? "2D (use 'dimension 2')" : "3D").text(", columns: id type x y z diameter density molecule").ch('\n');
  // Lines stay short: LIGGGHTS 3.8 reads at most 256 characters a line and aborts without a word beyond.
  b.text("# each atom is a member ball of a clump: molecule = clump id + 1, so that 'fix rigid/small molecule'").ch('\n');
  b.text("# (LIGGGHTS: fix rigid molecule) runs the clumps as they are (README); the clumps are also listed in").ch('\n');
  b.text("# '").text(companion).text("': atoms come in clump order (clump 0's members first),").ch('\n');
  b.text("# type = shape_id + 1 (particle template)").ch('\n');
  b.ch('\n');
  b.integer(n_balls).text(" atoms").ch('\n');
  b.integer(static_cast<std::int64_t>(n_types)).text(" atom types").ch('\n');
  b.ch('\n');
  const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    b.coordinate(lo[k], axes[k]).ch(' ').coordinate(hi[k], axes[k]).ch(' ').text(axis[k]).text("lo ").text(axis[k]).text("hi").ch('\n');
  b.ch('\n');
  b.text("Atoms # hybrid").ch('\n');
  b.ch('\n');

  TextBuffer m(clumps);
  m.text("# ").text(producer(rec)).text(" multisphere listing: the clumps of '").text(file_name(path));
  m.text("' (LAMMPS data file, atom_style hybrid sphere bond), ").integer(D).text("D").ch('\n');
  m.text("# ").integer(static_cast<std::int64_t>(p.size())).text(" clumps, ").integer(n_balls).text(" member balls").ch('\n');
  m.text("# per clump one line: clump_id member_count shape_id x y z qw qx qy qz").ch('\n');
  m.text("#   clump_id = particle id (0-based), shape_id = atom type - 1, (x y z) = clump reference point in the world,")
      .ch('\n');
  m.text("#   (qw qx qy qz) = unit quaternion of the rotation body -> world").ch('\n');
  m.text("# then member_count lines: x y z r = member centre in the clump's body frame and radius;").ch('\n');
  m.text("#   world centre = (x y z of the clump) + rotation(q) * (x y z of the member)").ch('\n');
  m.text("# the data file lists the same member balls as atoms, in this order (atom ids 1, 2, ...)");
  m.text(D == 2 ? "; 2D: z = 0, q is a rotation about z" : "").ch('\n');

  std::int64_t atom = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p.particles[i];
    const auto balls = q.shape->hull_balls();
    const Vec3 x = embed<D>(q.pose.position);
    const Eigen::Vector4d w = quaternion_of<D>(q.pose.rotation);
    m.integer(static_cast<std::int64_t>(i)).ch(' ').integer(static_cast<std::int64_t>(balls.size()));
    m.ch(' ').integer(q.template_id);
    for (int k = 0; k < 3; ++k) m.ch(' ').coordinate(x[k], axes[k]);
    for (int k = 0; k < 4; ++k) m.ch(' ').number(w[k]);
    m.ch('\n');
    for (const auto& ball : balls) {
      const Vec3 body = embed<D>(ball.center);
      m.number(body.x()).ch(' ').number(body.y()).ch(' ').number(body.z()).ch(' ').number(ball.radius).ch('\n');
      const Vec3 c = embed<D>(q.pose.to_world(ball.center));
      b.integer(++atom).ch(' ').integer(q.template_id + 1);
      for (int k = 0; k < 3; ++k) b.ch(' ').coordinate(c[k], axes[k]);
      b.ch(' ').number(2.0 * ball.radius).ch(' ').number(rec.density).ch(' ').integer(static_cast<std::int64_t>(i) + 1);
      b.ch('\n');
    }
  }
  if (atom != n_balls) fail(path, "a shape returned a different number of hull balls on a second call");
  b.flush();
  m.flush();
}

// ---- two files at once ----------------------------------------------------------------

// Writes `path` and `companion` through temporaries and renames them only when both are
// complete; if the second rename fails the first is removed again.
void write_pair(const std::string& path, const std::string& companion,
                const std::function<void(std::ostream& main, std::ostream& second)>& body) {
  if (std::filesystem::path(path).lexically_normal() == std::filesystem::path(companion).lexically_normal())
    fail(path, "its companion file would be the file itself");
  AtomicFile main_file(path);
  AtomicFile second_file(companion);
  body(main_file.stream(), second_file.stream());
  main_file.stream().flush();
  second_file.stream().flush();
  if (!main_file.stream()) fail(path, "write error (disk full or I/O error?)");
  if (!second_file.stream()) fail(companion, "write error (disk full or I/O error?)");
  second_file.commit();
  try {
    main_file.commit();
  } catch (...) {
    std::remove(companion.c_str());  // never leave a companion without its main file
    throw;
  }
}

std::string with_suffix(const std::string& path, const char* suffix) {
  std::filesystem::path p(path);
  p.replace_extension(suffix);
  return p.string();
}

}  // namespace

std::string surfaces_path(const std::string& path) { return with_suffix(path, ".surfaces.vtu"); }

std::string multisphere_path(const std::string& path) { return with_suffix(path, ".multisphere.txt"); }

std::vector<std::string> companion_paths(OutputFormat format, const std::string& path, SurfaceDetail surfaces) {
  if (format == OutputFormat::Vtu) return surfaces == SurfaceDetail::None ? std::vector<std::string>{} : std::vector<std::string>{surfaces_path(path)};
  if (format == OutputFormat::Lammps) return {multisphere_path(path)};
  return {};
}

template <int D>
void check_shape_format(OutputFormat format, const std::vector<std::string>& families) {
  if (!format_writes_balls_only(format)) return;
  std::vector<std::string> bad;
  for (const auto& f : families)
    if (!is_ball_family(f) && std::find(bad.begin(), bad.end(), f) == bad.end()) bad.push_back(f);
  if (bad.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < bad.size(); ++k)
    list += (k == 0 ? "'" : k + 1 == bad.size() ? " and '" : ", '") + bad[k] + "'";
  throw std::invalid_argument(std::string("format '") + output_format_name(format) +
                              "' writes spheres and clusters only; this scene has " + list +
                              " particles; use vtu, csv or json");
}

template <int D>
void write_packing(OutputFormat format, const std::string& path, const ShapePacking<D>& packing,
                         const RunRecord& record, SurfaceDetail surfaces) {
  std::vector<std::string> kinds;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const auto& q = packing.particles[i];
    if (!q.shape) fail(path, "particle " + std::to_string(i) + " has no shape");
    if (q.template_id < 0)
      fail(path, "particle " + std::to_string(i) + " has a negative template id " + std::to_string(q.template_id));
    const std::string kind = q.shape->kind();
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  }
  try {
    check_shape_format<D>(format, kinds);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("cannot write '" + path + "': " + e.what());
  }

  try {
    switch (format) {
      case OutputFormat::Vtu:
        if (surfaces == SurfaceDetail::None) {
          write_file_atomically(path, [&](std::ostream& out) { write_centres_vtu(out, path, packing); });
          break;
        }
        write_pair(path, surfaces_path(path), [&](std::ostream& main, std::ostream& side) {
          write_centres_vtu(main, path, packing);
          write_surfaces_vtu(side, surfaces_path(path), packing, surface_resolution<D>(surfaces));
        });
        break;
      case OutputFormat::Lammps:
        write_pair(path, multisphere_path(path), [&](std::ostream& data, std::ostream& clumps) {
          write_lammps(data, clumps, path, packing, record);
        });
        break;
      case OutputFormat::Yade: write_file_atomically(path, [&](std::ostream& out) { write_yade(out, packing, record); }); break;
      case OutputFormat::Csv: write_file_atomically(path, [&](std::ostream& out) { write_csv(out, packing); }); break;
      case OutputFormat::Json:
        write_file_atomically(path, [&](std::ostream& out) { write_json(out, packing, record); });
        break;
    }
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.find("'" + path + "'") != std::string::npos) throw;  // already names the file
    fail(path, what);  // e.g. the companion file's error
  }
}

template void write_packing<2>(OutputFormat, const std::string&, const ShapePacking<2>&, const RunRecord&, SurfaceDetail);
template void write_packing<3>(OutputFormat, const std::string&, const ShapePacking<3>&, const RunRecord&, SurfaceDetail);
template void check_shape_format<2>(OutputFormat, const std::vector<std::string>&);
template void check_shape_format<3>(OutputFormat, const std::vector<std::string>&);

}  // namespace fp
