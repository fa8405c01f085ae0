#include "solvers/kink_sides.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

KinkSides::KinkSides(BoxQp& qp, const Kinks& kinks, bool newton)
    : qp_(qp),
      kinks_(kinks),
      b_(kinks.size()),
      lower_(kinks.size()),
      upper_(kinks.size()),
      side_(kinks.size(), 0) {
  if (newton) diagonal_.resize(kinks.size());
  for (int k = 0; k < kinks.size(); ++k) {
    const int i = kinks.dof[k];
    b_[k] = qp.b[i], lower_[k] = qp.lower[i], upper_[k] = qp.upper[i];
    if (newton) diagonal_[k] = qp.A.coeff(i, i);
  }
}

KinkSides::~KinkSides() {
  for (int k = 0; k < kinks_.size(); ++k) {
    const int i = kinks_.dof[k];
    qp_.b[i] = b_[k], qp_.lower[i] = lower_[k], qp_.upper[i] = upper_[k];
  }
}

void KinkSides::choose(const Vector& x, Vector& r) {
  for (int k = 0; k < kinks_.size(); ++k) {
    const int i = kinks_.dof[k];
    const double o = kinks_.at[k], w = kinks_.weight[k];
    const double gradient = qp_.b[i] - r[i] - b_[k];  // of the smooth part: A x − b
    signed char side = 0;
    if (!diagonal_.size()) {
      // A kink of weight 0 (Coulomb's bound 0 on both edges of a vertex out of contact) is no
      // kink: the DOF keeps its own bounds instead of being stopped at o for an iteration and
      // then truncated from the coarse levels there (docs/method.md §8.4).
      if (w == 0.0)
        side = 0;
      else if (x[i] > o || (x[i] == o && gradient + w < 0.0))
        side = 1;
      else if (x[i] < o || (x[i] == o && gradient - w > 0.0))
        side = -1;
    } else {
      // Semismooth Newton: the side of the prox point x − ∇/A_ii (iterates may cross).
      const double c = diagonal_[k], y = x[i] - gradient / c - o;
      side = y > w / c ? 1 : y < -w / c ? -1 : 0;
      // A DOF whose side would turn over is held at its kink for one step first: without it
      // the sides of neighbouring DOFs were seen to flip in turn without end.
      if (side * side_[k] < 0) side = 0;
    }
    side_[k] = side;
    const double b_new = b_[k] - side * w;
    r[i] += b_new - qp_.b[i];
    qp_.b[i] = b_new;
    // The side's bound at the kink keeps a monotone method on its side; a Newton step on the
    // side's linearisation chooses its side again from the prox point instead.
    const bool bounded = (!diagonal_.size() && w != 0.0) || (diagonal_.size() && side == 0);
    qp_.lower[i] = side < 0 || !bounded ? lower_[k] : std::max(lower_[k], o);
    qp_.upper[i] = side > 0 || !bounded ? upper_[k] : std::min(upper_[k], o);
  }
}

double KinkSides::energy_offset() const {
  double offset = kinks_.constant;
  for (int k = 0; k < kinks_.size(); ++k) offset -= side_[k] * kinks_.weight[k] * kinks_.at[k];
  return offset;
}

double KinkSides::kkt_residual(const Vector& x, const Vector& r, double sided_kkt) const {
  return kkt_residual(x, r, sided_kkt, kinks_.weight);
}

double KinkSides::kkt_residual(const Vector& x, const Vector& r, double sided_kkt,
                               const std::vector<double>& weights) const {
  double s = sided_kkt * sided_kkt;
  for (int k = 0; k < kinks_.size(); ++k) {
    const int i = kinks_.dof[k];
    const double sided = x[i] - std::clamp(x[i] + r[i], qp_.lower[i], qp_.upper[i]);
    // The prox of w |· − o| within the DOF's own bounds, at x − ∇ of the smooth part.
    const double o = kinks_.at[k], w = weights[k];
    const double y = x[i] + r[i] - qp_.b[i] + b_[k] - o;
    const double shrunk = o + std::copysign(std::max(0.0, std::abs(y) - w), y);
    const double kinked = x[i] - std::clamp(shrunk, lower_[k], upper_[k]);
    s += kinked * kinked - sided * sided;
  }
  return std::sqrt(std::max(0.0, s));
}

}  // namespace fosls
