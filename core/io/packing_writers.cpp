#include "core/io/packing_writers.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "core/io/atomic_file.hpp"
#include "core/io/lammps_box.hpp"
#include "core/io/text_buffer.hpp"
#include "core/io/vtu_appended.hpp"
#include "core/io/vtu_frame_field.hpp"

namespace fp {
namespace {

template <int D>
double coord(const Packing<D>& p, std::size_t i, int k) {
  return k < D ? p.centers[i][k] : 0.0;
}

/// Absolute coordinates are written as the exact decimal of origin + local (exact_decimal.hpp).
template <int D>
std::array<OffsetAxis, 3> axes_of(const Packing<D>& p) {
  return offset_axes(p.origin.data(), D);
}

template <int D>
void write_yade(std::ostream& out, const Packing<D>& p) {
  const auto axes = axes_of(p);
  TextBuffer b(out);
  b.text("#format x_y_z_r").ch('\n');
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 3; ++k) b.coordinate(coord(p, i, k), axes[k]).ch(' ');
    b.number(p.radii[i]).ch('\n');
  }
  b.flush();
}

template <int D>
void write_csv(std::ostream& out, const Packing<D>& p) {
  const auto axes = axes_of(p);
  TextBuffer b(out);
  b.text(D == 3 ? "id,x,y,z,r" : "id,x,y,r").ch('\n');
  for (std::size_t i = 0; i < p.size(); ++i) {
    b.integer(i);
    for (int k = 0; k < D; ++k) b.ch(',').coordinate(p.centers[i][k], axes[k]);
    b.ch(',').number(p.radii[i]).ch('\n');
  }
  b.flush();
}

template <int D>
void write_lammps(std::ostream& out, const Packing<D>& p, const RunRecord& rec) {
  LammpsBox<D> box_of(rec);
  for (std::size_t i = 0; i < p.size(); ++i) box_of.add_atom(p.centers[i], p.radii[i]);
  const Aabb<3> box = box_of.finish();
  const Vec3& lo = box.lo;
  const Vec3& hi = box.hi;
  const auto axes = axes_of(p);

  TextBuffer b(out);
  b.text("LAMMPS data file (atom_style sphere) written by frontpack ").text(rec.version).text(", ");
  b.text(D == 2 ? "2D (use 'dimension 2')" : "3D").text(", columns: id type diameter density x y z").ch('\n');
  b.ch('\n');
  b.integer(p.size()).text(" atoms").ch('\n');
  b.text("1 atom types").ch('\n');
  b.ch('\n');
  const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    b.coordinate(lo[k], axes[k]).ch(' ').coordinate(hi[k], axes[k]).ch(' ').text(axis[k]).text("lo ").text(axis[k]).text("hi").ch('\n');
  }
  b.ch('\n');
  b.text("Atoms # sphere").ch('\n');
  b.ch('\n');
  for (std::size_t i = 0; i < p.size(); ++i) {
    b.integer(i + 1).text(" 1 ").number(2.0 * p.radii[i]).ch(' ').number(rec.density);
    for (int k = 0; k < 3; ++k) b.ch(' ').coordinate(coord(p, i, k), axes[k]);
    b.ch('\n');
  }
  b.flush();
}

// VTU: one VTK_VERTEX cell per particle, data appended as raw binary (exact doubles, ~57
// bytes per particle; core/io/vtu_appended.hpp). Points are absolute, rounded to doubles; away
// from the origin the exact centres follow (core/io/vtu_frame_field.hpp).
template <int D>
void write_vtu(std::ostream& out, const std::string& path, const Packing<D>& p) {
  const std::uint64_t n = p.size();
  using S = VtuArray;
  std::vector<VtuArray> a;
  a.push_back({S::PointData, "Float64", "radius", 1, n, 8, [&p](VtuRawOut& o) {
                 for (const double r : p.radii) o.put<double>(r);
               }});
  a.push_back({S::PointData, "Int64", "id", 1, n, 8, [n](VtuRawOut& o) {
                 for (std::uint64_t i = 0; i < n; ++i) o.put<std::int64_t>(static_cast<std::int64_t>(i));
               }});
  a.push_back({S::Points, "Float64", "Points", 3, 3 * n, 8, [&p, n](VtuRawOut& o) {
                 for (std::uint64_t i = 0; i < n; ++i)
                   for (int k = 0; k < 3; ++k) o.put<double>((k < D ? p.origin[k] : 0.0) + coord(p, i, k));
               }});
  append_vertex_cells(a, n);
  std::string field;
  if (!p.origin.isZero()) {  // listed with the point data, appended last
    a.push_back({S::PointData, "Float64", "local_position", 3, 3 * n, 8, [&p, n](VtuRawOut& o) {
                   for (std::uint64_t i = 0; i < n; ++i)
                     for (int k = 0; k < 3; ++k) o.put<double>(coord(p, i, k));
                 }});
    field = vtu_frame_origin_field(p.origin[0], p.origin[1], D == 3 ? p.origin[D - 1] : 0.0);
  }
  write_vtu_appended(out, path, n, n, " Scalars=\"radius\"", a, field);
}

template <int D>
void write_json(std::ostream& out, const Packing<D>& p, const RunRecord& rec) {
  RunRecord with_particles = rec;
  with_particles.embed_particles = true;
  with_particles.n = p.size();
  const std::string text = run_record_json(with_particles, p);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

template <int D>
void write_packing(OutputFormat format, const std::string& path, const Packing<D>& packing, const RunRecord& record) {
  if (packing.centers.size() != packing.radii.size())
    throw std::runtime_error("cannot write '" + path + "': packing has " + std::to_string(packing.centers.size()) +
                             " centres but " + std::to_string(packing.radii.size()) + " radii");
  AtomicFile file(path);
  std::ostream& out = file.stream();
  switch (format) {
    case OutputFormat::Vtu: write_vtu(out, path, packing); break;
    case OutputFormat::Yade: write_yade(out, packing); break;
    case OutputFormat::Lammps: write_lammps(out, packing, record); break;
    case OutputFormat::Csv: write_csv(out, packing); break;
    case OutputFormat::Json: write_json(out, packing, record); break;
  }
  file.commit();
}

template void write_packing<2>(OutputFormat, const std::string&, const Packing<2>&, const RunRecord&);
template void write_packing<3>(OutputFormat, const std::string&, const Packing<3>&, const RunRecord&);

}  // namespace fp
