// The rough time guide of `fosls-contact estimate` (docs/case-format.md, "Resources") against
// the solver table it was fitted on (docs/performance.md, "Solver table", two threads):
// within a factor 1.5 of every measured total up to 525k unknowns, O(N) for the multilevel methods,
// faster than N for pdas; in 3D against one thread's measured CPU time.
#include <gtest/gtest.h>

#include "case/admission/time_estimate.hpp"
#include "case/format/solver_methods.hpp"

namespace fosls {
namespace {

/// A measured solve: two threads' wall time in 2D, one thread's CPU time in 3D.
struct Row {
  long long unknowns;
  SolverMethod method;
  double seconds;
};

/// A 2D count whose coarsest level is not known: the solver table's fit alone.
ProblemCount count_of(long long unknowns) { return ProblemCount{.unknowns = unknowns}; }

TEST(TimeEstimate, FollowsTheMeasuredSolverTable) {
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

TEST(TimeEstimate, In3dFollowsOneThreadsMeasuredCpuTime) {
  // docs/performance.md, "3D: the time guide": the Hertz ball at λ = ∞ and λ = 1, the
  // incompressible block and rounded punch of the robustness cases.
  const Row measured[] = {
      {79384, SolverMethod::kMmg, 10.4},     {636976, SolverMethod::kMmg, 81.7},
      {79384, SolverMethod::kTnnmg, 25.8},   {636976, SolverMethod::kTnnmg, 231.6},
      {79384, SolverMethod::kPdas, 6.1},     {636976, SolverMethod::kPdas, 83.9},
      {79384, SolverMethod::kMmg, 6.0},      {636976, SolverMethod::kMmg, 64.1},
      {79384, SolverMethod::kTnnmg, 12.4},   {636976, SolverMethod::kTnnmg, 121.1},
      {79384, SolverMethod::kPdas, 4.1},     {636976, SolverMethod::kPdas, 86.0},
      {9868, SolverMethod::kPdas, 1.0},      {79640, SolverMethod::kMmg, 11.15},
      {638000, SolverMethod::kMmg, 65.0},    {79640, SolverMethod::kTnnmg, 17.3},
      {638000, SolverMethod::kTnnmg, 129.6}, {79640, SolverMethod::kPdas, 4.9},
      {638000, SolverMethod::kPdas, 103.0},  {46722, SolverMethod::kMmg, 7.37},
      {374076, SolverMethod::kMmg, 83.35},   {46722, SolverMethod::kTnnmg, 12.15},
      {46722, SolverMethod::kPdas, 3.36},    {374076, SolverMethod::kPdas, 90.83},
  };
  for (const Row& r : measured) {
    const auto s =
        estimated_seconds(ProblemCount{.unknowns = r.unknowns, .dimension = 3}, r.method);
    ASSERT_TRUE(s);
    // Not far below any measurement (the service bounds a job by it); at most 4 times above,
    // the spread of the cost per unknown between these geometries and materials.
    EXPECT_GT(*s, r.seconds / 1.2) << r.unknowns << " " << method_info(r.method).name;
    EXPECT_LT(*s, 4.0 * r.seconds) << r.unknowns << " " << method_info(r.method).name;
  }
  // Beyond the measured sizes pdas grows like a 3D factorisation, faster than N^1.5.
  const auto pdas = [](long long n) {
    return *estimated_seconds(ProblemCount{.unknowns = n, .dimension = 3}, SolverMethod::kPdas);
  };
  EXPECT_GT(pdas(4000000) / pdas(1000000), 8.0);
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
