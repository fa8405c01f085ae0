#pragma once
// Production wiring of the service to the solver library: validation of submitted cases and
// the job runner that solves them (case/case_runner.hpp).

#include <nlohmann/json.hpp>
#include <vector>

#include "case/case_error.hpp"
#include "job_runner.hpp"

namespace fosls::service {

/// Validates a submitted case as the service must: `mesh.geo_file` is refused, because a gmsh
/// .geo script can run shell commands and read or write files.
std::vector<CaseError> validate_submitted_case(const nlohmann::json& case_json);

/// Solves a case with read_case + run_case, honouring cancellation through RunControl::cancel
/// and reporting every iteration. Case problems that only show while running
/// (CaseException) become a failed outcome listing each pointer and reason.
JobRunOutcome run_case_job(const nlohmann::json& case_json, const JobRunContext& context);

}  // namespace fosls::service
