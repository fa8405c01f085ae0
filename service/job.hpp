#pragma once
// A job of the service: one submitted case, its lifecycle state and what the API shows of it.

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace fosls::service {

/// Lifecycle: queued → running → succeeded | failed | cancelled (running → queued again when
/// the service stops or crashes while solving).
enum class JobState { kQueued, kRunning, kSucceeded, kFailed, kCancelled };

/// Every state, in lifecycle order (for metrics and listings).
inline constexpr std::array<JobState, 5> kAllJobStates = {JobState::kQueued, JobState::kRunning,
                                                          JobState::kSucceeded, JobState::kFailed,
                                                          JobState::kCancelled};

/// The API spelling: "queued", "running", "succeeded", "failed", "cancelled".
std::string_view to_string(JobState state);

/// Inverse of to_string; nothing for an unknown word.
std::optional<JobState> parse_job_state(std::string_view text);

/// Finished states never change again.
bool is_finished(JobState state);

/// The solver's last reported iteration (throttled while it runs). A job with load steps, a
/// sweep or adaptive levels runs several solves, each counting its iterations from 0: `step`
/// says which one (RunControl::on_solve, solver/case/run/case_runner.hpp).
struct JobProgress {
  int iteration = 0;
  double kkt_residual = 0.0;
  double energy = 0.0;
  int step = 0;   ///< the solve running, 0 first
  int steps = 0;  ///< how many solves the job makes at most; 0 when not known
};

/// How a solve that produced a result stopped, copied from the result's `converged` and
/// `stop_reason` (docs/result-format.md) so that job listings show it without reading results.
struct JobConvergence {
  std::optional<bool> converged;  ///< nothing: no result, or one without the field
  std::string stop_reason;        ///< "converged", "max_iterations", …; empty when unknown
};

/// The convergence fields of a result JSON text; empty ones when it has none or is not JSON.
JobConvergence convergence_of_result(const std::string& result_json);

/// The job as stored, without its case, result and VTU text (those are fetched separately).
struct Job {
  std::int64_t id = 0;
  std::string name;
  JobState state = JobState::kQueued;
  std::int64_t created_at_ms = 0;              ///< Unix time in milliseconds
  std::optional<std::int64_t> started_at_ms;   ///< start of the latest attempt
  std::optional<std::int64_t> finished_at_ms;  ///< set once the job is finished
  int attempts = 0;                            ///< how many times a worker started it
  std::optional<JobProgress> progress;         ///< nothing before the first iteration
  std::string error;                           ///< why it failed (empty otherwise)
  bool cancel_requested = false;               ///< cancel asked while it was running
  JobConvergence convergence;                  ///< set once a result was stored
};

/// The job resource of the HTTP API (docs/service.md, "API").
nlohmann::json job_to_json(const Job& job);
/// Its JSON Schema (the OpenAPI document's components.schemas.Job; tests validate real jobs
/// against it). Beside job_to_json so that a new field is written in one file.
nlohmann::json job_json_schema();

/// Current wall-clock time as Unix milliseconds.
std::int64_t now_unix_ms();

/// RFC 3339 UTC time with milliseconds, e.g. "2024-05-01T12:00:00.123Z".
std::string format_rfc3339(std::int64_t unix_ms);

}  // namespace fosls::service
