// Stopping at the rounding level (docs/method.md §5.2): a tolerance below what double precision
// can show ends the solve where the KKT residual stalls, converged and with a warning, not at
// max_iterations; a tolerance that can be reached still decides.
#include <gtest/gtest.h>

#include <cmath>

#include "../shipped_example.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"
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
  // Measured 20 iterations (17 to 1e-10); 200 and not converged without the rule. The residual
  // stalls at 5e-13 to 2e-12 of its initial value from iteration 19 on.
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
  // Measured 15, 11, 11, 14, 15, 14 (the last three stopped at the rounding level).
  for (const auto& s : r["adaptivity"]["steps"]) {
    EXPECT_TRUE(s["converged"].get<bool>()) << s["step"];
    EXPECT_LE(s["iterations"].get<int>(), 20) << s["step"];
  }
}

TEST(RoundingLevel, TheLevelIsTheRoundingOfTheResidual) {
  // ρ(x) = u ‖|A||x| + |b|‖ (u = 2⁻⁵³) against the actual rounding of the residual the solver
  // computes (symmetric_multiply, then b − A x) at an iterate-like x: the error against the same
  // residual accumulated in long double is below ρ, and not zero.
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 3),
                               testing::signorini_square(1.0));
  const BoxQp& qp = disc.problem().qp;
  Vector x(qp.size());
  for (int i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * i);
  Vector ax;
  symmetric_multiply(qp.A, x, ax);
  const Vector r = qp.b - ax;
  std::vector<long double> exact(qp.b.data(), qp.b.data() + qp.size());
  for (int col = 0; col < qp.A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(qp.A, col); it; ++it)
      exact[it.row()] -= static_cast<long double>(it.value()) * x[col];
  long double error = 0;
  for (int i = 0; i < qp.size(); ++i) error += (r[i] - exact[i]) * (r[i] - exact[i]);
  const double level = qp.rounding_level(x);
  EXPECT_GT(std::sqrt(static_cast<double>(error)), 0.0);
  EXPECT_LT(std::sqrt(static_cast<double>(error)), level);
}

}  // namespace
}  // namespace fosls
