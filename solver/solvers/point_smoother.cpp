#include "solvers/point_smoother.hpp"

#include <algorithm>

#include "solvers/smoother_table.hpp"

namespace fosls {

PointSmoother::PointSmoother(const SparseMatrix& A) : A_(A), diagonal_(A.diagonal()) {}

void PointSmoother::sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi,
                          bool forward) const {
  const int n = static_cast<int>(x.size());
  for (int k = 0; k < n; ++k) {
    const int i = forward ? k : n - 1 - k;
    if (diagonal_[i] <= 0.0) continue;
    const double xi = std::clamp(x[i] + r[i] / diagonal_[i], lo[i], hi[i]);
    const double d = xi - x[i];
    if (d == 0.0) continue;
    x[i] = xi;
    update_residual(A_, i, d, r);
  }
}

std::unique_ptr<Smoother> make_point_smoother(const SparseMatrix& A, const Level&) {
  return std::make_unique<PointSmoother>(A);
}

}  // namespace fosls
