#include "solvers/rounding_level_stop.hpp"

#include <algorithm>

namespace fosls {

RoundingLevelStop::RoundingLevelStop(const BoxQp& qp, const Vector& x)
    : qp_(qp), rounding_level_(qp.rounding_level(x)) {}

bool RoundingLevelStop::met(const std::vector<IterationRecord>& history, const Vector& x) {
  const int h = static_cast<int>(history.size());
  if (h < 3) return false;
  const double kkt = history[h - 1].kkt_residual;
  const double before = std::min(history[h - 2].kkt_residual, history[h - 3].kkt_residual);
  if (kkt < 0.5 * before) return false;
  // The level is recomputed at x only near it, or once the residual has fallen by 10⁻⁶: the
  // level of the initial iterate can be far too small when it was 0.
  if (kkt > 1e3 * kRoundingLevelFactor * rounding_level_ && kkt > 1e-6 * history[0].kkt_residual)
    return false;
  rounding_level_ = qp_.rounding_level(x);
  return kkt <= kRoundingLevelFactor * rounding_level_;
}

}  // namespace fosls
