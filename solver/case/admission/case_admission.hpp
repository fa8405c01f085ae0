#pragma once
// The one admission rule of every program that runs cases (the CLI's estimate, solve and bench,
// the service), for both dimensions: what can be said about a case before anything is meshed with
// gmsh — everything read_case finds, the geometry checks and coarse-mesh size guards, the
// boundary groups, and the unknowns, memory and time the solve will need against CaseLimits
// (max_dofs, max_memory_bytes, max_seconds).
// Cheap enough for a request thread: gmsh never runs here (the coarse mesh of a geometry or of
// the built-in hertz is estimated from what drives it, mesh/coarse_mesh_estimate.hpp; a 3D
// builtin from its cells); a square, a 2D or 3D msh mesh, built without gmsh, is counted
// exactly. Once a run has built the coarse mesh, the same rule is applied again to the exact
// unknowns (check_against_groups, check_size).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/admission/job_time.hpp"
#include "case/admission/resource_estimate.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/case_spec.hpp"

namespace fosls {

struct CaseAdmission {
  std::vector<CaseError> errors;             ///< empty when the case may run
  std::optional<CaseSpec> spec;              ///< set when read_case accepted the case
  std::optional<ResourceEstimate> estimate;  ///< set when the size could be estimated
  std::optional<CaseTimeEstimate> time;      ///< set with `estimate`: the whole case's time
};

/// Checks a case without gmsh (see above); the size against `options.limits`.
CaseAdmission admit_case(const nlohmann::json& j, const CaseReadOptions& options = {});

/// The estimate a case is admitted with, for `count` on its finest uniform level: for an
/// adaptive case the larger of that and the run's at adaptivity.max_dofs.
ResourceEstimate admission_estimate(const CaseSpec& spec, const ProblemCount& count);

/// Problems of the boundary conditions against the mesh's groups (`group_names`; none given:
/// only whether the dirichlet groups prescribe every component), and of the size (check_size).
/// Called before meshing with estimated unknowns and once the coarse mesh is built with exact
/// ones (`count.exact`), so a mesh larger than its estimate is stopped before it is refined.
std::vector<CaseError> check_against_groups(
    const CaseSpec& spec, const std::optional<std::vector<std::string>>& group_names,
    const ProblemCount& count, const CaseLimits& limits);

/// Problems of the size against `limits`: the unknowns against max_dofs, the memory estimate
/// against max_memory_bytes, the time estimate against max_seconds.
std::vector<CaseError> check_size(const CaseSpec& spec, const ProblemCount& count,
                                  const CaseLimits& limits);

/// The problem (at estimate.limited_by) of an estimate above a memory budget, naming both and
/// what to change — among methods, only those that solve `spec`, converge on fine meshes and
/// fit; nothing when it fits.
std::optional<CaseError> check_memory_budget(const ResourceEstimate& estimate, const CaseSpec& spec,
                                             double budget_bytes, const std::string& budget_name);

}  // namespace fosls
