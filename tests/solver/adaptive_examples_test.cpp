// The shipped adaptive examples as shipped: the loop runs its steps, the estimator falls at
// every step, and each example's key number (the contact force) is right.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../shipped_example.hpp"
#include "case/case_reader.hpp"
#include "case/case_runner.hpp"

namespace fosls {
namespace {

nlohmann::json run_example(const std::string& name, int steps = -1) {
  nlohmann::json j = testing::load_shipped_example(name);
  if (steps >= 0) {
    j["adaptivity"]["steps"] = steps;
    j["adaptivity"].erase("max_dofs");
  }
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec) << name;
  return run_case(*read.spec, {.want_vtu = false}).result;
}

/// Steps made, estimator falling by at least 5 % per step, bounded iterations.
void check_loop(const nlohmann::json& r, int steps) {
  ASSERT_TRUE(r.contains("adaptivity"));
  const auto& s = r["adaptivity"]["steps"];
  ASSERT_EQ(static_cast<int>(s.size()), steps + 1);
  EXPECT_EQ(r["adaptivity"]["stop_reason"], "steps");
  for (std::size_t k = 1; k < s.size(); ++k) {
    EXPECT_GT(s[k]["dofs"], s[k - 1]["dofs"]);
    EXPECT_LT(s[k]["estimator"].get<double>(), 0.95 * s[k - 1]["estimator"].get<double>()) << k;
    EXPECT_LE(s[k]["iterations"].get<int>(), 30) << k;
    EXPECT_TRUE(s[k]["converged"].get<bool>()) << k;
  }
  EXPECT_EQ(r["dofs"], s.back()["dofs"]);
  EXPECT_EQ(r["levels"], s.back()["levels"]);
}

TEST(AdaptiveExamples, HertzReachesTheReferenceForceWithFewerUnknowns) {
  const nlohmann::json r = run_example("hertz_adaptive");
  check_loop(r, 5);
  // Reference F = 0.0125226 ± 3e-7 (issue 11, an independent displacement FEM); uniform
  // refinement needs 27 216 unknowns (refinements 3) for +0.25 %, the adapted mesh gets
  // within 0.25 % with fewer than 8 000 (measured +0.21 %).
  const double force = r["contact"]["force"][1].get<double>();
  EXPECT_NEAR(force / 0.0125226, 1.0, 2.5e-3);
  EXPECT_LT(r["dofs"].get<int>(), 8000);
}

TEST(AdaptiveExamples, SignoriniSquareRefinesTheContactZoneEnds) {
  const nlohmann::json r = run_example("signorini_square_adaptive");
  check_loop(r, 6);
  // The force of uniform refinements 3 (0.084140 on 8 224 unknowns, docs/validation.md) to
  // 0.1 % (measured: 0.002 %) with fewer than a third of its unknowns.
  const double force = r["contact"]["force"][1].get<double>();
  EXPECT_NEAR(force / 0.084140, 1.0, 1e-3);
  EXPECT_LT(r["dofs"].get<int>(), 8224 / 3);
}

// Ten steps make an 11-level bisection hierarchy, where the rounding of the truncated chain
// made a level's strip block lose definiteness and the case was refused as "indefinite
// weights" (MultilevelCycle::rebuild_coarse_levels now shifts that level). Measured: 61 801
// unknowns, 15–26 iterations per step, F within 0.02 % of the reference.
TEST(AdaptiveExamples, DeepBisectionHierarchiesAreNotRefused) {
  const nlohmann::json r = run_example("hertz_adaptive", 10);
  check_loop(r, 10);
  const double force = r["contact"]["force"][1].get<double>();
  EXPECT_NEAR(force, 0.0125226, 0.0005 * 0.0125226);
}

}  // namespace
}  // namespace fosls
