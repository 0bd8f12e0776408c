#include "core/io/container_vtu.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/bed_region.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/vtu_appended.hpp"

namespace fp {
namespace {

constexpr double kTwoPi = 6.283185307179586;

/// A boundary in the local frame: points and cells (3D: triangles, wound with their normals
/// outwards for the shapes made here; 2D: one closed loop of all the points, in order).
struct Boundary {
  std::vector<Vec3> points;
  std::vector<std::array<std::int64_t, 3>> triangles;
};

std::int64_t add(Boundary& b, const Vec3& p) {
  b.points.push_back(p);
  return static_cast<std::int64_t>(b.points.size()) - 1;
}
void quad(Boundary& b, std::int64_t p, std::int64_t q, std::int64_t r, std::int64_t s) {
  b.triangles.push_back({p, q, r});
  b.triangles.push_back({p, r, s});
}

Boundary box_faces(const Vec3& lo, const Vec3& hi) {
  Boundary b;
  for (int corner = 0; corner < 8; ++corner)
    add(b, Vec3(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z()));
  for (int a = 0; a < 3; ++a) {
    const int u = 1 << ((a + 1) % 3), v = 1 << ((a + 2) % 3);
    quad(b, 0, v, u | v, u);  // the low face, wound so that its normal points out (-a)
    const int hi = 1 << a;
    quad(b, hi, hi | u, hi | u | v, hi | v);
  }
  return b;
}

Boundary sphere_surface(const Vec3& centre, double radius) {
  Boundary b;
  const int around = kContainerSegments, rings = kContainerSegments / 2;
  const std::int64_t south = add(b, centre - radius * Vec3::UnitZ());
  for (int j = 1; j < rings; ++j) {
    const double theta = -0.5 * kTwoPi / 2 + j * (kTwoPi / 2) / rings;  // latitude
    for (int k = 0; k < around; ++k) {
      const double phi = k * kTwoPi / around;
      add(b, centre + radius * Vec3(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)));
    }
  }
  const std::int64_t north = add(b, centre + radius * Vec3::UnitZ());
  const auto at = [&](int ring, int k) { return 1 + static_cast<std::int64_t>((ring - 1) * around + k % around); };
  for (int k = 0; k < around; ++k) {
    b.triangles.push_back({south, at(1, k + 1), at(1, k)});
    b.triangles.push_back({north, at(rings - 1, k), at(rings - 1, k + 1)});
    for (int j = 1; j + 1 < rings; ++j) quad(b, at(j, k), at(j, k + 1), at(j + 1, k + 1), at(j + 1, k));
  }
  return b;
}

Boundary cylinder_surface(const CylinderContainer& c) {
  Boundary b;
  const int around = kContainerSegments;
  const Vec3 e1 = c.axis().unitOrthogonal(), e2 = c.axis().cross(e1);  // e1 x e2 = axis
  const Vec3 top = c.base_center() + c.height() * c.axis();
  for (const Vec3& cap : {c.base_center(), top})
    for (int k = 0; k < around; ++k) {
      const double phi = k * kTwoPi / around;
      add(b, cap + c.radius() * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  const std::int64_t bottom_centre = add(b, c.base_center()), top_centre = add(b, top);
  for (int k = 0; k < around; ++k) {
    const std::int64_t k0 = k, k1 = (k + 1) % around;
    quad(b, k0, k1, around + k1, around + k0);
    b.triangles.push_back({bottom_centre, k1, k0});
    b.triangles.push_back({top_centre, around + k0, around + k1});
  }
  return b;
}

Boundary boundary_of(const Container<3>& c) {
  if (const auto* bed = dynamic_cast<const BedRegion<3>*>(&c)) {  // the walls below the level; open above, over the particles
    const Boundary whole = boundary_of(bed->base());
    Boundary b;
    for (const auto& t : whole.triangles) {
      const std::vector<Vec3> cut = clip_below<3>({whole.points[static_cast<std::size_t>(t[0])], whole.points[static_cast<std::size_t>(t[1])],
                                                   whole.points[static_cast<std::size_t>(t[2])]},
                                                  bed->up(), bed->level());
      if (cut.size() < 3) continue;
      const std::int64_t first = add(b, cut[0]);
      for (std::size_t k = 1; k < cut.size(); ++k) add(b, cut[k]);
      for (std::size_t k = 1; k + 1 < cut.size(); ++k)
        b.triangles.push_back({first, first + static_cast<std::int64_t>(k), first + static_cast<std::int64_t>(k + 1)});
    }
    return b;
  }
  if (const auto* box = dynamic_cast<const BoxContainer<3>*>(&c)) return box_faces(box->lo(), box->hi());
  if (const auto* ball = dynamic_cast<const BallContainer<3>*>(&c)) return sphere_surface(ball->center(), ball->radius());
  if (const auto* cyl = dynamic_cast<const CylinderContainer*>(&c)) return cylinder_surface(*cyl);
  if (const auto* mesh = dynamic_cast<const MeshContainer*>(&c)) {
    Boundary b;
    b.points = mesh->vertices();
    for (const auto& t : mesh->triangles()) b.triangles.push_back({t[0], t[1], t[2]});
    return b;
  }
  throw std::logic_error("write_container_vtu: no boundary picture for container " + c.describe());
}

Boundary boundary_of(const Container<2>& c) {
  Boundary b;
  const auto in_plane = [&](const Vec2& p) { add(b, Vec3(p.x(), p.y(), 0)); };
  if (const auto* bed = dynamic_cast<const BedRegion<2>*>(&c)) {  // the outline closed by the level's line
    std::vector<Vec2> whole;
    for (const Vec3& p : boundary_of(bed->base()).points) whole.emplace_back(p.x(), p.y());
    for (const Vec2& p : clip_below<2>(whole, bed->up(), bed->level())) in_plane(p);
    return b;
  }
  if (const auto* box = dynamic_cast<const BoxContainer<2>*>(&c)) {
    const Vec2 lo = box->lo(), hi = box->hi();
    for (const Vec2& p : {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())}) in_plane(p);
  } else if (const auto* disk = dynamic_cast<const BallContainer<2>*>(&c)) {
    for (int k = 0; k < kContainerSegments; ++k) {
      const double phi = k * kTwoPi / kContainerSegments;
      in_plane(disk->center() + disk->radius() * Vec2(std::cos(phi), std::sin(phi)));
    }
  } else if (const auto* polygon = dynamic_cast<const PolygonContainer*>(&c)) {
    for (const Vec2& p : polygon->vertices()) in_plane(p);
  } else {
    throw std::logic_error("write_container_vtu: no boundary picture for container " + c.describe());
  }
  return b;
}

template <int D>
void write_vtu(std::ostream& out, const std::string& path, const Boundary& b, const Vec<D>& origin) {
  using S = VtuArray;
  const std::uint64_t n = b.points.size();
  const Vec3 shift = D == 3 ? Vec3(origin[0], origin[1], origin[D - 1]) : Vec3(origin[0], origin[1], 0);
  // 3D: the triangles; 2D: one closed polyline through every point.
  const std::uint64_t cells = D == 3 ? b.triangles.size() : 1;
  const std::uint64_t connectivity = D == 3 ? 3 * cells : n + 1;
  std::vector<VtuArray> a;
  a.push_back({S::Points, "Float64", "Points", 3, 3 * n, 8, [&b, shift](VtuRawOut& o) {
                 for (const Vec3& p : b.points) o.put3(shift + p);
               }});
  a.push_back({S::Cells, "Int64", "connectivity", 1, connectivity, 8, [&b, n](VtuRawOut& o) {
                 if (D == 3) {
                   for (const auto& t : b.triangles)
                     for (const std::int64_t k : t) o.put<std::int64_t>(k);
                 } else {
                   for (std::uint64_t k = 0; k <= n; ++k) o.put<std::int64_t>(static_cast<std::int64_t>(k % n));
                 }
               }});
  a.push_back({S::Cells, "Int64", "offsets", 1, cells, 8, [cells, connectivity](VtuRawOut& o) {
                 for (std::uint64_t c = 1; c <= cells; ++c)
                   o.put<std::int64_t>(static_cast<std::int64_t>(D == 3 ? 3 * c : connectivity));
               }});
  a.push_back({S::Cells, "UInt8", "types", 1, cells, 1, [cells](VtuRawOut& o) {
                 for (std::uint64_t c = 0; c < cells; ++c) o.put<std::uint8_t>(D == 3 ? kVtkTriangle : kVtkPolyLine);
               }});
  write_vtu_appended(out, path, n, cells, "", a);
}

}  // namespace

std::string container_vtu_path(const std::string& vtu_path) {
  std::filesystem::path p(vtu_path);
  p.replace_extension(".container.vtu");
  return p.string();
}

template <int D>
void write_container_vtu(const std::string& path, const Container<D>& container) {
  const Boundary b = boundary_of(container);
  AtomicFile file(path);
  write_vtu<D>(file.stream(), path, b, container.origin());
  file.commit();
}

template void write_container_vtu<2>(const std::string&, const Container<2>&);
template void write_container_vtu<3>(const std::string&, const Container<3>&);

}  // namespace fp
