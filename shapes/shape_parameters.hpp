#pragma once
// Typed, checked access to a family's parameters: every error is a SceneError naming the file,
// line and key where the parameter was (or should have been) written.
#include <string>
#include <vector>

#include "core/io/scene.hpp"

namespace fp {

class ParameterReader {
 public:
  explicit ParameterReader(const ShapeParameters& p) : p_(p) {}

  /// Required number; `what` explains it in the error when it is missing.
  double number(const std::string& key, const std::string& what) const;
  double number_or(const std::string& key, double fallback) const;
  /// A number in (lo, hi] (or [lo, hi] with closed_lo).
  double number_in(const std::string& key, const std::string& what, double lo, double hi, bool closed_lo = false) const;
  std::vector<double> list(const std::string& key, const std::string& what) const;
  /// A list of points of dimension `dim`.
  std::vector<std::vector<double>> points(const std::string& key, const std::string& what, int dim) const;
  /// Required word (e.g. `preset: cube`).
  std::string word(const std::string& key, const std::string& what) const;
  bool has(const std::string& key) const;
  /// Rejects keys not in `known` (with the family's name in the message).
  void check_known(const std::vector<std::string>& known, const std::string& family) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const ShapeParameters& p_;
};

/// An elongated family's width over its total length, from `elongation` (total length / width:
/// above 1 a rod, below 1 a disc, as the DEM literature's aspect ratio L/D) or from the older key
/// `aspect_ratio` (its inverse, width / total length), kept as an alias; one of the two.
/// `length` and `width` name the family's own (e.g. "height", "diameter"); `rod_only`: its length
/// is never below its width (a capsule: elongation >= 1, 1 a sphere).
double width_over_length(const ParameterReader& r, const std::string& length, const std::string& width, bool rod_only);

}  // namespace fp
