// Load steps and sweeps of a 3D case run through the same series runners as 2D
// (case/run/load_step_runner.hpp, case/run/sweep_runner.hpp; issue 47): each step or point is one
// 3D solve, started from the previous one's solution, and the last one's force is the plain
// solve's.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../case3d_runs.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/rule_checker.hpp"
#include "case/result/result_rules.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;
using testing::hertz_3d;

/// The problems of the result rules with a 3D result, one per line; empty when it is documented.
std::string undocumented(const json& r) {
  RuleChecker checker(CaseReadOptions{});
  checker.check_object(r, *result_rule(3), "");
  std::string s;
  for (const auto& e : checker.errors()) s += e.pointer + ": " + e.detail + "\n";
  return s;
}

double force_z(const json& r) { return r["contact"]["force"][2].get<double>(); }

/// hertz_3d at refinements 1 pressed to `depth` (the shipped case presses 0.01).
json pressed(double depth) {
  json j = hertz_3d(1);
  j["boundary"]["top"]["displacement"][2] = -depth;
  return j;
}

TEST(Case3dSeries, LoadStepsPressTheBallAndTheirLastForceIsThePlainSolves) {
  const double plain = force_z(testing::run_3d(pressed(0.01)));
  json j = pressed(0.0025);
  j["load_steps"] = json::array(
      {{{"/boundary/top/displacement/2", -0.005}}, {{"/boundary/top/displacement/2", -0.01}}});
  const json r = testing::run_3d(j);
  ASSERT_TRUE(r["converged"].get<bool>()) << r.dump().substr(0, 400);
  EXPECT_EQ(undocumented(r), "");
  const json& steps = r["load_steps"]["steps"];
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(r["load_steps"]["count"], 3);
  // Hertz: F grows like δ^{3/2}, so each doubling of the depth more than doubles the force.
  for (std::size_t k = 1; k < steps.size(); ++k) {
    EXPECT_GT(force_z(steps[k]), 2.0 * force_z(steps[k - 1])) << "step " << k;
    EXPECT_LE(steps[k]["iterations"].get<int>(), 40) << "step " << k;
    EXPECT_FALSE(steps[k].contains("history"));
  }
  // The last step is the plain solve up to the solver's tolerance (a different start).
  EXPECT_NEAR(force_z(r), plain, 1e-6 * plain);
  EXPECT_EQ(force_z(steps[2]), force_z(r));
}

TEST(Case3dSeries, ASweepGivesEveryPointsForceAndRadiusAndEndsAtThePlainSolve) {
  const json deepest = testing::run_3d(pressed(0.01));
  json j = hertz_3d(1);
  j["sweep"] = {{"pointer", "/boundary/top/displacement/2"}, {"values", {-0.005, -0.01}}};
  const json r = testing::run_3d(j);
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_EQ(undocumented(r), "");
  const json& points = r["sweep"]["points"];
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1]["value"], -0.01);
  ASSERT_EQ(points[1]["force"].size(), 3u);
  EXPECT_NEAR(points[1]["force"][2].get<double>(), force_z(deepest), 1e-6 * force_z(deepest));
  // The zone grows with the depth (Hertz: a ∝ δ^{1/2}).
  EXPECT_GT(points[1]["contact_radius"].get<double>(), points[0]["contact_radius"].get<double>());
  EXPECT_FALSE(points[0].contains("contact_length"));
}

TEST(Case3dSeries, AStepThatCannotBeSolvedKeepsTheStepsBeforeIt) {
  json j = pressed(0.005);
  j["weights"]["c3"] = 0.1;  // 3D's default, given so that a step may change it
  // Step 2 makes the matrix indefinite (c3 far too large): only its solve shows it.
  j["load_steps"] =
      json::array({{{"/boundary/top/displacement/2", -0.01}}, {{"/weights/c3", 1e6}}});
  const json r = testing::run_3d(j);
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["stop_reason"], "step_failed");
  EXPECT_EQ(r["load_steps"]["count"], 2);
  EXPECT_EQ(r["load_steps"]["stopped_before"]["step"], 2);
  EXPECT_TRUE(r["review_required"].get<bool>());
  EXPECT_EQ(undocumented(r), "");
}

}  // namespace
}  // namespace fosls
