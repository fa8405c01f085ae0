#pragma once
// One iteration of a solver method, the part the solve loop (solve_loop.hpp) takes from the
// method: mmg_step.hpp, tnnmg_step.hpp, pdas_step.hpp, pgs_step.hpp. The loop owns the rest —
// the residual recomputation, the subspace acceleration, the history, the stopping criteria, the
// observer — so a new method is a new step (docs/architecture.md, "Where to add").

#include <functional>

#include "core/box_qp.hpp"
#include "solvers/multilevel_cycle.hpp"

namespace fosls {

class IterationStep {
 public:
  virtual ~IterationStep() = default;
  /// x and r = b − A x in, the next iterate and its residual out.
  virtual void iterate(Vector& x, Vector& r) = 0;
  virtual CycleStatistics statistics() const { return {}; }
  /// Called after every fine-level smoother sweep with the current iterate and residual, by the
  /// steps that sweep within an iteration (SolverObserver::on_sweep); others ignore it.
  virtual void set_sweep_hook(std::function<void(const Vector& x, const Vector& r)>) {}
};

}  // namespace fosls
