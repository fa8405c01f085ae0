#pragma once
// A case with a sweep: its points solved in order, each starting from the previous point's
// solution (continuation), and one result that holds the last point's fields and the curve
// (docs/result-format.md, `sweep`).

#include <functional>

#include "case/result/result_warnings.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {

/// The outcome of a series of solves (a sweep's points, load steps) in its last result `r`: the
/// case's name, converged only if every solve did, the first failure's stop_reason, a message
/// counting the failures ("<k> of <n> <what>") and the series' warnings.
void close_series(nlohmann::json& r, const std::string& name, const std::string& first_failure,
                  const std::vector<ResultWarning>& warnings, std::size_t n,
                  const std::string& what);

/// Runs spec.sweep_points with `run_point` (one point, as run_case without a sweep). The
/// result is the last point's, with `sweep.points` for all of them; `converged` and
/// `stop_reason` say whether every point converged. A cancel ends the sweep at once.
RunOutput run_sweep(const CaseSpec& spec, const RunControl& control,
                    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point);

}  // namespace fosls
