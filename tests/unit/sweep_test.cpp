// A case with a sweep: its pointer and values are validated with pointers, the points are
// solved in order from the previous solution, and each point's answer equals the answer of
// the case written with that value.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "../solved_case.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/rule_checker.hpp"
#include "case/result/result_rules.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

const char* kLift = "/boundary/contact/obstacle/displacement/1";

/// The shipped Hertz case at rest, lifted by its obstacle (docs/case-format.md, "Sweeps").
json hertz_indentation(json values) {
  std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/solver/examples/hertz.json");
  std::stringstream text;
  text << in.rdbuf();
  json j = json::parse(text.str());
  j["mesh"]["refinements"] = 2;
  j["boundary"]["top"]["displacement"] = {0, 0};
  j["boundary"]["contact"]["obstacle"]["displacement"] = {0, values[0]};
  j["boundary"]["contact"]["direction"] = "obstacle_normal";
  j["sweep"] = {{"pointer", kLift}, {"values", std::move(values)}};
  return j;
}

std::vector<CaseError> errors_of(const json& j) { return read_case(j).errors; }

json solve(const json& j) { return testing::solved_case(j); }

TEST(Sweep, PointerAndValuesAreValidatedWithPointers) {
  json mesh = hertz_indentation({0.001});
  mesh["sweep"]["pointer"] = "/mesh/size";
  ASSERT_FALSE(errors_of(mesh).empty());
  EXPECT_EQ(errors_of(mesh)[0].pointer, "/sweep/pointer");
  EXPECT_NE(errors_of(mesh)[0].detail.find("same mesh"), std::string::npos);

  json missing = hertz_indentation({0.001});
  missing["sweep"]["pointer"] = "/solver/time_limit_s";  // not given in the case
  ASSERT_FALSE(errors_of(missing).empty());
  EXPECT_EQ(errors_of(missing)[0].pointer, "/sweep/pointer");

  json bad_value = hertz_indentation({0.001, 0.002});
  bad_value["sweep"]["pointer"] = "/material/mu";
  bad_value["sweep"]["values"] = {1, -1};
  const auto errors = errors_of(bad_value);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pointer, "/sweep/values/1");
  EXPECT_NE(errors[0].detail.find("/material/mu"), std::string::npos) << errors[0].detail;

  json empty = hertz_indentation({0.001});
  empty["sweep"]["values"] = json::array();
  ASSERT_FALSE(errors_of(empty).empty());
  EXPECT_EQ(errors_of(empty)[0].pointer, "/sweep/values");
}

TEST(Sweep, EachPointEqualsTheCaseWithItsValue) {
  const json values = {0.002, 0.004, 0.006, 0.008};
  const json r = solve(hertz_indentation(values));
  ASSERT_TRUE(r.contains("sweep"));
  EXPECT_EQ(r["sweep"]["pointer"], kLift);
  const json& points = r["sweep"]["points"];
  ASSERT_EQ(points.size(), values.size());
  EXPECT_EQ(r["converged"], true);
  double previous = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i]["value"], values[i]);
    EXPECT_EQ(points[i]["converged"], true);
    const double force = points[i]["force"][1];
    EXPECT_GT(force, previous) << "the force grows with the indentation";
    previous = force;
  }
  // Continuation changes the start, not the answer: the points equal single solves.
  for (std::size_t i : {std::size_t{0}, points.size() - 1}) {
    json single = hertz_indentation({values[i]});
    single.erase("sweep");
    const double expected = solve(single)["contact"]["force"][1];
    EXPECT_NEAR(points[i]["force"][1].get<double>(), expected, 1e-5 * expected) << i;
  }
  // The curve has 2D Hertz theory's shape: δ = F/(πE*)·(2 ln(4R/a) − 1) with
  // a = √(4FR/(πE*)), so the stiffness F/δ grows with the load as πE*/(2 ln(4R/a) − 1). The
  // finite body shifts its level (≈ 4 % here), not its trend: the ratio of the two is constant
  // along the curve to 1 %, while each of them grows by over 20 %.
  const double e_star = 8.0 / 3.0, radius = 1.0;  // μ = λ = 1; the Hertz case's disk
  double lo = 1e300, hi = 0.0;
  for (const auto& p : points) {
    const double f = p["force"][1], a = std::sqrt(4 * f * radius / (M_PI * e_star));
    const double ratio =
        (f / p["value"].get<double>()) / (M_PI * e_star / (2 * std::log(4 * radius / a) - 1));
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  EXPECT_LT(hi / lo, 1.01);
  EXPECT_GT(points.back()["force"][1].get<double>() / values.back().get<double>(),
            1.2 * points[0]["force"][1].get<double>() / values[0].get<double>());
  // The last point's fields are the result's own.
  EXPECT_EQ(r["contact"]["force"], points.back()["force"]);
  RuleChecker checker(CaseReadOptions{});
  checker.check_object(r, *result_rule(), "");
  EXPECT_TRUE(checker.errors().empty()) << checker.errors()[0].pointer;
}

TEST(Sweep, APointThatDoesNotConvergeIsFlagged) {
  json j = hertz_indentation({0.002, 0.004});
  j["sweep"]["pointer"] = "/solver/max_iterations";
  j["solver"]["max_iterations"] = 200;
  j["sweep"]["values"] = {200, 1};
  const json r = solve(j);
  ASSERT_EQ(r["sweep"]["points"].size(), 2u);
  EXPECT_EQ(r["sweep"]["points"][0]["converged"], true);
  EXPECT_EQ(r["sweep"]["points"][1]["converged"], false);
  EXPECT_EQ(r["sweep"]["points"][1]["stop_reason"], "max_iterations");
  EXPECT_EQ(r["converged"], false);
  EXPECT_EQ(r["stop_reason"], "max_iterations");
  bool flagged = false;
  for (const auto& w : r["warnings"])
    flagged |= w.get<std::string>().find("sweep point 1") != std::string::npos;
  EXPECT_TRUE(flagged) << r["warnings"];
}

}  // namespace
}  // namespace fosls
