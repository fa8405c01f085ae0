// The monotone smoothers (docs/method.md §4.1) on their own: from feasible iterates close to
// the contact bounds, every sweep of the pointwise, vertex-patch and contact-strip smoothers
// keeps the iterate within the bounds, does not increase J, lowers it over the first sweeps,
// and keeps the residual r = b − A x it updates in place.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <random>

#include "contact_problems.hpp"
#include "solvers/patch_smoother.hpp"
#include "solvers/point_smoother.hpp"
#include "solvers/smoother_table.hpp"
#include "solvers/strip_smoother.hpp"

namespace fosls {
namespace {

using Sweep = std::function<void(Vector& x, Vector& r, bool forward)>;

/// A feasible x with many bounded DOFs at or just below their bound, random elsewhere.
Vector near_the_bounds(const BoxQp& qp, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector x(qp.size());
  for (int i = 0; i < qp.size(); ++i) {
    x[i] = 0.05 * (2.0 * u(rng) - 1.0);
    if (is_bounded_above(qp.upper[i])) x[i] = qp.upper[i] - (u(rng) < 0.5 ? 0.0 : 0.01 * u(rng));
  }
  return x;
}

void expect_monotone(const BoxQp& qp, const Sweep& sweep, const char* name) {
  std::mt19937 rng(4);
  for (int start = 0; start < 3; ++start) {
    Vector x = near_the_bounds(qp, rng);
    ASSERT_TRUE(qp.feasible(x));
    Vector r = qp.b - qp.A * x;
    const double initial = qp.energy(x);
    double energy = initial;
    for (int s = 0; s < 6; ++s) {
      const Vector x_old = x, r_old = r;
      sweep(x, r, s % 2 == 0);
      // J(x + δ) − J(x) = ½ δᵀAδ − δᵀr_old, accurate where J itself is not.
      const Vector step = x - x_old;
      const double change = 0.5 * step.dot(qp.A * step) - step.dot(r_old);
      EXPECT_LE(change, 1e-13 * std::abs(initial))
          << name << ", start " << start << ", sweep " << s;
      EXPECT_TRUE(qp.feasible(x)) << name << ", start " << start << ", sweep " << s;
      const Vector exact = qp.b - qp.A * x;
      EXPECT_LE((r - exact).norm(), 1e-10 * (1.0 + exact.norm())) << name << ", sweep " << s;
      energy += change;
    }
    EXPECT_LT(energy, initial - 1e-6 * std::abs(initial)) << name << ": no progress";
  }
}

class Smoothers : public ::testing::TestWithParam<bool> {
 protected:
  Smoothers()
      : disc_(GetParam() ? Discretization<2>(build_mesh_hierarchy(make_hertz({.size = 0.2}), 1),
                                             testing::hertz(1.0))
                         : Discretization<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 1),
                                             testing::signorini_square(1.0))),
        hierarchy_(disc_.build_level_hierarchy()) {}
  const BoxQp& qp() const { return disc_.problem().qp; }
  const Level& finest() const { return hierarchy_.levels.back(); }

  Discretization<2> disc_;
  LevelHierarchy hierarchy_;
};

TEST_P(Smoothers, PointwiseGaussSeidelIsMonotoneAndFeasible) {
  const PointSmoother smoother(qp().A);
  expect_monotone(
      qp(), [&](Vector& x, Vector& r, bool f) { smoother.sweep(x, r, qp().lower, qp().upper, f); },
      "point");
}

TEST_P(Smoothers, VertexPatchSmootherIsMonotoneAndFeasible) {
  const PatchSmoother smoother(qp().A, finest().patches);
  expect_monotone(
      qp(), [&](Vector& x, Vector& r, bool f) { smoother.sweep(x, r, qp().lower, qp().upper, f); },
      "patch");
}

// What the cycle and pgs construct: every row of the smoother table, through its make function.
TEST_P(Smoothers, EverySmootherOfTheTableIsMonotoneAndFeasible) {
  for (const SmootherInfo& info : kSmootherTable) {
    const std::unique_ptr<Smoother> smoother = info.make(qp().A, finest());
    expect_monotone(
        qp(),
        [&](Vector& x, Vector& r, bool f) { smoother->sweep(x, r, qp().lower, qp().upper, f); },
        info.name);
  }
}

TEST_P(Smoothers, ContactStripSolveIsMonotoneFeasibleAndExactOnItsBlock) {
  ASSERT_FALSE(finest().contact_strip.empty());
  for (BlockFactorization kind : {BlockFactorization::reduced, BlockFactorization::held_rows}) {
    StripSmoother smoother(qp().A, finest().contact_strip, kind);
    expect_monotone(
        qp(),
        [&](Vector& x, Vector& r, bool) { smoother.sweep(x, r, qp().lower, qp().upper, true); },
        "strip");
    // Exact on the block: a second solve right after the first changes nothing.
    std::mt19937 rng(8);
    Vector x = near_the_bounds(qp(), rng);
    Vector r = qp().b - qp().A * x;
    smoother.sweep(x, r, qp().lower, qp().upper, true);
    const Vector once = x;
    smoother.sweep(x, r, qp().lower, qp().upper, true);
    EXPECT_LE((x - once).norm(), 1e-10 * (1.0 + once.norm()));
  }
}

INSTANTIATE_TEST_SUITE_P(Problems, Smoothers, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "hertz" : "square"; });

}  // namespace
}  // namespace fosls
