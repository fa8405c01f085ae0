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

/// Dense version for vertex patches. Returns false when A restricted to the free set is not
/// positive definite (weights that make the functional indefinite).
bool solve_box_qp_dense(const Eigen::MatrixXd& A, const Vector& r, const Vector& lo,
                        const Vector& hi, Vector& delta);

/// Sparse version for the coarsest level, with the factorisation of the unconstrained matrix
/// kept between calls while A does not change.
class CoarseBoxQpSolver {
 public:
  /// Throws std::runtime_error when A is not positive definite.
  explicit CoarseBoxQpSolver(const SparseMatrix& A);
  /// δ = argmin, feasible; returns false if the iteration cap was hit (δ is still a feasible
  /// point with J(δ) ≤ J(0)).
  bool solve(const Vector& r, const Vector& lo, const Vector& hi, Vector& delta) const;

 private:
  SparseMatrix A_;
  struct Factor;
  std::shared_ptr<Factor> full_;
  std::shared_ptr<Factor> last_;
};

}  // namespace fosls
