// Load steps: pointers and values validated with their own pointers, each step solved from the
// previous one, frictionless steps equal to the final state solved directly, and friction's slip
// measured from the previous step's displacement (the steps' slips add up to the total).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json cattaneo(double coefficient) {
  json j = testing::load_shipped_example("cattaneo_mindlin");
  j["mesh"]["refinements"] = 2;
  j["boundary"]["top"]["displacement"] = {0, -0.01};
  j["boundary"]["contact"]["friction"] = {{"coefficient", coefficient}};
  j["load_steps"] = json::array(
      {{{"/boundary/top/displacement/0", 0.001}}, {{"/boundary/top/displacement/0", 0.003}}});
  return j;
}

json solve(const json& j) { return testing::solved_case(j); }

TEST(LoadSteps, BadPointersAndValuesAreNamed) {
  json j = cattaneo(0.3);
  j["load_steps"] = json::array({{{"/mesh/size", 0.1}},
                                 {{"/boundary/nothere/x", 1}},
                                 {{"/material/mu", -1}},
                                 {{"no pointer", 1}}});
  const auto errors = read_case(j).errors;
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(errors[0].pointer, "/load_steps/0/~1mesh~1size");
  EXPECT_EQ(errors[1].pointer, "/load_steps/1/~1boundary~1nothere~1x");
  EXPECT_EQ(errors[2].pointer, "/load_steps/2");
  EXPECT_NE(errors[2].detail.find("/material/mu"), std::string::npos);
  EXPECT_EQ(errors[3].pointer, "/load_steps/3/no pointer");

  json with_sweep = cattaneo(0.3);
  with_sweep["sweep"] = {{"pointer", "/material/mu"}, {"values", {1, 2}}};
  ASSERT_FALSE(read_case(with_sweep).errors.empty());
  EXPECT_EQ(read_case(with_sweep).errors[0].pointer, "/load_steps");

  json without_contact = cattaneo(0.3);
  without_contact["boundary"]["contact"] = {{"type", "neumann"}, {"traction", {0, 0}}};
  ASSERT_FALSE(read_case(without_contact).errors.empty());
  EXPECT_EQ(read_case(without_contact).errors[0].pointer, "/load_steps");
}

TEST(LoadSteps, FrictionlessStepsEndWhereTheFinalStateDoes) {
  json stepped = cattaneo(0.0);
  const json r = solve(stepped);
  ASSERT_TRUE(r["converged"].get<bool>());
  ASSERT_EQ(r["load_steps"]["count"], 3);
  EXPECT_EQ(r["load_steps"]["steps"][2]["changes"]["/boundary/top/displacement/0"], 0.003);
  json direct = cattaneo(0.0);
  direct.erase("load_steps");
  direct["boundary"]["top"]["displacement"] = {0.003, -0.01};
  const json d = solve(direct);
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(r["contact"]["force"][c].get<double>(), d["contact"]["force"][c].get<double>(),
                1e-6 * d["contact"]["force"][1].get<double>());
}

TEST(LoadSteps, FrictionMeasuresEachStepsSlipFromThePreviousStep) {
  const json r = solve(cattaneo(0.3));
  ASSERT_TRUE(r["converged"].get<bool>());
  const json& steps = r["load_steps"]["steps"];
  ASSERT_EQ(steps.size(), 3u);
  // The slips of the steps add up to u·t of the last state, which is its slip from u = 0 when
  // solved as one step from the undeformed state: per edge, Σ_k slip_k equals the total.
  json one_step = cattaneo(0.3);
  one_step.erase("load_steps");
  one_step["boundary"]["top"]["displacement"] = {0.003, -0.01};
  const json total = solve(one_step);
  double largest = 0.0, difference = 0.0;
  for (std::size_t e = 0; e < total["contact"]["slip"].size(); ++e) {
    double sum = 0.0;
    for (const auto& s : steps) sum += s["contact"]["slip"][e].get<double>();
    largest = std::max(largest, std::abs(sum));
    difference = std::max(difference, std::abs(sum - total["contact"]["slip"][e].get<double>()));
  }
  EXPECT_GT(largest, 1e-4);  // the body moved sideways
  // The path changes u·t within the slip zones a little (press then shift is not both at once);
  // slips measured from u = 0 in every step would add to 0.001 + 0.003 against 0.003.
  EXPECT_LT(difference, 0.2 * largest);
  // Each step's tangential force grows with the shift, below the Coulomb limit.
  double previous = 0.0;
  for (const auto& s : steps) {
    const double fx = std::abs(s["contact"]["force"][0].get<double>());
    EXPECT_GE(fx, previous);
    EXPECT_LE(fx, 0.3 * s["contact"]["force"][1].get<double>() * 1.05);
    previous = fx;
  }
}

// RunControl::on_solve numbers the steps for progress, out of most_solves; watching them
// changes no result.
TEST(LoadSteps, OnSolveNumbersTheStepsAndChangesNoResult) {
  const CaseReadResult read = read_case(cattaneo(0.3));
  ASSERT_TRUE(read.spec);
  EXPECT_EQ(most_solves(*read.spec), 3);
  std::vector<std::pair<int, int>> solves;
  RunControl control;
  control.on_solve = [&](int solve, int most) { solves.emplace_back(solve, most); };
  const json watched = run_case(*read.spec, control).result;
  EXPECT_EQ(solves, (std::vector<std::pair<int, int>>{{0, 3}, {1, 3}, {2, 3}}));
  const json plain = run_case(*read.spec).result;
  EXPECT_EQ(watched["contact"], plain["contact"]);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(watched["load_steps"]["steps"][k]["iterations"],
              plain["load_steps"]["steps"][k]["iterations"]);
}

}  // namespace
}  // namespace fosls
