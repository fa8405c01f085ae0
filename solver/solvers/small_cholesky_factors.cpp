#include "solvers/small_cholesky_factors.hpp"

#include <atomic>
#include <cmath>

namespace fosls {

namespace {

/// Solves L Lᵀ y = y in place for L lower triangular, packed by columns (column b holds rows
/// b … m−1).
template <typename T>
void solve_packed(const T* l, int m, Vector& y) {
  // Column b starts at b·m − b(b−1)/2.
  auto column = [m](int b) { return b * m - b * (b - 1) / 2; };
  for (int b = 0; b < m; ++b) {
    const T* c = l + column(b);
    y[b] /= c[0];
    for (int a = b + 1; a < m; ++a) y[a] -= c[a - b] * y[b];
  }
  for (int b = m - 1; b >= 0; --b) {
    const T* c = l + column(b);
    double s = y[b];
    for (int a = b + 1; a < m; ++a) s -= c[a - b] * y[a];
    y[b] = s / c[0];
  }
}

}  // namespace

// With G = L⁻¹(L_f − L), L⁻¹(L_f L_fᵀ − L Lᵀ)L⁻ᵀ = G + Gᵀ + G Gᵀ. L_f − L is lower
// triangular, so column b of G has rows b … m−1 only: forward substitution from row b, about
// m³/6 multiply-adds like the factorisation itself (a general solve costs three times that).
double SmallCholeskyFactors::rounding_bound(const Eigen::MatrixXd& l) {
  const int m = static_cast<int>(l.rows());
  double norm2 = 0.0;
  Eigen::VectorXd g(m);
  for (int b = 0; b < m; ++b) {
    for (int a = b; a < m; ++a) g[a] = double{static_cast<float>(l(a, b))} - l(a, b);
    for (int a = b; a < m; ++a) {
      g[a] /= l(a, a);
      for (int c = a + 1; c < m; ++c) g[c] -= l(c, a) * g[a];
      norm2 += g[a] * g[a];
    }
  }
  const double n = std::sqrt(norm2);
  return 2 * n + n * n;
}

SmallCholeskyFactors::SmallCholeskyFactors(const std::vector<int>& sizes,
                                           const std::function<void(int, Eigen::MatrixXd&)>& fill,
                                           int& failed)
    : order_(sizes) {
  offset_.assign(sizes.size() + 1, 0);
  for (std::size_t k = 0; k < sizes.size(); ++k)
    offset_[k + 1] = offset_[k] + static_cast<std::size_t>(sizes[k]) * (sizes[k] + 1) / 2;
  failed = -1;
  if (factorise(sizes, fill, single_, failed) || failed >= 0) return;
  // A matrix too ill-conditioned for a rounded factor: all of them in double (not seen on
  // the benchmarks; one storage type keeps the solve loop simple). The double pass also finds
  // an indefinite matrix the skipped part of the first may have held.
  std::vector<float>().swap(single_);
  single_precision_ = false;
  factorise(sizes, fill, double_, failed);
}

template <typename T>
bool SmallCholeskyFactors::factorise(const std::vector<int>& sizes,
                                     const std::function<void(int, Eigen::MatrixXd&)>& fill,
                                     std::vector<T>& out, int& failed) {
  out.resize(offset_.back());
  const int count = static_cast<int>(sizes.size());
  // Once one bound fails the factors go to double: the rest of this pass is skipped.
  std::atomic<bool> within{true};
#pragma omp parallel
  {
    Eigen::MatrixXd block;
#pragma omp for schedule(dynamic, 256)
    for (int k = 0; k < count; ++k) {
      if (!within.load(std::memory_order_relaxed)) continue;
      const int m = sizes[k];
      block.setZero(m, m);
      fill(k, block);
      Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(block);  // in place: block becomes L
      if (llt.info() != Eigen::Success) {
#pragma omp critical
        if (failed < 0 || k < failed) failed = k;
        continue;
      }
      block.triangularView<Eigen::StrictlyUpper>().setZero();
      if constexpr (sizeof(T) < sizeof(double))
        if (!(rounding_bound(block) <= kMaxSinglePerturbation)) within = false;
      T* packed = out.data() + offset_[k];
      for (int b = 0; b < m; ++b)
        for (int a = b; a < m; ++a) *packed++ = static_cast<T>(block(a, b));
    }
  }
  return within.load();
}

void SmallCholeskyFactors::solve(int k, Vector& y) const {
  if (single_precision_)
    solve_packed(single_.data() + offset_[k], order_[k], y);
  else
    solve_packed(double_.data() + offset_[k], order_[k], y);
}

Eigen::MatrixXd SmallCholeskyFactors::lower(int k) const {
  const int m = order_[k];
  Eigen::MatrixXd l = Eigen::MatrixXd::Zero(m, m);
  for (int b = 0, i = 0; b < m; ++b)
    for (int a = b; a < m; ++a, ++i)
      l(a, b) = single_precision_ ? double{single_[offset_[k] + i]} : double_[offset_[k] + i];
  return l;
}

}  // namespace fosls
