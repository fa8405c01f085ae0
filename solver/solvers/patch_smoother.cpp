#include "solvers/patch_smoother.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/indefinite_system.hpp"
#include "solvers/exact_box_qp.hpp"
#include "solvers/smoother_table.hpp"

namespace fosls {

namespace {

std::vector<int> patch_sizes(const std::vector<std::vector<int>>& patches) {
  std::vector<int> sizes(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) sizes[p] = static_cast<int>(patches[p].size());
  return sizes;
}

}  // namespace

PatchSmoother::PatchSmoother(const SparseMatrix& A, const std::vector<std::vector<int>>& patches,
                             std::array<int, 2> split)
    : A_(A), patches_(patches), split_(split), factors_(factorise_patches(A, patches)) {}

SmallCholeskyFactors PatchSmoother::factorise_patches(
    const SparseMatrix& A, const std::vector<std::vector<int>>& patches) {
  // Each thread marks the local index of the patch's DOFs in its own copy of `local`.
  std::vector<std::vector<int>> local(omp_get_max_threads());
  auto fill = [&](int p, Eigen::MatrixXd& block) {
    std::vector<int>& mine = local[omp_get_thread_num()];
    if (mine.empty()) mine.assign(A.rows(), -1);
    const auto& idx = patches[p];
    const int m = static_cast<int>(idx.size());
    for (int a = 0; a < m; ++a) mine[idx[a]] = a;
    for (int b = 0; b < m; ++b)
      for (SparseMatrix::InnerIterator it(A, idx[b]); it; ++it)
        if (int a = mine[it.row()]; a >= 0) block(a, b) = it.value();
    for (int a = 0; a < m; ++a) mine[idx[a]] = -1;
  };
  int failed = -1;
  SmallCholeskyFactors factors(patch_sizes(patches), fill, failed);
  if (failed >= 0)
    throw IndefiniteSystemError("the local matrix of vertex patch " + std::to_string(failed) +
                                " is not positive definite");
  return factors;
}

void PatchSmoother::solve_patch(int p, const Vector& rl, Vector& x, const Vector& lo,
                                const Vector& hi, Vector& change) const {
  const auto& idx = patches_[p];
  const int m = static_cast<int>(idx.size());
  Vector delta(m);
  change.setZero(m);
  bool bounded = false;
  for (int a = 0; a < m; ++a)
    bounded |= is_bounded_above(hi[idx[a]]) || is_bounded_below(lo[idx[a]]);
  if (!bounded) {
    delta = rl;
    factors_.solve(p, delta);
  } else {
    const Eigen::MatrixXd lower = factors_.lower(p);
    const Eigen::MatrixXd a = lower * lower.transpose();
    Vector dlo(m), dhi(m);
    for (int k = 0; k < m; ++k) {
      dlo[k] = std::min(0.0, lo[idx[k]] - x[idx[k]]);
      dhi[k] = std::max(0.0, hi[idx[k]] - x[idx[k]]);
    }
    solve_dense_box_qp(a, rl, dlo, dhi, delta);
  }
  for (int a = 0; a < m; ++a) {
    if (delta[a] == 0.0) continue;
    const int j = idx[a];
    const double target = x[j] + delta[a];
    // Land exactly on a bound the local solve reached (x_j + (hi_j − x_j) may round).
    const double updated = (delta[a] > 0 && target >= hi[j])   ? hi[j]
                           : (delta[a] < 0 && target <= lo[j]) ? lo[j]
                                                               : target;
    change[a] = updated - x[j];
    x[j] = updated;
  }
}

void PatchSmoother::sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi,
                          bool forward) const {
  const int np = static_cast<int>(patches_.size());
  const auto [end0, end1] = split_;
  const bool parallel = omp_get_max_threads() > 1 && end0 >= kMinParallelPatches &&
                        end1 - end0 >= kMinParallelPatches;
  if (!forward) sweep_range(end1, np, x, r, lo, hi, false);
  if (parallel) {
    // The blocks share no entry of x, r (patch_blocks.hpp): no locks, one meeting at the end.
#pragma omp parallel num_threads(2)
    {
      if (omp_get_thread_num() == 0)
        sweep_range(0, end0, x, r, lo, hi, forward);
      else
        sweep_range(end0, end1, x, r, lo, hi, forward);
    }
  } else if (forward) {
    sweep_range(0, end0, x, r, lo, hi, true);
    sweep_range(end0, end1, x, r, lo, hi, true);
  } else {
    sweep_range(end0, end1, x, r, lo, hi, false);
    sweep_range(0, end0, x, r, lo, hi, false);
  }
  if (forward) sweep_range(end1, np, x, r, lo, hi, true);
}

void PatchSmoother::sweep_range(int begin, int end, Vector& x, Vector& r, const Vector& lo,
                                const Vector& hi, bool forward) const {
  Vector rl, change;
  for (int k = begin; k < end; ++k) {
    const int p = forward ? k : end - 1 - (k - begin);
    const auto& idx = patches_[p];
    rl.resize(idx.size());
    for (std::size_t a = 0; a < idx.size(); ++a) rl[a] = r[idx[a]];
    solve_patch(p, rl, x, lo, hi, change);
    for (std::size_t a = 0; a < idx.size(); ++a)
      if (change[a] != 0.0) update_residual(A_, idx[a], change[a], r);
  }
}

std::unique_ptr<Smoother> make_patch_smoother(const SparseMatrix& A, const Level& level) {
  return std::make_unique<PatchSmoother>(A, level.patches, level.patch_split);
}

}  // namespace fosls
