#include "core/io/packing_readers.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/geometry/local_frame.hpp"
#include "core/io/exact_decimal.hpp"
#include "core/io/input_file.hpp"
#include "core/io/run_record.hpp"

namespace fp {
namespace {

std::string read_whole_file(const std::string& path) {
  if (const std::string problem = input_file_problem(path); !problem.empty())
    throw std::runtime_error("packing file '" + path + "' " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path + "' for reading");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("read error on '" + path + "'");
  return text;
}

// Line-by-line view of a text file that knows the current line number (1-based).
class Lines {
 public:
  Lines(const std::string& text, std::string path) : text_(text), path_(std::move(path)) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    line = std::string_view(text_).substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return true;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(path_ + ":" + std::to_string(number_) + ": " + why);
  }
  int number() const { return number_; }

 private:
  const std::string& text_;
  std::string path_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  if (sep == ' ') {
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
      const std::size_t start = i;
      while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
      if (i > start) out.push_back(s.substr(start, i - start));
    }
  } else {
    std::size_t start = 0;
    for (;;) {
      const std::size_t end = s.find(sep, start);
      out.push_back(trim(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
  }
  return out;
}

template <typename T>
std::optional<T> parse_number(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  T v{};
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (res.ec != std::errc() || res.ptr != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

double number_or_fail(const Lines& lines, std::string_view field, const char* what) {
  const auto v = parse_number<double>(field);
  if (!v) lines.fail(std::string("expected a number for ") + what + ", got '" + std::string(field) + "'");
  return *v;
}

/// A coordinate in the reader's frame: the text minus the axis origin, subtracted exactly.
double coordinate_or_fail(const Lines& lines, std::string_view field, const OffsetAxis& axis, const char* what) {
  if (axis.zero()) return number_or_fail(lines, field, what);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  const auto v = axis.local_from_text(field);
  if (!v) lines.fail(std::string("expected a number for ") + what + ", got '" + std::string(field) + "'");
  return *v;
}

// Places particles by id (ids first..first+n-1, any order) and checks ids are a permutation.
template <int D>
class ById {
 public:
  explicit ById(std::int64_t first) : first_(first) {}
  void add(const Lines& lines, std::int64_t id, const Vec<D>& c, double r) {
    rows_.push_back({id, c, r, lines.number()});
  }
  Packing<D> finish(const std::string& path, const Vec<D>& origin) {
    const std::int64_t n = static_cast<std::int64_t>(rows_.size());
    std::vector<int> slot(rows_.size(), -1);
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      // The id is compared with first_ before subtracting it: INT64_MIN - 1 overflows.
      const std::int64_t i = rows_[k].id < first_ ? -1 : rows_[k].id - first_;
      auto fail = [&](const std::string& why) {
        throw std::runtime_error(path + ":" + std::to_string(rows_[k].line) + ": " + why);
      };
      if (i < 0 || i >= n)
        fail("id " + std::to_string(rows_[k].id) + " out of range (ids run from " + std::to_string(first_) + " to " +
             std::to_string(first_ + n - 1) + ")");
      if (slot[static_cast<std::size_t>(i)] >= 0)
        fail("duplicate id " + std::to_string(rows_[k].id) + " (first on line " +
             std::to_string(rows_[static_cast<std::size_t>(slot[static_cast<std::size_t>(i)])].line) + ")");
      slot[static_cast<std::size_t>(i)] = static_cast<int>(k);
    }
    Packing<D> p;
    p.origin = origin;
    p.reserve(rows_.size());
    for (const int k : slot) p.add(rows_[static_cast<std::size_t>(k)].c, rows_[static_cast<std::size_t>(k)].r);
    return p;
  }

 private:
  struct Row {
    std::int64_t id;
    Vec<D> c;
    double r;
    int line;
  };
  std::int64_t first_;
  std::vector<Row> rows_;
};

template <int D>
Vec<D> center_from(const Lines& lines, const double xyz[3]) {
  if constexpr (D == 2) {
    if (xyz[2] != 0.0) lines.fail("z must be 0 in a 2D packing (got " + std::to_string(xyz[2]) + ")");
    return Vec2(xyz[0], xyz[1]);
  } else {
    return Vec3(xyz[0], xyz[1], xyz[2]);
  }
}

template <int D>
Packing<D> read_yade(const std::string& path, const Vec<D>& origin) {
  const std::string text = read_whole_file(path);
  const auto axes = offset_axes(origin.data(), D);
  Lines lines(text, path);
  Packing<D> p;
  p.origin = origin;
  std::string_view line;
  while (lines.next(line)) {
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    const auto f = split(line, ' ');
    if (f.size() != 4) lines.fail("expected 4 columns 'x y z r', got " + std::to_string(f.size()));
    const double xyz[3] = {coordinate_or_fail(lines, f[0], axes[0], "x"), coordinate_or_fail(lines, f[1], axes[1], "y"),
                           coordinate_or_fail(lines, f[2], axes[2], "z")};
    p.add(center_from<D>(lines, xyz), number_or_fail(lines, f[3], "r"));
  }
  return p;
}

template <int D>
Packing<D> read_csv(const std::string& path, const Vec<D>& origin) {
  const std::string text = read_whole_file(path);
  const auto axes = offset_axes(origin.data(), D);
  Lines lines(text, path);
  std::string_view line;
  const std::string header = D == 3 ? "id,x,y,z,r" : "id,x,y,r";
  if (!lines.next(line)) lines.fail("empty file (expected the header '" + header + "')");
  std::string got;
  for (const auto f : split(line, ',')) got += std::string(got.empty() ? "" : ",") + std::string(f);
  if (got != header) lines.fail("expected the header '" + header + "' for a " + std::to_string(D) + "D packing, got '" + got + "'");
  ById<D> rows(0);
  while (lines.next(line)) {
    if (trim(line).empty()) continue;
    const auto f = split(line, ',');
    if (f.size() != static_cast<std::size_t>(D + 2))
      lines.fail("expected " + std::to_string(D + 2) + " fields '" + header + "', got " + std::to_string(f.size()));
    const auto id = parse_number<std::int64_t>(f[0]);
    if (!id) lines.fail("expected an integer id, got '" + std::string(f[0]) + "'");
    Vec<D> c;
    const char* names[] = {"x", "y", "z"};
    for (int k = 0; k < D; ++k) c[k] = coordinate_or_fail(lines, f[static_cast<std::size_t>(k) + 1], axes[k], names[k]);
    rows.add(lines, *id, c, number_or_fail(lines, f[static_cast<std::size_t>(D) + 1], "r"));
  }
  return rows.finish(path, origin);
}

std::string_view strip_comment(std::string_view s) {
  const std::size_t hash = s.find('#');
  return trim(hash == std::string_view::npos ? s : s.substr(0, hash));
}

template <int D>
Packing<D> read_lammps(const std::string& path, const Vec<D>& origin) {
  const std::string text = read_whole_file(path);
  const auto axes = offset_axes(origin.data(), D);
  Lines lines(text, path);
  std::string_view line;
  if (!lines.next(line)) lines.fail("empty file");  // first line: the title, always skipped
  std::optional<std::int64_t> n_atoms;
  bool in_atoms = false, hybrid = false;  // hybrid: the shape writers' clumps (atom_style hybrid sphere bond)
  while (lines.next(line)) {
    const std::string_view body = strip_comment(line);
    if (body.empty()) continue;
    const auto f = split(body, ' ');
    if (f.size() == 2 && f[1] == "atoms") {
      n_atoms = parse_number<std::int64_t>(f[0]);
      if (!n_atoms || *n_atoms < 0) lines.fail("bad atom count '" + std::string(f[0]) + "'");
      continue;
    }
    if (f.size() == 1 && f[0] == "Atoms") {
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) {
        const std::string_view style = trim(line.substr(hash + 1));
        if (style != "sphere" && style != "hybrid")
          lines.fail("Atoms section of style '" + std::string(style) + "', expected 'sphere' (or 'hybrid': sphere bond)");
        hybrid = style == "hybrid";
      }
      in_atoms = true;
      break;
    }
    if (std::isalpha(static_cast<unsigned char>(f[0][0]))) lines.fail("section '" + std::string(body) + "' before the Atoms section is not supported");
  }
  if (!in_atoms) lines.fail("no 'Atoms # sphere' (or '# hybrid') section");
  if (!n_atoms) lines.fail("the header does not give the number of atoms ('N atoms')");
  ById<D> rows(1);
  std::int64_t read = 0;
  while (read < *n_atoms && lines.next(line)) {
    const std::string_view body = strip_comment(line);
    if (body.empty()) continue;
    const auto f = split(body, ' ');
    // sphere: id type diameter density x y z [ix iy iz]; hybrid sphere bond: id type x y z
    // diameter density molecule [ix iy iz]
    if (!hybrid && f.size() != 7 && f.size() != 10)
      lines.fail("expected 'id type diameter density x y z' (atom_style sphere), got " + std::to_string(f.size()) + " columns");
    if (hybrid && f.size() != 8 && f.size() != 11)
      lines.fail("expected 'id type x y z diameter density molecule' (atom_style hybrid sphere bond), got " +
                 std::to_string(f.size()) + " columns");
    const auto id = parse_number<std::int64_t>(f[0]);
    if (!id) lines.fail("expected an integer atom id, got '" + std::string(f[0]) + "'");
    const std::size_t at_x = hybrid ? 2 : 4;
    const double diameter = number_or_fail(lines, f[hybrid ? 5 : 2], "the diameter");
    const double xyz[3] = {coordinate_or_fail(lines, f[at_x], axes[0], "x"), coordinate_or_fail(lines, f[at_x + 1], axes[1], "y"),
                           coordinate_or_fail(lines, f[at_x + 2], axes[2], "z")};
    rows.add(lines, *id, center_from<D>(lines, xyz), 0.5 * diameter);
    ++read;
  }
  if (read < *n_atoms)
    lines.fail("the header announces " + std::to_string(*n_atoms) + " atoms, the Atoms section has " + std::to_string(read));
  return rows.finish(path, origin);
}

// --- VTU: frontpack's own layout (appended raw, UInt64 headers, native byte order) -------

std::map<std::string, std::string> attributes(std::string_view tag) {
  std::map<std::string, std::string> out;
  std::size_t i = 0;
  while (true) {
    const std::size_t eq = tag.find("=\"", i);
    if (eq == std::string_view::npos) break;
    std::size_t k = eq;
    while (k > 0 && tag[k - 1] != ' ' && tag[k - 1] != '\n' && tag[k - 1] != '\t') --k;
    const std::size_t close = tag.find('"', eq + 2);
    if (close == std::string_view::npos) break;
    out[std::string(tag.substr(k, eq - k))] = std::string(tag.substr(eq + 2, close - eq - 2));
    i = close + 1;
  }
  return out;
}

template <int D>
Packing<D> read_vtu(const std::string& path, const Vec<D>& origin) {
  const std::string data = read_whole_file(path);
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(path + ": " + why + " (only frontpack's own VTU layout, appended raw binary, can be read)");
  };
  const std::size_t appended = data.find("<AppendedData encoding=\"raw\">");
  if (appended == std::string::npos) throw fail("no raw <AppendedData> section");
  const std::size_t underscore = data.find('_', appended);
  if (underscore == std::string::npos) throw fail("no '_' marker in <AppendedData>");
  const std::size_t base = underscore + 1;
  const std::string_view header = std::string_view(data).substr(0, appended);

  const std::size_t vtk = header.find("<VTKFile");
  if (vtk == std::string::npos) throw fail("no <VTKFile> element");
  const auto file_attr = attributes(header.substr(vtk, header.find('>', vtk) - vtk));
  const char* native = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  if (file_attr.count("type") == 0 || file_attr.at("type") != "UnstructuredGrid") throw fail("not an UnstructuredGrid");
  if (file_attr.count("byte_order") == 0 || file_attr.at("byte_order") != native)
    throw fail("byte order is not this machine's (" + std::string(native) + ")");
  if (file_attr.count("header_type") == 0 || file_attr.at("header_type") != "UInt64") throw fail("header_type is not UInt64");
  const std::size_t piece = header.find("<Piece");
  if (piece == std::string::npos) throw fail("no <Piece>");
  const auto piece_attr = attributes(header.substr(piece, header.find('>', piece) - piece));
  const auto n = piece_attr.count("NumberOfPoints") ? parse_number<std::uint64_t>(piece_attr.at("NumberOfPoints")) : std::nullopt;
  if (!n) throw fail("no NumberOfPoints");

  std::map<std::string, std::map<std::string, std::string>> arrays;
  for (std::size_t at = header.find("<DataArray"); at != std::string::npos; at = header.find("<DataArray", at + 1)) {
    auto a = attributes(header.substr(at, header.find('>', at) - at));
    arrays[a["Name"]] = a;
  }
  if (arrays.count("quaternion") && !arrays.count("radius"))  // shapes/io/shape_packing_writers' layout
    throw std::runtime_error(path + ": holds non-spherical particles (a 'quaternion' array); " + kSpheresAndDisksOnly);
  auto block = [&](const std::string& name, const char* type, int comps) -> const char* {
    const auto it = arrays.find(name);
    if (it == arrays.end()) throw fail("no DataArray '" + name + "'");
    auto& a = it->second;
    const std::string got_comps = a.count("NumberOfComponents") ? a["NumberOfComponents"] : "1";
    if (a["type"] != type || got_comps != std::to_string(comps) || a["format"] != "appended")
      throw fail("DataArray '" + name + "' is not appended " + type + " x" + std::to_string(comps));
    const auto offset = parse_number<std::uint64_t>(a["offset"]);
    if (!offset) throw fail("DataArray '" + name + "' has no valid offset");
    // Compared by division first: a crafted NumberOfPoints or offset must not wrap round.
    if (*n > data.size() / (static_cast<std::uint64_t>(comps) * 8) || *offset > data.size())
      throw fail("DataArray '" + name + "' runs past the end of the file");
    const std::uint64_t want = *n * static_cast<std::uint64_t>(comps) * 8;
    if (base + *offset + 8 + want > data.size()) throw fail("DataArray '" + name + "' runs past the end of the file");
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, data.data() + base + *offset, 8);
    if (bytes != want)
      throw fail("DataArray '" + name + "' holds " + std::to_string(bytes) + " bytes, expected " + std::to_string(want));
    return data.data() + base + *offset + 8;
  };
  const char* radius = block("radius", "Float64", 1);
  const char* points = block("Points", "Float64", 3);
  // A packing written in a local frame carries its exact centres (packing_writers.cpp):
  // local_position relative to frame_origin, an ascii field of three numbers.
  const char* local = nullptr;
  double shift[3] = {0, 0, 0};  // file frame - reader frame
  if (arrays.count("local_position")) {
    local = block("local_position", "Float64", 3);
    const std::size_t at = header.find("Name=\"frame_origin\"");
    if (at == std::string::npos) throw fail("DataArray 'local_position' without the field 'frame_origin'");
    const std::size_t open = header.find('>', at), close = header.find('<', open);
    const auto values = split(trim(header.substr(open + 1, close - open - 1)), ' ');
    if (values.size() != 3) throw fail("the field 'frame_origin' must hold 3 numbers");
    for (int k = 0; k < 3; ++k) {
      const auto v = parse_number<double>(values[static_cast<std::size_t>(k)]);
      if (!v) throw fail("the field 'frame_origin' must hold 3 numbers");
      shift[k] = *v - (k < D ? origin[k] : 0.0);
    }
  }
  Packing<D> p;
  p.origin = origin;
  p.reserve(*n);
  for (std::uint64_t i = 0; i < *n; ++i) {
    double xyz[3];
    double r;
    std::memcpy(xyz, (local ? local : points) + 24 * i, 24);
    std::memcpy(&r, radius + 8 * i, 8);
    for (int k = 0; k < 3; ++k)  // exact when the frames agree (shift 0)
      xyz[k] = local ? (shift[k] == 0.0 ? xyz[k] : xyz[k] + shift[k]) : xyz[k] - (k < D ? origin[k] : 0.0);
    if constexpr (D == 2) {
      if (xyz[2] != 0.0) throw std::runtime_error(path + ": point " + std::to_string(i) + " has z != 0 in a 2D packing");
      p.add(Vec2(xyz[0], xyz[1]), r);
    } else {
      p.add(Vec3(xyz[0], xyz[1], xyz[2]), r);
    }
  }
  return p;
}

template <int D>
Packing<D> read_json(const std::string& path, const Vec<D>& origin) {
  return packing_from_json<D>(read_whole_file(path), path, origin);
}

}  // namespace

template <int D>
Packing<D> read_packing(OutputFormat format, const std::string& path, const Vec<D>& origin) {
  switch (format) {
    case OutputFormat::Vtu: return read_vtu<D>(path, origin);
    case OutputFormat::Yade: return read_yade<D>(path, origin);
    case OutputFormat::Lammps: return read_lammps<D>(path, origin);
    case OutputFormat::Csv: return read_csv<D>(path, origin);
    case OutputFormat::Json: return read_json<D>(path, origin);
  }
  throw std::invalid_argument("invalid OutputFormat value");
}

int packing_file_dimension(OutputFormat format, const std::string& path) {
  if (format == OutputFormat::Json) return run_record_dimension(read_whole_file(path), path);
  if (format == OutputFormat::Csv) {
    const std::string text = read_whole_file(path);
    Lines lines(text, path);
    std::string_view line;
    if (!lines.next(line)) lines.fail("empty file");
    const auto f = split(line, ',');
    if (f.size() > 1 && trim(f[1]) == "shape_id")  // shapes/io/shape_packing_writers' layout
      lines.fail("holds non-spherical particles (a 'shape_id' column); " + std::string(kSpheresAndDisksOnly));
    if (f.size() == 5) return 3;
    if (f.size() == 4) return 2;
    lines.fail("expected the header 'id,x,y,z,r' (3D) or 'id,x,y,r' (2D)");
  }
  const Packing<3> p = read_packing<3>(format, path, Vec3::Zero());
  for (const auto& c : p.centers)
    if (c.z() != 0.0) return 3;
  return p.empty() ? 3 : 2;
}

template <int D>
Packing<D> read_packing_in_own_frame(OutputFormat format, const std::string& path) {
  Packing<D> p = read_packing<D>(format, path, Vec<D>::Zero());
  Aabb<D> box;
  for (const auto& c : p.centers)
    if (c.allFinite()) box.extend(c);
  if (p.empty() || !(box.lo.array() <= box.hi.array()).all()) return p;
  const Vec<D> origin = frame_origin<D>(box);
  return origin.isZero() ? p : read_packing<D>(format, path, origin);
}

std::string read_packing_text(const std::string& path) { return read_whole_file(path); }

template Packing<2> read_packing<2>(OutputFormat, const std::string&, const Vec2&);
template Packing<3> read_packing<3>(OutputFormat, const std::string&, const Vec3&);
template Packing<2> read_packing_in_own_frame<2>(OutputFormat, const std::string&);
template Packing<3> read_packing_in_own_frame<3>(OutputFormat, const std::string&);

}  // namespace fp
