#pragma once
// The body's length scale ℓ: the power of ten nearest to the square root of its area (2D) or
// the cube root of its volume (3D).

#include "mesh/mesh.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// 10^round(log10(√|Ω|)) for the mesh's domain Ω (1 for an empty mesh). The FOSLS functional's
/// c1 term ‖div σ + f‖² does not grow with the body's size L like the c2 and contact terms
/// (which grow as L² against it); weighting it by ℓ² keeps the balance the default weights were
/// chosen for (docs/method.md §2). A power of ten leaves every body of size 0.3 to 3 as it was,
/// and makes a case in millimetres and the same case in metres the same discrete problem.
double length_scale(const Mesh& mesh);

/// 10^round(log10(∛|Ω|)) for a tetrahedral mesh's domain Ω (1 for an empty mesh): the same
/// balance in 3D, where the c1 term also loses L² against the others.
double length_scale(const TetMesh& mesh);

}  // namespace fosls
