#include "core/io/run_record.hpp"

#include <nlohmann/json.hpp>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "core/io/atomic_file.hpp"
#include "core/io/exact_decimal.hpp"
#include "core/io/packing_readers.hpp"

namespace fp {
namespace {

using Json = nlohmann::ordered_json;

std::string dump(const Json& j) {
  // replace: scene text copied from a user file may not be valid UTF-8; never throw on it.
  return j.dump(2, ' ', false, Json::error_handler_t::replace);
}

Json record_object(const RunRecord& r) {
  Json j;
  j["frontpack_version"] = r.version;
  j["dimension"] = r.dimension;
  j["seed"] = r.seed;
  j["n"] = r.n;
  j["scene"] = Json{{"path", r.scene_path}, {"text", r.scene_text}};
  if (!r.scene_overrides.empty()) j["scene"]["overrides"] = r.scene_overrides;  // --set, a study's run
  j["container"] = r.container_description;
  j["distribution"] = r.distribution_description;
  if (r.bounds) {
    const auto& b = *r.bounds;
    const Vec3 lo = b.lo + r.origin, hi = b.hi + r.origin;
    j["bounds"] = Json{{"lo", {lo.x(), lo.y(), lo.z()}}, {"hi", {hi.x(), hi.y(), hi.z()}}};
  } else {
    j["bounds"] = nullptr;
  }
  j["frame_origin"] = {r.origin.x(), r.origin.y(), r.origin.z()};
  j["density"] = r.density;
  j["timings"] = Json::object();
  for (const auto& [k, v] : r.timings) j["timings"][k] = v;
  j["metrics"] = Json::object();
  for (const auto& [k, v] : r.metrics) j["metrics"][k] = v;
  j["counters"] = Json::object();
  for (const auto& [k, v] : r.counters) j["counters"][k] = v;
  j["info"] = Json::object();
  for (const auto& [k, v] : r.info) j["info"][k] = v;
  if (!r.analysis_json.empty()) j["analysis"] = Json::parse(r.analysis_json);
  return j;
}

}  // namespace

std::string run_record_json(const RunRecord& record) { return dump(record_object(record)) + "\n"; }

template <int D>
std::string run_record_json(const RunRecord& record, const Packing<D>& packing) {
  if (!record.embed_particles) return run_record_json(record);
  std::string text = dump(record_object(record));
  // The record is pretty-printed; the particle arrays are written compact (one line per
  // coordinate), else a million particles would take four million lines.
  const std::size_t n = packing.size();
  std::string particles = ",\n  \"particles\": {";
  const char* names[] = {"x", "y", "z"};
  const auto axes = offset_axes(packing.origin.data(), D);
  std::vector<double> column(n);
  for (int k = 0; k < D; ++k) {
    particles += std::string(k == 0 ? "" : ",") + "\n    \"" + names[k] + "\": ";
    if (axes[k].zero()) {
      for (std::size_t i = 0; i < n; ++i) column[i] = packing.centers[i][k];
      particles += Json(column).dump();
      continue;
    }
    particles += '[';
    for (std::size_t i = 0; i < n; ++i) {
      if (i) particles += ',';
      const double x = packing.centers[i][k];
      if (std::isfinite(x)) axes[k].append_absolute(particles, x);
      else particles += "null";
    }
    particles += ']';
  }
  particles += ",\n    \"r\": " + Json(packing.radii).dump() + "\n  }\n}\n";
  text.pop_back();  // the closing '}'
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text + particles;
}

void write_run_record(const std::string& path, const RunRecord& record) {
  write_text_file_atomically(path, run_record_json(record));
}

std::string json_error_text(const char* what) {
  const std::string_view s(what);
  const std::size_t close = s.find("] ");
  return std::string(s.starts_with("[json.exception.") && close != std::string_view::npos ? s.substr(close + 2) : s);
}

namespace {

Json parse_record(const std::string& text, const std::string& source_name, int& dimension) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::exception& e) {  // a parse_error, or an out_of_range for a number beyond the doubles (1e999)
    throw std::runtime_error(source_name + ": invalid JSON: " + json_error_text(e.what()));
  }
  if (!j.is_object()) throw std::runtime_error(source_name + ": not a frontpack run record (top level is not an object)");
  if (!j.contains("dimension") || !j["dimension"].is_number_integer())
    throw std::runtime_error(source_name + ": missing integer key 'dimension'");
  dimension = j["dimension"].get<int>();
  if (dimension != 2 && dimension != 3)
    throw std::runtime_error(source_name + ": 'dimension' must be 2 or 3 (got " + std::to_string(dimension) + ")");
  return j;
}

/// The text of every number directly inside the arrays `select` picks (json_number_texts).
class NumberTexts : public nlohmann::json_sax<Json> {
 public:
  NumberTexts(std::size_t slots, const JsonArraySelect& select) : texts(slots), select_(select) {}
  std::vector<std::vector<std::string>> texts;

  bool null() override { return put("null"); }
  bool boolean(bool) override { return put("?"); }
  bool number_integer(number_integer_t v) override { return put(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return put(std::to_string(v)); }
  bool number_float(number_float_t, const string_t& s) override { return put(s); }
  bool string(string_t&) override { return put("?"); }
  bool binary(binary_t&) override { return put("?"); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    pending_ = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool open(bool array) {
    const std::string under = !kinds_.empty() && kinds_.back() == 'a' ? "[]" : pending_;
    int slot = -1;
    if (array && !kinds_.empty()) {  // its path: the keys below the top level, and its own
      std::vector<std::string> path(under_.begin() + 1, under_.end());
      path.push_back(under);
      slot = select_(path);
      if (slot >= static_cast<int>(texts.size())) slot = -1;
    }
    kinds_.push_back(array ? 'a' : 'o');
    under_.push_back(under);
    slots_.push_back(slot);
    return true;
  }
  bool close() {
    kinds_.pop_back();
    under_.pop_back();
    slots_.pop_back();
    return true;
  }
  bool put(const std::string& s) {
    if (!slots_.empty() && slots_.back() >= 0) texts[static_cast<std::size_t>(slots_.back())].push_back(s);
    return true;
  }
  const JsonArraySelect& select_;
  std::string kinds_;               // the containers open, outermost first: 'o' object, 'a' array
  std::vector<std::string> under_;  // per open container: the key it is the value of ("[]": an item)
  std::vector<int> slots_;          // per open container: its slot, -1 if not picked
  std::string pending_;             // the last key read
};

}  // namespace

std::vector<std::vector<std::string>> json_number_texts(const std::string& text, std::size_t slots, const JsonArraySelect& select) {
  NumberTexts tokens(slots, select);
  Json::sax_parse(text, &tokens);
  return std::move(tokens.texts);
}

int run_record_dimension(const std::string& text, const std::string& source_name) {
  int dimension = 0;
  parse_record(text, source_name, dimension);
  return dimension;
}

template <int D>
Packing<D> packing_from_json(const std::string& text, const std::string& source_name, const Vec<D>& origin) {
  int dimension = 0;
  Json j = parse_record(text, source_name, dimension);
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(source_name + ": " + why);
  };
  if (dimension != D)
    throw fail("the file is " + std::to_string(dimension) + "D, expected " + std::to_string(D) + "D");
  if (j.contains("shapes"))  // the json output of a scene of shapes (shapes/io/shape_packing_writers)
    throw fail("holds non-spherical particles (a 'shapes' list); " + std::string(kSpheresAndDisksOnly));
  if (!j.contains("particles") || !j["particles"].is_object())
    throw fail("no 'particles' in this file (a record-only run record? use the json output format)");
  const Json& p = j["particles"];
  const char* names[] = {"x", "y", "z", "r"};
  std::vector<std::vector<double>> cols;
  for (int k = 0; k <= D; ++k) {
    const char* name = k == D ? names[3] : names[k];
    if (!p.contains(name) || !p[name].is_array()) throw fail(std::string("missing array 'particles.") + name + "'");
    std::vector<double> col;
    col.reserve(p[name].size());
    for (std::size_t i = 0; i < p[name].size(); ++i) {
      const Json& v = p[name][i];
      if (!v.is_number()) throw fail(std::string("particles.") + name + "[" + std::to_string(i) + "] is not a number");
      col.push_back(v.get<double>());
    }
    if (!cols.empty() && col.size() != cols.front().size())
      throw fail(std::string("particles.") + name + " has " + std::to_string(col.size()) + " entries, particles.x has " +
                 std::to_string(cols.front().size()));
    cols.push_back(std::move(col));
  }
  // Far from the origin the doubles of the DOM lost digits: subtract the origin from the text.
  if (!origin.isZero()) {
    const auto tokens = json_number_texts(text, 3, [](const std::vector<std::string>& path) {  // particles.{x,y,z}
      if (path.size() != 2 || path[0] != "particles") return -1;
      return path[1] == "x" ? 0 : path[1] == "y" ? 1 : path[1] == "z" ? 2 : -1;
    });
    for (int k = 0; k < D; ++k) {
      if (origin[k] == 0.0) continue;
      const OffsetAxis axis(origin[k]);
      if (tokens[k].size() != cols[k].size()) throw fail(std::string("cannot re-read particles.") + names[k]);
      for (std::size_t i = 0; i < cols[k].size(); ++i) {
        const auto v = axis.local_from_text(tokens[k][i]);
        if (!v) throw fail(std::string("particles.") + names[k] + "[" + std::to_string(i) + "] is not a number");
        cols[k][i] = *v;
      }
    }
  }
  Packing<D> out;
  out.origin = origin;
  const std::size_t n = cols.front().size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> c;
    for (int k = 0; k < D; ++k) c[k] = cols[k][i];
    out.add(c, cols[D][i]);
  }
  return out;
}

template std::string run_record_json<2>(const RunRecord&, const Packing<2>&);
template std::string run_record_json<3>(const RunRecord&, const Packing<3>&);
template Packing<2> packing_from_json<2>(const std::string&, const std::string&, const Vec2&);
template Packing<3> packing_from_json<3>(const std::string&, const std::string&, const Vec3&);

}  // namespace fp
