#include "case/admission/job_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "case/admission/resource_estimate.hpp"
#include "case/admission/time_estimate.hpp"
#include "case/format/solver_methods.hpp"

namespace fosls {

namespace {

/// An adaptive run is taken as this many solves at its largest size (steps + 1 if fewer): its
/// levels grow step by step, so most of its solves are far smaller than the last.
constexpr double kAdaptiveSolves = 3.0;

/// The iterations a solve of `point` is priced at: the fits' count, or fewer when
/// solver.max_iterations stops it first; with friction every one max_iterations allows, since
/// Coulomb's slip bounds are a fixed point the method does not bound (docs/method.md §8: 20–47
/// iterations where it settles, not within 200 at 5 refinements of the Hertz case).
int priced_iterations(const CaseSpec& point, int fitted) {
  const int most = point.solver.max_iterations;
  return has_friction(point) ? most : std::min(most, fitted);
}

/// Seconds of one solve of `point` on `count`: the fitted estimate scaled to its priced
/// iterations, or for pgs the set-up and every iteration solver.max_iterations allows.
double solve_seconds(const CaseSpec& point, const ProblemCount& count) {
  const SolverOptions& solver = point.solver;
  if (auto s = estimated_seconds(count, solver.method)) {
    const int fitted = fitted_iterations(solver.method, count.dimension);
    const double share = setup_share(solver.method, count.dimension);
    return *s * (share + (1.0 - share) * priced_iterations(point, fitted) / fitted);
  }
  // Mesh and assembly as measured with pgs (docs/service.md, "Time limits").
  return 0.1 + 3e-6 * static_cast<double>(count.unknowns) +
         solver.max_iterations * pgs_seconds_per_iteration(count.unknowns);
}

/// `count` with `unknowns` on the finest level (a larger level of the same hierarchy).
ProblemCount with_unknowns(ProblemCount count, long long unknowns) {
  count.unknowns = unknowns;
  return count;
}

/// One sweep point (or the case without a sweep): its solves, bounded by its time limit.
double point_seconds(const CaseSpec& point, const ProblemCount& count, bool& bounded) {
  double seconds = solve_seconds(point, count);
  if (point.adaptivity && point.adaptivity->steps > 0) {
    const long long largest = std::max(count.unknowns, point.adaptivity->max_dofs);
    seconds = solve_seconds(point, with_unknowns(count, largest)) *
              std::min(kAdaptiveSolves, point.adaptivity->steps + 1.0);
  }
  // The accuracy loop's levels grow by 4: all of them take about 4/3 of the largest.
  if (point.accuracy) {
    const long long largest = accuracy_largest_unknowns(count.unknowns, point.accuracy->max_dofs);
    seconds = solve_seconds(point, with_unknowns(count, largest)) * 4.0 / 3.0;
  }
  const double limit = point.solver.time_limit_s;
  bounded = limit > 0 && limit < seconds;
  return bounded ? limit : seconds;
}

}  // namespace

std::string budget_text(double seconds) {
  char text[48];
  if (seconds >= 3600 && std::fmod(seconds, 3600) == 0)
    std::snprintf(text, sizeof text, "%g h", seconds / 3600);
  else if (seconds >= 120 && std::fmod(seconds, 60) == 0)
    std::snprintf(text, sizeof text, "%g min", seconds / 60);
  else
    std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

namespace {

/// "about 55 h: 100 sweep points, each up to 100000 pgs iterations of about 0.02 s on about
/// 131200 unknowns".
std::string describe_time(const CaseTimeEstimate& e, const CaseSpec& spec,
                          const ProblemCount& count) {
  const long long unknowns = count.unknowns;
  const SolverOptions& solver =
      spec.sweep_points.empty() ? spec.solver : spec.sweep_points[0].solver;
  std::string text = describe_seconds(e.seconds) + ": ";
  if (e.points > 1)
    text += std::to_string(e.points) +
            (spec.load_step_points.empty() ? " sweep points, each " : " load steps, each ");
  if (e.bounded_by_time_limit) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", solver.time_limit_s);
    return text + "stopped by solver.time_limit_s " + limit + " s";
  }
  const std::string method = method_info(solver.method).name;
  if (solver.method == SolverMethod::kPgs)
    return text + "up to " + std::to_string(solver.max_iterations) + " pgs iterations (" +
           describe_seconds(pgs_seconds_per_iteration(unknowns)) + " each) on about " +
           std::to_string(unknowns) + " unknowns";
  if (spec.accuracy)
    return text + method + " on levels of up to " +
           std::to_string(accuracy_largest_unknowns(unknowns, spec.accuracy->max_dofs)) +
           " DOFs (accuracy.max_dofs), all levels together about 4/3 of the largest";
  if (has_friction(spec))
    return text + "up to " + std::to_string(solver.max_iterations) + " " + method +
           " iterations (solver.max_iterations: with friction the slip bounds may need every "
           "one) on about " +
           std::to_string(unknowns) + " unknowns";
  return text + method + " on about " + std::to_string(unknowns) + " unknowns";
}

/// What to change: methods that converge on fine meshes and fit, then the case's sizes.
std::string advice(const CaseTimeEstimate& e, const CaseSpec& spec, const ProblemCount& count,
                   double budget_seconds) {
  std::vector<std::string> options;
  const SolverMethod method = spec.solver.method;
  for (const MethodInfo& m : solver_methods()) {
    if (m.method == method || !converges_on_fine_meshes(m.method) || !method_solves(m.method, spec))
      continue;
    CaseSpec other = spec;
    other.solver.method = m.method;
    for (CaseSpec& point : other.sweep_points) point.solver.method = m.method;
    const CaseTimeEstimate t = estimate_case_time(other, count);
    if (t.seconds <= budget_seconds)
      options.push_back("solver.method " + std::string(m.name) + " (" +
                        describe_seconds(t.seconds) + " in all)");
  }
  if (e.points > 1) options.push_back("fewer sweep values");
  if (method == SolverMethod::kPgs || has_friction(spec))
    options.push_back("fewer solver.max_iterations");
  if (spec.accuracy)
    options.push_back("a larger accuracy.force or a lower accuracy.max_dofs");
  else
    options.push_back(spec.dimension == 3 ? "fewer refinements or a coarser mesh"
                                          : "fewer refinements or a coarser mesh.size");
  options.push_back(e.bounded_by_time_limit ? "a lower solver.time_limit_s"
                    : spec.accuracy
                        ? "a solver.time_limit_s (the loop then stops at it with the last "
                          "level solved)"
                        : "a solver.time_limit_s (each solve then stops at it with its last "
                          "iterate)");
  std::string text = "use ";
  for (std::size_t i = 0; i < options.size(); ++i)
    text += (i == 0 ? "" : i + 1 == options.size() ? ", or " : ", ") + options[i];
  return text;
}

}  // namespace

double pgs_seconds_per_iteration(long long unknowns) {
  // Measured on the Signorini square on two cores (docs/service.md, "Time limits").
  return 0.15e-6 * static_cast<double>(unknowns);
}

CaseTimeEstimate estimate_case_time(const CaseSpec& spec, const ProblemCount& count) {
  const long long unknowns = count.unknowns;
  CaseTimeEstimate e;
  // Load steps: the case as given and every step, one solve each.
  std::vector<CaseSpec> single =
      spec.sweep_points.empty() ? std::vector<CaseSpec>{spec} : std::vector<CaseSpec>{};
  if (spec.sweep_points.empty())
    single.insert(single.end(), spec.load_step_points.begin(), spec.load_step_points.end());
  const std::vector<CaseSpec>& points = spec.sweep_points.empty() ? single : spec.sweep_points;
  e.points = static_cast<int>(points.size());
  bool all_bounded = true;
  for (const CaseSpec& point : points) {
    bool bounded = false;
    e.seconds += point_seconds(point, count, bounded);
    all_bounded &= bounded;
  }
  e.bounded_by_time_limit = all_bounded;
  // solver.time_limit_s bounds the whole run of load steps (load_step_runner.cpp).
  const double limit = spec.solver.time_limit_s;
  if (!spec.load_step_points.empty() && limit > 0 && e.seconds > limit) {
    e.seconds = limit;
    e.bounded_by_time_limit = true;
  }
  const bool adaptive_size =
      spec.adaptivity && spec.adaptivity->steps > 0 && spec.adaptivity->max_dofs > unknowns;
  const bool accuracy_size =
      spec.accuracy && accuracy_largest_unknowns(unknowns, spec.accuracy->max_dofs) > unknowns;
  e.limited_by = e.bounded_by_time_limit ? "/solver/time_limit_s"
                 : spec.solver.method == SolverMethod::kPgs || has_friction(spec)
                     ? "/solver/max_iterations"
                 : e.points > 1 && !spec.load_step_points.empty() ? "/load_steps"
                 : e.points > 1                                   ? "/sweep/values"
                 : adaptive_size                                  ? "/adaptivity/max_dofs"
                 : accuracy_size                                  ? "/accuracy/max_dofs"
                                                                  : "/mesh/refinements";
  return e;
}

std::optional<CaseError> check_time_budget(const CaseTimeEstimate& estimate, const CaseSpec& spec,
                                           const ProblemCount& count, double budget_seconds,
                                           const std::string& budget_name) {
  if (budget_seconds <= 0 || estimate.seconds <= budget_seconds) return std::nullopt;
  return CaseError{estimate.limited_by, "the case needs " + describe_time(estimate, spec, count) +
                                            ", more than the " + budget_text(budget_seconds) + " " +
                                            budget_name + "; " +
                                            advice(estimate, spec, count, budget_seconds)};
}

double job_time_limit_seconds(double estimate_seconds, double cap_seconds) {
  if (cap_seconds <= 0) return 0;
  return std::min(cap_seconds, std::max(kJobTimeFloorSeconds, kJobTimeMargin * estimate_seconds));
}

}  // namespace fosls
