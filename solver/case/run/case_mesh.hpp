#pragma once
// A case's coarse mesh, in 2D and 3D: built from its source and checked against the case's
// groups and the size limits before anything is refined or assembled. The two dimensions
// differ only in the mesh sources they read (mesh_factory.hpp; volume_mesh_checks.hpp) and in
// when the groups are checked: in 3D once more on the finest mesh, whose sphere surfaces the
// refinement moved (a contact face must face its plane).

#include <optional>
#include <vector>

#include "case/admission/case_limits.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// Step 1 of a point: the coarse mesh of spec.mesh, checked. Throws CaseException for the
/// case's problems (the mesh source's, unknown groups, sizes over `limits`); nothing when
/// `meshing.cancel` stopped the mesher.
template <int dim>
std::optional<SimplexMesh<dim>> checked_coarse_mesh(const CaseSpec& spec,
                                                    const MeshingControl& meshing,
                                                    const CaseLimits& limits);

/// Step 3: the groups against the finest mesh (3D; nothing to check in 2D). Throws
/// CaseException.
template <int dim>
void check_finest_mesh(const CaseSpec& spec, const SimplexMesh<dim>& finest);

/// What validate_case says of a case read without errors once its coarse mesh is built: the
/// mesh source's problems, the groups and the size. Throws MeshingCancelled.
std::vector<CaseError> check_case_mesh(const CaseSpec& spec, const MeshingControl& meshing,
                                       const CaseLimits& limits);

}  // namespace fosls
