#pragma once
// The vertex-patch smoother (docs/method.md §4.1), the default: robust in H(div).

#include <array>
#include <vector>

#include "solvers/small_cholesky_factors.hpp"
#include "solvers/smoother.hpp"

namespace fosls {

/// Vertex-patch smoother: for each vertex, the exact minimiser over its displacement DOFs and
/// both stress rows on every edge through it (≈ 14 unknowns), subject to the bounds. Patches
/// without active bounds use a Cholesky factor computed once (in single precision where that
/// provably keeps every correction a decrease of J: small_cholesky_factors.hpp).
class PatchSmoother : public Smoother {
 public:
  /// Throws IndefiniteSystemError naming the patch when a local matrix is not positive
  /// definite. `split` (Level::patch_split): patches [0, split[0]) and [split[0], split[1])
  /// touch disjoint entries of x and r; {0, 0} makes every sweep sequential.
  PatchSmoother(const SparseMatrix& A, const std::vector<std::vector<int>>& patches,
                std::array<int, 2> split = {0, 0});
  /// One Gauss–Seidel sweep over the patches in the order [block 0, block 1, rest] (reversed
  /// backwards). With two or more OpenMP threads and large blocks, the two blocks run on two
  /// threads that meet once per sweep: the same iterate as the sequential sweep. (A sweep by
  /// colours, a barrier per colour, was no faster, and much slower when another process held a
  /// core: docs/performance.md, "Measurements behind choices in the code".)
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const override;
  /// Whether the patch factors are kept in single precision (small_cholesky_factors.hpp).
  bool single_precision() const { return factors_.single_precision(); }
  bool double_precision_factors() const override { return !single_precision(); }

  /// Blocks with fewer patches are swept on one thread. This many take far longer than the
  /// threads' meeting, and the W-cycle's small levels are visited often, so a low threshold
  /// pays; iterates bit for bit the same (docs/performance.md, "Small levels on two threads").
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

}  // namespace fosls
