#pragma once
// What a run's control (case_runner.hpp) asks of the solve loop (strategy/level_loop.hpp): its
// progress, cancel and time limit, the same for a 2D and a 3D point.

#include "case/run/case_runner.hpp"
#include "strategy/level_loop.hpp"

namespace fosls {

/// The loop's observers from `control`, with the run's `deadline`; `control` must outlive them
/// (the cancel check reads its flag).
LevelLoopObserver solve_observer(const RunControl& control, const Deadline& deadline);

}  // namespace fosls
