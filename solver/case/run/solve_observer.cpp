#include "case/run/solve_observer.hpp"

namespace fosls {

LevelLoopObserver solve_observer(const RunControl& control, const Deadline& deadline) {
  LevelLoopObserver observer;
  if (control.on_iteration) observer.solver.on_iteration = control.on_iteration;
  if (control.cancel)
    observer.solver.cancelled = [&control] {
      return control.cancel->load(std::memory_order_relaxed);
    };
  if (deadline.is_set()) observer.solver.out_of_time = [deadline] { return deadline.passed(); };
  observer.deadline = deadline;
  observer.on_step = control.on_step;
  return observer;
}

}  // namespace fosls
