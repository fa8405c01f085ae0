// The quarter half ball of the shipped hertz_3d_accuracy (symmetry rollers), first as the
// previous example ran it: adaptive steps of tetrahedron bisection from refinements 1 with mmg,
// stopped after its ninth step. That step's
// solve, on a hierarchy of 12 levels, was refused as "not positive definite" at a vertex patch
// of the eighth step's level. There a coarse U_n whose fine U_n were all truncated kept only
// its leakage into the fine tangential components (the normals of the two levels at the vertex
// differ by 2·10⁻⁵), so the truncated Galerkin matrix had a diagonal entry 10⁻¹⁰ of its
// neighbours'; such a column is now truncated away entirely (TruncatedProlongation::
// kNegligibleColumn). Every step converges in a bounded number of iterations, J never increases
// after a sweep, the iterate is feasible, and the force approaches the ball's own (validation.md
// §16: +1.12 % at this step, measured). Then the shipped accuracy loop, whose claim must hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <variant>

#include "../shipped_example.hpp"
#include "../step_energy_counter.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_problem_data.hpp"
#include "case/run/level_loop_options.hpp"
#include "case/run/volume_mesh_checks.hpp"
#include "mesh/length_scale.hpp"
#include "mesh/tet_refinement.hpp"
#include "strategy/level_loop.hpp"

namespace fosls {
namespace {

/// The ball's own force at λ = 1 (the independent axisymmetric solve, validation.md §16).
constexpr double kBallForce = 0.0037014;

TEST(AdaptiveQuarterBall, TheNinthBisectionStepSolvesMonotoneAndFeasible) {
  nlohmann::json j = testing::load_shipped_example("3d/hertz_3d_accuracy");
  j.erase("accuracy");  // the shipped loop's bisection steps, from refinements 1, nine of them
  j["mesh"]["refinements"] = 1;
  j["adaptivity"] = {{"steps", 9}, {"theta", 0.5}};
  j["solver"] = {{"method", "mmg"}, {"tolerance", 1e-8}};
  const auto read = read_case(j);
  ASSERT_TRUE(read.errors.empty()) << read.errors[0].detail;
  CaseSpec spec = *read.spec;
  auto built = builtin_3d_mesh(spec.mesh);
  ASSERT_TRUE(std::holds_alternative<TetMesh>(built));
  TetMesh coarse = std::move(std::get<TetMesh>(built));
  spec.weights.length_scale = length_scale(coarse);
  TetHierarchy meshes = build_tet_hierarchy(std::move(coarse), spec.mesh.refinements);
  ProblemData<3> data = problem_data<3>(spec, meshes.finest());
  choose_contact_weight<3>(spec, meshes, data);

  testing::StepEnergyCounter energy;
  const LevelSolution<3> s =
      solve_levels<3>(std::move(meshes), data, level_loop_options(spec), energy.observer());
  EXPECT_EQ(s.stop_reason, "steps");
  ASSERT_EQ(s.steps.size(), 10u);
  EXPECT_GT(energy.sweeps, 0);
  EXPECT_EQ(energy.increases, 0);
  EXPECT_TRUE(s.disc->problem().qp.feasible(s.x));
  for (const AdaptiveStepRecord& r : s.steps) {
    std::printf("step %d: %d levels, %lld unknowns, 4 F_z %.7f (%+.2f %%), %d iterations\n", r.step,
                r.levels, r.dofs, 4 * r.force[2], 100 * (4 * r.force[2] / kBallForce - 1),
                r.iterations);
    EXPECT_TRUE(r.converged) << r.step;
    EXPECT_LE(r.iterations, 40) << r.step;  // measured 9–22 (7–22 on every level)
  }
  EXPECT_GE(s.steps.back().levels, 12);
  // The solvers' levels are a factor apart (assembly/solver_levels.hpp).
  const int solver_levels = s.disc->build_level_hierarchy().num_levels();
  std::printf("last step: %d mesh levels, %d for the solvers\n", s.disc->num_levels(),
              solver_levels);
  EXPECT_LT(solver_levels, s.disc->num_levels() - 2);
  // Measured +1.12 %; the steps before range from +1.08 % to +2.31 %.
  EXPECT_NEAR(4 * s.steps.back().force[2] / kBallForce, 1.0, 0.02);
}

/// The shipped case as read, its accuracy request replaced by `force`.
LevelSolution<3> solved_shipped_accuracy(double force) {
  nlohmann::json j = testing::load_shipped_example("3d/hertz_3d_accuracy");
  j["accuracy"]["force"] = force;
  const auto read = read_case(j);
  EXPECT_TRUE(read.errors.empty()) << read.errors[0].detail;
  CaseSpec spec = *read.spec;
  auto built = builtin_3d_mesh(spec.mesh);
  TetMesh coarse = std::move(std::get<TetMesh>(built));
  spec.weights.length_scale = length_scale(coarse);
  TetHierarchy meshes = build_tet_hierarchy(std::move(coarse), spec.mesh.refinements);
  ProblemData<3> data = problem_data<3>(spec, meshes.finest());
  choose_contact_weight<3>(spec, meshes, data);
  return solve_levels<3>(std::move(meshes), data, level_loop_options(spec));
}

// The shipped accuracy loop (adaptive in 3D by default), asked for 3 % to keep the test short
// (the shipped 1 % takes more steps, validation.md §16): it bisects, claims the accuracy at the
// eighth step (measured: estimate 1.51 %, true +0.81 %; the seventh's estimate, 1.78 % at a true
// 1.26 %, is a single span's and claims nothing, method.md §9), and the claim holds against the
// ball's own force.
TEST(AdaptiveQuarterBall, TheAccuracyLoopReachesThreePerCentAndItHolds) {
  const double tolerance = 0.03;
  const LevelSolution<3> s = solved_shipped_accuracy(tolerance);
  ASSERT_EQ(s.stop_reason, "reached");
  EXPECT_EQ(s.steps.size(), 8u);
  for (std::size_t k = 1; k < s.steps.size(); ++k)
    EXPECT_LT(s.steps[k].dofs, 2 * s.steps[k - 1].dofs) << k;  // bisection steps, not red
  const ForceErrorEstimate& e = s.steps.back().force_error;
  const double error = std::abs(4 * s.force[2] / kBallForce - 1);
  std::printf("estimate %.4f, true error %.4f, efficiency %.2f\n", e.estimate, error,
              e.estimate / error);
  EXPECT_LE(e.estimate, tolerance);
  EXPECT_LE(error, tolerance);  // reached means it
  EXPECT_GE(e.estimate, error);
}

}  // namespace
}  // namespace fosls
