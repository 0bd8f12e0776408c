#pragma once
// The error of a bad scene file: always says where (file, line, column) and which key
// (dotted path, e.g. "container.radius" or "output[1].format").
//   what() == "scene.yaml:7:11: key 'container.radius': must be positive (got -1)"
#include <stdexcept>
#include <string>

namespace fp {

class SceneError : public std::runtime_error {
 public:
  /// line/column are 1-based; 0 when unknown (e.g. the file cannot be read). key may be empty
  /// (YAML syntax errors).
  SceneError(std::string file, int line, int column, std::string key, std::string message)
      : std::runtime_error(compose(file, line, column, key, message)),
        file_(std::move(file)), line_(line), column_(column), key_(std::move(key)), message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& key() const { return key_; }
  /// The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  static std::string compose(const std::string& file, int line, int column, const std::string& key,
                             const std::string& message) {
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
    s += ": ";
    if (!key.empty()) s += "key '" + key + "': ";
    return s + message;
  }

  std::string file_;
  int line_;
  int column_;
  std::string key_;
  std::string message_;
};

}  // namespace fp
