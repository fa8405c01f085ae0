#include "solvers/tnnmg_step.hpp"

#include <algorithm>

namespace fosls {

void TnnmgStep::iterate(Vector& x, Vector& r) {
  for (int s = 0; s < std::max(1, options_.pre_smoothing); ++s) cycle_.smooth(x, r, true);
  const std::vector<char> frozen = qp_.active_set(x);
  Vector c = Vector::Zero(x.size()), rc = r;
  cycle_.linear_cycle(frozen, c, rc);
  // The projected direction d = P_K(x + c) − x.
  Vector d = x + c;
  qp_.clip(d);
  d -= x;
  Vector ad;
  symmetric_multiply(qp_.A, d, ad);
  const double curvature = d.dot(ad);
  const double alpha = curvature > 0 ? std::clamp(r.dot(d) / curvature, 0.0, 1.0) : 0.0;
  if (alpha > 0) {
    // Clipped at alpha = 1 too: x + d lands exactly on the bounds the projection reached.
    x += alpha * d;
    qp_.clip(x);
    r -= alpha * ad;
  }
  for (int s = 0; s < options_.post_smoothing; ++s) cycle_.smooth(x, r, false);
}

}  // namespace fosls
