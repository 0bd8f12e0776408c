#include "core/io/packing_writers.hpp"

#include <algorithm>
#include <array>
#include <bit>
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
// bytes per particle). Each appended block is a UInt64 byte count followed by the bytes.
// Points are absolute, rounded to doubles; away from the origin the exact centres follow
// (core/io/vtu_frame_field.hpp).
template <typename T>
void write_raw(std::ostream& out, const T* data, std::size_t count) {
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
}

template <typename T, typename Fill>
void write_block(std::ostream& out, std::size_t count, Fill fill) {
  const std::uint64_t bytes = count * sizeof(T);
  write_raw(out, &bytes, 1);
  std::vector<T> chunk;
  constexpr std::size_t kChunk = 1 << 14;
  chunk.reserve(kChunk);
  for (std::size_t i = 0; i < count; ++i) {
    chunk.push_back(fill(i));
    if (chunk.size() == kChunk) {
      write_raw(out, chunk.data(), chunk.size());
      chunk.clear();
    }
  }
  write_raw(out, chunk.data(), chunk.size());
}

template <int D>
void write_vtu(std::ostream& out, const Packing<D>& p) {
  const std::uint64_t n = p.size();
  const std::uint64_t head = sizeof(std::uint64_t);
  const std::uint64_t off_radius = 0;
  const std::uint64_t off_id = off_radius + head + 8 * n;
  const std::uint64_t off_points = off_id + head + 8 * n;
  const std::uint64_t off_conn = off_points + head + 24 * n;
  const std::uint64_t off_offsets = off_conn + head + 8 * n;
  const std::uint64_t off_types = off_offsets + head + 8 * n;
  const bool local = !p.origin.isZero();
  const std::uint64_t off_local = off_types + head + n;
  const std::string ns = std::to_string(n);
  auto array = [](const char* type, const char* name, int comps, std::uint64_t offset) {
    std::string s = std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\"";
    if (comps > 1) s += " NumberOfComponents=\"" + std::to_string(comps) + "\"";
    return s + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  };
  std::string h;
  h += "<?xml version=\"1.0\"?>\n";
  h += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  h += std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  h += "\" header_type=\"UInt64\">\n";
  h += "  <UnstructuredGrid>\n";
  if (local) h += vtu_frame_origin_field(p.origin[0], p.origin[1], D == 3 ? p.origin[D - 1] : 0.0);
  h += "    <Piece NumberOfPoints=\"" + ns + "\" NumberOfCells=\"" + ns + "\">\n";
  h += "      <PointData Scalars=\"radius\">\n";
  h += array("Float64", "radius", 1, off_radius);
  h += array("Int64", "id", 1, off_id);
  if (local) h += array("Float64", "local_position", 3, off_local);
  h += "      </PointData>\n";
  h += "      <Points>\n";
  h += array("Float64", "Points", 3, off_points);
  h += "      </Points>\n";
  h += "      <Cells>\n";
  h += array("Int64", "connectivity", 1, off_conn);
  h += array("Int64", "offsets", 1, off_offsets);
  h += array("UInt8", "types", 1, off_types);
  h += "      </Cells>\n";
  h += "    </Piece>\n";
  h += "  </UnstructuredGrid>\n";
  h += "  <AppendedData encoding=\"raw\">\n   _";
  out.write(h.data(), static_cast<std::streamsize>(h.size()));

  write_block<double>(out, n, [&](std::size_t i) { return p.radii[i]; });
  write_block<std::int64_t>(out, n, [](std::size_t i) { return static_cast<std::int64_t>(i); });
  write_block<double>(out, 3 * n, [&](std::size_t j) {
    const int k = static_cast<int>(j % 3);
    return (k < D ? p.origin[k] : 0.0) + coord(p, j / 3, k);
  });
  write_block<std::int64_t>(out, n, [](std::size_t i) { return static_cast<std::int64_t>(i); });
  write_block<std::int64_t>(out, n, [](std::size_t i) { return static_cast<std::int64_t>(i + 1); });
  write_block<std::uint8_t>(out, n, [](std::size_t) { return std::uint8_t{1}; });  // VTK_VERTEX
  if (local) write_block<double>(out, 3 * n, [&](std::size_t j) { return coord(p, j / 3, static_cast<int>(j % 3)); });
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
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
    case OutputFormat::Vtu: write_vtu(out, packing); break;
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
