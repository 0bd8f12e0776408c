#include "shapes/regular_polytopes.hpp"

#include <cmath>

namespace fp {

std::vector<Vec2> regular_polygon(int sides) {
  std::vector<Vec2> v;
  for (int k = 0; k < sides; ++k) {
    const double t = -0.5 * kPi + kPi / sides + 2 * kPi * k / sides;
    v.emplace_back(std::cos(t), std::sin(t));
  }
  return v;
}

std::vector<Vec3> platonic_solid(int faces) {
  const double phi = 0.5 * (1 + std::sqrt(5.0));
  std::vector<Vec3> v;
  auto cyclic = [&](double x, double y, double z) {  // (x, y, z) and its two cyclic permutations
    v.emplace_back(x, y, z);
    v.emplace_back(z, x, y);
    v.emplace_back(y, z, x);
  };
  switch (faces) {
    case 4:
      v = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
      break;
    case 6:
      for (int s = 0; s < 8; ++s) v.emplace_back(s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1);
      break;
    case 8:
      for (int s : {-1, 1}) cyclic(s, 0, 0);
      break;
    case 12:
      for (int s = 0; s < 8; ++s) v.emplace_back(s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1);
      for (int a : {-1, 1})
        for (int b : {-1, 1}) cyclic(0, a / phi, b * phi);
      break;
    case 20:
      for (int a : {-1, 1})
        for (int b : {-1, 1}) cyclic(0, a, b * phi);
      break;
    default:
      return {};
  }
  for (Vec3& p : v) p.normalize();
  return v;
}

}  // namespace fp
