#pragma once
// The step a worker runs for one job. Production wiring solves the case with the library
// (case_job_runner.hpp); tests inject their own runner.

#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "job.hpp"

namespace fosls::service {

/// What a running job can see of its worker.
struct JobRunContext {
  /// Becomes true when the job is cancelled or the service stops; stop soon after.
  const std::atomic<bool>& cancel;
  /// Report progress after each iteration (the worker throttles the database writes).
  std::function<void(const JobProgress&)> report_progress;
  /// Admission's estimate of the solve's time, as stored with the job (none: not estimated).
  std::optional<double> time_estimate_seconds = std::nullopt;
  /// Load steps: after each step but the last, the result a cancel would leave (the steps
  /// solved so far, marked partial); none: not wanted.
  std::function<void(const std::string& result_json)> report_partial = nullptr;
};

/// How one run ended.
struct JobRunOutcome {
  enum class Kind { kSucceeded, kFailed, kCancelled };
  Kind kind = Kind::kFailed;
  std::string result_json;  ///< kSucceeded; kCancelled: the steps solved before it, or empty
  std::string vtu;          ///< kSucceeded
  std::string error;        ///< kFailed: a message a person can act on
};

/// Solves one case. May throw; the worker turns any exception into a failed job.
using JobRunner =
    std::function<JobRunOutcome(const nlohmann::json& case_json, const JobRunContext& context)>;

}  // namespace fosls::service
