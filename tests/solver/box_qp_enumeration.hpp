#pragma once
// Brute-force reference for small bound-constrained QPs: the minimiser of
// ½ δᵀAδ − rᵀδ over lo ≤ δ ≤ hi (A SPD) by enumerating which DOFs sit at which bound.

#include <Eigen/Dense>
#include <limits>
#include <random>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls::testing {

/// Whether lo ≤ x ≤ hi holds exactly.
inline bool within(const Vector& x, const Vector& lo, const Vector& hi) {
  for (int i = 0; i < x.size(); ++i)
    if (x[i] < lo[i] || x[i] > hi[i]) return false;
  return true;
}

/// Every bounded DOF is free, at its lower or at its upper bound (unbounded sides skipped,
/// unbounded DOFs always free); for each choice the stationary point on that face, and of the
/// feasible ones the one of least energy. A strictly convex QP has exactly one minimiser, the
/// stationary point of the face its active set spans, so this is the exact answer (up to
/// rounding). Cost: the product over DOFs of their number of states, each a dense solve.
inline Vector enumerate_box_qp(const SparseMatrix& sparse_a, const Vector& r, const Vector& lo,
                               const Vector& hi) {
  const Eigen::MatrixXd a(sparse_a);
  const int n = static_cast<int>(r.size());
  std::vector<std::vector<int>> states(n);  // 0 free, 1 at lower, 2 at upper
  long long choices = 1;
  for (int i = 0; i < n; ++i) {
    states[i].push_back(0);
    if (is_bounded_below(lo[i])) states[i].push_back(1);
    if (is_bounded_above(hi[i])) states[i].push_back(2);
    choices *= static_cast<long long>(states[i].size());
  }
  Vector best;
  double best_energy = std::numeric_limits<double>::infinity();
  for (long long code = 0; code < choices; ++code) {
    Vector x = Vector::Zero(n);
    std::vector<int> free;
    long long c = code;
    for (int i = 0; i < n; ++i) {
      const int k = static_cast<int>(states[i].size());
      const int state = states[i][c % k];
      c /= k;
      if (state == 0) free.push_back(i);
      if (state == 1) x[i] = lo[i];
      if (state == 2) x[i] = hi[i];
    }
    const int m = static_cast<int>(free.size());
    if (m > 0) {
      Eigen::MatrixXd aff(m, m);
      Vector rhs(m);
      for (int p = 0; p < m; ++p) {
        rhs[p] = r[free[p]] - a.row(free[p]).dot(x);
        for (int q = 0; q < m; ++q) aff(p, q) = a(free[p], free[q]);
      }
      const Vector y = aff.llt().solve(rhs);
      for (int p = 0; p < m; ++p) x[free[p]] = y[p];
    }
    if (!within(x, lo, hi)) continue;
    const double energy = 0.5 * x.dot(a * x) - r.dot(x);
    if (energy < best_energy) best_energy = energy, best = x;
  }
  return best;
}

/// A random problem of the shape the solvers see: SPD A (sparse storage, some zero
/// couplings), bounds lo ≤ 0 ≤ hi with each side finite, zero or absent, some DOFs fixed.
struct RandomBoxQp {
  SparseMatrix A;
  Vector r, lo, hi;
};

inline RandomBoxQp random_box_qp(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 5);
  Eigen::MatrixXd b(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) b(i, j) = (kind(rng) == 0) ? 0.0 : u(rng);
  Eigen::MatrixXd a = b * b.transpose() + 0.05 * Eigen::MatrixXd::Identity(n, n);
  RandomBoxQp p;
  p.A = a.sparseView();
  p.r.resize(n), p.lo.resize(n), p.hi.resize(n);
  for (int i = 0; i < n; ++i) {
    p.r[i] = 2.0 * u(rng);
    auto side = [&](double sign) {
      switch (kind(rng)) {
        case 0:
        case 1:
          return sign * kNoBound;
        case 2:
          return 0.0;
        default:
          return sign * 0.5 * (1.0 + u(rng));
      }
    };
    p.lo[i] = side(-1.0);
    p.hi[i] = side(1.0);
    if (kind(rng) == 0 && i % 3 == 0) p.lo[i] = p.hi[i] = 0.0;  // fixed
  }
  return p;
}

}  // namespace fosls::testing
