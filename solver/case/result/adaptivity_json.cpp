// The result's `adaptivity` object (level_loop_json.hpp): the steps, and what the result says
// about how the loop ended: the estimator's reduction, the last step's change of the force, and
// a sentence saying why the loop stopped and what adaptivity.target means (a reduction of the
// estimator, not an accuracy).

#include <cmath>

#include "case/result/level_loop_json.hpp"
#include "case/result/result_warnings.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

namespace {

std::string num(double v, int digits = 3) { return sentence_number(v, digits); }

double estimator_reduction(const std::vector<AdaptiveStepRecord>& steps) {
  const double first = steps.front().estimator;
  return first > 0 ? steps.back().estimator / first : 0.0;
}

/// |F_k − F_(k−1)| / |F_k| of the last step; null for one step or a zero force.
nlohmann::json last_force_change(const std::vector<AdaptiveStepRecord>& steps) {
  if (steps.size() < 2) return nullptr;
  const ForceComponents& a = steps[steps.size() - 2].force;
  const ForceComponents& b = steps.back().force;
  const double size = force_norm(b);
  if (!(size > 0)) return nullptr;
  ForceComponents change = b;
  for (std::size_t i = 0; i < change.size(); ++i) change[i] -= a[i];
  return force_norm(change) / size;
}

std::string why(const std::string& reason, const AdaptivitySpec& a) {
  if (reason == "steps")
    return "the " + std::to_string(a.steps) + " refinement steps were made (adaptivity.steps)";
  if (reason == "max_dofs")
    return "the next refinement would exceed adaptivity.max_dofs = " + std::to_string(a.max_dofs);
  if (reason == "target")
    return "the estimator reached adaptivity.target = " + num(a.target) +
           " of its first value (or vanished)";
  if (reason == "not_converged")
    return "a solve did not converge (marking from it would refine where the algebraic error is)";
  if (reason == "time_limit") return "solver.time_limit_s ran out";
  if (reason == "cancelled") return "the run was cancelled";
  return reason;
}

/// Adds estimator_reduction, last_force_change and stop_message to an adaptivity object.
void add_adaptive_summary(nlohmann::json& adaptivity, const std::vector<AdaptiveStepRecord>& steps,
                          const std::string& stop_reason, const AdaptivitySpec& spec) {
  if (steps.empty()) return;
  const double reduction = estimator_reduction(steps);
  const nlohmann::json change = last_force_change(steps);
  adaptivity["estimator_reduction"] = reduction;
  adaptivity["last_force_change"] = change;
  std::string m = "stopped: " + why(stop_reason, spec) + ". The estimator J^1/2 fell to " +
                  num(reduction) + " of its value on the starting mesh";
  if (change.is_number())
    m += "; the force changed by " + num(100.0 * change.get<double>(), 2) + " % in the last step";
  m += ". adaptivity.target is such a reduction of the estimator (an energy-type error of the "
       "whole solution), not the relative accuracy of the force or the pressure";
  adaptivity["stop_message"] = m;
}

}  // namespace

nlohmann::json adaptivity_json(const std::vector<AdaptiveStepRecord>& records,
                               const std::string& stop_reason, const AdaptivitySpec& spec,
                               int dim) {
  nlohmann::json steps = nlohmann::json::array();
  for (const AdaptiveStepRecord& s : records)
    steps.push_back(
        {{"step", s.step},
         {"levels", s.levels},
         {"dofs", s.dofs},
         {"dofs_total", s.dofs_total},
         {dim == 2 ? "triangles" : "tetrahedra", s.cells},
         {"estimator", s.estimator},
         {"force", s.force},
         {"iterations", s.iterations},
         {"converged", s.converged},
         {"converged_by", converged_by_name(s.converged_by)},
         {"algebraic_error",
          std::isfinite(s.algebraic_error) ? nlohmann::json(s.algebraic_error) : nlohmann::json()},
         {"marked", s.marked},
         {"time_s", s.time_s}});
  nlohmann::json a = {{"theta", spec.theta},
                      {"max_dofs", spec.max_dofs},
                      {"target", spec.target},
                      {"stop_reason", stop_reason},
                      {"steps", steps}};
  add_adaptive_summary(a, records, stop_reason, spec);
  return a;
}

}  // namespace fosls
