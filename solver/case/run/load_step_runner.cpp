#include "case/run/load_step_runner.hpp"

#include <chrono>

#include "case/format/case_error.hpp"
#include "case/run/sweep_runner.hpp"
#include "core/deadline.hpp"
#include "core/non_finite.hpp"

namespace fosls {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

/// A step's result as the load_steps list keeps it: all but the iteration history.
json step_json(std::size_t step, const json& changes, const json& result) {
  json r = result;
  r.erase("history");
  r["step"] = step;
  r["changes"] = changes;
  return r;
}

/// Step k as it is solved: the case as given (k = 0) or step k's state with the case's mesh
/// (the reader keeps the mesh once, since no step may change it), and solver.time_limit_s cut
/// to what the steps before it left, so that the limit bounds the whole run.
CaseSpec step_spec(const CaseSpec& spec, std::size_t k, double seconds_left) {
  CaseSpec step = k == 0 ? spec : spec.load_step_points[k - 1];
  if (k > 0) step.mesh = spec.mesh;
  step.load_step_points.clear();
  if (spec.solver.time_limit_s > 0) step.solver.time_limit_s = seconds_left;
  return step;
}

/// Why the run stopped before solving step k, when it did.
struct StepStop {
  std::string reason;   ///< "time_limit" or "step_failed"
  std::string message;  ///< what a person reads
};

std::string step_errors_text(std::size_t k, const std::vector<CaseError>& errors) {
  std::string text = "load step " + std::to_string(k) + " could not be solved: ";
  for (std::size_t i = 0; i < errors.size(); ++i)
    text += (i ? "; " : "") + (errors[i].pointer.empty() ? "/" : errors[i].pointer) + ": " +
            errors[i].detail;
  return text;
}

/// Solves step k, or says why it could not be solved. The case as given (k = 0) has no
/// solved steps to keep, so its failures propagate as the run's.
std::optional<StepStop> solve_step(const std::function<RunOutput()>& run, std::size_t k,
                                   RunOutput& out) {
  try {
    out = run();
    return std::nullopt;
  } catch (const TimeLimitReached& e) {
    if (k == 0) throw;
    return StepStop{"time_limit", "solver.time_limit_s ran out during load step " +
                                      std::to_string(k) + " (" + e.stage() + ")"};
  } catch (const CaseException& e) {
    if (k == 0) throw;
    return StepStop{"step_failed", step_errors_text(k, e.errors())};
  } catch (const NonFiniteError& e) {
    if (k == 0) throw;
    return StepStop{"step_failed", "load step " + std::to_string(k) + ": " + e.what()};
  }
}

/// The result of a run that stopped at step k: the last solved step's fields, not converged,
/// with the reason, a warning that asks for review, and the steps solved so far kept.
void close_partial(json& r, const CaseSpec& spec, std::size_t k, const StepStop& stop) {
  r["name"] = spec.name;
  r["converged"] = false;
  r["stop_reason"] = stop.reason;
  if (stop.reason == "cancelled") r["cancelled"] = true;
  r["message"] = stop.message + "; the result holds the " + std::to_string(k) +
                 " steps solved before it (load_steps.steps), the last one's fields at the top";
  add_warnings(r, {{"load_steps_partial", r["message"].get<std::string>(), true}});
}

/// What a cancel during step k says.
StepStop cancelled_during(std::size_t k) {
  return {"cancelled", "the run was cancelled during load step " + std::to_string(k)};
}

/// The run's result after the steps in `steps`, the last of which gave `last`: complete, or
/// stopped before the next step by `stop`.
json series_result(const CaseSpec& spec, const json& last, json steps, const std::string& failure,
                   const std::vector<ResultWarning>& warnings,
                   const std::optional<StepStop>& stop) {
  json r = last;
  const std::size_t solved = steps.size();
  close_series(r, spec.name, failure, warnings, spec.load_step_points.size() + 1,
               "load steps did not converge (see warnings and load_steps.steps)");
  if (stop) close_partial(r, spec, solved, *stop);
  r["load_steps"] = {{"count", solved}, {"steps", std::move(steps)}};
  if (stop) r["load_steps"]["stopped_before"] = {{"step", solved}, {"reason", stop->reason}};
  return r;
}

}  // namespace

RunOutput run_load_steps(
    const CaseSpec& spec, const RunControl& control,
    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point) {
  const Clock::time_point t0 = Clock::now();
  json steps = json::array();
  RunOutput last;
  Vector previous;
  std::vector<Point> displacement;
  std::string first_failure;
  std::vector<ResultWarning> warnings;
  std::optional<StepStop> stop;
  const std::size_t n = spec.load_step_points.size() + 1;
  for (std::size_t k = 0; k < n && !stop; ++k) {
    const double left =
        spec.solver.time_limit_s - std::chrono::duration<double>(Clock::now() - t0).count();
    if (k > 0 && spec.solver.time_limit_s > 0 && left <= 0) {
      stop = StepStop{"time_limit",
                      "solver.time_limit_s ran out before load step " + std::to_string(k)};
      break;
    }
    RunControl step_control = control;
    step_control.want_vtu = control.want_vtu && k + 1 == n;  // the last step's only
    step_control.start = previous.size() ? &previous : nullptr;
    step_control.reference = displacement.empty() ? nullptr : &displacement;
    RunOutput solved;
    stop = solve_step([&] { return run_point(step_spec(spec, k, left), step_control); }, k, solved);
    if (stop) break;
    if (solved.cancelled) {
      if (k == 0) return solved;  // nothing solved to keep
      stop = cancelled_during(k);
      break;
    }
    last = std::move(solved);
    steps.push_back(
        step_json(k, k == 0 ? json::object() : spec.load_step_changes[k - 1], last.result));
    if (!last.result["converged"].get<bool>()) {
      if (first_failure.empty()) first_failure = last.result["stop_reason"];
      warnings.push_back(
          {"load_step_not_converged", "load step " + std::to_string(k) + " did not converge: " +
                                          last.result.value("message", std::string("no message"))});
    }
    // What a cancel (or a kill) before the next step would leave: the solved steps, kept.
    if (control.on_partial && k + 1 < n)
      control.on_partial(series_result(spec, last.result, steps, first_failure, warnings,
                                       cancelled_during(k + 1)));
    previous = std::move(last.solution);
    displacement = std::move(last.displacement);
  }
  last.result = series_result(spec, last.result, std::move(steps), first_failure, warnings, stop);
  last.cancelled = stop && stop->reason == "cancelled";
  if (last.cancelled) last.vtu.clear();  // a VTU is the last step's only
  last.solution = std::move(previous);
  last.displacement = std::move(displacement);
  return last;
}

}  // namespace fosls
