#pragma once
// Monotone smoothers: successive exact minimisation of J over small subspaces within the
// bounds (docs/method.md §4.1). Both work on x and the residual r = b − A x, kept up to date.

#include <array>
#include <memory>
#include <vector>

#include "core/box_qp.hpp"
#include "solvers/small_cholesky_factors.hpp"

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
/// without active bounds use a Cholesky factor computed once (in single precision where that
/// provably keeps every correction a decrease of J: small_cholesky_factors.hpp).
class PatchSmoother {
 public:
  /// Throws IndefiniteSystemError naming the patch when a local matrix is not positive
  /// definite. `split` (Level::patch_split): patches [0, split[0]) and [split[0], split[1])
  /// touch disjoint entries of x and r; {0, 0} makes every sweep sequential.
  PatchSmoother(const SparseMatrix& A, const std::vector<std::vector<int>>& patches,
                std::array<int, 2> split = {0, 0});
  /// One Gauss–Seidel sweep over the patches in the order [block 0, block 1, rest] (reversed
  /// backwards). With two or more OpenMP threads and large blocks, the two blocks run on two
  /// threads that meet once per sweep: the same iterate as the sequential sweep. (A sweep by
  /// colours, a barrier per colour, was measured no faster, 2.01 s against 2.18 s at 131k DOFs,
  /// and 6× slower when another process held a core.)
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const;
  /// Whether the patch factors are kept in single precision (small_cholesky_factors.hpp).
  bool single_precision() const { return factors_.single_precision(); }

  /// Blocks with fewer patches are swept on one thread. 250 patches take ≈ 0.5 ms, far more
  /// than the threads' meeting; lowering this from 2000 made the square 5–7 % faster at levels
  /// 5–7 on two threads (the W-cycle's small levels are visited often), iterates bit for bit
  /// the same (docs/performance.md, "Small levels on two threads").
  static constexpr int kMinParallelPatches = 250;

 private:
  /// Minimises over patch p given its current local residual; returns the change of x there.
  void solve_patch(int p, const Vector& r_local, Vector& x, const Vector& lo, const Vector& hi,
                   Vector& change) const;

  /// Patches [begin, end) in sweep order.
  void sweep_range(int begin, int end, Vector& x, Vector& r, const Vector& lo, const Vector& hi,
                   bool forward) const;

  static SmallCholeskyFactors factorise_patches(const SparseMatrix& A,
                                                const std::vector<std::vector<int>>& patches);

  const SparseMatrix& A_;
  const std::vector<std::vector<int>>& patches_;
  std::array<int, 2> split_;
  SmallCholeskyFactors factors_;  ///< of the patch matrices, in single precision when safe
};

/// Exact minimisation over the strip of triangles along the contact boundary, within the
/// bounds. Where neither U_n nor S_n is at its bound (at the edge of the contact zone) the
/// functional only weakly controls the normal boundary data (through c3), so the error has
/// modes a few elements wide along the boundary that neither vertex patches nor the coarse
/// levels reach; one exact solve on the strip removes them. A monotone subspace step like the
/// others.
class StripSmoother {
 public:
  /// Throws IndefiniteSystemError when the strip's matrix is not positive definite.
  StripSmoother(const SparseMatrix& A, std::vector<int> strip);
  ~StripSmoother();
  /// Not const: the QP solver keeps the factorisation of the last free set.
  void solve(Vector& x, Vector& r, const Vector& lo, const Vector& hi);

 private:
  const SparseMatrix& A_;
  std::vector<int> strip_;
  std::unique_ptr<class SparseBoxQpSolver> solver_;
};

/// Subtracts A[:, j] · d from r (the residual update after x_j changed by d).
inline void update_residual(const SparseMatrix& A, int j, double d, Vector& r) {
  for (SparseMatrix::InnerIterator it(A, j); it; ++it) r[it.row()] -= it.value() * d;
}

}  // namespace fosls
