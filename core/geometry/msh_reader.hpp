#pragma once
// A strict reader of Gmsh's MSH files, versions 2.2 and 4.1, ASCII and binary (little-endian,
// 8-byte data, as Gmsh writes them): the nodes, the linear tetrahedra (element type 4) and
// triangles (type 2) with their physical groups, and the groups' names. Other element types
// (points, lines, quadrangles, hexahedra, prisms, pyramids, second-order elements) are read
// past; an element type whose node count is unknown is an error (a binary block could not be
// skipped). Physical groups: version 2.2 gives each element its physical tag; version 4.1 gives
// them to the entities, and an element takes the first physical tag of its entity (0: none).
// Every deviation is an error naming where it is: "line 12: ..." in ASCII parts, "byte 4711:
// ..." in binary ones: a missing or unknown section end, a count the file is too small to hold
// (checked before anything is allocated), a node tag an element uses that no node has, a
// duplicate node tag, a file that ends early. Sections other than $MeshFormat,
// $PhysicalNames, $Entities, $Nodes and $Elements are skipped to their $End line.
#include <string>

#include "core/geometry/tet_mesh.hpp"

namespace fp {

/// Reads `path` into `mesh`. On failure returns false and sets `error` ("line 7: ..." or
/// "byte 4711: ...", without the path).
bool read_msh(const std::string& path, TetMesh& mesh, std::string& error);

}  // namespace fp
