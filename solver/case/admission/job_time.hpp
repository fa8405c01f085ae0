#pragma once
// How long a whole case may take: every sweep point, an adaptive run's steps, pgs's iterations,
// bounded by the case's own solver.time_limit_s. The service refuses a case whose estimate
// exceeds its --max-job-seconds and gives every job a limit of a margin times its estimate
// (docs/service.md, "Time limits"). A guide with a margin, not a promise: the same run varies
// 2–3× with the machine's load, and hard cases take more iterations than the fitted ones.

#include <optional>
#include <string>

#include "case/admission/resource_estimate.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"

namespace fosls {

/// pgs: seconds of one iteration on `unknowns` with the patch smoother (the point smoother's
/// are cheaper). pgs is not expected to converge on fine meshes, so its time is bounded by
/// solver.max_iterations of these, not estimated to a tolerance.
double pgs_seconds_per_iteration(long long unknowns);

struct CaseTimeEstimate {
  double seconds = 0;  ///< the whole case
  int points = 1;      ///< sweep points (1 without a sweep)
  /// Whether solver.time_limit_s bounds the run below the estimate of its work.
  bool bounded_by_time_limit = false;
  /// The case field to change when it is too long.
  std::string limited_by = "/mesh/refinements";
};

/// The estimate for `count` on the finest uniform level (adaptivity.max_dofs for an adaptive
/// run when larger).
CaseTimeEstimate estimate_case_time(const CaseSpec& spec, const ProblemCount& count);

/// The problem (at estimate.limited_by) of a case estimated above `budget_seconds`, naming the
/// time, the budget and what to change; nothing when it fits.
std::optional<CaseError> check_time_budget(const CaseTimeEstimate& estimate, const CaseSpec& spec,
                                           const ProblemCount& count, double budget_seconds,
                                           const std::string& budget_name);

/// "1 h", "20 min", "2 s", "1.5 s": a time budget as it was given.
std::string budget_text(double seconds);

/// A job's limit is this many times its estimate (load, harder cases than the fitted ones) …
inline constexpr double kJobTimeMargin = 10.0;
/// … and never less than this (process start, meshing, a small case on a busy machine).
inline constexpr double kJobTimeFloorSeconds = 60.0;

/// The wall-clock seconds a job estimated at `estimate_seconds` may run: kJobTimeMargin times
/// the estimate, at least kJobTimeFloorSeconds, at most `cap_seconds`; 0 (none) when the cap
/// is 0.
double job_time_limit_seconds(double estimate_seconds, double cap_seconds);

}  // namespace fosls
