#include "process_job_runner.hpp"

#include <signal.h>

#include <cstdio>

#include "case_job_runner.hpp"
#include "job_process_protocol.hpp"
#include "memory_budget.hpp"
#include "process/child_process.hpp"

namespace fosls::service {

namespace {

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.pop_back();
  const auto nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

JobRunOutcome failed(std::string error) {
  JobRunOutcome o;
  o.kind = JobRunOutcome::Kind::kFailed;
  o.error = std::move(error);
  return o;
}

/// "its peak memory was 1.2 GiB of the 2 GiB a job may use".
std::string peak_of(const ChildResult& r, const ProcessJobRunnerOptions& options) {
  return "its peak memory was " + format_bytes(static_cast<double>(r.peak_rss_bytes)) + " of the " +
         format_bytes(static_cast<double>(options.memory_bytes)) +
         " a job may use (the service's --max-job-memory)";
}

/// Why a solve process died of a signal, from the signal and what the kernel counted, never
/// guessed: the job's memory limit makes allocations fail (a message on stderr), so a SIGKILL
/// that was not ours came from the system's out-of-memory killer (counted meanwhile) or from
/// outside (a person, another program).
JobRunOutcome signal_outcome(const ChildResult& r, const ProcessJobRunnerOptions& options,
                             const std::string& memory) {
  if (r.ran_out_of_memory()) return failed(memory);
  if (r.killed_by_oom_killer())
    return failed(
        "the solve process was killed by the system's out-of-memory killer: the "
        "machine ran out of memory (" +
        peak_of(r, options) +
        "); run fewer workers or a lower --max-job-memory so that all jobs together "
        "fit the machine, or make this case smaller");
  if (r.signal == SIGKILL)
    return failed(
        "the solve process was killed by signal 9 (SIGKILL) from outside the service, "
        "not by one of its limits and not by the out-of-memory killer (" +
        peak_of(r, options) + "); submit the case again");
  return failed(
      "the solver crashed (" + r.describe() + "; " + peak_of(r, options) + "); " +
      (r.errors.empty() ? std::string("no message") : "its last message: " + last_line(r.errors)));
}

/// Every way the solve process can end, as the job's outcome.
JobRunOutcome outcome_of(const ChildResult& r, const JobProcessReader& reader,
                         const ProcessJobRunnerOptions& options, const JobTimeLimit& time) {
  const std::string memory =
      "the solve ran out of memory: a job may use " + format_bytes(options.memory_bytes) +
      " (the service's --max-job-memory); use fewer refinements, a coarser mesh.size or "
      "another solver.method";
  switch (r.end) {
    case ChildResult::End::kCancelled: {
      JobRunOutcome o;
      o.kind = JobRunOutcome::Kind::kCancelled;
      o.result_json = reader.partial_result();  // load steps solved before the cancel
      return o;
    }
    case ChildResult::End::kTimedOut:
      return failed("the solve did not finish within " + time.describe() +
                    "; use fewer refinements, a looser solver.tolerance, fewer "
                    "solver.max_iterations, or a solver.time_limit_s to get the last iterate "
                    "back");
    case ChildResult::End::kOutputTooLarge:
      return failed("the result is too large to be stored");
    case ChildResult::End::kSignaled:
      return signal_outcome(r, options, memory);
    case ChildResult::End::kExited:
      break;
  }
  if (r.exit_code == 0 && reader.outcome()) return *reader.outcome();
  if (r.ran_out_of_memory()) return failed(memory);
  if (!reader.malformed().empty())
    return failed("internal error: the solve process answered " + reader.malformed());
  return failed("internal error while solving (" + r.describe() + "): " + last_line(r.errors));
}

}  // namespace

JobRunner process_job_runner(ProcessJobRunnerOptions options) {
  if (options.program.empty())
    options.program = sibling_program("fosls-solve-job", "FOSLS_SOLVE_JOB");
  return [options](const nlohmann::json& case_json, const JobRunContext& context) {
    JobProcessReader reader(context.report_progress);
    ChildOptions child;
    child.argv = {options.program};
    if (options.admission_memory_bytes > 0)
      child.argv.insert(child.argv.end(),
                        {"--max-job-memory", std::to_string(options.admission_memory_bytes)});
    child.input = case_json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    child.limits.address_space_bytes = options.memory_bytes + kSolveAddressSpaceHeadroom;
    child.limits.max_output_bytes = std::size_t{4} << 30;
    const JobTimeLimit time =
        job_time_limit(context.time_estimate_seconds, options.max_job_seconds);
    child.limits.wall = std::chrono::milliseconds(static_cast<std::int64_t>(time.seconds * 1000));
    child.cancel = &context.cancel;
    child.on_output = [&reader](std::string_view data) { reader.feed(data); };
    const std::string threads = std::to_string(options.threads);
    child.environment = {"OMP_NUM_THREADS=" + threads, "OPENBLAS_NUM_THREADS=" + threads};
    return outcome_of(run_child(child), reader, options, time);
  };
}

}  // namespace fosls::service
