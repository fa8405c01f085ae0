#include "core/box_qp.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace fosls {

std::pair<int, int> entry_balanced_columns(const int* outer, int n, int share, int shares) {
  auto start = [&](int k) {
    if (k >= shares) return n;
    const long long target = static_cast<long long>(outer[n]) * k / shares;
    return static_cast<int>(std::lower_bound(outer, outer + n, target) - outer);
  };
  return {start(share), start(share + 1)};
}

void symmetric_multiply(const SparseMatrix& A, const Vector& x, Vector& y) {
  // For symmetric A, row i of A equals column i: each output entry is a column dot product,
  // which parallelises without write conflicts. Each thread takes an equal share of the
  // entries, not of the columns: a FOSLS matrix numbers the u DOFs, whose columns hold about
  // twice the entries of a σ column, first, and equal column counts left one thread waiting
  // for the other (docs/performance.md, "Small levels on two threads").
  const int n = static_cast<int>(A.cols());
  y.resize(n);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* val = A.valuePtr();
  const int threads = n > 20000 ? std::max(1, omp_get_max_threads()) : 1;
#pragma omp parallel num_threads(threads)
  {
    const auto [begin, end] =
        entry_balanced_columns(outer, n, omp_get_thread_num(), omp_get_num_threads());
    for (int i = begin; i < end; ++i) {
      double s = 0.0;
      for (int k = outer[i]; k < outer[i + 1]; ++k) s += val[k] * x[inner[k]];
      y[i] = s;
    }
  }
}

void clip(Vector& x, const Vector& lo, const Vector& hi) {
  for (int i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], lo[i], hi[i]);
}

void step_within_bounds(Vector& x, double t, Vector& s, const Vector& lo, const Vector& hi) {
  for (int i = 0; i < x.size(); ++i) {
    const double updated = std::clamp(x[i] + t * s[i], lo[i], hi[i]);
    s[i] = updated - x[i];
    x[i] = updated;
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

double BoxQp::rounding_level(const Vector& x) const {
  Vector magnitude = b.cwiseAbs();
  for (int col = 0; col < A.outerSize(); ++col) {
    const double xc = std::abs(x[col]);
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      magnitude[it.row()] += std::abs(it.value()) * xc;
  }
  return 0.5 * std::numeric_limits<double>::epsilon() * magnitude.norm();
}

bool BoxQp::feasible(const Vector& x) const {
  for (int i = 0; i < size(); ++i)
    if (x[i] < lower[i] || x[i] > upper[i]) return false;
  return true;
}

std::vector<char> BoxQp::active_set(const Vector& x) const {
  std::vector<char> a(x.size(), 0);
  for (int i = 0; i < x.size(); ++i) a[i] = is_at_bound(x[i], lower[i], upper[i]);
  return a;
}

}  // namespace fosls
