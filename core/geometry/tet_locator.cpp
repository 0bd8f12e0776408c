#include "core/geometry/tet_locator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace fp {

TetLocator::TetLocator(const TetMesh& mesh) : mesh_(mesh) {
  if (mesh.tets.empty()) return;
  Aabb<3> box;
  for (const Vec3& p : mesh.nodes) box.extend(p);
  double edges = 0;
  for (const auto& t : mesh.tets) edges += (mesh.nodes[t[1]] - mesh.nodes[t[0]]).norm();
  lo_ = box.lo;
  const Vec3 size = box.size();
  cell_ = std::max(edges / static_cast<double>(mesh.tets.size()), 1e-300);
  // At most about 8 cells per tetrahedron: a mesh of very uneven sizes gets coarser cells.
  while ((size / cell_).prod() > 8.0 * static_cast<double>(mesh.tets.size()) + 64) cell_ *= 1.26;
  for (int a = 0; a < 3; ++a) n_[static_cast<std::size_t>(a)] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(size[a] / cell_)));
  const auto cell_range = [&](const std::array<std::uint32_t, 4>& t, std::array<std::int64_t, 3>& from, std::array<std::int64_t, 3>& to) {
    for (int a = 0; a < 3; ++a) {
      double l = mesh.nodes[t[0]][a], h = l;
      for (const std::uint32_t v : t) l = std::min(l, mesh.nodes[v][a]), h = std::max(h, mesh.nodes[v][a]);
      const auto k = static_cast<std::size_t>(a);
      from[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((l - lo_[a]) / cell_)), 0, n_[k] - 1);
      to[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((h - lo_[a]) / cell_)), 0, n_[k] - 1);
    }
  };
  const auto index = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    return static_cast<std::size_t>(x + n_[0] * (y + n_[1] * z));
  };
  std::vector<std::uint32_t> count(static_cast<std::size_t>(n_[0] * n_[1] * n_[2]) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i = 0; i < mesh.tets.size(); ++i) {
      std::array<std::int64_t, 3> from{}, to{};
      cell_range(mesh.tets[i], from, to);
      for (std::int64_t z = from[2]; z <= to[2]; ++z)
        for (std::int64_t y = from[1]; y <= to[1]; ++y)
          for (std::int64_t x = from[0]; x <= to[0]; ++x) {
            if (pass == 0) ++count[index(x, y, z) + 1];
            else tets_[start_[index(x, y, z)] + count[index(x, y, z)]++] = i;
          }
    }
    if (pass == 0) {
      start_.assign(count.size(), 0);
      for (std::size_t c = 1; c < count.size(); ++c) start_[c] = start_[c - 1] + count[c];
      tets_.resize(start_.back());
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

int TetLocator::tet_at(const Vec3& p) const {
  if (mesh_.tets.empty()) return -1;
  std::array<std::int64_t, 3> c{};
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((p[a] - lo_[a]) / cell_);
    const auto k = static_cast<std::size_t>(a);
    if (!(f >= -1 && f <= static_cast<double>(n_[k]))) return -1;
    c[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(f), 0, n_[k] - 1);
  }
  const std::size_t cell = static_cast<std::size_t>(c[0] + n_[0] * (c[1] + n_[1] * c[2]));
  for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
    const auto& t = mesh_.tets[tets_[k]];
    const Vec3 &a = mesh_.nodes[t[0]];
    Eigen::Matrix3d M;
    M << mesh_.nodes[t[1]] - a, mesh_.nodes[t[2]] - a, mesh_.nodes[t[3]] - a;
    const Vec3 w = M.partialPivLu().solve(p - a);
    const double slack = 1e-12;
    if (w.minCoeff() >= -slack && w.sum() <= 1 + slack) return static_cast<int>(tets_[k]);
  }
  return -1;
}

}  // namespace fp
