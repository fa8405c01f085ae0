// The one adaptive loop of strategy/level_loop.hpp in 3D (issues 47, 48): the Signorini
// block of tests/tet_problems.hpp solved, estimated, marked (Dörfler) and bisected
// (tet_bisection.hpp) three times. On every adapted level mmg keeps J non-increasing and every
// iterate feasible after every smoother sweep and coarse correction, each step's solve converges in
// a bounded number of iterations from the prolongated solution, and the estimator J^½ decreases.
// The last steps' solver levels skip bisection levels of the contact zone, so those checks run
// across contact links of chains of midpoints, vertices inside coarse faces and faces with more
// than four children.
// The same loop with an accuracy section refines uniformly and estimates the force's error, which
// bounds the error against the force of the next uniform refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../contact_zone_skips.hpp"
#include "../step_energy_counter.hpp"
#include "../sweep_checks.hpp"
#include "../tet_problems.hpp"
#include "case/run/level_loop_options.hpp"
#include "strategy/level_loop.hpp"

namespace fosls {
namespace {

CaseSpec adaptive_spec(int steps) {
  CaseSpec spec;
  spec.dimension = 3;
  spec.solver.method = SolverMethod::kMmg;
  spec.solver.tolerance = 1e-8;
  AdaptivitySpec a;
  a.steps = steps;
  a.theta = 0.5;
  spec.adaptivity = a;
  return spec;
}

/// The first `levels` meshes of `h`: the hierarchy of an earlier step of the loop.
TetHierarchy first_levels(const TetHierarchy& h, int levels) {
  TetHierarchy p;
  p.meshes.assign(h.meshes.begin(), h.meshes.begin() + levels);
  p.maps.assign(h.maps.begin(), h.maps.begin() + levels);
  return p;
}

TEST(AdaptiveLoop3d, MonotoneFeasibleBoundedAndTheEstimatorDecreases) {
  const ProblemData<3> data = testing::signorini_block(1.0);
  // J after every fine-level sweep of every step's solve: non-increasing within a step.
  testing::StepEnergyCounter energy;
  const LevelSolution<3> s =
      solve_levels<3>(build_tet_hierarchy(make_box({2, 2, 2}), 1), data,
                      level_loop_options(adaptive_spec(3)), energy.observer());
  EXPECT_EQ(s.stop_reason, "steps");
  ASSERT_EQ(s.steps.size(), 4u);
  EXPECT_GT(energy.sweeps, 0);
  EXPECT_EQ(energy.increases, 0);
  EXPECT_TRUE(s.disc->problem().qp.feasible(s.x));
  const int uniform_tets = build_tet_hierarchy(make_box({2, 2, 2}), 2).finest().num_tets();
  for (std::size_t k = 0; k < s.steps.size(); ++k) {
    const AdaptiveStepRecord& r = s.steps[k];
    std::printf(
        "step %zu: %d levels, %lld unknowns, %lld tetrahedra, J^1/2 %.6g, F_z %.8f, %d "
        "iterations, %d marked\n",
        k, r.levels, r.dofs, r.cells, r.estimator, r.force[2], r.iterations, r.marked);
    EXPECT_TRUE(r.converged) << k;
    // Measured 9–14 (the first from the nested iteration, the others from the prolongation).
    EXPECT_LE(r.iterations, 25) << k;
    if (k > 0) {
      EXPECT_LT(r.estimator, s.steps[k - 1].estimator) << k;
      EXPECT_GT(r.cells, s.steps[k - 1].cells) << k;
    }
  }
  // Local: the last adapted mesh has fewer tetrahedra than the next uniform refinement.
  EXPECT_LT(s.steps.back().cells, uniform_tets);
  // Every adapted level's hierarchy: J non-increasing and every iterate feasible after every
  // sweep and coarse correction of cycles from zero.
  const TetHierarchy& all = s.disc->meshes();
  int skips_last = 0;
  for (const AdaptiveStepRecord& r : s.steps) {
    const Discretization<3> disc(first_levels(all, r.levels), data);
    const LevelHierarchy h = disc.build_level_hierarchy();
    EXPECT_GE(testing::checked_cycles_from_zero(disc.problem().qp, h, 5), 10) << r.levels;
    skips_last = testing::contact_zone_skips(h, 3);
    std::printf("%d mesh levels: %d solver levels, %d contact-zone links across skipped levels\n",
                r.levels, h.num_levels(), skips_last);
  }
  // The last step's solver levels skip bisection levels of the contact zone too, and the checks
  // above ran across them.
  EXPECT_GT(skips_last, 0);
}

TEST(AccuracyLoop3d, TheForceErrorEstimateBoundsTheErrorAgainstAFinerLevel) {
  const ProblemData<3> data = testing::signorini_block(1.0);
  CaseSpec spec;
  spec.dimension = 3;
  spec.solver.tolerance = 1e-9;
  AccuracySpec a;
  a.force = 1e-9;  // not reachable: the loop stops at max_dofs after refinement 2
  a.max_dofs = 100'000;
  a.adaptive = false;  // the uniform levels, whose refinement 3 is the reference
  spec.accuracy = a;
  const LevelSolution<3> s =
      solve_levels<3>(build_tet_hierarchy(make_box({2, 2, 2}), 0), data, level_loop_options(spec));
  EXPECT_EQ(s.stop_reason, "max_dofs");
  ASSERT_EQ(s.steps.size(), 3u);  // refinements 0 to 2
  // The reference: refinement 3 solved on its own.
  CaseSpec plain;
  plain.dimension = 3;
  const LevelSolution<3> fine =
      solve_levels<3>(build_tet_hierarchy(make_box({2, 2, 2}), 3), data, level_loop_options(plain));
  const double reference = fine.force[2];
  for (std::size_t k = 1; k < s.steps.size(); ++k) {
    const AdaptiveStepRecord& r = s.steps[k];
    const double error = std::abs(r.force[2] - reference) / std::abs(r.force[2]);
    std::printf(
        "refinement %zu: F_z %.8f, estimate %.3g, error against refinement 3 %.3g, "
        "efficiency %.2f\n",
        k, r.force[2], r.force_error.estimate, error, r.force_error.estimate / error);
    ASSERT_TRUE(r.force_error.available());
    // An upper bound (issue 48): measured efficiencies 7.4 and 3.0. The block's force
    // oscillates over the refinements (0.0473, 0.0515, 0.0485 at 1, 2, 3), so refinement 2's
    // changes have opposite signs and its estimate is the larger change, not change / (ρ − 1).
    EXPECT_GE(r.force_error.estimate, error) << k;
    EXPECT_LE(r.force_error.estimate, 10.0 * error) << k;
  }
  EXPECT_FALSE(s.steps[2].force_error.monotone);
}

}  // namespace
}  // namespace fosls
