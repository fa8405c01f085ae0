// Coulomb friction converges on the fine meshes (issue 49): the half disk of
// hertz_incompressible pressed by 0.01 and shifted by 0.004, 𝔣 = 0.3, at refinements 5
// (434 816 unknowns) and 6 (1 737 344), where the previous update schedule stopped at 200
// iterations without converging. The bounds are measured counts (docs/performance.md,
// "Friction": 60 and 72; 51 at refinements 5 since the stopping rule of docs/method.md §8.4
// accepts an update that moves the iterate by no more than its residual, 6 not re-measured)
// with a margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"

namespace fosls {
namespace {

nlohmann::json shifted_hertz(int refinements) {
  nlohmann::json j = testing::load_shipped_example("hertz_incompressible");
  j["mesh"]["refinements"] = refinements;
  j["boundary"]["top"]["displacement"] = {0.004, -0.01};
  j["boundary"]["contact"]["friction"] = {{"coefficient", 0.3}};
  return j;
}

/// Minutes each and up to 1.3 GiB: only when asked (FOSLS_LARGE_TESTS=1), not in the default run.
bool asked() { return std::getenv("FOSLS_LARGE_TESTS") != nullptr; }

void expect_converged_coulomb(const nlohmann::json& r, int max_iterations) {
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_LE(r["iterations"].get<int>(), max_iterations);
  // Converged by Coulomb's residual (docs/method.md §8.4): the last update may change a bound
  // by more than friction_tolerance where it moved the iterate by no more than that residual.
  // Coulomb's cone on every edge, to 10⁻⁵ of the largest bound: the residual is a norm over all
  // edges, and an edge near the zone's end, at a hundredth of the peak pressure, keeps the bound
  // of the last update, 𝔣 times its pressure before it, to a few 10⁻⁴ of its own bound.
  // The shift transmits some tangential force.
  const nlohmann::json& c = r["contact"];
  double largest_bound = 0.0;
  for (const auto& p : c["pressure"])
    largest_bound = std::max(largest_bound, 0.3 * p.get<double>());
  for (std::size_t e = 0; e < c["shear"].size(); ++e)
    EXPECT_LE(std::abs(c["shear"][e].get<double>()),
              0.3 * c["pressure"][e].get<double>() + 1e-5 * largest_bound)
        << "edge " << e;
  EXPECT_GT(std::abs(c["force"][0].get<double>()), 0.05 * c["force"][1].get<double>());
}

TEST(FrictionLarge, CoulombConvergesAtRefinements5) {
  if (!asked()) GTEST_SKIP() << "set FOSLS_LARGE_TESTS=1 to run (minutes, 330 MiB)";
  expect_converged_coulomb(testing::solved_case(shifted_hertz(5)), 70);
}

TEST(FrictionLarge, CoulombConvergesAtRefinements6) {
  if (!asked())
    GTEST_SKIP() << "set FOSLS_LARGE_TESTS=1 to run (about 16 minutes on two busy cores, 1.3 GiB)";
  expect_converged_coulomb(testing::solved_case(shifted_hertz(6)), 85);
}

/// The shipped cattaneo_mindlin (press, then shift in two steps) at refinements 5, where its
/// shift steps stopped at 200 iterations before the stopping rule of docs/method.md §8.4 took the
/// last update's move instead of the bounds' change (measured: 32/14/14 iterations per step,
/// 32/22/23 before kinks of weight 0 were left free; docs/performance.md "Friction").
TEST(FrictionLarge, CattaneoMindlinLoadStepsConvergeAtRefinements5) {
  if (!asked()) GTEST_SKIP() << "set FOSLS_LARGE_TESTS=1 to run (a minute or two, 340 MiB)";
  nlohmann::json j = testing::load_shipped_example("cattaneo_mindlin");
  j["mesh"]["refinements"] = 5;
  const nlohmann::json r = testing::solved_case(j);
  ASSERT_TRUE(r["converged"].get<bool>());
  const nlohmann::json& steps = r["load_steps"]["steps"];
  ASSERT_EQ(steps.size(), 3u);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_TRUE(steps[k]["converged"].get<bool>()) << "step " << k;
    EXPECT_LE(steps[k]["iterations"].get<int>(), k == 0 ? 40 : 20) << "step " << k;
  }
}

}  // namespace
}  // namespace fosls
