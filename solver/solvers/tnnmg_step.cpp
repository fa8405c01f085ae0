#include "solvers/tnnmg_step.hpp"

#include <algorithm>

namespace fosls {

void TnnmgStep::iterate(Vector& x, Vector& r) {
  for (int s = 0; s < std::max(1, options_.pre_smoothing); ++s) cycle_.smooth(x, r, true);
  const std::vector<char> frozen = qp_.active_set(x);
  Vector c = Vector::Zero(x.size()), rc = r;
  cycle_.linear_cycle(frozen, c, rc);
  Vector d(x.size());
  for (int i = 0; i < x.size(); ++i)
    d[i] = std::clamp(x[i] + c[i], qp_.lower[i], qp_.upper[i]) - x[i];
  Vector ad;
  symmetric_multiply(qp_.A, d, ad);
  const double curvature = d.dot(ad);
  const double alpha = curvature > 0 ? std::clamp(r.dot(d) / curvature, 0.0, 1.0) : 0.0;
  if (alpha > 0) {
    for (int i = 0; i < x.size(); ++i)
      x[i] =
          alpha == 1.0 ? x[i] + d[i] : std::clamp(x[i] + alpha * d[i], qp_.lower[i], qp_.upper[i]);
    // Land exactly on bounds reached by the projection.
    if (alpha == 1.0)
      for (int i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], qp_.lower[i], qp_.upper[i]);
    r -= alpha * ad;
  }
  for (int s = 0; s < options_.post_smoothing; ++s) cycle_.smooth(x, r, false);
}

}  // namespace fosls
