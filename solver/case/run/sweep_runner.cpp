#include "case/run/sweep_runner.hpp"

#include "case/result/result_warnings.hpp"

namespace fosls {

namespace {

using nlohmann::json;

json warning_codes_of(const json& r) {
  json codes = json::array();
  for (const auto& w : r["warning_details"]) codes.push_back(w["code"]);
  return codes;
}

/// What a force–indentation (or any parameter) curve needs of one point: the zone's length and
/// width along a 2D contact boundary, its radius on a 3D one.
json point_json(double value, const json& r) {
  const json& contact = r["contact"];
  const json& zone = contact["zone"];
  json point = {
      {"value", value}, {"force", contact["force"]}, {"peak_pressure", zone["peak_pressure"]}};
  if (r.value("dimension", 2) == 3) {
    point["contact_radius"] = zone["radius"];
  } else {
    point["contact_length"] = zone["length"];
    point["contact_width"] = zone["width"];
  }
  point["converged"] = r["converged"];
  point["stop_reason"] = r["stop_reason"];
  point["converged_by"] = r["stopping"]["converged_by"];
  point["iterations"] = r["iterations"];
  point["warning_codes"] = warning_codes_of(r);
  return point;
}

}  // namespace

void close_series(json& r, const std::string& name, const std::string& first_failure,
                  const std::vector<ResultWarning>& warnings, std::size_t n,
                  const std::string& what) {
  r["name"] = name;
  r["converged"] = first_failure.empty();
  r["stop_reason"] = first_failure.empty() ? "converged" : first_failure;
  if (!first_failure.empty() && !r.contains("message"))
    r["message"] = std::to_string(warnings.size()) + " of " + std::to_string(n) + " " + what;
  add_warnings(r, warnings);
}

RunOutput run_sweep(const CaseSpec& spec, const RunControl& control,
                    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point) {
  json points = json::array();
  RunOutput last;
  Vector previous;
  std::string first_failure;  // stop_reason of the first point that did not converge
  std::vector<ResultWarning> warnings;
  const std::size_t n = spec.sweep_points.size();
  for (std::size_t i = 0; i < n; ++i) {
    RunControl point_control = control;
    point_control.want_vtu = control.want_vtu && i + 1 == n;  // the last point's only
    point_control.start = previous.size() ? &previous : nullptr;
    last = run_point(spec.sweep_points[i], point_control);
    if (last.cancelled) return last;
    const double value = spec.sweep->values[i];
    points.push_back(point_json(value, last.result));
    if (!last.result["converged"].get<bool>()) {
      if (first_failure.empty()) first_failure = last.result["stop_reason"];
      warnings.push_back({"sweep_point_not_converged",
                          "sweep point " + std::to_string(i) + " (" + spec.sweep->pointer + " = " +
                              json(value).dump() + ") did not converge: " +
                              last.result.value("message", std::string("no message"))});
    }
    previous = std::move(last.solution);
  }
  json& r = last.result;
  close_series(r, spec.name, first_failure, warnings, n,
               "sweep points did not converge (see warnings and sweep.points)");
  r["sweep"] = {{"pointer", spec.sweep->pointer}, {"points", std::move(points)}};
  last.solution = std::move(previous);
  return last;
}

}  // namespace fosls
