// Three dimensions, stage 2 (docs/method.md §11): frictionless contact of a block pressed onto a
// curved gap — the 3D Signorini block. The monotone multilevel method keeps J non-increasing and
// every iterate feasible after each smoother sweep and coarse correction, agrees with pdas on
// the same discrete problem, and converges in at most 45 iterations (not yet flat over levels).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "../tet_problems.hpp"
#include "assembly/tet_hierarchy.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

class TetContact : public ::testing::TestWithParam<double> {};

TEST_P(TetContact, MonotoneFeasibleAndEqualToPdas) {
  for (int r = 1; r <= 2; ++r) {
    const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), r),
                                 testing::signorini_block(GetParam()));
    const BoxQp& qp = disc.problem().qp;
    const LevelHierarchy h = disc.build_level_hierarchy();
    EXPECT_EQ(hierarchy_inconsistency(h, qp.size()), "");
    if (r == 2) {  // every step of the cycle, from zero, as monotonicity_test does in 2D
      MultilevelCycle cycle(qp, h, MultilevelOptions{});
      Vector x = Vector::Zero(qp.size()), r0 = qp.b;
      Vector x_prev = x, r_prev = r0;
      const double scale = std::abs(qp.energy(x)) + 1.0;
      int checks = 0;
      cycle.set_sweep_hook([&](const Vector& xs, const Vector&) {
        const Vector step = xs - x_prev;
        EXPECT_LE(0.5 * step.dot(qp.A * step) - step.dot(r_prev), 1e-14 * scale) << checks;
        EXPECT_TRUE(qp.feasible(xs)) << checks;
        x_prev = xs;
        r_prev = qp.b - qp.A * xs;
        ++checks;
      });
      for (int k = 0; k < 10; ++k) {
        cycle.nonlinear_cycle(x, r0);
        r0 = qp.b - qp.A * x;
      }
      EXPECT_GE(checks, 30);
    }
    SolverOptions options;
    options.tolerance = 1e-10;  // so that the forces compare to 1e-6
    Vector x = Vector::Zero(qp.size());
    const SolverReport mmg = solve_box_qp(qp, h, options, {}, x);
    EXPECT_TRUE(mmg.converged) << r;
    options.method = SolverMethod::kPdas;
    Vector y = Vector::Zero(qp.size());
    const SolverReport pdas = solve_box_qp(qp, h, options, {}, y);
    EXPECT_TRUE(pdas.converged) << r;
    const TetAssembler& a = disc.assembler();
    const Point3 f_mmg = a.contact_force(a.full_vector(disc.problem(), x));
    const Point3 f_pdas = a.contact_force(a.full_vector(disc.problem(), y));
    EXPECT_GT(f_pdas.z(), 0.0);  // the obstacle pushes the block up
    EXPECT_NEAR(f_mmg.z(), f_pdas.z(), 1e-6 * f_pdas.z()) << r;
    EXPECT_NEAR(f_mmg.x(), 0.0, 1e-6 * f_pdas.z());  // symmetric about x = ½ and y = ½
    std::printf("λ = %g, r = %d: %d unknowns, mmg %d iterations, F_z %.8f (pdas %.8f)\n",
                GetParam(), r, qp.size(), mmg.iterations, f_mmg.z(), f_pdas.z());
    EXPECT_LE(mmg.iterations, 45) << r;  // measured 20–40 to 1e-10 (validation.md §16)
  }
}

INSTANTIATE_TEST_SUITE_P(Lambda, TetContact,
                         ::testing::Values(1.0, std::numeric_limits<double>::infinity()));

}  // namespace
}  // namespace fosls
