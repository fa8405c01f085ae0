// Load steps that cannot all be solved: solver.time_limit_s bounds the whole run, and a run that
// stops before a step keeps the steps solved before it, marked partial, instead of losing them.
// The runner is driven with a stand-in for one state's solve, so where it stops is decided here.

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "../shipped_example.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/load_step_runner.hpp"
#include "core/deadline.hpp"

namespace fosls {
namespace {

using nlohmann::json;

CaseSpec stepped_case(int steps, double time_limit_s) {
  json j = testing::load_shipped_example("cattaneo_mindlin");
  j["solver"]["time_limit_s"] = time_limit_s;
  j["load_steps"] = json::array();
  for (int k = 1; k <= steps; ++k)
    j["load_steps"].push_back({{"/boundary/top/displacement/0", 0.001 * k}});
  CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.errors.empty()) << (read.errors.empty() ? "" : read.errors[0].detail);
  return *read.spec;
}

/// A converged answer whose force names the step it solved.
RunOutput answer(int step) {
  RunOutput out;
  out.result = {{"converged", true},
                {"stop_reason", "converged"},
                {"contact", {{"force", {0.0, -1.0 - step}}}},
                {"warnings", json::array()},
                {"warning_details", json::array()}};
  return out;
}

bool has_warning(const json& r, const std::string& code) {
  for (const json& w : r["warning_details"])
    if (w["code"] == code) return true;
  return false;
}

TEST(LoadStepStops, AStepThatCannotBeSolvedKeepsTheStepsBeforeIt) {
  const CaseSpec spec = stepped_case(5, 0);
  int calls = 0;
  const RunOutput out = run_load_steps(spec, {}, [&](const CaseSpec&, const RunControl&) {
    if (calls == 3) throw CaseException("/weights", "is not positive after this change");
    return answer(calls++);
  });
  const json& r = out.result;
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["stop_reason"], "step_failed");
  EXPECT_EQ(r["load_steps"]["count"], 3);
  ASSERT_EQ(r["load_steps"]["steps"].size(), 3u);
  EXPECT_EQ(r["load_steps"]["stopped_before"]["step"], 3);
  EXPECT_EQ(r["load_steps"]["stopped_before"]["reason"], "step_failed");
  EXPECT_EQ(r["contact"]["force"][1], -3.0);  // the last solved step's fields
  const std::string message = r["message"];
  EXPECT_NE(message.find("load step 3"), std::string::npos) << message;
  EXPECT_NE(message.find("/weights"), std::string::npos) << message;
  EXPECT_TRUE(has_warning(r, "load_steps_partial"));
  EXPECT_TRUE(r["review_required"].get<bool>());
}

TEST(LoadStepStops, TheCaseAsGivenFailingIsTheRunsFailure) {
  const CaseSpec spec = stepped_case(2, 0);
  EXPECT_THROW(run_load_steps(spec, {},
                              [](const CaseSpec&, const RunControl&) -> RunOutput {
                                throw CaseException("/weights", "not positive");
                              }),
               CaseException);
  EXPECT_THROW(run_load_steps(spec, {},
                              [](const CaseSpec&, const RunControl&) -> RunOutput {
                                throw TimeLimitReached("assembling the finest level");
                              }),
               TimeLimitReached);
}

TEST(LoadStepStops, TheTimeLimitBoundsTheWholeRunNotEachStep) {
  const double limit = 0.25;
  const CaseSpec spec = stepped_case(10, limit);
  std::vector<double> given;
  const RunOutput out = run_load_steps(spec, {}, [&](const CaseSpec& step, const RunControl&) {
    given.push_back(step.solver.time_limit_s);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return answer(static_cast<int>(given.size()) - 1);
  });
  const json& r = out.result;
  ASSERT_GE(given.size(), 1u);
  EXPECT_LT(given.size(), 11u) << "every step ran: the limit bounded each step, not the run";
  EXPECT_LE(given[0], limit);
  for (std::size_t k = 1; k < given.size(); ++k) EXPECT_LT(given[k], given[k - 1]);
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["stop_reason"], "time_limit");
  EXPECT_EQ(r["load_steps"]["count"], given.size());
  EXPECT_EQ(r["load_steps"]["stopped_before"]["reason"], "time_limit");
  EXPECT_TRUE(has_warning(r, "load_steps_partial"));
}

TEST(LoadStepStops, TheCaseKeepsItsMeshOnceAndEachStepGetsItBack) {
  const CaseSpec spec = stepped_case(3, 0);
  for (const CaseSpec& point : spec.load_step_points)
    EXPECT_TRUE(point.mesh.msh_text.empty() && point.mesh.params.empty());
  int calls = 0;
  run_load_steps(spec, {}, [&](const CaseSpec& step, const RunControl&) {
    EXPECT_EQ(step.mesh.kind, spec.mesh.kind);
    EXPECT_EQ(step.mesh.builtin, spec.mesh.builtin);
    EXPECT_EQ(step.mesh.params, spec.mesh.params);
    EXPECT_EQ(step.mesh.refinements, spec.mesh.refinements);
    EXPECT_TRUE(step.load_step_points.empty());
    return answer(calls++);
  });
  EXPECT_EQ(calls, 4);
}

TEST(LoadStepStops, AStepMayGiveAnyStringTheFieldItLandsInAccepts) {
  json j = testing::load_shipped_example("cattaneo_mindlin");
  j["load_steps"] = json::array({{{"/solver/method", "pgs"}}});
  EXPECT_TRUE(read_case(j).errors.empty());
  j["load_steps"] = json::array({{{"/solver/method", "newton"}}});
  const auto errors = read_case(j).errors;
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pointer, "/load_steps/0");
  EXPECT_NE(errors[0].detail.find("/solver/method"), std::string::npos) << errors[0].detail;
}

TEST(LoadStepStops, ACancelKeepsTheStepsSolvedBeforeItAndEachStepLeavesThemBehind) {
  const CaseSpec spec = stepped_case(4, 0);
  int calls = 0;
  std::vector<json> partials;
  RunControl control;
  control.on_partial = [&partials](const json& r) { partials.push_back(r); };
  const RunOutput out = run_load_steps(spec, control, [&](const CaseSpec&, const RunControl&) {
    if (calls == 3) {  // cancelled during step 3: the solve returns at once
      RunOutput cancelled;
      cancelled.cancelled = true;
      return cancelled;
    }
    return answer(calls++);
  });
  EXPECT_TRUE(out.cancelled);
  const json& r = out.result;
  EXPECT_EQ(r["stop_reason"], "cancelled");
  EXPECT_TRUE(r["cancelled"].get<bool>());
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["load_steps"]["count"], 3);
  EXPECT_EQ(r["load_steps"]["stopped_before"]["reason"], "cancelled");
  EXPECT_EQ(r["contact"]["force"][1], -3.0);
  EXPECT_TRUE(has_warning(r, "load_steps_partial"));
  // After steps 0, 1 and 2 (not after the last), what a kill would leave: so far the same.
  ASSERT_EQ(partials.size(), 3u);
  EXPECT_EQ(partials[2], r);
  EXPECT_EQ(partials[0]["load_steps"]["count"], 1);
  EXPECT_EQ(partials[0]["load_steps"]["stopped_before"]["step"], 1);
  EXPECT_EQ(partials[0]["stop_reason"], "cancelled");
}

TEST(LoadStepStops, ACancelOfTheCaseAsGivenHasNoStepsToKeep) {
  const CaseSpec spec = stepped_case(2, 0);
  const RunOutput out = run_load_steps(spec, {}, [](const CaseSpec&, const RunControl&) {
    RunOutput cancelled;
    cancelled.cancelled = true;
    return cancelled;
  });
  EXPECT_TRUE(out.cancelled);
  EXPECT_TRUE(out.result.is_null() || !out.result.contains("load_steps"));
}

}  // namespace
}  // namespace fosls
