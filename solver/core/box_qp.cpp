#include "core/box_qp.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

void symmetric_multiply(const SparseMatrix& A, const Vector& x, Vector& y) {
  // For symmetric A, row i of A equals column i: each output entry is a column dot product,
  // which parallelises without write conflicts.
  const int n = static_cast<int>(A.cols());
  y.resize(n);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* val = A.valuePtr();
#pragma omp parallel for schedule(static) if (n > 20000)
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int k = outer[i]; k < outer[i + 1]; ++k) s += val[k] * x[inner[k]];
    y[i] = s;
  }
}

double BoxQp::energy(const Vector& x) const {
  Vector ax;
  symmetric_multiply(A, x, ax);
  return 0.5 * x.dot(ax) - b.dot(x) + constant;
}

double BoxQp::energy_from_residual(const Vector& x, const Vector& r) const {
  return 0.5 * x.dot(b - r) - b.dot(x) + constant;
}

double BoxQp::kkt_residual(const Vector& x, const Vector& r) const {
  double s = 0.0;
  for (int i = 0; i < size(); ++i) {
    double y = std::clamp(x[i] + r[i], lower[i], upper[i]);
    double d = x[i] - y;
    s += d * d;
  }
  return std::sqrt(s);
}

bool BoxQp::feasible(const Vector& x) const {
  for (int i = 0; i < size(); ++i)
    if (x[i] < lower[i] || x[i] > upper[i]) return false;
  return true;
}

}  // namespace fosls
