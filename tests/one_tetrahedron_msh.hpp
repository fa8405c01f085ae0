#pragma once
// The smallest 3D mesh as gmsh ASCII 4.1 text: one tetrahedron (0,0,0), (1,0,0), (0,1,0),
// (0,0,1) with the boundary groups bottom (its face on z = 0) and rest (the other three), for
// tests of meshes given as msh text or file.

#include <string>

namespace fosls::testing {

inline std::string one_tetrahedron_msh() {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$PhysicalNames\n2\n2 1 \"bottom\"\n2 2 \"rest\"\n$EndPhysicalNames\n"
         "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 1 1 0\n2 0 0 0 1 1 1 1 2 0\n1 0 0 0 1 1 1 0 0\n"
         "$EndEntities\n"
         "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
         "$Elements\n3 5 1 5\n2 1 2 1\n1 1 2 3\n2 2 2 3\n2 1 2 4\n3 1 3 4\n4 2 3 4\n"
         "3 1 4 1\n5 1 2 3 4\n$EndElements\n";
}

}  // namespace fosls::testing
