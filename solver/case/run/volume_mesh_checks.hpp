#pragma once
// What a 3D case's mesh shows before it is solved: the coarse mesh counted without building a
// builtin (admission, case_admission.hpp), an msh text's mesh read and its groups checked, and
// the checks of the groups against the mesh the runner repeats on the finest mesh (unknown
// groups, data that is not a number on its group, contact faces that do not face their plane,
// dirichlet groups that leave a rigid motion free).

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "case/admission/resource_estimate.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// A builtin's coarse unknowns from its parameters, before it is built; nothing for a mesh from
/// msh text or a geo_file (counted once read or meshed).
std::optional<double> builtin_3d_unknowns(const MeshSpec& mesh);

/// A built mesh's unknowns: three per vertex (u) and three per face (the stress rows' fluxes).
double tet_mesh_unknowns(const TetMesh& mesh);

/// The mesh's index of the boundary group `name`, −1 when it has none of that name.
int tet_group_index(const TetMesh& mesh, const std::string& name);

/// Every group the case names is one of the mesh's, its data is a number on it, every face of
/// a contact group faces its plane (the gap along the body normal is then finite everywhere),
/// and the dirichlet groups hold the body: the problems at the groups' pointers.
std::vector<CaseError> check_3d_groups(const CaseSpec& spec, const TetMesh& mesh);

/// Unknowns of the finest level for `coarse_unknowns` on the coarse mesh: they grow about
/// eightfold per refinement (vertices and faces each do).
double finest_3d_unknowns(double coarse_unknowns, int refinements);

/// What admission knows of a 3D case's mesh without building a builtin or running gmsh: a
/// builtin's estimated count, an msh text's exact one (its mesh read, its problems and its
/// groups' checked: `errors`; a small builtin is built and checked the same way); nothing for a
/// geo_file.
struct Mesh3dCount {
  std::vector<CaseError> errors;
  std::optional<ProblemCount> count;
};
Mesh3dCount count_3d_mesh(const CaseSpec& spec);

/// A builtin's coarse mesh (box or half ball), or why its parameters give none, at the mesh
/// source's pointer.
std::variant<TetMesh, std::vector<CaseError>> builtin_3d_mesh(const MeshSpec& m);

}  // namespace fosls
