#pragma once
// What a run's control (case_runner.hpp) asks of the solve loop (adaptive_runner.hpp): its
// progress, cancel and time limit, the same for a 2D and a 3D point.

#include "case/run/case_runner.hpp"
#include "case/strategy/adaptive_runner.hpp"

namespace fosls {

/// The loop's observers from `control`, with the run's `deadline`; `control` must outlive them
/// (the cancel check reads its flag).
CaseSolveObserver solve_observer(const RunControl& control, const Deadline& deadline);

}  // namespace fosls
