#include "core/io/study_yaml.hpp"

#include <charconv>
#include <filesystem>
#include <set>

#include "core/io/document_file.hpp"
#include "core/io/scene_yaml.hpp"
#include "core/io/yaml_document.hpp"

namespace fp {
namespace {

using namespace yaml_document;

/// A value as YAML text on one line (flow style), for --set and labels.
std::string flow_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

bool is_number(const std::string& s) {
  double v = 0;
  const char* b = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const auto r = std::from_chars(b, s.data() + s.size(), v);
  return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

SceneOverride override_at(const Value& v, const std::string& key) {
  SceneOverride o;
  o.key = key;
  o.value = flow_text(v.node());
  o.origin = v.spot();
  o.origin.key.clear();
  return o;
}

/// `key`, given at `where`, checked as --set checks a key.
std::string scene_key(const Value& where, const std::string& key) {
  if (!is_scene_key(key)) where.fail("'" + key + "' is not a scene key (" + kSceneKeyForm + ")");
  return key;
}

/// A file named in the study, relative to its folder.
std::string study_relative(const Context& ctx, const std::string& p) {
  const std::filesystem::path f(p);
  return (f.is_absolute() ? f : ctx.folder / f).lexically_normal().string();
}

/// One change a value makes: `scene` names another base scene, any other key is a --set.
void add_change(StudyLevel& level, const Context& ctx, const std::string& key, const Value& value) {
  if (key == "scene") level.scene_path = study_relative(ctx, value.string());
  else level.overrides.push_back(override_at(value, scene_key(value, key)));
}

StudyParameter parse_parameter(const Value& v, const Context& ctx) {
  const Map m = v.map();
  m.check_known({"key", "values", "name", "cases"});
  StudyParameter p;
  p.spot = v.spot();
  if (m.has("cases")) {
    if (m.has("key") || m.has("values")) m.fail("give either 'key' and 'values' (one key swept) or 'name' and 'cases' (several keys at once)");
    p.name = m.get("name", "the parameter's name: its CSV column").string();
    const Map cases = m.get("cases").map();
    for (const std::string& label : cases.keys()) {
      StudyLevel level;
      level.label = label;
      const Map changes = cases.get(label).map();
      for (const std::string& key : changes.keys()) add_change(level, ctx, key, *changes.find(key));
      if (level.overrides.empty() && level.scene_path.empty()) cases.get(label).fail("a case changes at least one key");
      p.levels.push_back(std::move(level));
    }
    if (p.levels.empty()) m.get("cases").fail("give at least one case");
  } else {
    const Value key_value = m.get("key", "the dotted scene key swept (or 'name' and 'cases')");
    const std::string key = scene_key(key_value, key_value.string());
    p.name = m.has("name") ? m.get("name").string() : key;
    const auto values = m.get("values", "the values the key takes").list();
    if (values.empty()) m.get("values").fail("give at least one value");
    for (const Value& x : values) {
      if (!x.node().IsDefined() || x.node().IsNull()) x.fail("a value is missing");
      StudyLevel level;
      level.label = flow_text(x.node());
      add_change(level, ctx, key, x);
      p.levels.push_back(std::move(level));
    }
  }
  if (p.name.empty() || p.name.find_first_of(",\"\n") != std::string::npos || p.name == "seed" || p.name == "run")
    v.fail("the parameter's name '" + p.name + "' must be a plain CSV column name (not seed, run; no comma or quote)");
  std::set<std::string> labels;
  p.numeric = true;
  for (const auto& level : p.levels) {
    if (!labels.insert(level.label).second) v.fail("the value '" + level.label + "' is given twice");
    p.numeric = p.numeric && is_number(level.label);
  }
  return p;
}

}  // namespace

StudySpec parse_study(const std::string& text, const std::string& source_name) {
  Context ctx;
  ctx.file = source_name;
  ctx.folder = std::filesystem::path(source_name).parent_path();
  const YAML::Node doc = load_document(ctx, text, "study", "required key: scene");
  StudySpec s;
  s.path = source_name;
  s.text = text;
  const Map root = document_root(ctx, doc);
  root.check_known({"scene", "seeds", "parameters", "jobs", "threads", "output", "packings", "plots"});
  const Value scene = root.get("scene", "the base scene file, relative to the study file's folder");
  s.scene_path = study_relative(ctx, scene.string());
  if (auto v = root.find("seeds")) {
    s.seeds.clear();
    if (v->node().IsScalar()) {
      const std::uint64_t n = v->unsigned_integer();
      if (n < 1 || n > kMaxStudyRuns) v->fail("a count of seeds is 1 .. " + std::to_string(kMaxStudyRuns) + " (got " + std::to_string(n) + ")");
      for (std::uint64_t i = 1; i <= n; ++i) s.seeds.push_back(i);
    } else {
      std::set<std::uint64_t> seen;
      for (const Value& x : v->list()) {
        s.seeds.push_back(x.unsigned_integer());
        if (!seen.insert(s.seeds.back()).second) x.fail("the seed " + std::to_string(s.seeds.back()) + " is given twice");
      }
      if (s.seeds.empty()) v->fail("give at least one seed");
    }
  }
  std::size_t runs = s.seeds.size();
  if (auto v = root.find("parameters")) {
    std::set<std::string> names;
    for (const Value& x : v->list()) {
      s.parameters.push_back(parse_parameter(x, ctx));
      if (!names.insert(s.parameters.back().name).second) x.fail("a second parameter named '" + s.parameters.back().name + "'");
      runs *= s.parameters.back().levels.size();
      if (runs > kMaxStudyRuns) x.fail("the study would have more than " + std::to_string(kMaxStudyRuns) + " runs");
    }
  }
  if (auto v = root.find("threads")) {
    const std::uint64_t t = v->unsigned_integer();
    if (t < 1 || t > kMaxThreads) v->fail("must be 1 .. " + std::to_string(kMaxThreads));
    s.threads = static_cast<int>(t);
  }
  if (auto v = root.find("jobs")) {
    const std::uint64_t j = v->unsigned_integer();
    if (j < 1 || j > static_cast<std::uint64_t>(kMaxStudyJobs)) v->fail("must be 1 .. " + std::to_string(kMaxStudyJobs) + " (runs at once)");
    s.jobs = static_cast<int>(j);
  }
  if (auto v = root.find("output")) s.output_dir = study_relative(ctx, v->string());
  else s.output_dir = study_relative(ctx, std::filesystem::path(source_name).filename().replace_extension(".out").string());
  if (auto v = root.find("packings")) s.keep_packings = v->boolean();
  if (auto v = root.find("plots")) {
    for (const Value& x : v->list()) {
      const Map m = x.map();
      m.check_known({"x", "y"});
      StudyPlot p;
      const Value xv = m.get("x", "a parameter's name");
      p.x = xv.string();
      bool known = false;
      for (const auto& par : s.parameters) known = known || par.name == p.x;
      if (!known) xv.fail("'" + p.x + "' is not one of the study's parameters");
      p.y = m.get("y", "a column of the study's CSV, e.g. metrics.mean_coordination").string();
      s.plots.push_back(p);
    }
  }
  return s;
}

StudySpec load_study(const std::string& path) {
  return parse_study(read_document_file(path, "study", "experiments/2d-vs-3d/study.yaml", kMaxSceneBytes), path);
}

}  // namespace fp
