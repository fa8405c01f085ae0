#pragma once
// The default stopping rule (docs/method.md §5.1): the KKT residual has fallen by the
// tolerance, kkt_k ≤ tolerance · kkt_0.

#include "solvers/stopping_criterion.hpp"

namespace fosls {

class KktResidualStop : public StoppingCriterion {
 public:
  explicit KktResidualStop(double tolerance) : tolerance_(tolerance) {}
  bool met(const std::vector<IterationRecord>& history, const Vector&) override {
    return history.back().kkt_residual <= tolerance_ * history.front().kkt_residual;
  }
  ConvergedBy reason() const override { return ConvergedBy::kKktResidual; }

 private:
  double tolerance_;
};

}  // namespace fosls
