#pragma once
// Meshing the inside of a closed triangulated surface into tetrahedra: CGAL's
// Mesh_3 on the surface as a polyhedral domain, refined to a target edge length, without the
// optional perturbation and exudation steps and without keeping sharp edges (the packer needs
// tetrahedra of the right size, not the surface's creases: the container stays the surface). For the tetrahedral-mesh packer of paper 000 when the container is an STL, OFF
// or OBJ surface: the paper sizes the mesh so that its mean edge is about 8 mean radii. CGAL is
// confined to tet_mesher_cgal.cpp (a library of its own: it is the heaviest translation unit).
#include <array>
#include <vector>

#include "core/geometry/tet_mesh.hpp"
#include "core/geometry/vec.hpp"

namespace fp {

/// The tetrahedra of the inside of the closed, outward-oriented surface (vertices, triangles), with
/// edges and cells of about `size`, nodes in the surface's frame, every tetrahedron positively
/// oriented, all in physical volume 1. The same input gives the same mesh (CGAL's random source
/// is reset first). Throws std::invalid_argument when the surface cannot be meshed.
TetMesh mesh_tetrahedra(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles, double size);

}  // namespace fp
