#pragma once
// The rounding-level rule (docs/method.md §5.2): a tolerance relative to a small initial
// residual (a prolongated or continued start) can lie below what double precision can show,
// and the residual then stalls near the rounding level of r = b − A x (BoxQp::rounding_level)
// instead of reaching it. A solve stops, converged, once its residual is within
// kRoundingLevelFactor of that level and has also stalled: it did not halve against the better
// of the two iterations before, so a residual still falling fast reaches its tolerance as
// before.

#include "solvers/stopping_criterion.hpp"

namespace fosls {

/// A solve whose KKT residual has stalled within this factor of the rounding level has converged
/// as far as double precision can tell (docs/method.md §5.2).
constexpr double kRoundingLevelFactor = 10.0;

class RoundingLevelStop : public StoppingCriterion {
 public:
  /// x: the initial iterate, whose rounding level is the first estimate.
  RoundingLevelStop(const BoxQp& qp, const Vector& x);
  bool met(const std::vector<IterationRecord>& history, const Vector& x) override;
  ConvergedBy reason() const override { return ConvergedBy::kRoundingLevel; }

 private:
  const BoxQp& qp_;
  double rounding_level_;
};

}  // namespace fosls
