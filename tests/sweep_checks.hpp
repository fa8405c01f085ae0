#pragma once
// The monotone multilevel method's invariants, checked after every smoother sweep and coarse
// correction (as tests/solver/monotonicity_test.cpp does in 2D): J never increases and every
// iterate is feasible.
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/multilevel_cycle.hpp"

namespace fosls::testing {

/// Installs the checks on `cycle`, whose iterations start from x; `checks` counts them. J's
/// change is measured from the step, J(x + δ) − J(x) = ½ δᵀAδ − δᵀr, so that it is exact to
/// rounding however large J is.
inline void check_every_sweep(MultilevelCycle& cycle, const BoxQp& qp, const Vector& x,
                              int& checks) {
  const double scale = std::abs(qp.energy(x)) + 1.0;
  Vector x_prev = x, r_prev = qp.b - qp.A * x;
  cycle.set_sweep_hook(
      [&qp, &checks, scale, x_prev, r_prev](const Vector& xs, const Vector&) mutable {
        const Vector step = xs - x_prev;
        EXPECT_LE(0.5 * step.dot(qp.A * step) - step.dot(r_prev), 1e-14 * scale) << checks;
        EXPECT_TRUE(qp.feasible(xs)) << checks;
        x_prev = xs;
        r_prev = qp.b - qp.A * xs;
        ++checks;
      });
}

/// `cycles` nonlinear cycles from zero with those checks; returns how many checks ran.
inline int checked_cycles_from_zero(const BoxQp& qp, const LevelHierarchy& h, int cycles) {
  MultilevelCycle cycle(qp, h, MultilevelOptions{});
  Vector x = Vector::Zero(qp.size()), r = qp.b;
  int checks = 0;
  check_every_sweep(cycle, qp, x, checks);
  for (int k = 0; k < cycles; ++k) {
    cycle.nonlinear_cycle(x, r);
    r = qp.b - qp.A * x;
  }
  return checks;
}

}  // namespace fosls::testing
