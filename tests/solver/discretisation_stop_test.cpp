// Stopping at the discretisation error (docs/method.md §5.1): the energy-history estimate of
// the algebraic error is exact on a geometric history and close to the true energy excess on
// Hertz, and the stopped solve keeps the contact force of the tight solve at a small fraction
// of its discretisation error in far fewer iterations.
#include <gtest/gtest.h>

#include <cmath>

#include "../shipped_example.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"
#include "solvers/algebraic_error.hpp"

namespace fosls {
namespace {

/// J_k = J_h + E_0 q^k for k = 0..n−1.
std::vector<IterationRecord> geometric_history(double j_h, double e0, double q, int n) {
  std::vector<IterationRecord> h(n);
  for (int k = 0; k < n; ++k) h[k] = {.iteration = k, .energy = j_h + e0 * std::pow(q, k)};
  return h;
}

TEST(AlgebraicError, ExactOnAGeometricHistory) {
  const auto h = geometric_history(2.0, 1.0, 0.3, 6);
  EXPECT_NEAR(energy_error_estimate(h), std::pow(0.3, 5), 1e-12);
  // E_5 = 0.3⁵ = 2.4e-3 ≤ f² J_5 ⇔ f ≥ 0.0349.
  EXPECT_TRUE(algebraic_error_is_small(h, 0.035));
  EXPECT_FALSE(algebraic_error_is_small(h, 0.034));
}

TEST(AlgebraicError, UnknownUntilThreeDecreasesAtARateBelowOne) {
  EXPECT_TRUE(std::isinf(energy_error_estimate(geometric_history(1.0, 1.0, 0.3, 3))));
  auto rising = geometric_history(1.0, 1.0, 0.3, 6);
  rising[5].energy = rising[4].energy + 1e-3;
  EXPECT_TRUE(std::isinf(energy_error_estimate(rising)));
  // A slowing iteration: the worse of the last two ratios counts.
  auto slowing = geometric_history(1.0, 1.0, 0.3, 5);
  slowing.push_back({.iteration = 5,
                     .energy = slowing[4].energy - 0.9 * (slowing[3].energy - slowing[4].energy)});
  EXPECT_NEAR(energy_error_estimate(slowing), 9 * (slowing[4].energy - slowing[5].energy), 1e-12);
  auto stalled = geometric_history(1.0, 1.0, 0.3, 5);
  stalled.push_back(stalled.back());
  EXPECT_EQ(energy_error_estimate(stalled), 0.0);
}

RunControl quiet() {
  RunControl control;
  control.want_vtu = false;
  return control;
}

nlohmann::json solve_hertz(const nlohmann::json& tolerance) {
  nlohmann::json j = testing::load_shipped_example("hertz");
  j["mesh"]["refinements"] = 3;
  j["solver"]["tolerance"] = tolerance;
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec) << tolerance;
  return run_case(*read.spec, quiet()).result;
}

TEST(DiscretisationStop, HertzKeepsTheForceInFewerIterations) {
  // Independent displacement-FEM reference for this case (docs/validation.md).
  constexpr double kReferenceForce = 0.0125226;
  const nlohmann::json tight = solve_hertz(1e-10);
  const nlohmann::json stopped = solve_hertz("discretisation");
  ASSERT_TRUE(tight["converged"].get<bool>());
  ASSERT_TRUE(stopped["converged"].get<bool>());
  EXPECT_EQ(stopped["stopping"]["rule"], "discretisation");
  EXPECT_EQ(stopped["stopping"]["converged_by"], "algebraic_error");
  EXPECT_EQ(tight["stopping"]["converged_by"], "kkt_residual");

  // Measured 8 against 41 (30 at tolerance 1e-8).
  EXPECT_LE(stopped["iterations"].get<int>(), 12);
  EXPECT_GE(tight["iterations"].get<int>(), 2 * stopped["iterations"].get<int>());

  // Measured 2.1 %: the energy-norm fraction 0.1 shows up smaller in the force.
  const double f_tight = tight["contact"]["force"][1].get<double>();
  const double f_stopped = stopped["contact"]["force"][1].get<double>();
  EXPECT_LE(std::abs(f_stopped - f_tight), 0.05 * std::abs(f_tight - kReferenceForce));

  // The estimate against the true energy excess J(x) − J(x_h), x_h by the tight solve:
  // measured 0.88 of it, and the true algebraic error is within 1.1 · fraction of J^½.
  const double excess =
      stopped["functional"]["total"].get<double>() - tight["functional"]["total"].get<double>();
  const double estimate = stopped["stopping"]["algebraic_error"].get<double>();
  ASSERT_GT(excess, 0.0);
  EXPECT_GE(estimate * estimate, 0.7 * excess);
  EXPECT_LE(estimate * estimate, 3.0 * excess);
  EXPECT_LE(std::sqrt(excess), 0.11 * stopped["functional"]["estimator"].get<double>());
}

TEST(DiscretisationStop, EveryAdaptiveStepStopsEarly) {
  nlohmann::json j = testing::load_shipped_example("hertz_adaptive");
  j["solver"]["tolerance"] = "discretisation";
  const CaseReadResult read = read_case(j);
  ASSERT_TRUE(read.spec);
  const nlohmann::json r = run_case(*read.spec, quiet()).result;
  EXPECT_EQ(r["adaptivity"]["stop_reason"], "steps");
  // Measured 3 iterations per step, 4 on the first (8 to 12 at tolerance 1e-8): three is the
  // rule's floor, so each step starts within the rule's reach of its solution. (Starts that
  // lost the Dirichlet values next to refined corners took up to 6.)
  for (const auto& s : r["adaptivity"]["steps"]) {
    EXPECT_TRUE(s["converged"].get<bool>());
    EXPECT_LE(s["algebraic_error"].get<double>(), 0.1 * s["estimator"].get<double>());
    EXPECT_LE(s["iterations"].get<int>(), s["step"] == 0 ? 5 : 3) << s["step"];
  }
}

}  // namespace
}  // namespace fosls
