// Three dimensions, stage 2 (docs/method.md §11): frictionless contact of a block pressed onto a
// curved gap — the 3D Signorini block. The monotone multilevel method keeps J non-increasing and
// every iterate feasible after each smoother sweep and coarse correction, agrees with pdas on
// the same discrete problem, and converges in at most 30 iterations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "../sweep_checks.hpp"
#include "../tet_problems.hpp"
#include "assembly/discretization.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

class TetContact : public ::testing::TestWithParam<double> {};

TEST_P(TetContact, MonotoneFeasibleAndEqualToPdas) {
  for (int r = 1; r <= 2; ++r) {
    const Discretization<3> disc(build_tet_hierarchy(make_box({2, 2, 2}), r),
                                 testing::signorini_block(GetParam()));
    const BoxQp& qp = disc.problem().qp;
    const LevelHierarchy h = disc.build_level_hierarchy();
    EXPECT_EQ(hierarchy_inconsistency(h, qp.size()), "");
    if (r == 2)  // every step of the cycle, from zero, as monotonicity_test does in 2D
      EXPECT_GE(testing::checked_cycles_from_zero(qp, h, 10), 30);
    const testing::MmgAndPdas s = testing::solve_with_mmg_and_pdas(disc, h);
    EXPECT_TRUE(s.mmg.converged) << r;
    EXPECT_TRUE(s.pdas.converged) << r;
    EXPECT_GT(s.pdas_force.z(), 0.0);  // the obstacle pushes the block up
    EXPECT_NEAR(s.force.z(), s.pdas_force.z(), 1e-6 * s.pdas_force.z()) << r;
    EXPECT_NEAR(s.force.x(), 0.0, 1e-6 * s.pdas_force.z());  // symmetric about x = ½ and y = ½
    std::printf("λ = %g, r = %d: %d unknowns, mmg %d iterations, F_z %.8f (pdas %.8f)\n",
                GetParam(), r, qp.size(), s.mmg.iterations, s.force.z(), s.pdas_force.z());
    // 19–26 to 1e-10 with the 3D flux moves, up to 40 without (validation.md §16).
    EXPECT_LE(s.mmg.iterations, 30) << r;
  }
}

INSTANTIATE_TEST_SUITE_P(Lambda, TetContact,
                         ::testing::Values(1.0, std::numeric_limits<double>::infinity()));

}  // namespace
}  // namespace fosls
