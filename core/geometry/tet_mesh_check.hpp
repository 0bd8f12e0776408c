#pragma once
// What a tetrahedral mesh must be before anything is packed into it: at least one
// tetrahedron; every tetrahedron positively oriented (Gmsh's convention: node 3 on the side of
// the face 0-1-2 its right-hand normal points to) and not flat, its volume above 1e-12 of its
// longest edge cubed; conforming: a triangular face shared by at most two tetrahedra, and the
// faces of only one (the boundary) closing up, each of their edges shared by exactly two of them
// (a hanging node or a crack leaves an edge of one); every physical volume the file names
// holding tetrahedra.
#include <string>

#include "core/geometry/tet_mesh.hpp"

namespace fp {

/// "" when `mesh` is fit to pack, else what is wrong with it, naming the element (1-based, in
/// the file's order of tetrahedra) or the nodes (the file's order, 1-based).
/// `boundary_closes` = false skips the boundary's edges: for a mesh whose conformity its mesher
/// guarantees and whose boundary may touch itself along an edge (a pinch in a thin part), which a
/// hanging node cannot be told from by counting.
std::string tet_mesh_problem(const TetMesh& mesh, bool boundary_closes = true);

}  // namespace fp
