#pragma once
// gmsh MSH 4.1 ASCII text → Mesh, parsed here rather than by gmsh: the text comes from the
// network, and gmsh's global state is neither thread-safe nor meant for untrusted input.

#include <string_view>

#include "mesh/mesh.hpp"

namespace fosls {

/// Parses an MSH 4.1 ASCII mesh: 3-node triangles (type 2) form the mesh, 2-node lines
/// (type 1) on curve entities give the boundary segments of the physical curve the entity
/// belongs to (group name from $PhysicalNames, else the physical tag as text, groups ordered
/// by tag). Points and other element types are ignored; quadrangles and second-order elements
/// are rejected. Every boundary edge must lie on a physical curve. Any problem (corrupt,
/// truncated or binary text, wrong version, nodes off the plane z = 0, an invalid
/// triangulation) throws MeshError with field /msh and a sentence naming the line.
/// Curved boundaries are not recognised: edges from msh text are straight (curve -1).
Mesh mesh_from_msh(std::string_view text);

}  // namespace fosls
