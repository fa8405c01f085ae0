#include "solvers/pgs_step.hpp"

namespace fosls {

PgsStep::PgsStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o)
    : qp_(qp), smoother_(smoother_info(o.smoother).make(qp.A, h.levels.back())) {}

void PgsStep::iterate(Vector& x, Vector& r) { smoother_->sweep(x, r, qp_.lower, qp_.upper, true); }

CycleStatistics PgsStep::statistics() const {
  CycleStatistics s;
  s.double_precision_smoothers = smoother_->double_precision_factors() ? 1 : 0;
  return s;
}

}  // namespace fosls
