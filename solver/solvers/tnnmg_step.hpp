#pragma once
// Truncated non-smooth Newton multigrid (Gräser & Kornhuber): non-linear smoothing, one
// truncated linear cycle (V, W or F, as the multilevel method's) on the inactive set,
// projection onto the bounds, exact line search on J.

#include <memory>

#include "solvers/iteration_step.hpp"

namespace fosls {

class TnnmgStep : public IterationStep {
 public:
  TnnmgStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o,
            std::shared_ptr<GalerkinChain> chain)
      : qp_(qp), options_(o), cycle_(qp, h, o, std::move(chain)) {}
  void iterate(Vector& x, Vector& r) override;
  CycleStatistics statistics() const override { return cycle_.statistics(); }

 private:
  const BoxQp& qp_;
  MultilevelOptions options_;
  MultilevelCycle cycle_;
};

}  // namespace fosls
