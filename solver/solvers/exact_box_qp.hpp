#pragma once
// Exact solution of small and coarse bound-constrained QPs by the primal active-set method
// (the sparse solver tries primal–dual steps first, see SparseBoxQpSolver):
//   minimise ½ δᵀ A δ − rᵀ δ   subject to   lo ≤ δ ≤ hi,   with lo ≤ 0 ≤ hi.
// Starting from the feasible δ = 0, every step moves towards the minimiser on the current
// free set and stops at the first blocking bound, so J decreases monotonically and δ stays
// feasible; a bound is released only when its multiplier has the wrong sign. Finite
// termination (barring degenerate cycling, which an iteration cap turns into "not exact").

#include <Eigen/Dense>
#include <memory>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

class FreeSetSolver;

/// Dense version for the vertex patches of the patch smoother. Returns false when A restricted
/// to the free set is not positive definite (weights that make the functional indefinite).
bool solve_dense_box_qp(const Eigen::MatrixXd& A, const Vector& r, const Vector& lo,
                        const Vector& hi, Vector& delta);

/// Sparse version for the coarsest level of the multilevel cycle and the block of the
/// contact-strip smoother. The factorisation of the whole matrix is computed once, and that of
/// the last free set is kept while the free set does not change (solvers/free_set_solver.hpp). Not
/// thread-safe: one solver per cycle or smoother.
///
/// The primal method factorises once per bound it meets, which from δ = 0 on a large coarsest
/// level with many contact bounds is most of a solve (docs/performance.md, "Measurements behind
/// choices in the code"). So a solve first tries primal–dual active-set steps, which change many
/// bounds per factorisation; when their active sets settle, the result is the exact minimiser,
/// feasible (clipped for rounding) and with J(δ) ≤ J(0) = 0 (checked) — all the cycle's
/// monotonicity needs of the coarse correction. Only when they do not settle (primal–dual steps can
/// cycle) or the check fails in rounding does the primal method run, from δ = 0 as before.
class SparseBoxQpSolver {
 public:
  /// Throws IndefiniteSystemError when A is not positive definite. `factorization`: how the
  /// free sets are solved (solvers/free_set_solver.hpp).
  explicit SparseBoxQpSolver(const SparseMatrix& A,
                             BlockFactorization factorization = BlockFactorization::reduced);
  ~SparseBoxQpSolver();
  /// The solver for a matrix of A's pattern with new values, reusing the factorisation's
  /// analysis and the last settled active set as the next solve's start (held_rows only);
  /// false, with nothing changed, where a new solver is needed. Throws as the constructor.
  bool refactor(const SparseMatrix& A);
  /// δ = argmin, feasible (after the iteration cap: a feasible point with J(δ) ≤ J(0)); false
  /// when a free block was not positive definite, which callers must not take for a solution.
  /// Throws std::bad_alloc when a factorisation runs out of memory (solvers/cholmod_checks.hpp).
  bool solve(const Vector& r, const Vector& lo, const Vector& hi, Vector& delta);

  /// Primal–dual steps taken and how many solves ended by them (the rest by the primal method).
  int primal_dual_steps() const { return primal_dual_steps_; }
  int solved_primal_dual() const { return solved_primal_dual_; }

 private:
  /// state: 0 free, ±1 at the upper/lower bound, 2 fixed; y: the minimiser over the free DOFs
  /// with the others at their value in d. False when the free block is not definite.
  bool solve_free(const std::vector<signed char>& state, const Vector& r, const Vector& d,
                  Vector& y);
  /// The primal–dual attempt; true with δ the exact minimiser (checked), false to fall back.
  bool solve_primal_dual(const Vector& r, const Vector& lo, const Vector& hi, Vector& delta);

  /// The last settled active set, where its bounds still exist, as the first primal–dual step's.
  void start_from_settled(const Vector& lo, const Vector& hi,
                          std::vector<signed char>& state) const;

  SparseMatrix A_;
  Vector diagonal_;  ///< A's diagonal: the primal–dual steps' scale of each DOF
  std::unique_ptr<FreeSetSolver> free_set_;
  /// Start from the last settled active set, whose factor the free-set solver still holds (with
  /// held rows: the 3D strip), instead of guessing it from δ = 0.
  bool warm_start_ = false;
  std::vector<signed char> settled_;
  int primal_dual_steps_ = 0;
  int solved_primal_dual_ = 0;
};

}  // namespace fosls
