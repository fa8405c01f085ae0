#pragma once
// gmsh MSH 4.1 ASCII text → TetMesh: the 3D counterpart of msh_reader.hpp (stage 1 of the 3D
// track, docs/method.md §11).

#include <string_view>

#include "mesh/tet_mesh.hpp"

namespace fosls {

/// Parses an MSH 4.1 ASCII mesh of 4-node tetrahedra (element type 4); 3-node triangles (type 2)
/// on surface entities give the boundary faces of the physical surface their entity belongs to
/// (group name from $PhysicalNames, else the physical tag as text, groups ordered by tag).
/// Points, lines and elements of other dimensions are ignored; hexahedra, prisms, pyramids,
/// quadrangles and second-order elements are refused. Every boundary face must lie on a
/// physical surface and every physical-surface triangle on the boundary. Any problem throws
/// MeshError with field /msh and a sentence naming the line or the face. Surfaces from msh
/// text are flat facets (no SphereSurface): refinement does not move onto a curved surface.
TetMesh tet_mesh_from_msh(std::string_view text);

}  // namespace fosls
