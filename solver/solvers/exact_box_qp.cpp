#include "solvers/exact_box_qp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "solvers/free_set_solver.hpp"

namespace fosls {

namespace {

/// The primal active-set iteration, generic in how the equality-constrained subproblem on the
/// free set is solved: `solve_free(state, delta, y)` must return the minimiser y over the DOFs
/// with state 0 while DOFs with state ±1 stay at their current (bound) value.
template <class SolveFree, class Gradient>
bool primal_active_set(int n, const Vector& lo, const Vector& hi, Vector& delta,
                       SolveFree&& solve_free, Gradient&& gradient, double scale) {
  // state: 0 free, -1 at lower bound, +1 at upper bound, 2 fixed (lo == hi).
  std::vector<signed char> state(n, 0);
  delta.setZero(n);
  for (int i = 0; i < n; ++i) {
    if (lo[i] == hi[i]) {
      state[i] = 2;
      delta[i] = lo[i];
    } else if (hi[i] == 0.0) {
      state[i] = 1;
    } else if (lo[i] == 0.0) {
      state[i] = -1;
    }
  }
  Vector y(n), g(n);
  const int max_steps = 4 * n + 50;
  const double tol = 1e-13 * scale;
  for (int step = 0; step < max_steps; ++step) {
    if (!solve_free(state, delta, y)) return false;
    double alpha = 1.0;
    int blocking = -1;
    for (int i = 0; i < n; ++i) {
      if (state[i] != 0) continue;
      const double a = step_to_bound(delta[i], y[i] - delta[i], y[i], lo[i], hi[i]);
      if (a < alpha) alpha = a, blocking = i;
    }
    if (blocking >= 0) {
      alpha = std::max(alpha, 0.0);
      for (int i = 0; i < n; ++i)
        if (state[i] == 0)
          delta[i] = std::clamp(delta[i] + alpha * (y[i] - delta[i]), lo[i], hi[i]);
      const bool upper = y[blocking] > hi[blocking];
      state[blocking] = upper ? 1 : -1;
      delta[blocking] = upper ? hi[blocking] : lo[blocking];
      continue;
    }
    for (int i = 0; i < n; ++i)
      if (state[i] == 0) delta[i] = y[i];
    // Multipliers: at an upper bound the gradient must be ≤ 0, at a lower bound ≥ 0.
    gradient(delta, g);
    int release = -1;
    double worst = tol;
    for (int i = 0; i < n; ++i) {
      double violation = state[i] == 1 ? g[i] : state[i] == -1 ? -g[i] : 0.0;
      if (violation > worst) worst = violation, release = i;
    }
    if (release < 0) return true;
    state[release] = 0;
  }
  return true;  // capped: delta is feasible and J did not increase
}

}  // namespace

bool solve_dense_box_qp(const Eigen::MatrixXd& A, const Vector& r, const Vector& lo,
                        const Vector& hi, Vector& delta) {
  const int n = static_cast<int>(r.size());
  bool definite = true;
  auto solve_free = [&](const std::vector<signed char>& state, const Vector& d, Vector& y) {
    std::vector<int> free;
    for (int i = 0; i < n; ++i)
      if (state[i] == 0) free.push_back(i);
    y = d;
    if (free.empty()) return true;
    const int m = static_cast<int>(free.size());
    Eigen::MatrixXd aff(m, m);
    Vector rhs(m);
    for (int a = 0; a < m; ++a) {
      rhs[a] = r[free[a]];
      for (int j = 0; j < n; ++j)
        if (state[j] != 0) rhs[a] -= A(free[a], j) * d[j];
      for (int b = 0; b < m; ++b) aff(a, b) = A(free[a], free[b]);
    }
    Eigen::LLT<Eigen::MatrixXd> llt(aff);
    if (llt.info() != Eigen::Success) return definite = false;
    Vector sol = llt.solve(rhs);
    for (int a = 0; a < m; ++a) y[free[a]] = sol[a];
    return true;
  };
  auto gradient = [&](const Vector& d, Vector& g) { g = A * d - r; };
  const double scale = std::max(1e-300, r.lpNorm<Eigen::Infinity>());
  primal_active_set(n, lo, hi, delta, solve_free, gradient, scale);
  return definite;
}

SparseBoxQpSolver::SparseBoxQpSolver(const SparseMatrix& A, BlockFactorization factorization)
    : A_(A),
      diagonal_(A.diagonal()),
      free_set_(FreeSetSolver::make(A_, factorization)),
      warm_start_(factorization == BlockFactorization::held_rows) {}

bool SparseBoxQpSolver::refactor(const SparseMatrix& A) {
  if (!free_set_->refactor(A)) return false;
  std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), A_.valuePtr());
  diagonal_ = A_.diagonal();
  return true;
}

void SparseBoxQpSolver::start_from_settled(const Vector& lo, const Vector& hi,
                                           std::vector<signed char>& state) const {
  for (int i = 0; i < static_cast<int>(state.size()); ++i) {
    const signed char s = settled_[i];
    if (lo[i] == hi[i])
      state[i] = 2;
    else if ((s == 1 && is_bounded_above(hi[i])) || (s == -1 && is_bounded_below(lo[i])))
      state[i] = s;
    else
      state[i] = 0;
  }
}

SparseBoxQpSolver::~SparseBoxQpSolver() = default;

bool SparseBoxQpSolver::solve_free(const std::vector<signed char>& state, const Vector& r,
                                   const Vector& d, Vector& y) {
  return free_set_->solve(state, r, d, y);
}

bool SparseBoxQpSolver::solve_primal_dual(const Vector& r, const Vector& lo, const Vector& hi,
                                          Vector& delta) {
  // Active sets from the multiplier estimate μ = r − Aδ and the bounds, each measured in the
  // units of μ by the diagonal: i is held at its upper bound when μ_i + a_ii (δ_i − hi_i) > 0
  // (the pull up outweighs the room left), at its lower bound when μ_i + a_ii (δ_i − lo_i) < 0.
  // Unchanged sets after a solve are the KKT conditions of the box QP.
  constexpr int kMaxSteps = 20;
  const int n = static_cast<int>(r.size());
  std::vector<signed char> state(n, 0), next(n, 0);
  Vector d = Vector::Zero(n), mu = r;
  delta.setZero(n);
  auto active_sets = [&](std::vector<signed char>& s) {
    for (int i = 0; i < n; ++i) {
      if (lo[i] == hi[i])
        s[i] = 2;
      else if (is_bounded_above(hi[i]) && mu[i] + diagonal_[i] * (delta[i] - hi[i]) > 0)
        s[i] = 1;
      else if (is_bounded_below(lo[i]) && mu[i] + diagonal_[i] * (delta[i] - lo[i]) < 0)
        s[i] = -1;
      else
        s[i] = 0;
    }
  };
  if (warm_start_ && static_cast<int>(settled_.size()) == n)
    start_from_settled(lo, hi, state);
  else
    active_sets(state);
  for (int step = 0; step < kMaxSteps; ++step) {
    ++primal_dual_steps_;
    for (int i = 0; i < n; ++i) d[i] = state[i] == 1 ? hi[i] : state[i] == 0 ? 0.0 : lo[i];
    if (!solve_free(state, r, d, delta)) return false;
    mu = r - A_ * delta;
    active_sets(next);
    if (next != state) {
      state.swap(next);
      continue;
    }
    // Settled: the KKT conditions hold — a DOF held at its bound sits on it, so the rule that
    // keeps it there says its multiplier has the right sign, strictly; a free DOF is within its
    // bounds up to μ_i / a_ii, which is rounding. Clip that rounding, and check in floating
    // point what the cycle relies on before trusting the result.
    clip(delta, lo, hi);
    settled_ = state;
    const double energy = 0.5 * delta.dot(A_ * delta) - r.dot(delta);
    return energy <= 0.0;
  }
  return false;
}

bool SparseBoxQpSolver::solve(const Vector& r, const Vector& lo, const Vector& hi, Vector& delta) {
  if (solve_primal_dual(r, lo, hi, delta)) {
    ++solved_primal_dual_;
    return true;
  }
  const int n = static_cast<int>(r.size());
  auto solve_free_here = [&](const std::vector<signed char>& state, const Vector& d, Vector& y) {
    return solve_free(state, r, d, y);
  };
  auto gradient = [&](const Vector& d, Vector& g) { g = A_ * d - r; };
  const double scale = std::max(1e-300, r.lpNorm<Eigen::Infinity>());
  return primal_active_set(n, lo, hi, delta, solve_free_here, gradient, scale);
}

}  // namespace fosls
