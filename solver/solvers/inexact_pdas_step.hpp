#pragma once
// pdas with multilevel cycles as its inner solve (issue 49, item 2; docs/method.md §8.4): the
// active-set test of the exact step (pdas_active_set.hpp), then, instead of the factorisation,
// a few linear multilevel cycles on A x = b with the active DOFs held at their bounds and the
// others free, warm-started from the current iterate. Newton's step is solved inexactly, so
// its cost per iteration is mmg's (no factorisation of the whole problem, mmg's memory), and
// its convergence is no longer Newton's where the cycles leave the step far from solved.
// Like the exact step, not a feasible-path method.

#include <memory>

#include "solvers/iteration_step.hpp"
#include "solvers/pdas_active_set.hpp"

namespace fosls {

class InexactPdasStep : public IterationStep {
 public:
  /// `cycles` linear cycles (of `options.cycle`'s shape) per Newton step, on `chain` (formed
  /// when not given); the cycle's rules about the chain's second-finest matrix hold
  /// (multilevel_cycle.hpp).
  InexactPdasStep(const BoxQp& qp, const LevelHierarchy& hierarchy,
                  const MultilevelOptions& options, std::shared_ptr<GalerkinChain> chain,
                  int cycles);
  ~InexactPdasStep() override;
  void iterate(Vector& x, Vector& r) override;
  CycleStatistics statistics() const override { return cycle_.statistics(); }
  /// TEMPORARY (experiment): the cycles run so far.
  int cycles_run() const { return cycles_run_; }

 private:
  const BoxQp& qp_;
  PdasActiveSet test_;
  MultilevelCycle cycle_;
  int cycles_;
  int cycles_run_ = 0;
};

}  // namespace fosls
