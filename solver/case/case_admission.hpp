#pragma once
// What can be said about a case before anything is meshed with gmsh: everything read_case
// finds, the geometry checks and coarse-mesh size guards, the boundary groups, and the
// resources the solve will need. Cheap enough for a request thread: gmsh never runs here (the
// coarse mesh of a geometry or of the built-in hertz is estimated, not built); a square or msh
// mesh, built without gmsh, is built and checked exactly.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/case_error.hpp"
#include "case/case_reader.hpp"
#include "case/case_spec.hpp"
#include "case/resource_estimate.hpp"

namespace fosls {

struct CaseAdmission {
  std::vector<CaseError> errors;             ///< empty when the case may be queued
  std::optional<CaseSpec> spec;              ///< set when read_case accepted the case
  std::optional<ResourceEstimate> estimate;  ///< set when errors is empty
};

/// Checks a case without gmsh (see above).
CaseAdmission admit_case(const nlohmann::json& j, const CaseReadOptions& options = {});

/// Problems of the boundary conditions against the mesh's groups, and of the number of
/// unknowns against the limit (only when `unknowns_exact`: an estimate is checked once the
/// coarse mesh is built).
std::vector<CaseError> check_against_groups(const CaseSpec& spec,
                                            const std::vector<std::string>& group_names,
                                            long long unknowns, bool unknowns_exact,
                                            const CaseLimits& limits);

/// The problem (at /mesh/refinements) of an estimate above a memory budget, naming both and
/// what to change; nothing when it fits.
std::optional<CaseError> check_memory_budget(const ResourceEstimate& estimate, Method method,
                                             double budget_bytes, const std::string& budget_name);

}  // namespace fosls
