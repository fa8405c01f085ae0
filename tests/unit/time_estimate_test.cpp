// The rough time guide of `fosls-contact estimate` (docs/case-format.md, "Resources") against
// the solver table it was fitted on (docs/performance.md, "Solver table", two threads):
// within a factor 1.5 of every measured total up to 525k unknowns, O(N) for the multilevel methods,
// faster than N for pdas.
#include <gtest/gtest.h>

#include "case/admission/time_estimate.hpp"
#include "case/format/solver_methods.hpp"

namespace fosls {
namespace {

/// A 2D count whose coarsest level is not known: the solver table's fit alone.
ProblemCount count_of(long long unknowns) { return ProblemCount{.unknowns = unknowns}; }

TEST(TimeEstimate, FollowsTheMeasuredSolverTable) {
  struct Row {
    long long unknowns;
    SolverMethod method;
    double seconds;
  };
  const Row measured[] = {
      {32832, SolverMethod::kMmg, 0.9},   {131200, SolverMethod::kMmg, 2.9},
      {524544, SolverMethod::kMmg, 11.8}, {32832, SolverMethod::kPdas, 1.1},
      {131200, SolverMethod::kPdas, 9.6}, {524544, SolverMethod::kPdas, 51.7},
  };
  for (const Row& r : measured) {
    const auto s = estimated_seconds(count_of(r.unknowns), r.method);
    ASSERT_TRUE(s);
    EXPECT_LT(*s, 1.5 * r.seconds) << r.unknowns << " " << method_info(r.method).name;
    EXPECT_GT(*s, r.seconds / 1.5) << r.unknowns << " " << method_info(r.method).name;
  }
  const double mmg = *estimated_seconds(count_of(4000000), SolverMethod::kMmg) /
                     *estimated_seconds(count_of(1000000), SolverMethod::kMmg);
  EXPECT_NEAR(mmg, 4.0, 0.1);
  const double pdas = *estimated_seconds(count_of(4000000), SolverMethod::kPdas) /
                      *estimated_seconds(count_of(1000000), SolverMethod::kPdas);
  EXPECT_GT(pdas, 5.0);
  EXPECT_FALSE(estimated_seconds(count_of(100000), SolverMethod::kPgs));
}

TEST(TimeEstimate, DescribesSecondsInAUnitReadAtAGlance) {
  EXPECT_EQ(describe_seconds(0.81), "about 0.81 s");
  EXPECT_EQ(describe_seconds(53.0), "about 53 s");
  EXPECT_EQ(describe_seconds(357.0), "about 6 min");
  EXPECT_EQ(describe_seconds(1400.0), "about 23 min");
  EXPECT_EQ(describe_seconds(9000.0), "about 2.5 h");
  EXPECT_EQ(describe_seconds(1e6), "about 278 h");
}

}  // namespace
}  // namespace fosls
