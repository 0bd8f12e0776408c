#include "core/io/study_yaml.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <filesystem>
#include <set>

#include "core/io/document_file.hpp"
#include "core/io/study_expression.hpp"
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

/// One change a value makes: `scene` names another base scene, any other key is a --set.
void add_change(StudyLevel& level, const Context& ctx, const std::string& key, const Value& value) {
  if (key == "scene") level.scene_path = ctx.relative(value.string());
  else level.overrides.push_back(override_at(value, scene_key(value, key)));
}

bool is_identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

/// A plain scalar that reads as a finite number in full (a leading '+' allowed), else nothing.
std::optional<double> number_of(const YAML::Node& n) {
  if (!n.IsScalar() || n.Tag() == "!" || n.Scalar().empty()) return std::nullopt;
  const std::string& s = n.Scalar();
  const char* b = s.data() + (s[0] == '+' ? 1 : 0);
  double v = 0;
  const auto r = std::from_chars(b, s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

/// A scalar's text with the parameter's value put in: `$name` by the value's text, `${...}` by
/// the number it computes, `$$` by a dollar sign. `where` reports a problem.
std::string interpolate(const Value& where, const std::string& text, const std::string& name, const YAML::Node& value, int& uses) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] != '$') {
      out += text[i++];
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '$') {
      out += '$';
      i += 2;
    } else if (i + 1 < text.size() && text[i + 1] == '{') {
      const std::size_t close = text.find('}', i + 2);
      if (close == std::string::npos) where.fail("'${' without its '}' in '" + excerpt(text) + "'");
      const std::optional<double> x = number_of(value);
      if (!x) where.fail("${...} computes with a number; the value of " + name + " is " + shown(value));
      ++uses;
      try {
        out += shortest_number_text(evaluate_expression(std::string_view(text).substr(i + 2, close - i - 2), name, *x));
      } catch (const ExpressionError& e) {
        where.fail(std::string(e.what()));
      }
      i = close + 1;
    } else {
      std::size_t end = i + 1;
      while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
      const std::string word = text.substr(i + 1, end - i - 1);
      if (word.empty()) where.fail("a '$' starts $" + name + " or ${expression} (write $$ for a dollar sign) in '" + excerpt(text) + "'");
      if (word != name)
        where.fail("'$" + word + "' is not this parameter's value: a parameter's 'set' uses its own value, $" + name);
      if (!value.IsScalar()) where.fail("$" + name + " inside text needs a single value; the value is " + shown(value) + " (write $" + name + " alone to put it in whole)");
      out += value.Scalar();
      ++uses;
      i = end;
    }
  }
  return out;
}

/// `tmpl` with the parameter's value put in: a scalar that is exactly `$name` becomes the value
/// itself (a number, a name, a list); in other scalars, see `interpolate`. Counts the uses.
YAML::Node put_value(const Context& ctx, const Value& where, const YAML::Node& tmpl, const std::string& name, const YAML::Node& value, int& uses) {
  if (tmpl.IsScalar()) {
    const std::string& text = tmpl.Scalar();
    if (text.find('$') == std::string::npos) return YAML::Clone(tmpl);
    if (text == "$" + name) {
      ++uses;
      return YAML::Clone(value);
    }
    return YAML::Node(interpolate(Value(ctx, tmpl, where.path(), tmpl.Mark()), text, name, value, uses));
  }
  if (tmpl.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const auto& item : tmpl) out.push_back(put_value(ctx, where, item, name, value, uses));
    return out;
  }
  if (tmpl.IsMap()) {
    YAML::Node out(YAML::NodeType::Map);
    for (const auto& item : tmpl) out[item.first] = put_value(ctx, where, item.second, name, value, uses);
    return out;
  }
  return YAML::Clone(tmpl);
}

/// A value as it reads in a run's name: scalars as written, a list's items joined by '_'
/// ([1, 0.5, 0.5]: 1_0.5_0.5), a mapping's as key-value ({min: 1, max: 2}: min-1_max-2).
std::string name_part_of(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  std::string out;
  if (n.IsSequence())
    for (const auto& item : n) out += (out.empty() ? "" : "_") + name_part_of(item);
  else if (n.IsMap())
    for (const auto& item : n) out += (out.empty() ? "" : "_") + item.first.Scalar() + "-" + name_part_of(item.second);
  return out;
}

/// The plots' axis for `values`: the numbers themselves; for lists of numbers of one length, the
/// entries that vary when they vary together ([1, 0.5, 0.5], [1, 0.7, 0.7]: 0.5, 0.7, labelled
/// "[1, x, x]"). Empty when the values have no such number, or two share one.
std::vector<double> numeric_axis(const std::vector<YAML::Node>& values, std::string& form) {
  std::vector<double> axis;
  form.clear();
  if (std::all_of(values.begin(), values.end(), [](const YAML::Node& n) { return number_of(n).has_value(); })) {
    for (const auto& n : values) axis.push_back(*number_of(n));
  } else {
    const std::size_t size = values.front().IsSequence() ? values.front().size() : 0;
    std::vector<std::vector<double>> rows;
    for (const auto& n : values) {
      if (!n.IsSequence() || n.size() != size || size == 0) return {};
      std::vector<double> row;
      for (const auto& item : n) {
        const auto x = number_of(item);
        if (!x) return {};
        row.push_back(*x);
      }
      rows.push_back(std::move(row));
    }
    std::vector<bool> varies(size, false);
    for (const auto& row : rows)
      for (std::size_t k = 0; k < size; ++k) varies[k] = varies[k] || row[k] != rows.front()[k];
    form = "[";
    for (std::size_t k = 0; k < size; ++k)
      form += (k ? ", " : "") + (varies[k] ? std::string("x") : values.front()[k].Scalar());
    form += "]";
    for (const auto& row : rows) {
      std::optional<double> x;
      for (std::size_t k = 0; k < size; ++k)
        if (varies[k]) {
          if (x && *x != row[k]) return {};
          x = row[k];
        }
      if (!x) return {};
      axis.push_back(*x);
    }
  }
  std::vector<double> sorted = axis;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};
  return axis;
}

/// The last part of a dotted key, without its index: particles[0].aspect_ratio -> aspect_ratio.
std::string last_key_part(const std::string& key) {
  std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  if (const auto bracket = last.find('['); bracket != std::string::npos) last = last.substr(0, bracket);
  return last.empty() ? key : last;
}

StudyParameter parse_parameter(const Value& v, const Context& ctx) {
  const Map m = v.map();
  m.check_known({"key", "values", "name", "cases", "set"});
  StudyParameter p;
  p.spot = v.spot();
  std::vector<YAML::Node> values;
  if (m.has("cases")) {
    if (m.has("key") || m.has("values") || m.has("set"))
      m.fail("give either 'key' and 'values' (one key swept), 'name', 'values' and 'set' (a value put into keys) or "
             "'name' and 'cases' (several keys at once)");
    p.name = m.get("name", "the parameter's name: its CSV column").string();
    p.name_part = p.name;
    const Map cases = m.get("cases").map();
    for (const std::string& label : cases.keys()) {
      StudyLevel level;
      level.label = label;
      level.name_part = label;
      const Map changes = cases.get(label).map();
      for (const std::string& key : changes.keys()) add_change(level, ctx, key, *changes.find(key));
      if (level.overrides.empty() && level.scene_path.empty()) cases.get(label).fail("a case changes at least one key");
      p.levels.push_back(std::move(level));
    }
    if (p.levels.empty()) m.get("cases").fail("give at least one case");
  } else {
    std::string key;
    if (m.has("set")) {
      if (m.has("key")) m.fail("give 'key' (the key takes the values) or 'set' (keys computed from the value), not both");
      const Value name = m.get("name", "the parameter's name: $name in 'set', its CSV column");
      p.name = name.string();
      if (!is_identifier(p.name)) name.fail("a parameter with 'set' is named as $name is written: letters, digits and _ (got '" + excerpt(p.name) + "')");
      p.name_part = p.name;
    } else {
      const Value key_value = m.get("key", "the dotted scene key swept (or 'name', 'values' and 'set'; or 'name' and 'cases')");
      key = scene_key(key_value, key_value.string());
      p.name = m.has("name") ? m.get("name").string() : key;
      p.name_part = m.has("name") ? p.name : last_key_part(key);
    }
    const auto listed = m.get("values", "the values the parameter takes").list();
    if (listed.empty()) m.get("values").fail("give at least one value");
    for (const Value& x : listed) {
      if (!x.node().IsDefined() || x.node().IsNull()) x.fail("a value is missing");
      StudyLevel level;
      level.label = flow_text(x.node());
      level.name_part = name_part_of(x.node());
      if (key.empty()) {
        const Map set = m.get("set").map();
        int uses = 0;
        for (const std::string& k : set.keys()) {
          const Value tmpl = *set.find(k);
          const Value bound(ctx, put_value(ctx, tmpl, tmpl.node(), p.name, x.node(), uses), tmpl.path(), tmpl.mark());
          add_change(level, ctx, k, bound);
        }
        if (set.keys().empty()) m.get("set").fail("give at least one key to set");
        if (uses == 0) m.get("set").fail("no value of 'set' uses $" + p.name + ": every value of the parameter would make the same runs");
      } else {
        add_change(level, ctx, key, x);
      }
      values.push_back(x.node());
      p.levels.push_back(std::move(level));
    }
  }
  if (p.name.empty() || p.name.find_first_of(",\"\n") != std::string::npos || p.name == "seed" || p.name == "run")
    v.fail("the parameter's name '" + p.name + "' must be a plain CSV column name (not seed, run; no comma or quote)");
  std::set<std::string> labels;
  for (const auto& level : p.levels)
    if (!labels.insert(level.label).second) v.fail("the value '" + level.label + "' is given twice");
  std::string form;
  if (!values.empty()) p.axis = numeric_axis(values, form);
  p.numeric = !p.axis.empty();
  p.axis_label = form.empty() ? p.name : p.name + " " + form;
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
  s.scene_path = ctx.relative(scene.string());
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
    // Two keys ending alike (particles[0].radius.max, packer.max) are told apart by their whole keys in run names.
    std::vector<bool> shared(s.parameters.size(), false);
    for (std::size_t a = 0; a < s.parameters.size(); ++a)
      for (std::size_t b = 0; b < s.parameters.size(); ++b)
        shared[a] = shared[a] || (a != b && s.parameters[a].name_part == s.parameters[b].name_part);
    for (std::size_t a = 0; a < s.parameters.size(); ++a)
      if (shared[a]) s.parameters[a].name_part = s.parameters[a].name;
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
  if (auto v = root.find("output")) s.output_dir = ctx.relative(v->string());
  else s.output_dir = ctx.relative(std::filesystem::path(source_name).filename().replace_extension(".out").string());
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
