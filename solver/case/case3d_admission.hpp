#pragma once
// What can be said about a 3D case before its mesh is refined (case3d_reader.hpp): its problems
// by field, and the unknowns, memory and time its solve will need against CaseLimits. The
// service admits a 3D case with it; the runner applies the same size rule again to the coarse
// mesh it built (a geo_file's size is known only then).
// The estimates are fitted to the measured tables of docs/performance.md, "3D": a guide with a
// margin, as 2D's (job_time.hpp).

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "case/case3d_spec.hpp"
#include "case/case_error.hpp"
#include "case/case_limits.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// The resources a 3D solve of `unknowns` on the finest level needs by its method.
struct Case3dEstimate {
  double unknowns = 0;
  double bytes = 0;
  double seconds = 0;
};

Case3dEstimate estimate_3d_solve(double unknowns, SolverMethod method);

/// A builtin's coarse unknowns from its parameters, before it is built; nothing for a mesh from
/// msh text or a geo_file (counted once read or meshed).
std::optional<double> builtin_3d_unknowns(const Mesh3dSpec& mesh);

/// A built mesh's unknowns: three per vertex (u) and three per face (the stress rows' fluxes).
double tet_mesh_unknowns(const TetMesh& mesh);

/// The mesh's index of the boundary group `name`, −1 when it has none of that name.
int tet_group_index(const TetMesh& mesh, const std::string& name);

/// Every group the case names is one of the mesh's, and every face of a contact group faces
/// its plane (the gap along the body normal is then finite everywhere): the problems at the
/// groups' pointers. Checked at admission on an msh text's mesh and by the runner on the
/// finest mesh.
std::vector<CaseError> check_3d_groups(const Case3dSpec& spec, const TetMesh& mesh);

/// Unknowns of the finest level for `coarse_unknowns` on the coarse mesh: they grow about
/// eightfold per refinement (vertices and faces each do).
double finest_3d_unknowns(double coarse_unknowns, const Mesh3dSpec& mesh);

/// Problems (at /mesh/refinements) of a solve of `unknowns` against limits.max_dofs,
/// max_memory_bytes and max_seconds, each naming the numbers and what to change.
std::vector<CaseError> check_3d_size(double unknowns, const Case3dSpec& spec,
                                     const CaseLimits& limits);

struct Case3dAdmission {
  std::vector<CaseError> errors;           ///< empty when the case may run
  std::optional<Case3dSpec> spec;          ///< set when the case reads
  std::optional<Case3dEstimate> estimate;  ///< set when its size is known before meshing
};

/// Reads the case; reads an msh text's mesh (its problems at /mesh/msh, its groups against the
/// boundary); counts a builtin's or that mesh's coarse unknowns (no gmsh: a geo_file's are
/// unknown until it is meshed) and checks the size against `options.limits`.
Case3dAdmission admit_case_3d(const nlohmann::json& j, const CaseReadOptions& options = {});

}  // namespace fosls
