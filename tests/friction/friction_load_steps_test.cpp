// Coulomb friction in load steps (issue 49): the shipped cattaneo_mindlin, pressed and then
// shifted in two steps, each step from the previous one's solution with the slip measured from
// it. Every step converges, in a bounded number of iterations, and the stopping rule of
// docs/method.md §8.4 (Coulomb's residual, the last update moving the iterate by no more than
// it) gives the forces of a far tighter solve. The bounds are measured counts
// (docs/performance.md, "Friction") with a small margin: before the rule, the shift steps took
// 14–21 iterations here and stopped at 200 at refinements 5 (tests/friction_large/). Here every
// step is within issue 49's 1.5 times frictionless on the same mesh; at refinements 5 the press
// step is not (tests/friction_large/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"

namespace fosls {
namespace {

nlohmann::json cattaneo_mindlin(int refinements) {
  nlohmann::json j = testing::load_shipped_example("cattaneo_mindlin");
  j["mesh"]["refinements"] = refinements;
  return j;
}

/// Each step converged within `press` (step 0) or `shift` iterations, with Coulomb's cone on
/// every contact edge.
void expect_steps_converge(const nlohmann::json& r, int press, int shift) {
  ASSERT_TRUE(r["converged"].get<bool>()) << r.value("message", std::string());
  const nlohmann::json& steps = r["load_steps"]["steps"];
  ASSERT_EQ(steps.size(), 3u);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const nlohmann::json& s = steps[k];
    EXPECT_TRUE(s["converged"].get<bool>()) << "step " << k;
    EXPECT_LE(s["iterations"].get<int>(), k == 0 ? press : shift) << "step " << k;
    const nlohmann::json& c = s["contact"];
    for (std::size_t e = 0; e < c["shear"].size(); ++e)
      EXPECT_LE(std::abs(c["shear"][e].get<double>()),
                0.3 * c["pressure"][e].get<double>() * (1 + 1e-4) + 1e-12)
          << "step " << k << ", edge " << e;
  }
}

TEST(FrictionLoadSteps, CattaneoMindlinEveryStepConvergesAtRefinements2To4) {
  // Measured: 16/10/14, 18/11/14, 19/15/13 iterations per step at refinements 2, 3, 4 (before
  // kinks of weight 0 were left free, docs/method.md §8.4: 18/12/13, 21/17/17, 23/14/14).
  for (int refinements = 2; refinements <= 4; ++refinements) {
    SCOPED_TRACE("refinements " + std::to_string(refinements));
    expect_steps_converge(testing::solved_case(cattaneo_mindlin(refinements)), 21, 17);
  }
}

TEST(FrictionLoadSteps, EveryStepWithinOneAndAHalfTimesFrictionlessAtRefinements2To4) {
  // Issue 49's target on the same mesh: frictionless takes 13/14/14 iterations per step here.
  for (int refinements = 2; refinements <= 4; ++refinements) {
    SCOPED_TRACE("refinements " + std::to_string(refinements));
    nlohmann::json frictionless = cattaneo_mindlin(refinements);
    frictionless["boundary"]["contact"].erase("friction");
    const nlohmann::json free = testing::solved_case(frictionless);
    const nlohmann::json coulomb = testing::solved_case(cattaneo_mindlin(refinements));
    ASSERT_TRUE(free["converged"].get<bool>());
    ASSERT_TRUE(coulomb["converged"].get<bool>());
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_LE(coulomb["load_steps"]["steps"][k]["iterations"].get<int>(),
                1.5 * free["load_steps"]["steps"][k]["iterations"].get<int>())
          << "step " << k;
  }
}

TEST(FrictionLoadSteps, StopsWhereATighterSolveAgreesInForceAndStickZone) {
  // The rule stops a step although its last update changed a slip bound by more than
  // solver.friction_tolerance (a noise of S_n on edges that stick, or that slip by 10⁻⁹ of
  // S_t): its forces agree with a solve to tolerance 10⁻¹¹ within 2·10⁻⁶ of |F| (measured at
  // refinements 3 and 4: 1.4·10⁻⁷ and 1.2·10⁻⁶), and its stick zones are the same edges.
  const nlohmann::json r = testing::solved_case(cattaneo_mindlin(3));
  nlohmann::json tight_case = cattaneo_mindlin(3);
  tight_case["solver"]["tolerance"] = 1e-11;
  tight_case["solver"]["max_iterations"] = 400;
  const nlohmann::json tight = testing::solved_case(tight_case);
  ASSERT_TRUE(r["converged"].get<bool>());
  ASSERT_TRUE(tight["converged"].get<bool>());
  bool loose_bounds_accepted = false;
  for (std::size_t k = 0; k < 3; ++k) {
    const nlohmann::json& a = r["load_steps"]["steps"][k];
    const nlohmann::json& b = tight["load_steps"]["steps"][k];
    loose_bounds_accepted |= a["friction"]["last_change"].get<double>() > 1e-6;
    const double fx = a["contact"]["force"][0], fy = a["contact"]["force"][1];
    const double tx = b["contact"]["force"][0], ty = b["contact"]["force"][1];
    EXPECT_LE(std::hypot(fx - tx, fy - ty), 2e-6 * std::hypot(tx, ty)) << "step " << k;
    EXPECT_EQ(a["contact"]["stick_zone"]["length"], b["contact"]["stick_zone"]["length"])
        << "step " << k;
  }
  // The rule is the one that stopped a step here, not the bounds' change.
  EXPECT_TRUE(loose_bounds_accepted);
}

}  // namespace
}  // namespace fosls
