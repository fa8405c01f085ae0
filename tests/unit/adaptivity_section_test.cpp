// The case's `adaptivity` section: read with its defaults, and every bad value reported at its
// JSON pointer with the reason.
#include <gtest/gtest.h>

#include <algorithm>

#include "../case_errors.hpp"
#include "case/admission/case_admission.hpp"
#include "case/format/case_reader.hpp"

namespace fosls {
namespace {

using nlohmann::json;
using testing::has_error;

json adaptive_case(json adaptivity) {
  json j = json::parse(R"({
    "mesh": {"builtin": "square", "size": 0.5, "refinements": 1},
    "material": {"mu": 1, "lambda": 1},
    "boundary": {
      "top": {"type": "dirichlet", "displacement": [0, -0.01]},
      "bottom": {"type": "contact", "obstacle": {"type": "plane", "point": [0, 0],
                                                 "normal": [0, 1]}}
    }
  })");
  j["adaptivity"] = std::move(adaptivity);
  return j;
}

TEST(AdaptivitySection, AbsentMeansUniformAndDefaultsFillAnEmptyObject) {
  json j = adaptive_case(nullptr);
  j.erase("adaptivity");
  EXPECT_FALSE(read_case(j).spec->adaptivity);
  const auto r = read_case(adaptive_case(json::object()));
  ASSERT_TRUE(r.spec && r.spec->adaptivity);
  const AdaptivitySpec defaults;
  EXPECT_EQ(r.spec->adaptivity->steps, defaults.steps);
  EXPECT_EQ(r.spec->adaptivity->max_dofs, defaults.max_dofs);
  EXPECT_EQ(r.spec->adaptivity->theta, 0.7);
  EXPECT_EQ(r.spec->adaptivity->target, 0.0);
}

TEST(AdaptivitySection, StepsStopAtTheDiscretisationErrorUnlessTheCaseGivesATolerance) {
  json uniform = adaptive_case(nullptr);
  uniform.erase("adaptivity");
  EXPECT_EQ(read_case(uniform).spec->solver.stopping, StoppingRule::kKktResidual);
  EXPECT_EQ(read_case(adaptive_case(json::object())).spec->solver.stopping,
            StoppingRule::kDiscretisation);
  json solver_without_tolerance = adaptive_case(json::object());
  solver_without_tolerance["solver"] = {{"method", "mmg"}};
  EXPECT_EQ(read_case(solver_without_tolerance).spec->solver.stopping,
            StoppingRule::kDiscretisation);
  json tight = adaptive_case(json::object());
  tight["solver"] = {{"tolerance", 1e-8}};
  const auto r = read_case(tight);
  EXPECT_EQ(r.spec->solver.stopping, StoppingRule::kKktResidual);
  EXPECT_EQ(r.spec->solver.tolerance, 1e-8);
}

TEST(AdaptivitySection, EveryFieldIsRead) {
  const auto r =
      read_case(adaptive_case({{"steps", 3}, {"max_dofs", 5000}, {"theta", 1}, {"target", 0.25}}));
  ASSERT_TRUE(r.spec && r.spec->adaptivity);
  EXPECT_EQ(r.spec->adaptivity->steps, 3);
  EXPECT_EQ(r.spec->adaptivity->max_dofs, 5000);
  EXPECT_EQ(r.spec->adaptivity->theta, 1.0);
  EXPECT_EQ(r.spec->adaptivity->target, 0.25);
}

TEST(AdaptivitySection, BadValuesAreReportedAtTheirPointers) {
  for (double theta : {0.0, -0.5, 1.5})
    EXPECT_TRUE(
        has_error(read_case(adaptive_case({{"theta", theta}})), "/adaptivity/theta", "in (0, 1]"))
        << theta;
  EXPECT_TRUE(
      has_error(read_case(adaptive_case({{"steps", -1}})), "/adaptivity/steps", "from 0 to 50"));
  EXPECT_TRUE(
      has_error(read_case(adaptive_case({{"steps", 2.5}})), "/adaptivity/steps", "integer"));
  EXPECT_TRUE(
      has_error(read_case(adaptive_case({{"target", 1}})), "/adaptivity/target", "in [0, 1)"));
  EXPECT_TRUE(
      has_error(read_case(adaptive_case({{"theta", "half"}})), "/adaptivity/theta", "number"));
  EXPECT_TRUE(
      has_error(read_case(adaptive_case({{"thetta", 0.5}})), "/adaptivity/thetta", "theta"));
  EXPECT_TRUE(has_error(read_case(adaptive_case(3)), "/adaptivity", "object"));
}

TEST(AdaptivitySection, MaxDofsIsBoundedByTheCaseLimit) {
  CaseReadOptions options;
  options.limits.max_dofs = 10000;
  const auto r = read_case(adaptive_case({{"max_dofs", 10001}}), options);
  EXPECT_TRUE(has_error(r, "/adaptivity/max_dofs", "from 1 to 10000"));
  EXPECT_TRUE(has_error(r, "/adaptivity/max_dofs", "case limit"));
  // Absent, it defaults to the smaller of the default and the limit.
  options.limits.max_dofs = 1000;
  const auto d = read_case(adaptive_case(json::object()), options);
  ASSERT_TRUE(d.spec);
  EXPECT_EQ(d.spec->adaptivity->max_dofs, 1000);
}

TEST(AdaptivitySection, AdmissionCountsTheUnknownsMaxDofsAllows) {
  const CaseAdmission uniform = admit_case(adaptive_case({{"steps", 0}, {"max_dofs", 1}}));
  ASSERT_TRUE(uniform.estimate);
  const CaseAdmission adaptive = admit_case(adaptive_case({{"max_dofs", 500000}}));
  ASSERT_TRUE(adaptive.estimate);
  EXPECT_EQ(adaptive.estimate->unknowns, 500000);
  EXPECT_GT(adaptive.estimate->memory_bytes, uniform.estimate->memory_bytes);
  // Too large for a budget: the error names the field to change.
  const auto e = check_memory_budget(*adaptive.estimate, *adaptive.spec, 1e8, "the budget");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pointer, "/adaptivity/max_dofs");
  EXPECT_NE(e->detail.find("lower adaptivity.max_dofs"), std::string::npos) << e->detail;
}

}  // namespace
}  // namespace fosls
