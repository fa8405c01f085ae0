#pragma once
// The discretisation rule (docs/method.md §5.1): the algebraic error estimated from the energy
// history (algebraic_error.hpp) is at most `fraction` times the discretisation error estimated
// by J^½. For monotone methods only: a history that does not decrease J says nothing.

#include "solvers/algebraic_error.hpp"
#include "solvers/stopping_criterion.hpp"

namespace fosls {

class AlgebraicErrorStop : public StoppingCriterion {
 public:
  explicit AlgebraicErrorStop(double fraction) : fraction_(fraction) {}
  bool met(const std::vector<IterationRecord>& history, const Vector&) override {
    return algebraic_error_is_small(history, fraction_);
  }
  ConvergedBy reason() const override { return ConvergedBy::kAlgebraicError; }

 private:
  double fraction_;
};

}  // namespace fosls
