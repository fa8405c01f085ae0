#pragma once
// A case with load steps: the case as given (step 0) and then each step's state, solved in
// order on one mesh, each from the previous step's solution and with friction measuring slip
// from the previous step's displacement; one result that holds the last step's fields and every
// step's result (docs/result-format.md, `load_steps`).

#include <functional>

#include "case/run/case_runner.hpp"

namespace fosls {

/// Runs the case and then spec.load_step_points with `run_point` (one state, as run_case
/// without load steps). `converged` and `stop_reason` say whether every step converged. A
/// cancel ends the run at once.
RunOutput run_load_steps(
    const CaseSpec& spec, const RunControl& control,
    const std::function<RunOutput(const CaseSpec&, const RunControl&)>& run_point);

}  // namespace fosls
