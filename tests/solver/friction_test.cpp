// Friction (docs/method.md §8): frictionless unchanged with coefficient 0, mmg monotone and in
// agreement with pdas on the same discrete problem, full slip at |F_x| = 𝔣 F_y, iteration counts
// near the frictionless ones, clear errors for what friction does not support.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

/// The incompressible half disk pressed by 0.01 and moved sideways by `shift`.
json hertz(const json& friction, double shift, int refinements, const std::string& method = "mmg") {
  json j = testing::load_shipped_example("hertz_incompressible");
  j["mesh"]["refinements"] = refinements;
  j["boundary"]["top"]["displacement"] = {shift, -0.01};
  if (!friction.is_null()) j["boundary"]["contact"]["friction"] = friction;
  j["solver"]["method"] = method;
  j["solver"]["tolerance"] = 1e-10;
  return j;
}

/// A unit square (μ = λ = 1) pressed 0.05 onto the plane y = 0 and moved sideways by `shift`.
json block(double coefficient, double shift) {
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = 2;
  j["boundary"]["top"]["displacement"] = {shift, -0.05};
  j["boundary"]["bottom"]["obstacle"] = {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}};
  j["boundary"]["bottom"]["friction"] = {{"coefficient", coefficient}};
  return j;
}

json solve(const json& j) { return testing::solved_case(j); }

double force_difference(const json& a, const json& b) {
  const json& fa = a["contact"]["force"];
  const json& fb = b["contact"]["force"];
  return std::hypot(fa[0].get<double>() - fb[0].get<double>(),
                    fa[1].get<double>() - fb[1].get<double>()) /
         std::hypot(fa[0].get<double>(), fa[1].get<double>());
}

TEST(Friction, CoefficientZeroIsFrictionlessBitForBit) {
  const json plain = solve(hertz(nullptr, 0.0, 2));
  const json zero = solve(hertz({{"coefficient", 0}}, 0.0, 2));
  EXPECT_EQ(plain["iterations"], zero["iterations"]);
  EXPECT_EQ(plain["contact"]["force"], zero["contact"]["force"]);
  EXPECT_EQ(plain["contact"]["pressure"], zero["contact"]["pressure"]);
  EXPECT_EQ(plain["functional"]["total"], zero["functional"]["total"]);
  EXPECT_FALSE(zero.contains("friction"));
}

TEST(Friction, MmgIsMonotoneAndMatchesPdasWithTresca) {
  const json friction = {{"bound", 0.01}};
  const json mmg = solve(hertz(friction, 0.004, 2));
  const json pdas = solve(hertz(friction, 0.004, 2, "pdas"));
  ASSERT_TRUE(mmg["converged"].get<bool>());
  ASSERT_TRUE(pdas["converged"].get<bool>());
  EXPECT_LT(force_difference(mmg, pdas), 1e-6);
  // J + the kinks never increases (the loop also asserts feasibility in checked builds).
  const json& h = mmg["history"];
  for (std::size_t k = 1; k < h.size(); ++k)
    EXPECT_LE(h[k]["energy"].get<double>(), h[k - 1]["energy"].get<double>() * (1 + 1e-12) + 1e-15)
        << "iteration " << k;
  // The tangential traction within the bound. On this coarse mesh every edge in contact slips
  // in the step (its slip is not 0), 8 of them with |σ_nt| below the bound: the state is the
  // slip's, and the diagnostic counts what |σ_nt| against the bound says otherwise.
  const json& c = mmg["contact"];
  int slip = 0, below_bound = 0;
  for (std::size_t e = 0; e < c["shear"].size(); ++e) {
    const double shear = std::abs(c["shear"][e].get<double>());
    EXPECT_LE(shear, 0.01 * (1 + 1e-9));
    if (c["state"][e] != "slip") continue;
    ++slip;
    EXPECT_NE(c["slip"][e].get<double>(), 0.0) << "edge " << e;
    below_bound += shear < 0.01 * (1 - 1e-6);
  }
  EXPECT_GT(slip, 0);
  EXPECT_EQ(c["stick_zone"]["slipping_below_bound"].get<int>(), below_bound);
  EXPECT_GT(below_bound, 0);
  EXPECT_EQ(c["stick_zone"]["sticking_at_bound"].get<int>(), 0);
}

TEST(Friction, MmgMatchesPdasWithCoulomb) {
  const json friction = {{"coefficient", 0.3}};
  const json mmg = solve(hertz(friction, 0.004, 2));
  const json pdas = solve(hertz(friction, 0.004, 2, "pdas"));
  ASSERT_TRUE(mmg["converged"].get<bool>());
  ASSERT_TRUE(pdas["converged"].get<bool>());
  EXPECT_LT(force_difference(mmg, pdas), 1e-6);
  EXPECT_GE(mmg["friction"]["updates"].get<int>(), 2);
  EXPECT_LE(mmg["friction"]["last_change"].get<double>(), 1e-6);
  // Coulomb's cone: |σ_nt| ≤ 𝔣 p on every edge.
  for (std::size_t e = 0; e < mmg["contact"]["shear"].size(); ++e)
    EXPECT_LE(std::abs(mmg["contact"]["shear"][e].get<double>()),
              0.3 * mmg["contact"]["pressure"][e].get<double>() * (1 + 1e-4) + 1e-12);
}

TEST(Friction, FullSlipTransmitsTheCoefficientTimesTheNormalForce) {
  const json r = solve(block(0.3, 0.2));
  ASSERT_TRUE(r["converged"].get<bool>());
  const double fx = r["contact"]["force"][0], fy = r["contact"]["force"][1];
  EXPECT_NEAR(std::abs(fx) / (0.3 * fy), 1.0, 0.005);
  for (const auto& state : r["contact"]["state"]) EXPECT_NE(state, "stick");
  // The obstacle's tangential force on the body opposes the motion.
  EXPECT_LT(fx, 0.0);
}

TEST(Friction, IterationsStayNearTheFrictionlessCount) {
  for (int refinements : {2, 3}) {
    const int plain = solve(hertz(nullptr, 0.004, refinements))["iterations"];
    const int tresca = solve(hertz({{"bound", 0.01}}, 0.004, refinements))["iterations"];
    const int coulomb = solve(hertz({{"coefficient", 0.3}}, 0.004, refinements))["iterations"];
    EXPECT_LE(tresca, 1.5 * plain) << "refinements " << refinements;
    // The fixed point of the Coulomb bounds costs more (docs/performance.md, friction).
    EXPECT_LE(coulomb, 2.5 * plain) << "refinements " << refinements;
  }
}

TEST(Friction, UnsupportedCombinationsAndBadBoundsAreNamed) {
  json tnnmg = hertz({{"coefficient", 0.3}}, 0.0, 1, "tnnmg");
  ASSERT_FALSE(read_case(tnnmg).errors.empty());
  EXPECT_EQ(read_case(tnnmg).errors[0].pointer, "/solver/method");

  json adaptive = testing::load_shipped_example("hertz_adaptive");
  adaptive["boundary"]["contact"]["friction"] = {{"bound", 0.1}};
  ASSERT_FALSE(read_case(adaptive).errors.empty());
  EXPECT_EQ(read_case(adaptive).errors[0].pointer, "/adaptivity");

  json negative = hertz({{"coefficient", -0.1}}, 0.0, 1);
  ASSERT_FALSE(read_case(negative).errors.empty());
  EXPECT_EQ(read_case(negative).errors[0].pointer, "/boundary/contact/friction/coefficient");

  json both = hertz({{"coefficient", 0.1}, {"bound", 1}}, 0.0, 1);
  ASSERT_FALSE(read_case(both).errors.empty());
  EXPECT_EQ(read_case(both).errors[0].pointer, "/boundary/contact/friction");

  // A constant negative bound is the case's alone: refused when it is read, not when it runs.
  const auto constant = read_case(hertz({{"bound", -0.5}}, 0.0, 1)).errors;
  ASSERT_EQ(constant.size(), 1u);
  EXPECT_EQ(constant[0].pointer, "/boundary/contact/friction/bound");
  EXPECT_NE(constant[0].detail.find(">= 0"), std::string::npos) << constant[0].detail;
  EXPECT_TRUE(read_case(hertz({{"bound", 0}}, 0.0, 1)).errors.empty());

  const CaseReadResult below = read_case(hertz({{"bound", "x"}}, 0.0, 1));
  ASSERT_TRUE(below.spec);
  try {
    run_case(*below.spec);
    FAIL() << "a negative slip bound was accepted";
  } catch (const CaseException& e) {
    EXPECT_EQ(e.errors()[0].pointer, "/boundary/contact/friction/bound");
  }
}

}  // namespace
}  // namespace fosls
