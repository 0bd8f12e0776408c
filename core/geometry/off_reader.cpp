#include "core/geometry/off_reader.hpp"

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

namespace fp::detail {
namespace {

// The shortest lines the counts need: "0 0 0\n" per vertex, "3 0 1 2\n" per face.
constexpr std::uintmax_t kMinVertexBytes = 6, kMinFaceBytes = 8;

/// Splits a line (comment removed) into its whitespace-separated words.
void words_of(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
}

template <typename T>
bool parse(std::string_view w, T& v) {
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  return !w.empty() && ec == std::errc() && end == w.data() + w.size();
}

class Reader {
 public:
  explicit Reader(const std::string& path) : in_(path, std::ios::binary) {}
  bool open() const { return static_cast<bool>(in_); }
  /// The next line with words on it; false at the end of the file.
  bool next(std::vector<std::string_view>& words) {
    while (std::getline(in_, line_)) {
      ++number_;
      words_of(line_, words);
      if (!words.empty()) return true;
    }
    return false;
  }
  std::string at() const { return "line " + std::to_string(number_) + ": "; }

 private:
  std::ifstream in_;
  std::string line_;
  int number_ = 0;
};

}  // namespace

bool read_off(const std::string& path, PolygonSoup& soup, std::string& error) {
  Reader r(path);
  if (!r.open()) {
    error = "cannot open the file";
    return false;
  }
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  std::vector<std::string_view> w;
  const auto fail = [&](const std::string& why) {
    error = why;
    return false;
  };
  if (!r.next(w)) return fail("empty file (an OFF file starts with the keyword OFF)");
  const std::string_view keyword = w[0];
  bool colours = false, normals = false;
  if (keyword == "OFF") {
  } else if (keyword == "COFF") colours = true;
  else if (keyword == "NOFF") normals = true;
  else if (keyword == "CNOFF") colours = normals = true;
  else return fail(r.at() + "the header is '" + std::string(keyword) + "'; supported: OFF, COFF, NOFF, CNOFF (text, 3D)");
  if (w.size() > 1 && w[1] == "BINARY") return fail(r.at() + "binary OFF is not supported");
  std::vector<std::string_view> counts(w.begin() + 1, w.end());
  if (counts.empty()) {
    if (!r.next(w)) return fail("the file ends before the counts 'vertices faces edges'");
    counts = w;
  }
  std::uint64_t nv = 0, nf = 0, ne = 0;
  if ((counts.size() != 2 && counts.size() != 3) || !parse(counts[0], nv) || !parse(counts[1], nf) ||
      (counts.size() == 3 && !parse(counts[2], ne)))
    return fail(r.at() + "expected the counts 'vertices faces edges' (non-negative integers)");
  // Checked before reserving: a false header must not allocate what it claims.
  if (!ec && (nv > file_bytes / kMinVertexBytes || nf > file_bytes / kMinFaceBytes ||
              nv * kMinVertexBytes + nf * kMinFaceBytes > file_bytes))
    return fail(r.at() + "the header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                " faces, more than the file's " + std::to_string(file_bytes) + " bytes can hold");

  const std::size_t per_vertex = 3 + (normals ? 3 : 0);
  soup.points.clear();
  soup.polygons.clear();
  soup.points.reserve(nv);
  soup.polygons.reserve(nf);
  for (std::uint64_t i = 0; i < nv; ++i) {
    if (!r.next(w)) return fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    const bool size_ok = w.size() == per_vertex || (colours && (w.size() == per_vertex + 3 || w.size() == per_vertex + 4));
    if (!size_ok)
      return fail(r.at() + "vertex " + std::to_string(i) + " has " + std::to_string(w.size()) + " numbers; expected " +
                  std::to_string(per_vertex) + (normals ? " (x y z nx ny nz)" : " (x y z)") +
                  (colours ? " and a colour of 3 or 4" : ""));
    Vec3 p;
    for (std::size_t k = 0; k < w.size(); ++k) {
      double v = 0;
      if (!parse(w[k], v)) return fail(r.at() + "'" + std::string(w[k]) + "' is not a number (vertex " + std::to_string(i) + ")");
      if (k < 3) p[static_cast<int>(k)] = v;
    }
    soup.points.push_back(p);
  }
  for (std::uint64_t f = 0; f < nf; ++f) {
    if (!r.next(w)) return fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    std::uint64_t k = 0;
    if (!parse(w[0], k) || k < 3)
      return fail(r.at() + "face " + std::to_string(f) + " must start with its number of vertices (3 or more), got '" +
                  std::string(w[0]) + "'");
    const std::uint64_t extra = w.size() - 1 < k ? 0 : w.size() - 1 - k;
    if (w.size() - 1 < k || (extra != 0 && extra != 1 && extra != 3 && extra != 4))
      return fail(r.at() + "face " + std::to_string(f) + " has " + std::to_string(w.size() - 1) + " numbers after its count " +
                  std::to_string(k) + "; expected " + std::to_string(k) + " vertex indices (and optionally a colour of 1, 3 or 4)");
    std::vector<std::size_t> poly(k);
    for (std::uint64_t j = 0; j < k; ++j) {
      std::uint64_t idx = 0;
      if (!parse(w[1 + j], idx) || idx >= nv)
        return fail(r.at() + "face " + std::to_string(f) + ": '" + std::string(w[1 + j]) + "' is not a vertex index (0 to " +
                    std::to_string(nv == 0 ? 0 : nv - 1) + ")");
      poly[j] = static_cast<std::size_t>(idx);
    }
    soup.polygons.push_back(std::move(poly));
  }
  if (r.next(w)) return fail(r.at() + "text after the last of the " + std::to_string(nf) + " faces");
  return true;
}

}  // namespace fp::detail
