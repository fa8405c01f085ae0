#pragma once
// The discrete problem every solver works on (docs/method.md §3):
//   minimise J(x) = ½ xᵀ A x − bᵀ x + c   subject to   lower ≤ x ≤ upper.

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <limits>
#include <utility>
#include <vector>

namespace fosls {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vector = Eigen::VectorXd;

/// Bounds at or beyond this magnitude mean "no bound". Finite, so that the coarse-obstacle
/// formulas (2a − b) never produce inf − inf.
constexpr double kNoBound = 1e300;

inline bool is_bounded_above(double upper) { return upper < 0.5 * kNoBound; }
inline bool is_bounded_below(double lower) { return lower > -0.5 * kNoBound; }
/// Whether x sits on one of its (finite) bounds: the active set of the solvers and the
/// truncated set of the multilevel cycle.
inline bool is_at_bound(double x, double lower, double upper) {
  return (is_bounded_above(upper) && x >= upper) || (is_bounded_below(lower) && x <= lower);
}

/// Bound-constrained quadratic program. A is symmetric positive definite and stored in full.
struct BoxQp {
  SparseMatrix A;
  Vector b;
  Vector lower;
  Vector upper;
  double constant = 0.0;

  int size() const { return static_cast<int>(b.size()); }
  /// J(x).
  double energy(const Vector& x) const;
  /// J(x) when the residual r = b − A x is known: ½ xᵀ(b − r) − bᵀx + c, O(n).
  double energy_from_residual(const Vector& x, const Vector& r) const;
  /// ‖x − P_K(x − (A x − b))‖₂ from the residual r = b − A x: zero exactly at the solution.
  double kkt_residual(const Vector& x, const Vector& r) const;
  /// u ‖ |A| |x| + |b| ‖₂, u = 2⁻⁵³ the double precision unit roundoff: the size of the rounding
  /// in a computed r = b − A x, below which the KKT residual cannot fall reliably.
  double rounding_level(const Vector& x) const;
  /// Whether lower ≤ x ≤ upper holds exactly.
  bool feasible(const Vector& x) const;
  /// The active set of x: 1 for the bounded DOFs at their bound (is_at_bound), else 0.
  std::vector<char> active_set(const Vector& x) const;
};

/// The columns [begin, end) of share `share` of `shares` when a compressed sparse matrix with
/// outer index `outer` (n + 1 entries) is cut into shares of about equal entry counts: the shares
/// cover 0..n in order without gap or overlap (some may be empty), each within one column's
/// entries of nnz / shares.
std::pair<int, int> entry_balanced_columns(const int* outer, int n, int share, int shares);

/// y = A x using both cores (A symmetric, column-major: y_i = Σ_j A_ji x_j by columns).
void symmetric_multiply(const SparseMatrix& A, const Vector& x, Vector& y);

}  // namespace fosls
