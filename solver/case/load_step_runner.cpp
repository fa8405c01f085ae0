#include "case/load_step_runner.hpp"

#include "case/sweep_runner.hpp"

namespace fosls {

namespace {

using nlohmann::json;

/// A step's result as the load_steps list keeps it: all but the iteration history.
json step_json(std::size_t step, const json& changes, const json& result) {
  json r = result;
  r.erase("history");
  r["step"] = step;
  r["changes"] = changes;
  return r;
}

}  // namespace

RunOutput run_load_steps(
    const CaseSpec& spec, const RunControl& control,
    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point) {
  json steps = json::array();
  RunOutput last;
  Vector previous;
  std::vector<Point> displacement;
  std::string first_failure;
  std::vector<ResultWarning> warnings;
  const std::size_t n = spec.load_step_points.size() + 1;
  for (std::size_t k = 0; k < n; ++k) {
    RunControl step_control = control;
    step_control.want_vtu = control.want_vtu && k + 1 == n;  // the last step's only
    step_control.start = previous.size() ? &previous : nullptr;
    step_control.reference = displacement.empty() ? nullptr : &displacement;
    last = run_point(k == 0 ? spec : spec.load_step_points[k - 1], step_control);
    if (last.cancelled) return last;
    steps.push_back(
        step_json(k, k == 0 ? json::object() : spec.load_step_changes[k - 1], last.result));
    if (!last.result["converged"].get<bool>()) {
      if (first_failure.empty()) first_failure = last.result["stop_reason"];
      warnings.push_back(
          {"load_step_not_converged", "load step " + std::to_string(k) + " did not converge: " +
                                          last.result.value("message", std::string("no message"))});
    }
    previous = std::move(last.solution);
    displacement = std::move(last.displacement);
  }
  json& r = last.result;
  close_series(r, spec.name, first_failure, warnings, n,
               "load steps did not converge (see warnings and load_steps.steps)");
  r["load_steps"] = {{"count", n}, {"steps", std::move(steps)}};
  last.solution = std::move(previous);
  last.displacement = std::move(displacement);
  return last;
}

}  // namespace fosls
