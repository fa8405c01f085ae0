// The multilevel cycle builds its coarse levels for the truncated set they are used with, and
// only then: constructing a cycle builds none, and every cycle of a constrained solve builds at
// most once (when its truncated set is new). A build that was thrown away at the first cycle
// cost one full coarse rebuild per solve, per adaptive step (docs/performance.md, adaptivity).
#include <gtest/gtest.h>

#include "adapted_hierarchy.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

TEST(CycleSetup, CoarseLevelsAreBuiltOncePerTruncatedSetAndNotBeforeTheFirstCycle) {
  const ProblemData<2> data = testing::hertz(1.0);
  const Discretization<2> disc(
      testing::adapted_hierarchy(build_mesh_hierarchy(make_hertz({.size = 0.1}), 1), data, 3),
      data);
  // Every bisection level kept (a share of 1): the default skips them down to three levels.
  const LevelHierarchy h = disc.build_level_hierarchy(1.0);
  ASSERT_GE(h.num_levels(), 4);
  const BoxQp& qp = disc.problem().qp;
  MultilevelCycle cycle(qp, h, MultilevelOptions{});
  EXPECT_EQ(cycle.statistics().galerkin_rebuilds, 0);
  Vector x = Vector::Zero(qp.size());
  Vector r = qp.b - qp.A * x;
  for (int k = 1; k <= 8; ++k) {
    cycle.nonlinear_cycle(x, r);
    r = qp.b - qp.A * x;
    // A cycle's truncated set is the fine active set after its pre-smoothing; the rebuilds
    // count the sets that differ from the last one, the first included.
    EXPECT_LE(cycle.statistics().galerkin_rebuilds, k);
  }
  EXPECT_GE(cycle.statistics().galerkin_rebuilds, 1);
}

TEST(CycleSetup, ASingleLevelHasItsExactSolverAtOnce) {
  const ProblemData<2> data = testing::signorini_square(1.0);
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.5}), 0), data);
  const LevelHierarchy h = disc.build_level_hierarchy();
  ASSERT_EQ(h.num_levels(), 1);
  const BoxQp& qp = disc.problem().qp;
  MultilevelCycle cycle(qp, h, MultilevelOptions{});
  Vector x = Vector::Zero(qp.size());
  Vector r = qp.b - qp.A * x;
  const double initial_kkt = qp.kkt_residual(x, r);
  ASSERT_GT(initial_kkt, 0.0);
  // One cycle on one level is the exact solve.
  cycle.nonlinear_cycle(x, r);
  r = qp.b - qp.A * x;
  EXPECT_LE(qp.kkt_residual(x, r), 1e-10 * initial_kkt);
}

}  // namespace
}  // namespace fosls
