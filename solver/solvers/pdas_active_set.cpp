#include "solvers/pdas_active_set.hpp"

namespace fosls {

std::vector<char> PdasActiveSet::next(const Vector& x, const Vector& r) {
  // Active-set test λ_i + c_i (x_i − ψ_i) > 0 with λ = b − A x on the current active set
  // (zero elsewhere) and c_i = A_ii, which makes the test invariant to scaling of DOFs; at a
  // lower bound the same with the signs turned. The first iteration takes λ = b − A x
  // everywhere as its multiplier estimate.
  const int n = qp_.size();
  std::vector<char> active(n, 0);
  for (int i = 0; i < n; ++i) {
    const double lambda = (first_ || current_[i]) ? r[i] : 0.0;
    if (qp_.lower[i] == qp_.upper[i])
      active[i] = kUpper;  // a DOF held at a kink
    else if (is_bounded_above(qp_.upper[i]) && lambda + diagonal_[i] * (x[i] - qp_.upper[i]) > 0)
      active[i] = kUpper;
    else if (is_bounded_below(qp_.lower[i]) && lambda + diagonal_[i] * (x[i] - qp_.lower[i]) < 0)
      active[i] = kLower;
  }
  first_ = false;
  current_ = active;
  return active;
}

Vector PdasActiveSet::held_values(const std::vector<char>& active) const {
  Vector psi = Vector::Zero(qp_.size());
  for (int i = 0; i < qp_.size(); ++i)
    if (active[i]) psi[i] = bound(active[i], i);
  return psi;
}

}  // namespace fosls
