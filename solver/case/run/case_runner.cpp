#include "case/run/case_runner.hpp"

#include <chrono>
#include <sstream>

#include "case/admission/case_admission.hpp"
#include "case/run/case_mesh.hpp"
#include "case/run/load_step_runner.hpp"
#include "case/run/point_runner.hpp"
#include "case/run/sweep_runner.hpp"
#include "core/non_finite.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;

/// What a run stopped by its time limit before the first iterate says (no result to return).
std::string time_limit_message(const CaseSpec& spec, const std::string& stage) {
  std::ostringstream m;
  m << "solver.time_limit_s (" << spec.solver.time_limit_s << " s) ran out while " << stage
    << ", before the solve had a first iterate, so there is no result to return; raise "
       "solver.time_limit_s, or use fewer mesh.refinements or a coarser mesh.size";
  if (!spec.sweep_points.empty()) m << " (each sweep point has the whole limit)";
  return m.str();
}

}  // namespace

Deadline run_deadline(Clock::time_point start, double time_limit_s) {
  if (time_limit_s <= 0) return {};
  return Deadline(start + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(time_limit_s)));
}

std::vector<CaseError> validate_case(const nlohmann::json& j, const CaseReadOptions& options,
                                     const MeshingControl& meshing) {
  CaseReadResult read = read_case(j, options);
  if (!read.errors.empty()) return read.errors;
  // The groups' rule here in 3D, before the mesh: 2D's is part of check_case_mesh.
  if (read.spec->dimension == 3)
    if (auto errors = check_against_groups(*read.spec, std::nullopt, ProblemCount{}, CaseLimits{});
        !errors.empty())
      return errors;
  return check_case_mesh(*read.spec, meshing, options.limits);
}

int most_solves(const CaseSpec& spec) {
  if (spec.accuracy) return 0;
  const std::size_t points = !spec.load_step_points.empty() ? spec.load_step_points.size() + 1
                             : !spec.sweep_points.empty()   ? spec.sweep_points.size()
                                                            : 1;
  const int per_point = spec.adaptivity ? spec.adaptivity->steps + 1 : 1;
  return static_cast<int>(points) * per_point;
}

RunOutput run_case(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
  // Every solve of every point starts with on_step (solve_levels), so counting its calls
  // numbers the solves of the whole run; the series runners need not know.
  RunControl counted = control;
  int solves = 0;
  if (control.on_solve)
    counted.on_step = [&control, &solves, most = most_solves(spec)](int step, long long dofs) {
      if (control.on_step) control.on_step(step, dofs);
      control.on_solve(solves++, most);
    };
  try {
    // One point of either dimension; load steps and sweeps repeat it.
    const auto point = [&limits](const CaseSpec& s, const RunControl& c) {
      return s.dimension == 3 ? run_point<3>(s, c, limits) : run_point<2>(s, c, limits);
    };
    if (!spec.load_step_points.empty()) return run_load_steps(spec, counted, point);
    if (spec.sweep_points.empty()) return point(spec, counted);
    return run_sweep(spec, counted, point);
  } catch (const TimeLimitReached& e) {
    throw TimeLimitReached(e.stage(), time_limit_message(spec, e.stage()));
  } catch (const NonFiniteError& e) {
    throw CaseException({non_finite_problem(e.what())});
  }
}

}  // namespace fosls
