// Stopping at the rounding level (docs/method.md §5.2): a tolerance below what double precision
// can show ends the solve where the KKT residual stalls, converged and with a warning, not at
// max_iterations; a tolerance that can be reached still decides.
#include <gtest/gtest.h>

#include <cmath>

#include "../shipped_example.hpp"
#include "case/case_reader.hpp"
#include "case/case_runner.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

nlohmann::json solve(nlohmann::json j) {
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec);
  RunControl control;
  control.want_vtu = false;
  return run_case(*read.spec, control).result;
}

nlohmann::json hertz(double tolerance) {
  nlohmann::json j = testing::load_shipped_example("hertz");
  j["mesh"]["refinements"] = 3;
  j["solver"]["tolerance"] = tolerance;
  return solve(j);
}

bool warns_about_the_tolerance(const nlohmann::json& r) {
  for (const auto& w : r["warnings"])
    if (w.get<std::string>().find("below what double precision can show") != std::string::npos)
      return true;
  return false;
}

TEST(RoundingLevel, AnUnreachableToleranceStopsThereConverged) {
  const nlohmann::json reachable = hertz(1e-10);
  const nlohmann::json unreachable = hertz(1e-16);
  EXPECT_EQ(reachable["stopping"]["converged_by"], "kkt_residual");
  EXPECT_FALSE(warns_about_the_tolerance(reachable));
  ASSERT_TRUE(unreachable["converged"].get<bool>()) << unreachable["warnings"];
  EXPECT_EQ(unreachable["stopping"]["converged_by"], "rounding_level");
  EXPECT_TRUE(warns_about_the_tolerance(unreachable));
  // Measured 18 iterations (17 to 1e-10); 200 and not converged without the rule.
  EXPECT_LE(unreachable["iterations"].get<int>(), 25);
  EXPECT_GE(unreachable["iterations"].get<int>(), reachable["iterations"].get<int>());
  const double f = unreachable["contact"]["force"][1].get<double>();
  EXPECT_NEAR(f, reachable["contact"]["force"][1].get<double>(), 1e-9 * std::abs(f));
}

TEST(RoundingLevel, EveryAdaptiveStepConvergesAtATightTolerance) {
  // Each step starts from the previous step's solution, so 1e-10 of its initial residual lies
  // below the rounding level: the shipped case stopped at step 4 after 200 iterations.
  nlohmann::json j = testing::load_shipped_example("hertz_adaptive");
  j["solver"]["tolerance"] = 1e-10;
  const nlohmann::json r = solve(j);
  EXPECT_EQ(r["adaptivity"]["stop_reason"], "steps");
  // Measured 15, 11, 10, 13, 13, 12.
  for (const auto& s : r["adaptivity"]["steps"]) {
    EXPECT_TRUE(s["converged"].get<bool>()) << s["step"];
    EXPECT_LE(s["iterations"].get<int>(), 20) << s["step"];
  }
}

TEST(RoundingLevel, TheLevelIsTheRoundingOfTheResidual) {
  // ρ(x) = ε‖|A||x| + |b|‖ bounds the rounding of a computed b − A x: the residual of the same x
  // computed in two summation orders differs by less than ρ, and by more than 0 (it is rounding,
  // not an exact quantity).
  const Discretization disc(build_mesh_hierarchy(make_square({.size = 0.25}), 3),
                            testing::signorini_square(1.0));
  const BoxQp& qp = disc.problem().qp;
  Vector x(qp.size());
  for (int i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * i);
  Vector forward = qp.b, backward = qp.b;
  for (int col = 0; col < qp.A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(qp.A, col); it; ++it)
      forward[it.row()] -= it.value() * x[col];
  for (int col = qp.A.outerSize() - 1; col >= 0; --col)
    for (SparseMatrix::InnerIterator it(qp.A, col); it; ++it)
      backward[it.row()] -= it.value() * x[col];
  const double level = qp.rounding_level(x);
  EXPECT_GT(level, 0.0);
  EXPECT_GT((forward - backward).norm(), 0.0);
  EXPECT_LT((forward - backward).norm(), level);
}

}  // namespace
}  // namespace fosls
