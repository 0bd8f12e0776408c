#include "core/geometry/tet_mesher_cgal.hpp"

#include <map>
#include <stdexcept>
#include <string>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <Eigen/Geometry>

namespace fp {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<K::Point_3>;
using Domain = CGAL::Polyhedral_mesh_domain_3<Surface, K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

}  // namespace

TetMesh mesh_tetrahedra(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles, double size) {
  if (!(size > 0)) throw std::invalid_argument("the target edge length must be positive");
  Surface surface;
  std::vector<Surface::Vertex_index> v;
  v.reserve(vertices.size());
  for (const Vec3& p : vertices) v.push_back(surface.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : triangles)
    if (surface.add_face(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])]) ==
        Surface::null_face())
      throw std::invalid_argument("the surface is not a manifold CGAL can mesh");
  CGAL::get_default_random() = CGAL::Random(0);  // Mesh_3 draws from it: the same input, the same mesh
  Domain domain(surface);
  // Sharp edges are not kept as edges of the mesh (detect_features): on a scanned surface (the
  // femur) every crease counts as one and the mesh followed them down to tiny tetrahedra (86,774
  // against 2,930 without); the container stays the true surface, the packer fills up to it.
  namespace params = CGAL::parameters;
  // The surface to a quarter edge: the packer removes what sticks out of the true surface and
  // fills up to it, so a closer approximation buys only tetrahedra.
  const Criteria criteria(params::facet_angle = 25, params::facet_size = size,
                          params::facet_distance = size / 4, params::cell_radius_edge_ratio = 3, params::cell_size = size);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  TetMesh mesh;
  std::map<Tr::Vertex_handle, std::uint32_t> index;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::uint32_t, 4> t{};
    for (int k = 0; k < 4; ++k) {
      const Tr::Vertex_handle h = c->vertex(k);
      auto [it, fresh] = index.try_emplace(h, static_cast<std::uint32_t>(mesh.nodes.size()));
      if (fresh) {
        const auto& p = h->point();
        mesh.nodes.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      t[static_cast<std::size_t>(k)] = it->second;
    }
    const Vec3 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &d = mesh.nodes[t[2]], &e = mesh.nodes[t[3]];
    if ((b - a).cross(d - a).dot(e - a) < 0) std::swap(t[2], t[3]);
    mesh.tets.push_back(t);
    mesh.tet_group.push_back(1);
  }
  if (mesh.tets.empty()) throw std::invalid_argument("meshing gave no tetrahedra (is the surface closed and outward?)");
  mesh.group_names[{3, 1}] = "inside";
  return mesh;
}

}  // namespace fp
