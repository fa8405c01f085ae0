#pragma once
// All problems of a case in one round: when read_case refuses a case for problems outside its
// mesh section, the mesh can often still be made, and the group names of `boundary` are checked
// against it too, so a wrong group name is not reported only after the other fields are fixed.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/admission/case_limits.hpp"
#include "case/format/case_error.hpp"

namespace fosls {

/// The problem of a group name the mesh lacks (the same words wherever it is found).
CaseError unknown_group_problem(const std::string& name, const std::vector<std::string>& groups);

/// The problem of a case no group of which is dirichlet, so that the body can move freely (the
/// same words in 2D and 3D).
CaseError no_dirichlet_problem();

/// Appends to `errors` the groups named in j["boundary"] that the mesh lacks, when the mesh
/// section passed its checks and its groups are known without gmsh (a geometry's or the hertz
/// outline's, or a square or msh mesh, which are made without gmsh); nothing otherwise.
void add_unknown_group_problems(const nlohmann::json& j, const CaseReadOptions& options,
                                std::vector<CaseError>& errors);

}  // namespace fosls
