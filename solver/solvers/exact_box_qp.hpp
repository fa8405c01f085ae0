#pragma once
// Exact solution of small and coarse bound-constrained QPs by the primal active-set method:
//   minimise ½ δᵀ A δ − rᵀ δ   subject to   lo ≤ δ ≤ hi,   with lo ≤ 0 ≤ hi.
// Starting from the feasible δ = 0, every step moves towards the minimiser on the current
// free set and stops at the first blocking bound, so J decreases monotonically and δ stays
// feasible; a bound is released only when its multiplier has the wrong sign. Finite
// termination (barring degenerate cycling, which an iteration cap turns into "not exact").

#include <Eigen/Dense>
#include <memory>

#include "core/box_qp.hpp"

namespace fosls {

/// Dense version for the vertex patches of the patch smoother. Returns false when A restricted
/// to the free set is not positive definite (weights that make the functional indefinite).
bool solve_dense_box_qp(const Eigen::MatrixXd& A, const Vector& r, const Vector& lo,
                        const Vector& hi, Vector& delta);

/// Sparse version for the coarsest level of the multilevel cycle and the block of the
/// contact-strip smoother. The factorisation of the whole matrix is computed once, and that of
/// the last free set is kept while the free set does not change. Not thread-safe: one solver
/// per cycle or smoother.
class SparseBoxQpSolver {
 public:
  /// Throws IndefiniteSystemError when A is not positive definite.
  explicit SparseBoxQpSolver(const SparseMatrix& A);
  ~SparseBoxQpSolver();
  /// δ = argmin, feasible; returns false if the iteration cap was hit (δ is still a feasible
  /// point with J(δ) ≤ J(0)).
  bool solve(const Vector& r, const Vector& lo, const Vector& hi, Vector& delta);

 private:
  SparseMatrix A_;
  struct Factor;
  std::unique_ptr<Factor> full_;
  std::unique_ptr<Factor> last_;
};

}  // namespace fosls
