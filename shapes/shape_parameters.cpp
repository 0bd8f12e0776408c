// g++ 12 -O3 warns falsely (-Wrestrict, GCC bug 105329) inside std::string's operator+ once
// SceneError's message composition is inlined here; the pragma must precede <string>.
#pragma GCC diagnostic ignored "-Wrestrict"

#include "shapes/shape_parameters.hpp"

#include <cmath>
#include <limits>
#include <set>

#include "core/io/scene_error.hpp"
#include "shapes/json_text.hpp"

namespace fp {

void ParameterReader::fail(const std::string& key, const std::string& message) const {
  // Where the key was written; a key that was not written at all is reported at its template,
  // under the dotted path it should have had.
  SourceSpot at = p_.spot;
  at.key = p_.spot.key.empty() ? key : p_.spot.key + "." + key;
  if (auto it = p_.spots.find(key); it != p_.spots.end()) {
    if (!it->second.file.empty()) at.file = it->second.file;
    at.line = it->second.line;
    at.column = it->second.column;
    if (!it->second.key.empty()) at.key = it->second.key;
  }
  throw SceneError(at.file, at.line, at.column, at.key, message);
}

bool ParameterReader::has(const std::string& key) const {
  return p_.numbers.count(key) != 0 || p_.lists.count(key) != 0 || p_.point_lists.count(key) != 0 ||
         p_.strings.count(key) != 0;
}

std::string ParameterReader::word(const std::string& key, const std::string& what) const {
  const auto it = p_.strings.find(key);
  if (it == p_.strings.end()) {
    if (has(key)) fail(key, "expected a word (" + what + ")");
    fail(key, "missing: " + what);
  }
  return it->second;
}

double ParameterReader::number(const std::string& key, const std::string& what) const {
  auto it = p_.numbers.find(key);
  if (it == p_.numbers.end()) {
    if (const auto w = p_.strings.find(key); w != p_.strings.end())
      fail(key, "expected a number (" + what + "), got the word '" + w->second + "'");
    if (has(key)) fail(key, "expected a number (" + what + "), got a list");
    fail(key, "missing: " + what);
  }
  if (!std::isfinite(it->second)) fail(key, "must be a finite number (" + what + ")");
  return it->second;
}

double ParameterReader::number_or(const std::string& key, double fallback) const {
  return has(key) ? number(key, "a number") : fallback;
}

double ParameterReader::number_in(const std::string& key, const std::string& what, double lo, double hi,
                                  bool closed_lo) const {
  const double x = number(key, what);
  const bool above = closed_lo ? x >= lo : x > lo;
  if (!above || x > hi) {
    std::string range;
    if (std::isinf(hi)) range = std::string(closed_lo ? ">= " : "> ") + json_number(lo);
    else range = std::string("in ") + (closed_lo ? "[" : "(") + json_number(lo) + ", " + json_number(hi) + "]";
    fail(key, "must be " + range + " (" + what + "; got " + json_number(x) + ")");
  }
  return x;
}

std::vector<double> ParameterReader::list(const std::string& key, const std::string& what) const {
  auto it = p_.lists.find(key);
  if (it == p_.lists.end()) {
    if (auto n = p_.numbers.find(key); n != p_.numbers.end()) return {number(key, what)};  // a scalar is a list of one
    if (has(key)) fail(key, "expected a list of numbers (" + what + "), got a list of lists");
    fail(key, "missing: " + what);
  }
  for (std::size_t i = 0; i < it->second.size(); ++i)
    if (!std::isfinite(it->second[i]))
      fail(key, "item " + std::to_string(i) + " must be a finite number (" + what + ")");
  return it->second;
}

std::vector<std::vector<double>> ParameterReader::points(const std::string& key, const std::string& what,
                                                         int dim) const {
  auto it = p_.point_lists.find(key);
  if (it == p_.point_lists.end()) {
    // An empty YAML list carries no type: accept it here and let the family say what it needs.
    if (auto l = p_.lists.find(key); l != p_.lists.end() && l->second.empty()) return {};
    if (has(key))
      fail(key, "expected a list of " + std::to_string(dim) + "D points, e.g. [[" +
                    std::string(dim == 2 ? "0, 0], [1, 0]" : "0, 0, 0], [1, 0, 0]") + ", ...] (" + what + ")");
    fail(key, "missing: " + what);
  }
  const auto& pts = it->second;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (static_cast<int>(pts[i].size()) != dim)
      fail(key, "point " + std::to_string(i) + " has " + std::to_string(pts[i].size()) + " coordinates; a " +
                    std::to_string(dim) + "D scene needs " + std::to_string(dim) + " (" + what + ")");
    for (double x : pts[i])
      if (!std::isfinite(x)) fail(key, "point " + std::to_string(i) + " has a non-finite coordinate (" + what + ")");
  }
  return pts;
}

void ParameterReader::check_known(const std::vector<std::string>& known, const std::string& family) const {
  const std::set<std::string> ok(known.begin(), known.end());
  std::string listed;
  for (const auto& k : known) listed += (listed.empty() ? "" : ", ") + k;
  auto check = [&](const std::string& key) {
    if (ok.count(key)) return;
    fail(key, "unknown parameter '" + key + "' of shape '" + family + "' (" +
                  (known.empty() ? std::string("it takes none") : "known: " + listed) + ")");
  };
  // Checked in key order over the three maps, so the reported key does not depend on map layout.
  std::set<std::string> keys;
  for (const auto& [k, v] : p_.numbers) keys.insert(k);
  for (const auto& [k, v] : p_.lists) keys.insert(k);
  for (const auto& [k, v] : p_.point_lists) keys.insert(k);
  for (const auto& [k, v] : p_.strings) keys.insert(k);
  for (const auto& k : keys) check(k);
}

double width_over_length(const ParameterReader& r, const std::string& length, const std::string& width, bool rod_only) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string elongation = length + " / " + width, aspect = width + " / " + length;
  if (r.has("elongation") && r.has("aspect_ratio"))
    r.fail("aspect_ratio", "give elongation (" + elongation + ") or aspect_ratio (its inverse, the older key), not both");
  if (r.has("aspect_ratio")) return r.number_in("aspect_ratio", aspect, 0.0, rod_only ? 1.0 : inf);
  if (!r.has("elongation")) r.fail("elongation", "missing: " + elongation + " (or aspect_ratio = " + aspect + ")");
  return 1.0 / r.number_in("elongation", elongation, rod_only ? 1.0 : 0.0, inf, /*closed_lo=*/rod_only);
}

}  // namespace fp
