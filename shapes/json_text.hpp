#pragma once
// Text pieces of Shape::definition_json(): numbers with 17 significant digits (they read back to
// the same double) and lists of points.
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

inline std::string json_number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

template <int D>
std::string json_point(const Vec<D>& p) {
  std::string s = "[";
  for (int i = 0; i < D; ++i) s += (i ? ", " : "") + json_number(p[i]);
  return s + "]";
}

template <class Range, class Item>
std::string json_list(const Range& items, Item item) {
  std::string s = "[";
  bool first = true;
  for (const auto& x : items) {
    s += (first ? "" : ", ") + item(x);
    first = false;
  }
  return s + "]";
}

}  // namespace fp
