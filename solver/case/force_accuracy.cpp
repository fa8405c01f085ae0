#include "case/force_accuracy.hpp"

#include <algorithm>
#include <cmath>

#include "case/adaptive_runner.hpp"
#include "case/result_warnings.hpp"

namespace fosls {

namespace {

double distance(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

std::string num(double v) { return sentence_number(v, 3); }

/// The last level's estimate, or what the levels before it said when it has none.
std::string estimate_text(const std::vector<AdaptiveStepRecord>& steps) {
  if (steps.empty()) return "no level solved";
  const ForceErrorEstimate& e = steps.back().force_error;
  if (e.available()) return "the estimated relative error of the force is " + num(e.estimate);
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

ForceErrorEstimate estimate_force_error(const std::vector<std::array<double, 2>>& forces) {
  ForceErrorEstimate e;
  const std::size_t k = forces.size();
  if (k < 2) return e;
  const double size = std::hypot(forces[k - 1][0], forces[k - 1][1]);
  if (!(size > 0)) return e;
  const double change = distance(forces[k - 1], forces[k - 2]);
  e.change = change / size;
  e.ratio = kAssumedForceRatio;
  e.estimate = e.change / (e.ratio - 1.0);
  if (k < 3 || !(change > 0)) return e;
  const double previous = distance(forces[k - 2], forces[k - 3]);
  e.ratio = std::clamp(previous / change, kMinForceRatio, kMaxForceRatio);
  e.ratio_observed = true;
  e.estimate = e.change / (e.ratio - 1.0);
  // The changes' components along F_k: of opposite signs, the errors cancel in a change.
  const auto along = [&](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - b[0]) * forces[k - 1][0] + (a[1] - b[1]) * forces[k - 1][1];
  };
  if (along(forces[k - 1], forces[k - 2]) * along(forces[k - 2], forces[k - 3]) < 0) {
    e.monotone = false;
    e.estimate = std::max(change, previous) / size;
  }
  return e;
}

std::string accuracy_stop_reason(const ForceErrorEstimate& e, const AccuracySpec& spec,
                                 const std::vector<std::array<double, 2>>& forces) {
  // A zero force on the first level may be a contact the coarse mesh does not resolve.
  const auto zero = [](const std::array<double, 2>& f) { return !(std::hypot(f[0], f[1]) > 0); };
  if (forces.size() >= 2 && zero(forces.back()) && zero(forces[forces.size() - 2]))
    return "no_force";
  if (e.available() && e.estimate <= spec.force) return "reached";
  return "";
}

nlohmann::json accuracy_json(const CaseSolution& solution, const AccuracySpec& spec) {
  nlohmann::json steps = nlohmann::json::array();
  for (const AdaptiveStepRecord& s : solution.steps)
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
      solution.steps.empty() ? ForceErrorEstimate{} : solution.steps.back().force_error;
  return {{"force", spec.force},
          {"max_dofs", spec.max_dofs},
          {"reached", solution.stop_reason == "reached"},
          {"stop_reason", solution.stop_reason},
          {"estimate", number_or_null(last.estimate)},
          {"steps", steps},
          {"stop_message", stop_message(solution.stop_reason, solution.steps, spec)}};
}

}  // namespace fosls
