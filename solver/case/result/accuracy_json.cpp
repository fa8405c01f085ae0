// The result's `accuracy` object (level_loop_json.hpp): the levels' forces and estimates, and
// a sentence saying what the estimate was and why the loop stopped.

#include <cmath>

#include "case/result/level_loop_json.hpp"
#include "case/result/result_warnings.hpp"

namespace fosls {

namespace {

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

std::string num(double v) { return sentence_number(v, 3); }

/// The last level's estimate, or what the levels before it said when it has none.
std::string estimate_text(const std::vector<AdaptiveStepRecord>& steps) {
  if (steps.empty()) return "no level solved";
  const ForceErrorEstimate& e = steps.back().force_error;
  if (e.available()) return "the estimated relative error of the force is " + num(e.estimate);
  if (e.growing)
    return "no error estimate: the force's change grew from " +
           num(steps[steps.size() - 2].force_error.change) + " to " + num(e.change) +
           " in the last level, so the levels are not yet where the change shrinks by a steady "
           "ratio and predicts the error";
  for (auto s = steps.rbegin() + 1; s != steps.rend(); ++s)
    if (s->force_error.available())
      return "the last level has no estimate (its solve did not converge); the level before, "
             "at " +
             std::to_string(s->levels - 1) + " refinements, had " + num(s->force_error.estimate);
  return steps.back().converged ? "no error estimate yet (it needs two levels)"
                                : "no error estimate (the level's solve did not converge)";
}

std::string stop_message(const std::string& reason, const std::vector<AdaptiveStepRecord>& steps,
                         const AccuracySpec& spec) {
  const std::string estimated = estimate_text(steps);
  const std::string requested = " (accuracy.force = " + num(spec.force) + ")";
  if (reason == "reached") return estimated + ", within accuracy.force = " + num(spec.force);
  if (reason == "no_force")
    return "the contact force is zero on two levels, so it has no relative error to reach; "
           "check that the obstacle touches the body";
  if (reason == "max_dofs")
    return "the next refinement would exceed accuracy.max_dofs = " + std::to_string(spec.max_dofs) +
           "; " + estimated + requested;
  if (reason == "not_converged")
    return "the last level's solve did not converge, so its force is not the level's; " +
           estimated + requested;
  if (reason == "time_limit") return "solver.time_limit_s ran out; " + estimated + requested;
  if (reason == "cancelled") return "the run was cancelled; " + estimated + requested;
  return reason;
}

}  // namespace

nlohmann::json accuracy_json(const std::vector<AdaptiveStepRecord>& records,
                             const std::string& stop_reason, const AccuracySpec& spec) {
  nlohmann::json steps = nlohmann::json::array();
  for (const AdaptiveStepRecord& s : records)
    steps.push_back({{"refinements", s.levels - 1},
                     {"dofs", s.dofs},
                     {"dofs_total", s.dofs_total},
                     {"force", s.force},
                     {"change", number_or_null(s.force_error.change)},
                     {"ratio", number_or_null(s.force_error.ratio)},
                     {"ratio_observed", s.force_error.ratio_observed},
                     {"monotone", s.force_error.monotone},
                     {"estimate", number_or_null(s.force_error.estimate)},
                     {"iterations", s.iterations},
                     {"converged", s.converged},
                     {"time_s", s.time_s}});
  const ForceErrorEstimate last =
      records.empty() ? ForceErrorEstimate{} : records.back().force_error;
  return {{"force", spec.force},
          {"max_dofs", spec.max_dofs},
          {"reached", stop_reason == "reached"},
          {"stop_reason", stop_reason},
          {"estimate", number_or_null(last.estimate)},
          {"steps", steps},
          {"stop_message", stop_message(stop_reason, records, spec)}};
}

}  // namespace fosls
