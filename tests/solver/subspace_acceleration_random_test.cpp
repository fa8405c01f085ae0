// The subspace acceleration (docs/method.md §4.5) around projected Gauss–Seidel sweeps on small
// random box QPs: ill-conditioned SPD matrices, bounds of every kind (absent as ±kNoBound or
// ±∞, one-sided, two-sided not containing 0, fixed DOFs lower == upper at non-zero values).
// At every accelerated step the iterate must be exactly feasible, J must not rise above the
// sweep's iterate, a step shortened by a bound must put that DOF exactly on it, and the final
// iterate must be the enumerated exact minimiser. Degenerate planes must leave the step alone.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "box_qp_enumeration.hpp"
#include "solvers/point_smoother.hpp"
#include "solvers/subspace_acceleration.hpp"

namespace fosls {
namespace {

/// A = Q diag(λ) Qᵀ with λ log-uniform in [10⁻³, 1] (slow for plain sweeps, so the acceleration
/// acts on many steps), b = A z with |z_i| ≤ 2 so that many bounds are active at the solution.
BoxQp random_problem(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 6);
  Eigen::MatrixXd g(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) g(i, j) = u(rng);
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(g).householderQ();
  Vector lambda(n);
  for (int i = 0; i < n; ++i) lambda[i] = std::pow(10.0, -1.5 + 1.5 * u(rng));
  const Eigen::MatrixXd a = q * lambda.asDiagonal() * q.transpose();
  BoxQp qp;
  qp.A = a.sparseView();
  Vector z(n);
  for (int i = 0; i < n; ++i) z[i] = 2.0 * u(rng);
  qp.b = a * z;
  qp.lower.resize(n), qp.upper.resize(n);
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double c = u(rng), w = 0.01 + 0.5 * std::abs(u(rng));
    double lo = -kNoBound, hi = kNoBound;
    switch (kind(rng)) {
      case 0:
        break;
      case 1:
        lo = -inf, hi = inf;
        break;
      case 2:
        hi = c;
        break;
      case 3:
        lo = c;
        break;
      case 4:
        lo = c - w, hi = c + w;
        break;
      case 5:
        lo = hi = c;
        break;
      default:
        lo = std::min(0.0, c), hi = std::max(0.0, c);
    }
    qp.lower[i] = lo, qp.upper[i] = hi;
  }
  return qp;
}

struct Tally {
  int steps = 0, accelerated = 0, shortened = 0;
  double worst_rise = 0.0;  ///< largest J(x) − J(x̂) relative to the size of its terms
};

/// Sweeps (alternating direction) with the acceleration until the KKT residual is 10⁻¹³ of
/// the initial one; checks every step; returns the final iterate.
Vector accelerated_sweeps(const BoxQp& qp, Tally& tally, const std::string& name) {
  const PointSmoother smoother(qp.A);
  SubspaceAcceleration acceleration(qp);
  Vector x = Vector::Zero(qp.size());
  for (int i = 0; i < qp.size(); ++i) x[i] = std::clamp(x[i], qp.lower[i], qp.upper[i]);
  Vector r = qp.b - qp.A * x;
  const double initial = qp.kkt_residual(x, r);
  for (int k = 0; k < 5000 && qp.kkt_residual(x, r) > 1e-13 * initial; ++k) {
    const Vector x_old = x, r_old = r;
    smoother.sweep(x, r, qp.lower, qp.upper, k % 2 == 0);
    const Vector x_hat = x, r_hat = qp.b - qp.A * x;
    const double t = acceleration.accelerate(x_old, r_old, x, r);
    ++tally.steps;
    EXPECT_TRUE(qp.feasible(x)) << name << " step " << k;
    EXPECT_TRUE(x.allFinite()) << name << " step " << k;
    if (t > 0.0) ++tally.accelerated;
    // J(x̂ + δ) − J(x̂) = ½ δᵀAδ − δᵀr̂, accurate where J itself is not.
    const Vector delta = x - x_hat;
    const double quad = 0.5 * delta.dot(qp.A * delta), lin = delta.dot(r_hat);
    const double scale = std::abs(quad) + std::abs(lin);
    if (scale > 0) tally.worst_rise = std::max(tally.worst_rise, (quad - lin) / scale);
    if (t > 0.0 && t < 1.0) {
      // The bound that shortened the move must be reached exactly, or the DOF does not enter
      // the active set (the truncation of the next cycle would treat it as free).
      ++tally.shortened;
      bool landed = false;
      for (int i = 0; i < qp.size(); ++i)
        landed |= x[i] != x_hat[i] && (x[i] == qp.lower[i] || x[i] == qp.upper[i]);
      EXPECT_TRUE(landed) << name << " step " << k << ": t = " << t;
    }
    const Vector exact = qp.b - qp.A * x;
    EXPECT_LE((r - exact).norm(), 1e-10 * (1.0 + exact.norm())) << name << " step " << k;
    r = exact;
    acceleration.remember(x_old, r_old, x, r);
  }
  EXPECT_LE(qp.kkt_residual(x, r), 1e-13 * initial) << name;
  return x;
}

TEST(SubspaceAccelerationRandom, FeasibleMonotoneAndExactOnRandomBoxQps) {
  std::mt19937 rng(2026);
  Tally tally;
  for (int trial = 0; trial < 5000; ++trial) {
    const BoxQp qp = random_problem(rng, 2 + trial % 7);
    const std::string name = "trial " + std::to_string(trial);
    const Vector x = accelerated_sweeps(qp, tally, name);
    const Vector best = testing::enumerate_box_qp(qp.A, qp.b, qp.lower, qp.upper);
    ASSERT_EQ(best.size(), x.size()) << name;
    EXPECT_LE((x - best).norm(), 1e-8 * (1.0 + best.norm())) << name;
  }
  // Rounding only: a rise of J beyond 10⁻¹² of the terms would be a wrong plane minimiser.
  EXPECT_LE(tally.worst_rise, 1e-12);
  // The test must exercise both the full move and the move shortened by a bound.
  EXPECT_GT(tally.accelerated, tally.steps / 4);
  EXPECT_GT(tally.shortened, 20);
  std::printf("%d steps, %d accelerated, %d shortened by a bound, worst relative rise %.2e\n",
              tally.steps, tally.accelerated, tally.shortened, tally.worst_rise);
}

/// ½ xᵀAx − bᵀx on three unbounded DOFs, A tridiagonal.
BoxQp unbounded_three() {
  Eigen::MatrixXd a(3, 3);
  a << 2, -1, 0, -1, 2, -1, 0, -1, 2;
  BoxQp qp;
  qp.A = a.sparseView();
  qp.b = Vector::Ones(3);
  qp.lower = Vector::Constant(3, -kNoBound);
  qp.upper = Vector::Constant(3, kNoBound);
  return qp;
}

/// Takes the step `step` from x_old (r follows exactly) and returns the accelerated iterate;
/// `taken` receives accelerate's t.
Vector step_and_accelerate(const BoxQp& qp, SubspaceAcceleration& acc, const Vector& x_old,
                           const Vector& step, double& taken) {
  const Vector r_old = qp.b - qp.A * x_old;
  Vector x = x_old + step, r = qp.b - qp.A * x;
  taken = acc.accelerate(x_old, r_old, x, r);
  return x;
}

TEST(SubspaceAccelerationRandom, DegeneratePlanesLeaveTheStepAlone) {
  const BoxQp qp = unbounded_three();
  const Vector zero = Vector::Zero(3), s = Vector(Vector::LinSpaced(3, 1.0, 2.0));
  double t = -1.0;
  SubspaceAcceleration acc(qp);
  // No previous step yet.
  EXPECT_EQ(step_and_accelerate(qp, acc, zero, s, t), s);
  EXPECT_EQ(t, 0.0);
  const auto remember = [&](const Vector& x_old, const Vector& x) {
    acc.remember(x_old, qp.b - qp.A * x_old, x, qp.b - qp.A * x);
  };
  remember(zero, s);
  // A zero step, the same step again, and a step parallel to the previous one (either sign).
  for (const Vector& d : {Vector(zero), Vector(s), Vector(-2.0 * s), Vector(1e-9 * s)}) {
    EXPECT_EQ(step_and_accelerate(qp, acc, s, d, t), s + d) << d.transpose();
    EXPECT_EQ(t, 0.0) << d.transpose();
  }
  // A zero previous step.
  remember(s, s);
  EXPECT_EQ(step_and_accelerate(qp, acc, s, s, t), 2.0 * s);
  EXPECT_EQ(t, 0.0);
  // Steps so large that the 2×2 system overflows (inf − inf): the method's iterate stays.
  const Vector big = 1e160 * s, other = 1e160 * Vector(Vector::LinSpaced(3, 2.0, -1.0));
  remember(zero, big);
  const Vector x = step_and_accelerate(qp, acc, big, other, t);
  EXPECT_TRUE(x.allFinite()) << x.transpose();
  EXPECT_EQ(t, 0.0);
}

}  // namespace
}  // namespace fosls
