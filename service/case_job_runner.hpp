#pragma once
// Production wiring of the service to the solver library: validation of submitted cases and
// the job runner that solves them (case/run/case_runner.hpp).

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "admission_budget.hpp"
#include "case/format/case_error.hpp"
#include "case_verdict.hpp"
#include "job_runner.hpp"

namespace fosls::service {

/// Validates a submitted case as the service must, on the request thread and without gmsh
/// (case/admission/case_admission.hpp): `mesh.geo_file` is refused, because a gmsh .geo script can
/// run shell commands and read or write files; problems that need the coarse mesh of a geometry are
/// found by the job (it fails naming them). A case whose estimated memory exceeds the budget
/// `budget` gives at the time (none when it is empty: --admit-over-budget) is refused at the field
/// that sets its size. A case whose whole time estimate (case/admission/job_time.hpp) exceeds
/// `max_job_seconds` (0: none) is refused too, at the field that sets its time. Its verdict carries
/// admission's time estimate of an admitted case.
CaseValidator submitted_case_validator(std::function<MemoryBudget()> budget,
                                       double max_job_seconds = 0);

/// The wall-clock time one job may run: kJobTimeMargin times its case's time estimate, at least
/// kJobTimeFloorSeconds, at most `max_job_seconds` (--max-job-seconds; 0: no limit at all).
struct JobTimeLimit {
  double seconds = 0;                      ///< 0: none
  std::optional<double> estimate_seconds;  ///< the case's estimate, if admission made one
  double cap_seconds = 0;                  ///< --max-job-seconds
  /// "60 s, the time this job may run (…)": the limit and how it was derived, for messages.
  std::string describe() const;
};
/// From the estimate admission stored with the job (none: a job queued before estimates were
/// stored, or one admission could not estimate; it gets the cap). Reads nothing of the case:
/// what runs in the server between a claim and the solve process is short, so a cancel then
/// takes effect at once.
JobTimeLimit job_time_limit(std::optional<double> estimate_seconds, double max_job_seconds);

/// Solves a case with read_case + run_case, honouring cancellation through RunControl::cancel
/// and reporting every iteration. Case problems that only show while running (CaseException:
/// among them a coarse mesh beyond `job_memory_bytes`, checked before it is refined) become a
/// failed outcome listing each pointer and reason.
JobRunOutcome run_case_job(const nlohmann::json& case_json, const JobRunContext& context,
                           std::size_t job_memory_bytes = 0);

}  // namespace fosls::service
