#include "case_job_runner.hpp"

#include "case/admission/case_admission.hpp"
#include "case/admission/job_time.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls::service {

namespace {

/// No local files, and, when `job_memory_bytes` is not 0, the memory budget every case is
/// admitted against (before meshing and again once meshed).
CaseReadOptions service_read_options(std::size_t job_memory_bytes) {
  CaseReadOptions options;
  options.allow_local_files = false;
  options.limits.max_memory_bytes = static_cast<double>(job_memory_bytes);
  options.limits.memory_budget_name = "a job may use (the service's --max-job-memory)";
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

CaseValidator submitted_case_validator(std::function<MemoryBudget()> budget,
                                       double max_job_seconds) {
  return [budget = std::move(budget), max_job_seconds](const nlohmann::json& case_json) {
    CaseReadOptions options = service_read_options(0);
    options.limits.max_seconds = max_job_seconds;
    options.limits.time_budget_name = "a job may run (the service's --max-job-seconds)";
    if (budget) {
      const MemoryBudget now = budget();
      options.limits.max_memory_bytes = static_cast<double>(now.bytes);
      options.limits.memory_budget_name = now.name;
    }
    CaseVerdict verdict;
    CaseAdmission admission = admit_case(case_json, options);
    verdict.errors = std::move(admission.errors);
    if (admission.time && verdict.errors.empty())
      verdict.estimate_seconds = admission.time->seconds;
    return verdict;
  };
}

JobTimeLimit job_time_limit(std::optional<double> estimate_seconds, double max_job_seconds) {
  JobTimeLimit limit;
  limit.cap_seconds = max_job_seconds;
  if (max_job_seconds <= 0) return limit;
  limit.estimate_seconds = estimate_seconds;
  limit.seconds = estimate_seconds ? job_time_limit_seconds(*estimate_seconds, max_job_seconds)
                                   : max_job_seconds;
  return limit;
}

std::string JobTimeLimit::describe() const {
  char text[400];
  if (!estimate_seconds)
    std::snprintf(text, sizeof text,
                  "%g s, the most a job may run (the service's --max-job-seconds); the job was "
                  "queued without a time estimate",
                  seconds);
  else if (seconds >= cap_seconds)
    std::snprintf(text, sizeof text,
                  "%g s, the most a job may run (the service's --max-job-seconds); the case was "
                  "estimated at %.3g s",
                  seconds, *estimate_seconds);
  else
    std::snprintf(text, sizeof text,
                  "%g s, the time this job may run: %g times its estimate of %.3g s, at least "
                  "%g s (the service's --max-job-seconds %g s caps it)",
                  seconds, kJobTimeMargin, *estimate_seconds, kJobTimeFloorSeconds, cap_seconds);
  return text;
}

namespace {

JobRunOutcome failed(const std::string& error) {
  JobRunOutcome outcome;
  outcome.kind = JobRunOutcome::Kind::kFailed;
  outcome.error = error;
  return outcome;
}

std::string text_of(const nlohmann::json& result) {
  return result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// A finished run: its result and VTU; when it was cancelled, the load steps solved before the
/// cancel (marked partial), or nothing.
JobRunOutcome finished(bool cancelled, const nlohmann::json& result, std::string vtu) {
  JobRunOutcome outcome;
  outcome.kind = cancelled ? JobRunOutcome::Kind::kCancelled : JobRunOutcome::Kind::kSucceeded;
  if (cancelled) {
    if (result.is_object() && result.contains("load_steps")) outcome.result_json = text_of(result);
    return outcome;
  }
  outcome.result_json = text_of(result);
  outcome.vtu = std::move(vtu);
  return outcome;
}

/// Reports every iteration as the job's progress (`progress` keeps the solve's step).
std::function<void(const IterationRecord&)> progress_reporter(JobProgress& progress,
                                                              const JobRunContext& context) {
  return [&progress, &context](const IterationRecord& r) {
    progress.iteration = r.iteration;
    progress.kkt_residual = r.kkt_residual;
    progress.energy = r.energy;
    context.report_progress(progress);
  };
}

}  // namespace

JobRunOutcome run_case_job(const nlohmann::json& case_json, const JobRunContext& context,
                           std::size_t job_memory_bytes) {
  const CaseReadOptions options = service_read_options(job_memory_bytes);
  CaseReadResult read = read_case(case_json, options);
  // Only reachable if validation rules changed between submit and run (e.g. an upgrade).
  if (!read.spec) return failed("invalid case: " + describe(read.errors));
  RunControl control;
  control.cancel = &context.cancel;
  control.want_vtu = true;
  // Both callbacks come from the solving thread, on_solve before each solve's iterations.
  JobProgress progress;
  control.on_solve = [&progress](int solve, int solves) {
    progress.step = solve;
    progress.steps = solves;
  };
  control.on_iteration = progress_reporter(progress, context);
  if (context.report_partial)
    control.on_partial = [&context](const nlohmann::json& r) {
      context.report_partial(text_of(r));
    };
  try {
    RunOutput output = run_case(*read.spec, control, options.limits);
    return finished(output.cancelled, output.result, std::move(output.vtu));
  } catch (const CaseException& e) {
    return failed("invalid case: " + describe(e.errors()));
  } catch (const TimeLimitReached& e) {
    return failed(e.what());
  }
}

}  // namespace fosls::service
