#pragma once
// Whether a 3D case's dirichlet groups hold the body: with rollers (null displacement
// components) they may leave it free to slide or turn, and frictionless contact cannot stop
// that, so the FOSLS matrix is singular (docs/case-format.md, "3D cases").

#include <optional>

#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// A problem at /boundary naming the rigid motions (translations along and rotations about
/// which axes) that every prescribed displacement component of the case's dirichlet groups
/// leaves at zero on `mesh`; nothing when there is none.
std::optional<CaseError> check_rigid_motions(const CaseSpec& spec, const TetMesh& mesh);

}  // namespace fosls
