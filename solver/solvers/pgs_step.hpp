#pragma once
// Projected Gauss–Seidel on the finest level alone, by the chosen smoother (pointwise or by
// vertex patches): the single-level comparison method.

#include <memory>

#include "core/level_hierarchy.hpp"
#include "solvers/iteration_step.hpp"

namespace fosls {

class PgsStep : public IterationStep {
 public:
  PgsStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o);
  void iterate(Vector& x, Vector& r) override;
  CycleStatistics statistics() const override;

 private:
  const BoxQp& qp_;
  std::unique_ptr<Smoother> smoother_;
};

}  // namespace fosls
