// The time a whole case may take (case/admission/job_time.hpp): pgs bounded by its max_iterations,
// sweeps by their points, solver.time_limit_s bounding it; admission against a time budget (the
// service's --max-job-seconds) refuses the hostile probe's pgs sweep naming the time and the
// flag, and the CLI, which sets no budget, admits it; a job's limit is a margin times its
// estimate within the floor and the cap.
#include <gtest/gtest.h>

#include <string>

#include "../shipped_example.hpp"
#include "case/admission/case_admission.hpp"
#include "case/admission/job_time.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json square(int refinements) {
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = refinements;
  return j;
}

/// Issue 31's probe: pgs at refinements 5 to 1e-15, 100 sweep points of 100 000 iterations.
json pgs_sweep() {
  json j = square(5);
  j["solver"] = {{"method", "pgs"}, {"tolerance", 1e-15}, {"max_iterations", 100000}};
  json values = json::array();
  for (int i = 0; i < 100; ++i) values.push_back(-0.01 - 0.0005 * i);
  j["sweep"] = {{"pointer", "/boundary/top/displacement/1"}, {"values", values}};
  return j;
}

CaseReadOptions with_budget(double seconds) {
  CaseReadOptions o;
  o.limits.max_seconds = seconds;
  o.limits.time_budget_name = "a job may run (the service's --max-job-seconds)";
  return o;
}

TEST(JobTime, PgsIsBoundedByItsIterationsAndASweepByItsPoints) {
  const CaseAdmission one = admit_case(square(5));
  json pgs = square(5);
  pgs["solver"] = {{"method", "pgs"}, {"max_iterations", 1000}};
  const CaseAdmission p = admit_case(pgs);
  const CaseAdmission sweep = admit_case(pgs_sweep());
  ASSERT_TRUE(one.time && p.time && sweep.time);
  EXPECT_LT(one.time->seconds, 60.0);  // mmg's fit: seconds at 131k unknowns
  EXPECT_EQ(p.time->limited_by, "/solver/max_iterations");
  EXPECT_EQ(sweep.time->points, 100);
  // 100 points of 100 times the iterations (the set-up is a small part of either).
  EXPECT_GT(sweep.time->seconds / p.time->seconds, 100.0 * 90.0);
  EXPECT_LT(sweep.time->seconds / p.time->seconds, 100.0 * 100.0);
}

// Issue 50, item 9: a Coulomb case with max_iterations 10^5 was admitted at 9 s and killed at
// 90 s. With friction a solve is priced at every iteration solver.max_iterations allows.
TEST(JobTime, FrictionIsPricedAtItsMaxIterations) {
  json plain = testing::load_shipped_example("cattaneo_mindlin");
  plain["boundary"]["contact"].erase("friction");
  json tresca = plain;
  tresca["boundary"]["contact"]["friction"] = {{"bound", 0.01}};
  json coulomb = plain;
  coulomb["boundary"]["contact"]["friction"] = {{"coefficient", 10}};
  json many = coulomb;
  many["solver"]["max_iterations"] = 100000;
  const double t0 = admit_case(plain).time->seconds;
  const double tc = admit_case(coulomb).time->seconds;
  const double tm = admit_case(many).time->seconds;
  EXPECT_GT(admit_case(tresca).time->seconds, 2 * t0);
  EXPECT_GT(tc, 2 * t0);
  EXPECT_GT(tm, 100 * tc);
  EXPECT_EQ(admit_case(many).time->limited_by, "/solver/max_iterations");
  // With a time limit the case says what it will take at most.
  many["solver"]["time_limit_s"] = 30;
  EXPECT_DOUBLE_EQ(admit_case(many).time->seconds, 30);
}

// solver.time_limit_s bounds a run of load steps as a whole (load_step_runner.cpp), so the
// estimate of 100 steps is at most that limit, not 100 times it.
TEST(JobTime, TheTimeLimitBoundsLoadStepsAsAWhole) {
  json j = testing::load_shipped_example("cattaneo_mindlin");
  j["solver"]["time_limit_s"] = 0.8;
  j["load_steps"] = json::array();
  for (int k = 1; k <= 100; ++k)
    j["load_steps"].push_back({{"/boundary/top/displacement/0", 1e-4 * k}});
  const CaseAdmission a = admit_case(j);
  ASSERT_TRUE(a.time);
  EXPECT_DOUBLE_EQ(a.time->seconds, 0.8);
  EXPECT_TRUE(a.time->bounded_by_time_limit);
  EXPECT_EQ(a.time->limited_by, "/solver/time_limit_s");
}

TEST(JobTime, TheCasesOwnTimeLimitBoundsIt) {
  json j = pgs_sweep();
  j["solver"]["time_limit_s"] = 2.0;
  const CaseAdmission a = admit_case(j);
  ASSERT_TRUE(a.time);
  EXPECT_TRUE(a.time->bounded_by_time_limit);
  EXPECT_DOUBLE_EQ(a.time->seconds, 200.0);
  EXPECT_EQ(a.time->limited_by, "/solver/time_limit_s");
  EXPECT_TRUE(admit_case(j, with_budget(3600)).errors.empty());
}

TEST(JobTime, TheProbesPgsSweepIsRefusedNamingTheTimeAndTheFlag) {
  const CaseAdmission a = admit_case(pgs_sweep(), with_budget(3600));
  ASSERT_EQ(a.errors.size(), 1u);
  EXPECT_EQ(a.errors[0].pointer, "/solver/max_iterations");
  const std::string& detail = a.errors[0].detail;
  for (const char* part : {"100 sweep points", "100000 pgs iterations",
                           "more than the 1 h a job "
                           "may run (the service's --max-job-seconds)",
                           "solver.method mmg", "solver.time_limit_s"})
    EXPECT_NE(detail.find(part), std::string::npos) << part << " in: " << detail;
  // The CLI sets no time budget: the same case is admitted there (a user's own machine).
  EXPECT_TRUE(admit_case(pgs_sweep()).errors.empty());
}

TEST(JobTime, AJobsLimitIsAMarginTimesItsEstimateWithinTheFloorAndTheCap) {
  EXPECT_EQ(job_time_limit_seconds(0.2, 3600), kJobTimeFloorSeconds);
  EXPECT_EQ(job_time_limit_seconds(100, 3600), kJobTimeMargin * 100);
  EXPECT_EQ(job_time_limit_seconds(1000, 3600), 3600);
  EXPECT_EQ(job_time_limit_seconds(0.2, 2), 2);
  EXPECT_EQ(job_time_limit_seconds(1e9, 0), 0);  // --max-job-seconds 0: no limit at all
}

}  // namespace
}  // namespace fosls
