#include "solvers/pdas_step.hpp"

#include "core/indefinite_system.hpp"
#include "solvers/cholmod_checks.hpp"

namespace fosls {

PdasStep::PdasStep(const BoxQp& qp, double complement_min_flops)
    : qp_(qp), diagonal_(qp.A.diagonal()) {
  std::vector<int> bounded;
  for (int i = 0; i < qp.size(); ++i)
    if (is_bounded_above(qp.upper[i]) || is_bounded_below(qp.lower[i])) bounded.push_back(i);
  complement_ = BoundedComplementSolver::make(qp.A, bounded, complement_min_flops);
}

std::vector<char> PdasStep::next_active_set(const Vector& x, const Vector& r) {
  // Active-set test λ_i + c_i (x_i − ψ_i) > 0 with λ = b − A x on the current active set
  // (zero elsewhere) and c_i = A_ii, which makes the test invariant to scaling of DOFs; at a
  // lower bound the same with the signs turned. The first iteration takes λ = b − A x
  // everywhere as its multiplier estimate. kUpper or kLower per DOF, 0 for inactive.
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

void PdasStep::hold_active_rows(const std::vector<char>& active) {
  const int n = qp_.size();
  const int* outer = qp_.A.outerIndexPtr();
  const int* inner = qp_.A.innerIndexPtr();
  const double* a = qp_.A.valuePtr();
  double* m = m_.valuePtr();
  for (int col = 0; col < n; ++col)
    for (int k = outer[col]; k < outer[col + 1]; ++k) {
      const int row = inner[k];
      m[k] = (active[row] || active[col]) ? (row == col ? 1.0 : 0.0) : a[k];
    }
}

void PdasStep::solve_by_factorisation(const std::vector<char>& active, const Vector& psi,
                                      Vector& x) {
  const int n = qp_.size();
  if (!analysed_) {
    // The held-rows matrix's storage only where it is used (a copy of A: the complement's path
    // does without it).
    m_ = qp_.A;
    analyse_checked(llt_, m_);
    analysed_ = true;
  }
  // M = A with active rows/columns replaced by the identity; same pattern as A.
  Vector rhs = qp_.b;
  Vector apsi;
  symmetric_multiply(qp_.A, psi, apsi);
  for (int i = 0; i < n; ++i) rhs[i] = active[i] ? psi[i] : rhs[i] - apsi[i];
  hold_active_rows(active);
  if (!factorize_checked(llt_, m_))
    throw IndefiniteSystemError("CHOLMOD: the matrix is not positive definite");
  x = solve_checked(llt_, rhs);
}

void PdasStep::iterate(Vector& x, Vector& r) {
  const int n = qp_.size();
  const std::vector<char> active = next_active_set(x, r);
  Vector psi = Vector::Zero(n);
  for (int i = 0; i < n; ++i)
    if (active[i]) psi[i] = bound(active[i], i);
  if (!complement_ || !complement_->solve(active, qp_.b, psi, x))
    solve_by_factorisation(active, psi, x);
  for (int i = 0; i < n; ++i)
    if (active[i]) x[i] = bound(active[i], i);
  Vector ax;
  symmetric_multiply(qp_.A, x, ax);
  r = qp_.b - ax;
}

}  // namespace fosls
