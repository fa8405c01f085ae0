#pragma once
// The discrete problem every solver works on (docs/method.md §3):
//   minimise J(x) = ½ xᵀ A x − bᵀ x + c   subject to   lower ≤ x ≤ upper.

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <algorithm>
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

/// x_i ← clamp(x_i, lo_i, hi_i) for every i.
void clip(Vector& x, const Vector& lo, const Vector& hi);

/// x_i ← clamp(x_i + t s_i, lo_i, hi_i) for every i, and s_i ← the change of x_i this made (what
/// the residual update needs; s is overwritten so that no second vector of the size is formed).
void step_within_bounds(Vector& x, double t, Vector& s, const Vector& lo, const Vector& hi);

/// The fraction t ≤ 1 of the step from x to x + d that keeps one DOF within [lo, hi], where
/// `moved` is x + d as the caller formed it (the test is on it, so that a caller that holds the
/// target, not the step, tests the target itself): 1 when `moved` is within the bounds.
inline double step_to_bound(double x, double d, double moved, double lo, double hi) {
  if (d > 0 && moved > hi) return (hi - x) / d;
  if (d < 0 && moved < lo) return (lo - x) / d;
  return 1.0;
}

/// The largest t ∈ [0, 1] with lo ≤ x + t d ≤ hi (by step_to_bound per DOF). `d` may be any
/// vector expression with d[i]: it is read once per DOF and not formed.
template <class Direction>
double max_feasible_step(const Vector& x, const Direction& d, const Vector& lo, const Vector& hi) {
  double t = 1.0;
  for (int i = 0; i < x.size(); ++i) {
    const double di = d[i];
    t = std::min(t, step_to_bound(x[i], di, x[i] + di, lo[i], hi[i]));
  }
  return std::max(t, 0.0);
}

/// Bound-constrained quadratic program. A is symmetric positive definite and stored in full.
struct BoxQp {
  SparseMatrix A;
  Vector b;
  Vector lower;
  Vector upper;
  double constant = 0.0;
  /// DOFs whose bounds the multilevel cycle carries to coarse levels through the rows of the
  /// prolongation (row_obstacle.hpp): the frictional contact DOFs, bounded on both sides or on
  /// the side of a kink, which the contact links' projections do not describe. Empty without
  /// friction.
  std::vector<int> row_obstacles;

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
  /// x clipped to [lower, upper].
  void clip(Vector& x) const { fosls::clip(x, lower, upper); }
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
