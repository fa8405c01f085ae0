#include "solvers/strip_smoother.hpp"

#include <algorithm>

#include "core/indefinite_system.hpp"
#include "solvers/exact_box_qp.hpp"

namespace fosls {

StripSmoother::StripSmoother(const SparseMatrix& A, std::vector<int> strip,
                             BlockFactorization factorization)
    : A_(A), strip_(std::move(strip)) {
  std::vector<int> local(A.rows(), -1);
  for (std::size_t a = 0; a < strip_.size(); ++a) local[strip_[a]] = static_cast<int>(a);
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t a = 0; a < strip_.size(); ++a)
    for (SparseMatrix::InnerIterator it(A, strip_[a]); it; ++it)
      if (int b = local[it.row()]; b >= 0) t.emplace_back(b, static_cast<int>(a), it.value());
  SparseMatrix sub(strip_.size(), strip_.size());
  sub.setFromTriplets(t.begin(), t.end());
  solver_ = std::make_unique<SparseBoxQpSolver>(sub, factorization);
}

StripSmoother::~StripSmoother() = default;

void StripSmoother::sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool) const {
  const int m = static_cast<int>(strip_.size());
  Vector rl(m), dlo(m), dhi(m), delta;
  for (int a = 0; a < m; ++a) {
    const int i = strip_[a];
    rl[a] = r[i];
    dlo[a] = std::min(0.0, lo[i] - x[i]);
    dhi[a] = std::max(0.0, hi[i] - x[i]);
  }
  if (!solver_->solve(rl, dlo, dhi, delta))
    throw IndefiniteSystemError(
        "the contact strip's matrix is not positive definite on a free set");
  for (int a = 0; a < m; ++a) {
    if (delta[a] == 0.0) continue;
    const int j = strip_[a];
    const double updated = std::clamp(x[j] + delta[a], lo[j], hi[j]);
    update_residual(A_, j, updated - x[j], r);
    x[j] = updated;
  }
}

}  // namespace fosls
