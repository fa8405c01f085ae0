#pragma once
// Production wiring of the service to the solver library: validation of submitted cases and
// the job runner that solves them (case/case_runner.hpp).

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "admission_budget.hpp"
#include "case/case_error.hpp"
#include "job_runner.hpp"

namespace fosls::service {

/// Validates a submitted case as the service must, on the request thread and without gmsh
/// (case/case_admission.hpp): `mesh.geo_file` is refused, because a gmsh .geo script can run
/// shell commands and read or write files; problems that need the coarse mesh of a geometry
/// are found by the job (it fails naming them). A case whose estimated memory exceeds the
/// budget `budget` gives at the time (none when it is empty: --admit-over-budget) is refused at
/// the field that sets its size.
std::function<std::vector<CaseError>(const nlohmann::json&)> submitted_case_validator(
    std::function<MemoryBudget()> budget);

/// Solves a case with read_case + run_case, honouring cancellation through RunControl::cancel
/// and reporting every iteration. Case problems that only show while running (CaseException:
/// among them a coarse mesh beyond `job_memory_bytes`, checked before it is refined) become a
/// failed outcome listing each pointer and reason.
JobRunOutcome run_case_job(const nlohmann::json& case_json, const JobRunContext& context,
                           std::size_t job_memory_bytes = 0);

}  // namespace fosls::service
