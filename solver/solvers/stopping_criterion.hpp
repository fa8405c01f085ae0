#pragma once
// A test that ends a solve as converged (docs/method.md §5.1, §5.2): the solve loop asks its
// criteria in order after every iteration and stops at the first that is met. The criteria:
// kkt_residual_stop.hpp, algebraic_error_stop.hpp, rounding_level_stop.hpp.

#include <vector>

#include "core/box_qp.hpp"
#include "solvers/iteration_record.hpp"

namespace fosls {

/// Which test a converged solve met. kRoundingLevel: the KKT residual stalled within a small
/// factor of the level that rounding in r = b − A x allows (BoxQp::rounding_level) before it
/// reached the tolerance.
enum class ConvergedBy { kNone, kKktResidual, kAlgebraicError, kRoundingLevel };

/// "kkt_residual", "algebraic_error", "rounding_level" or "none" (result JSON's converged_by).
const char* converged_by_name(ConvergedBy c);

class StoppingCriterion {
 public:
  virtual ~StoppingCriterion() = default;
  /// Whether the solve has converged at x, the iterate of history.back() (history[0] is the
  /// initial iterate's record).
  virtual bool met(const std::vector<IterationRecord>& history, const Vector& x) = 0;
  /// What the result reports when this criterion ended the solve.
  virtual ConvergedBy reason() const = 0;
};

}  // namespace fosls
