#pragma once
// Shape measures of a tetrahedral mesh: how far its worst tetrahedron is from degenerate.
// The multilevel method's iteration counts depend on them (docs/validation.md §16).

#include "mesh/tet_mesh.hpp"

namespace fosls {

/// The smallest of a tetrahedron's six dihedral angles, in degrees (70.5° for a regular one,
/// 45° for a Kuhn tetrahedron, 0 for a flat one).
double smallest_dihedral_angle(const TetMesh& mesh, int tet);

/// The smallest dihedral angle over the whole mesh, in degrees.
double smallest_dihedral_angle(const TetMesh& mesh);

}  // namespace fosls
