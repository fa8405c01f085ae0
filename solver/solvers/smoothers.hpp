#pragma once
// Monotone smoothers: successive exact minimisation of J over small subspaces within the
// bounds (method.md §4.1). Both work on x and the residual r = b − A x, kept up to date.

#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

/// Pointwise projected (non-linear) Gauss–Seidel: x_i ← clamp(x_i + r_i / A_ii).
class PointSmoother {
 public:
  explicit PointSmoother(const SparseMatrix& A);
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const;

 private:
  const SparseMatrix& A_;
  Vector diagonal_;
};

/// Vertex-patch smoother: for each vertex, the exact minimiser over its displacement DOFs and
/// both stress rows on every edge through it (≈ 14 unknowns), subject to the bounds. Patches
/// without active bounds use a Cholesky factor computed once.
class PatchSmoother {
 public:
  /// Throws std::runtime_error naming the patch when a local matrix is not positive definite.
  PatchSmoother(const SparseMatrix& A, const std::vector<std::vector<int>>& patches);
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const;

 private:
  void solve_patch(int p, Vector& x, Vector& r, const Vector& lo, const Vector& hi) const;

  const SparseMatrix& A_;
  const std::vector<std::vector<int>>& patches_;
  std::vector<std::size_t> offset_;  ///< start of each patch's factor in factors_
  std::vector<double> factors_;      ///< lower Cholesky factor, column-major m × m
};

/// Subtracts A[:, j] · d from r (the residual update after x_j changed by d).
inline void update_residual(const SparseMatrix& A, int j, double d, Vector& r) {
  for (SparseMatrix::InnerIterator it(A, j); it; ++it) r[it.row()] -= it.value() * d;
}

}  // namespace fosls
