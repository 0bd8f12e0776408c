#pragma once
// The YAML documents frontpack reads (scenes, studies) as checked values: every value knows its
// dotted key and where it was written, every mapping checks its keys (unknown, duplicate, not
// used), and every problem is a SceneError naming the file, line, column and key. Only the
// readers of fp_io include this (yaml-cpp is private to fp_io).
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/scene.hpp"
#include "core/io/scene_error.hpp"
#include "core/io/scene_override.hpp"
#include "core/io/text_excerpt.hpp"

namespace fp::yaml_document {

using Keys = std::vector<std::string>;

inline std::string join(const Keys& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// Edit distance, for "did you mean" hints on misspelt keys and values.
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

inline std::string suggestion(const std::string& word, const Keys& allowed) {
  std::size_t best = std::numeric_limits<std::size_t>::max();
  std::string best_word;
  for (const auto& a : allowed) {
    const std::size_t d = edit_distance(word, a);
    if (d < best) {
      best = d;
      best_word = a;
    }
  }
  return best <= std::max<std::size_t>(1, std::min<std::size_t>(3, word.size() / 3)) ? " (did you mean '" + best_word + "'?)" : "";
}

inline bool contains(const Keys& keys, const std::string& k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); }

inline std::string shown(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return n.Tag() == "!" ? "the string \"" + excerpt(n.Scalar()) + "\"" : "'" + excerpt(n.Scalar()) + "'";
  if (n.IsSequence()) return "a list";
  return "a mapping";
}

struct Context {
  std::string file;
  std::filesystem::path folder;  // of the file: its relative paths start here (relative())
  std::vector<std::string>* read_files = nullptr;  // Scene::read_files: the mesh is added
  std::shared_ptr<const TetMesh>* tet_mesh = nullptr;  // Scene::tet_mesh: set by a .msh container

  const std::vector<SceneOverride>* overrides = nullptr;  // applied to the document before it is read

  /// A path written in the document: relative to its file's folder, as every path in a file is,
  /// so that it names the same file from whatever folder frontpack runs.
  std::string relative(const std::string& name) const {
    const std::filesystem::path p(name);
    return (p.is_absolute() ? p : folder / p).lexically_normal().string();
  }

  /// Where the value at `key`, written at `m`, was given: the override that set it, else the file.
  SourceSpot locate(const YAML::Mark& m, const std::string& key) const {
    if (overrides)
      for (auto o = overrides->rbegin(); o != overrides->rend(); ++o)
        if (override_covers(o->key, key)) {
          SourceSpot s = o->origin;
          s.key = key;
          return s;
        }
    const bool known = !m.is_null() && m.line >= 0;
    return SourceSpot{file, known ? m.line + 1 : 0, known ? m.column + 1 : 0, key};
  }

  [[noreturn]] void fail(const YAML::Mark& m, const std::string& key, const std::string& message) const {
    const SourceSpot s = locate(m, key);
    // A problem in the file may come from a change (dimension: 2 and a 3D box): say which.
    const bool changed = overrides && !overrides->empty() && s.file == file;
    throw SceneError(s.file, s.line, s.column, key,
                     changed ? message + " (in the scene as changed by " + describe_overrides(*overrides) + ")" : message);
  }
};

/// Where a document starts (line 1, column 1), for what is reported about it as a whole.
inline YAML::Mark document_start() {
  YAML::Mark start;
  start.line = 0;
  start.column = 0;
  return start;
}

/// The document of `text` (a scene, a study), read for `ctx`: a syntax error, running out of
/// memory and an empty document (`empty`: what it lacks) are SceneErrors at their place.
inline YAML::Node load_document(const Context& ctx, const std::string& text, const std::string& what, const std::string& empty) {
  YAML::Node doc;
  try {
    // Every document, so that a second one (after '---') is refused rather than ignored.
    std::vector<YAML::Node> docs = YAML::LoadAll(text);
    if (docs.size() > 1)
      ctx.fail(docs[1].Mark(), "", "a second YAML document (after '---'): the " + what + " file holds one document; "
               "remove the '---' line and what follows it, or merge it into the first");
    if (!docs.empty()) doc = docs[0];
  } catch (const YAML::Exception& e) {
    ctx.fail(e.mark, "", "YAML syntax error: " + e.msg);
  } catch (const std::bad_alloc&) {
    throw SceneError(ctx.file, 0, 0, "", "out of memory while reading the " + what + " file");
  }
  if (!doc.IsDefined() || doc.IsNull()) ctx.fail(document_start(), "", "the " + what + " is empty (" + empty + ")");
  return doc;
}

/// Applies `overrides` to `doc` in order (cli/core/io/scene_override.hpp); throws SceneError at the
/// override's origin when its key or value is not usable.
void apply_overrides(YAML::Node& doc, const std::vector<SceneOverride>& overrides);

class Map;

// One value of the document with its dotted path and a position to report.
class Value {
 public:
  Value(const Context& ctx, YAML::Node node, std::string path, YAML::Mark mark)
      : ctx_(&ctx), node_(std::move(node)), path_(std::move(path)), mark_(mark) {}

  const std::string& path() const { return path_; }
  const YAML::Mark& mark() const { return mark_; }
  const YAML::Node& node() const { return node_; }
  [[noreturn]] void fail(const std::string& message) const { ctx_->fail(mark_, path_, message); }
  /// Where this value was written, for errors raised after parsing (shapes/).
  SourceSpot spot() const { return ctx_->locate(mark_, path_); }

  double number() const {
    if (!node_.IsScalar() || node_.Tag() == "!") fail("expected a number, got " + shown(node_));
    std::string_view s = node_.Scalar();
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
      if (res.ec == std::errc::result_out_of_range) fail("number out of range (got " + excerpt(node_.Scalar()) + ")");
      fail("expected a number, got " + shown(node_));
    }
    if (!std::isfinite(v)) fail("must be a finite number (got " + excerpt(node_.Scalar()) + ")");
    return v;
  }
  double positive() const {
    const double v = number();
    if (!(v > 0)) fail("must be positive (got " + excerpt(node_.Scalar()) + ")");
    return v;
  }
  /// Non-negative integer. With `float_notation`, "1e6" or "1000.0" are accepted when exact.
  std::uint64_t unsigned_integer(bool float_notation = false) const {
    if (!node_.IsScalar() || node_.Tag() == "!") fail("expected a non-negative integer, got " + shown(node_));
    std::string_view s = node_.Scalar();
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    std::uint64_t v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (!s.empty() && res.ec == std::errc() && res.ptr == s.data() + s.size()) return v;
    if (res.ec == std::errc::result_out_of_range) fail("integer out of range 0 .. 2^64-1 (got " + excerpt(node_.Scalar()) + ")");
    if (float_notation) {
      const double d = number();
      if (d >= 0 && d < 0x1.0p53 && d == std::floor(d)) return static_cast<std::uint64_t>(d);
    }
    fail("expected a non-negative integer, got " + shown(node_));
  }
  bool boolean() const {
    bool b = false;
    if (!node_.IsScalar() || !YAML::convert<bool>::decode(node_, b)) fail("expected true or false, got " + shown(node_));
    return b;
  }
  std::string string() const {
    if (!node_.IsScalar()) fail("expected a string, got " + shown(node_));
    return node_.Scalar();
  }
  /// One of `allowed`.
  std::string choice(const Keys& allowed) const {
    if (!node_.IsScalar()) fail("expected one of " + join(allowed) + ", got " + shown(node_));
    const std::string s = node_.Scalar();
    if (!contains(allowed, s)) fail("unknown value '" + s + "'" + suggestion(s, allowed) + "; allowed: " + join(allowed));
    return s;
  }
  std::vector<Value> list() const {
    if (!node_.IsSequence()) fail("expected a list, got " + shown(node_));
    std::vector<Value> out;
    std::size_t i = 0;
    for (const auto& item : node_) {
      const YAML::Mark m = item.Mark().is_null() ? mark_ : item.Mark();
      out.emplace_back(*ctx_, item, path_ + "[" + std::to_string(i++) + "]", m);
    }
    return out;
  }
  std::vector<double> numbers(std::optional<std::size_t> count = std::nullopt) const {
    const auto items = list();
    if (count && items.size() != *count)
      fail("expected " + std::to_string(*count) + " numbers, got " + std::to_string(items.size()));
    std::vector<double> out;
    for (const auto& v : items) out.push_back(v.number());
    return out;
  }
  template <int D>
  Vec<D> vec(const std::string& what_dimension) const {
    const auto items = list();
    if (items.size() != static_cast<std::size_t>(D))
      fail("must have " + std::to_string(D) + " components (" + what_dimension + "), got " + std::to_string(items.size()));
    Vec<D> v;
    for (int k = 0; k < D; ++k) v[k] = items[static_cast<std::size_t>(k)].number();
    return v;
  }
  /// [[a, b], ...] as pairs.
  std::vector<std::pair<double, double>> pairs(const std::string& shape) const {
    std::vector<std::pair<double, double>> out;
    for (const auto& item : list()) {
      if (!item.node().IsSequence() || item.node().size() != 2) item.fail("expected a pair " + shape + ", got " + shown(item.node()));
      const auto ab = item.list();
      out.emplace_back(ab[0].number(), ab[1].number());
    }
    return out;
  }
  Map map() const;

 private:
  const Context* ctx_;
  YAML::Node node_;
  std::string path_;
  YAML::Mark mark_;
};

// A mapping of the document: checks its keys (unknown, duplicate, not used) and hands out
// values with their paths.
class Map {
 public:
  Map(const Context& ctx, const YAML::Node& node, std::string path, YAML::Mark mark)
      : ctx_(&ctx), path_(std::move(path)), mark_(mark) {
    if (!node.IsMap()) ctx.fail(mark_, path_, "expected a mapping (key: value lines), got " + shown(node));
    for (const auto& kv : node) {  // kv is a temporary pair of node handles: copy them
      const YAML::Node key = kv.first;
      const YAML::Mark key_mark = key.Mark();
      if (!key.IsScalar()) ctx.fail(key_mark, path_, "keys must be plain names");
      const std::string name = key.Scalar();
      for (const auto& e : entries_)
        if (e.name == name)
          ctx.fail(key_mark, child_path(name),
                   "duplicate key (first given on line " + std::to_string(e.key_mark.line + 1) + ")");
      // A null value's mark points past the key; report such values at their key.
      const YAML::Node value = kv.second;
      const YAML::Mark value_mark = value.IsNull() || value.Mark().is_null() ? key_mark : value.Mark();
      entries_.push_back({name, key_mark, Value(ctx, value, child_path(name), value_mark)});
    }
  }

  const std::string& path() const { return path_; }
  const YAML::Mark& mark() const { return mark_; }

  /// Every key must be in `allowed`.
  void check_known(const Keys& allowed) const {
    for (const auto& e : entries_)
      if (!contains(allowed, e.name))
        ctx_->fail(e.key_mark, child_path(e.name),
                   "unknown key" + suggestion(e.name, allowed) + "; allowed keys " +
                       (path_.empty() ? "at the top level" : "in '" + path_ + "'") + ": " + join(allowed));
  }
  /// Every key must be in `used` (keys known in general but not used by this kind).
  void check_used(const Keys& used, const std::string& by_what) const {
    for (const auto& e : entries_)
      if (!contains(used, e.name))
        ctx_->fail(e.key_mark, child_path(e.name), "not used by " + by_what + " (its keys: " + join(used) + ")");
  }

  bool has(const std::string& key) const { return find(key).has_value(); }
  /// The keys in the order they were written.
  Keys keys() const {
    Keys out;
    for (const auto& e : entries_) out.push_back(e.name);
    return out;
  }
  std::optional<Value> find(const std::string& key) const {
    for (const auto& e : entries_)
      if (e.name == key) return e.value;
    return std::nullopt;
  }
  Value get(const std::string& key, const std::string& hint = "") const {
    if (auto v = find(key)) return *v;
    ctx_->fail(mark_, child_path(key), "missing required key" + (hint.empty() ? "" : " (" + hint + ")"));
  }
  [[noreturn]] void fail(const std::string& message) const { ctx_->fail(mark_, path_, message); }

 private:
  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  struct Entry {
    std::string name;
    YAML::Mark key_mark;
    Value value;
  };
  const Context* ctx_;
  std::string path_;
  YAML::Mark mark_;
  std::vector<Entry> entries_;
};

inline Map Value::map() const { return Map(*ctx_, node_, path_, mark_); }

/// The root mapping of a loaded document.
inline Map document_root(const Context& ctx, const YAML::Node& doc) {
  return Map(ctx, doc, "", doc.Mark().is_null() ? document_start() : doc.Mark());
}

}  // namespace fp::yaml_document
