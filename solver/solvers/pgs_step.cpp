#include "solvers/pgs_step.hpp"

namespace fosls {

PgsStep::PgsStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o) : qp_(qp) {
  if (o.smoother == SmootherType::kPatch)
    patch_ =
        std::make_unique<PatchSmoother>(qp.A, h.levels.back().patches, h.levels.back().patch_split);
  else
    point_ = std::make_unique<PointSmoother>(qp.A);
}

void PgsStep::iterate(Vector& x, Vector& r) {
  if (patch_)
    patch_->sweep(x, r, qp_.lower, qp_.upper, true);
  else
    point_->sweep(x, r, qp_.lower, qp_.upper, true);
}

CycleStatistics PgsStep::statistics() const {
  CycleStatistics s;
  s.double_precision_smoothers = patch_ && !patch_->single_precision() ? 1 : 0;
  return s;
}

}  // namespace fosls
