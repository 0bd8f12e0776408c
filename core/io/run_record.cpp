#include "core/io/run_record.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io/atomic_file.hpp"

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
  j["container"] = r.container_description;
  j["distribution"] = r.distribution_description;
  if (r.bounds) {
    const auto& b = *r.bounds;
    j["bounds"] = Json{{"lo", {b.lo.x(), b.lo.y(), b.lo.z()}}, {"hi", {b.hi.x(), b.hi.y(), b.hi.z()}}};
  } else {
    j["bounds"] = nullptr;
  }
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
  std::vector<double> column(n);
  for (int k = 0; k < D; ++k) {
    for (std::size_t i = 0; i < n; ++i) column[i] = packing.centers[i][k];
    particles += std::string(k == 0 ? "" : ",") + "\n    \"" + names[k] + "\": " + Json(column).dump();
  }
  particles += ",\n    \"r\": " + Json(packing.radii).dump() + "\n  }\n}\n";
  text.pop_back();  // the closing '}'
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text + particles;
}

void write_run_record(const std::string& path, const RunRecord& record) {
  write_text_file_atomically(path, run_record_json(record));
}

namespace {

Json parse_record(const std::string& text, const std::string& source_name, int& dimension) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw std::runtime_error(source_name + ": invalid JSON: " + e.what());
  }
  if (!j.is_object()) throw std::runtime_error(source_name + ": not a frontpack run record (top level is not an object)");
  if (!j.contains("dimension") || !j["dimension"].is_number_integer())
    throw std::runtime_error(source_name + ": missing integer key 'dimension'");
  dimension = j["dimension"].get<int>();
  if (dimension != 2 && dimension != 3)
    throw std::runtime_error(source_name + ": 'dimension' must be 2 or 3 (got " + std::to_string(dimension) + ")");
  return j;
}

}  // namespace

int run_record_dimension(const std::string& text, const std::string& source_name) {
  int dimension = 0;
  parse_record(text, source_name, dimension);
  return dimension;
}

template <int D>
Packing<D> packing_from_json(const std::string& text, const std::string& source_name) {
  int dimension = 0;
  Json j = parse_record(text, source_name, dimension);
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(source_name + ": " + why);
  };
  if (dimension != D)
    throw fail("the file is " + std::to_string(dimension) + "D, expected " + std::to_string(D) + "D");
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
  Packing<D> out;
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
template Packing<2> packing_from_json<2>(const std::string&, const std::string&);
template Packing<3> packing_from_json<3>(const std::string&, const std::string&);

}  // namespace fp
