#include "core/io/scene_override.hpp"

#include <cctype>
#include <stdexcept>

#include "core/io/yaml_document.hpp"

namespace fp {
namespace {

/// One step of a dotted key: a name and the list indices after it ("particles[0]").
struct KeyStep {
  std::string name;
  std::vector<std::size_t> indices;
};

/// The steps of `key`; an empty vector when it is malformed.
std::vector<KeyStep> key_steps(const std::string& key) {
  std::vector<KeyStep> steps;
  std::size_t i = 0;
  while (i <= key.size()) {
    KeyStep step;
    while (i < key.size() && (std::isalnum(static_cast<unsigned char>(key[i])) || key[i] == '_')) step.name += key[i++];
    if (step.name.empty()) return {};
    while (i < key.size() && key[i] == '[') {
      const std::size_t close = key.find(']', i);
      if (close == std::string::npos || close == i + 1) return {};
      const std::string digits = key.substr(i + 1, close - i - 1);
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return {};
      step.indices.push_back(std::stoul(digits));
      i = close + 1;
    }
    steps.push_back(std::move(step));
    if (i == key.size()) break;
    if (key[i] != '.') return {};
    ++i;
    if (i == key.size()) return {};
  }
  return steps;
}

}  // namespace

bool is_scene_key(const std::string& key) { return !key_steps(key).empty(); }

SceneOverride scene_override_argument(const std::string& arg) {
  const std::size_t eq = arg.find('=');
  if (eq == std::string::npos)
    throw std::invalid_argument("--set " + excerpt(arg) + ": expected KEY=VALUE (a dotted scene key, e.g. packer.front=fifo)");
  SceneOverride o;
  o.key = arg.substr(0, eq);
  o.value = arg.substr(eq + 1);
  if (!is_scene_key(o.key)) throw std::invalid_argument("--set " + excerpt(arg) + ": '" + excerpt(o.key) + "' is not a scene key (" + kSceneKeyForm + ")");
  o.origin.file = "--set " + excerpt(arg);
  return o;
}

std::string describe_overrides(const std::vector<SceneOverride>& overrides) {
  std::string s;
  for (const auto& o : overrides) s += (s.empty() ? "" : ", ") + excerpt(o.key + "=" + o.value);
  return s;
}

bool override_covers(const std::string& override_key, const std::string& key) {
  if (key.compare(0, override_key.size(), override_key) != 0) return false;
  return key.size() == override_key.size() || key[override_key.size()] == '.' || key[override_key.size()] == '[';
}

namespace yaml_document {

void apply_overrides(YAML::Node& doc, const std::vector<SceneOverride>& overrides) {
  for (const auto& o : overrides) {
    const auto fail = [&](const std::string& message) -> void {
      throw SceneError(o.origin.file, o.origin.line, o.origin.column, o.key, message);
    };
    const std::vector<KeyStep> steps = key_steps(o.key);
    if (steps.empty()) fail(std::string("not a scene key (") + kSceneKeyForm + ")");
    YAML::Node value;
    try {
      std::vector<YAML::Node> docs = YAML::LoadAll(o.value);
      if (docs.size() > 1) fail("the value holds a second YAML document (after '---'): give one value");
      if (!docs.empty()) value = docs[0];
    } catch (const YAML::Exception& e) {
      fail("the value '" + excerpt(o.value) + "' is not YAML: " + e.msg);
    }
    if (!value.IsDefined() || value.IsNull()) fail("no value given (write KEY=VALUE)");
    if (!doc.IsMap()) fail("the scene is not a mapping of keys");
    // reset() moves the handle down the document; `=` on a handle would overwrite the node.
    YAML::Node node;
    node.reset(doc);
    std::string at;
    for (std::size_t s = 0; s < steps.size(); ++s) {
      const KeyStep& step = steps[s];
      if (!node.IsMap()) fail("'" + at + "' is not a mapping, so it has no key '" + step.name + "'");
      at += (at.empty() ? "" : ".") + step.name;
      const bool last = s + 1 == steps.size();
      if (last && step.indices.empty()) {
        node[step.name] = value;
        break;
      }
      if (!node[step.name]) {
        if (!step.indices.empty()) fail("'" + at + "' is not in the scene, so it has no item [" + std::to_string(step.indices[0]) + "]");
        node[step.name] = YAML::Node(YAML::NodeType::Map);
      }
      YAML::Node child = node[step.name];
      node.reset(child);
      for (std::size_t k = 0; k < step.indices.size(); ++k) {
        const std::size_t i = step.indices[k];
        if (!node.IsSequence() || i >= node.size())
          fail("'" + at + "' has no item [" + std::to_string(i) + "]" +
               (node.IsSequence() ? " (it has " + std::to_string(node.size()) + ")" : " (it is not a list)"));
        at += "[" + std::to_string(i) + "]";
        if (last && k + 1 == step.indices.size()) {
          node[i] = value;
        } else {
          YAML::Node item = node[i];
          node.reset(item);
        }
      }
    }
  }
}

}  // namespace yaml_document
}  // namespace fp
