#pragma once
// A case with a sweep: its points solved in order, each starting from the previous point's
// solution (continuation), and one result that holds the last point's fields and the curve
// (docs/result-format.md, `sweep`).

#include <functional>

#include "case/case_runner.hpp"

namespace fosls {

/// Runs spec.sweep_points with `run_point` (one point, as run_case without a sweep). The
/// result is the last point's, with `sweep.points` for all of them; `converged` and
/// `stop_reason` say whether every point converged. A cancel ends the sweep at once.
RunOutput run_sweep(const CaseSpec& spec, const RunControl& control,
                    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point);

}  // namespace fosls
