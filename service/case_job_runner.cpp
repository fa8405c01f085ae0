#include "case_job_runner.hpp"

#include "case/case_admission.hpp"
#include "case/case_reader.hpp"
#include "case/case_runner.hpp"

namespace fosls::service {

namespace {
CaseReadOptions service_read_options() {
  CaseReadOptions options;
  options.allow_geo_file = false;
  return options;
}

std::string describe(const std::vector<CaseError>& errors) {
  std::string text;
  for (const CaseError& e : errors) {
    if (!text.empty()) text += "; ";
    text += (e.pointer.empty() ? std::string("/") : e.pointer) + ": " + e.detail;
  }
  return text;
}
}  // namespace

std::function<std::vector<CaseError>(const nlohmann::json&)> submitted_case_validator(
    std::size_t job_memory_bytes, bool check_memory) {
  return [job_memory_bytes, check_memory](const nlohmann::json& case_json) {
    CaseAdmission admission = admit_case(case_json, service_read_options());
    if (check_memory && admission.estimate)
      if (auto e = check_memory_budget(*admission.estimate, admission.spec->solver.method,
                                       static_cast<double>(job_memory_bytes),
                                       "the service's --max-job-memory"))
        admission.errors.push_back(*e);
    return admission.errors;
  };
}

JobRunOutcome run_case_job(const nlohmann::json& case_json, const JobRunContext& context) {
  JobRunOutcome outcome;
  const CaseReadOptions options = service_read_options();
  CaseReadResult read = read_case(case_json, options);
  if (!read.spec) {
    // Only reachable if validation rules changed between submit and run (e.g. an upgrade).
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = "invalid case: " + describe(read.errors);
    return outcome;
  }
  RunControl control;
  control.cancel = &context.cancel;
  control.want_vtu = true;
  control.on_iteration = [&](const IterationRecord& r) {
    context.report_progress(JobProgress{r.iteration, r.kkt_residual, r.energy});
  };
  try {
    RunOutput output = run_case(*read.spec, control, options.limits);
    if (output.cancelled) {
      outcome.kind = JobRunOutcome::Kind::kCancelled;
      return outcome;
    }
    outcome.kind = JobRunOutcome::Kind::kSucceeded;
    outcome.result_json =
        output.result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    outcome.vtu = std::move(output.vtu);
  } catch (const CaseException& e) {
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = "invalid case: " + describe(e.errors());
  }
  return outcome;
}

}  // namespace fosls::service
