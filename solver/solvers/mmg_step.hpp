#pragma once
// The monotone multilevel method's iteration (docs/method.md §4): one nonlinear cycle.

#include <memory>

#include "solvers/iteration_step.hpp"

namespace fosls {

class MmgStep : public IterationStep {
 public:
  MmgStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o,
          std::shared_ptr<GalerkinChain> chain)
      : cycle_(qp, h, o, std::move(chain)) {}
  void iterate(Vector& x, Vector& r) override { cycle_.nonlinear_cycle(x, r); }
  CycleStatistics statistics() const override { return cycle_.statistics(); }
  void set_sweep_hook(std::function<void(const Vector& x, const Vector& r)> hook) override {
    cycle_.set_sweep_hook(std::move(hook));
  }

 private:
  MultilevelCycle cycle_;
};

}  // namespace fosls
