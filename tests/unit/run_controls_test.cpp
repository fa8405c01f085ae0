// Case fields that steer a run: solver.time_limit_s stops the solve at the last iterate with
// stop_reason time_limit, and a run with no iterate yet with TimeLimitReached; an obstacle's rigid
// displacement is the same indentation as the opposite displacement of the body; rollers (a null
// displacement component) give the exact uniaxial solution.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../shipped_example.hpp"
#include "../uniaxial_case.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/rule_checker.hpp"
#include "case/result/result_rules.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;
using testing::uniaxial_case;

json hertz(int refinements) {
  std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/solver/examples/hertz.json");
  std::stringstream text;
  text << in.rdbuf();
  json j = json::parse(text.str());
  j["mesh"]["refinements"] = refinements;
  return j;
}

json solve(const json& j) {
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec) << (read.errors.empty() ? "" : read.errors[0].detail);
  return read.spec ? run_case(*read.spec).result : json();
}

TEST(RunControls, ATimeLimitBeforeTheFirstIterateStopsTheSetUpAndSaysSo) {
  // The limit runs out while gmsh meshes: the run stops at the next check, once the mesh is
  // refined, instead of assembling and setting up first.
  json j = hertz(3);
  j["solver"]["time_limit_s"] = 1e-6;
  const CaseReadResult read = read_case(j);
  ASSERT_TRUE(read.spec);
  try {
    run_case(*read.spec);
    FAIL() << "the run went on past its time limit";
  } catch (const TimeLimitReached& e) {
    EXPECT_EQ(e.stage(), "refining the mesh");
    const std::string message = e.what();
    EXPECT_NE(message.find("solver.time_limit_s (1e-06 s) ran out while refining the mesh, "
                           "before the solve had a first iterate"),
              std::string::npos)
        << message;
  }
}

TEST(RunControls, TimeLimitStopsAtTheLastIterateAndSaysWhy) {
  // The square, built without gmsh: its set-up is a small part of the limit even on a loaded
  // machine, so the iterations are reached (a limit that runs out before them: test above).
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = 4;
  // Projected Gauss–Seidel to an unreachable tolerance would run for hours.
  j["solver"] = {
      {"method", "pgs"}, {"tolerance", 1e-15}, {"max_iterations", 100000}, {"time_limit_s", 1.0}};
  const json r = solve(j);
  EXPECT_EQ(r["stop_reason"], "time_limit");
  EXPECT_EQ(r["converged"], false);
  EXPECT_EQ(r["cancelled"], false);
  EXPECT_LT(r["iterations"].get<int>(), 100000);
  ASSERT_TRUE(r.contains("message"));
  EXPECT_NE(r["message"].get<std::string>().find("solver.time_limit_s (1 s) ran out"),
            std::string::npos)
      << r["message"];
  ASSERT_FALSE(r["warnings"].empty());
  // The result stays valid for its documented rules (docs/result-format.md).
  RuleChecker checker(CaseReadOptions{});
  checker.check_object(r, *result_rule(), "");
  EXPECT_TRUE(checker.errors().empty()) << checker.errors()[0].pointer;
}

TEST(RunControls, ATimeLimitIsANonNegativeNumber) {
  json j = hertz(1);
  j["solver"]["time_limit_s"] = -1;
  const CaseReadResult read = read_case(j);
  ASSERT_FALSE(read.errors.empty());
  EXPECT_EQ(read.errors[0].pointer, "/solver/time_limit_s");
}

// With the constraint along the plane's normal the problem is invariant under a rigid
// translation: the body pressed down by δ and the obstacle lifted by δ give the same stresses.
TEST(RunControls, MovingTheObstacleEqualsMovingTheBody) {
  json pressed = hertz(1);
  pressed["boundary"]["contact"]["direction"] = "obstacle_normal";
  json lifted = pressed;
  lifted["boundary"]["top"]["displacement"] = {0, 0};
  lifted["boundary"]["contact"]["obstacle"]["displacement"] = {0, 0.01};
  const json a = solve(pressed), b = solve(lifted);
  ASSERT_EQ(a["converged"], true);
  ASSERT_EQ(b["converged"], true);
  const double fa = a["contact"]["force"][1], fb = b["contact"]["force"][1];
  EXPECT_GT(std::abs(fa), 0.0);
  EXPECT_NEAR(fb, fa, 1e-5 * std::abs(fa));
  ASSERT_EQ(a["contact"]["pressure"].size(), b["contact"]["pressure"].size());
  double peak = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a["contact"]["pressure"].size(); ++i) {
    const double pa = a["contact"]["pressure"][i], pb = b["contact"]["pressure"][i];
    peak = std::max(peak, std::abs(pa));
    diff = std::max(diff, std::abs(pa - pb));
  }
  EXPECT_LT(diff, 1e-4 * peak);
  // And without any motion there is no contact force at all.
  json none = lifted;
  none["boundary"]["contact"]["obstacle"]["displacement"] = {0, 0};
  EXPECT_NEAR(solve(none)["contact"]["force"][1].get<double>(), 0.0, 1e-8 * std::abs(fa));
}

TEST(RunControls, AGapObstacleCannotBeMoved) {
  json j = hertz(1);
  j["boundary"]["contact"]["obstacle"] = {{"type", "gap"}, {"g", 0.0}, {"displacement", {0, 0.01}}};
  const CaseReadResult read = read_case(j);
  ASSERT_FALSE(read.errors.empty());
  EXPECT_EQ(read.errors[0].pointer, "/boundary/contact/obstacle/displacement");
}

TEST(RunControls, RollersGiveTheExactUniaxialSolution) {
  for (const auto& [lambda, modulus] : {std::pair<json, double>{1.0, 8.0 / 3.0}, {"inf", 4.0}}) {
    const json r = solve(uniaxial_case(lambda));
    ASSERT_EQ(r["converged"], true) << lambda;
    const double p = modulus * 0.01;
    const auto& pressure = r["contact"]["pressure"];
    ASSERT_FALSE(pressure.empty());
    for (const auto& pe : pressure) EXPECT_NEAR(pe.get<double>(), p, 1e-6 * p) << lambda;
    EXPECT_NEAR(r["contact"]["force"][1].get<double>(), p, 1e-6 * p) << lambda;
    EXPECT_NEAR(r["contact"]["force"][0].get<double>(), 0.0, 1e-6 * p) << lambda;
  }
}

TEST(RunControls, ABodyThatCanSlideIsRefusedBeforeSolving) {
  json j = uniaxial_case(1.0);
  j["boundary"].erase("left");  // nothing holds u_x: the body slides on the frictionless plane
  const auto errors = validate_case(j);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pointer, "/boundary");
  EXPECT_NE(errors[0].detail.find("no dirichlet group prescribes u_x"), std::string::npos)
      << errors[0].detail;
  EXPECT_TRUE(validate_case(uniaxial_case(1.0)).empty());
}

/// The values of the point array `name` of a VTU text, flattened.
std::vector<double> point_array(const std::string& vtu, const std::string& name) {
  const auto at = vtu.find("Name=\"" + name + "\"");
  const auto begin = vtu.find('>', at) + 1, end = vtu.find("</DataArray>", at);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

// A pressure p on the top of a block held by rollers below and on the left: uniaxial stress
// σ_yy = −p, so u_y(top) = −p (λ+2μ)/(4μ(λ+μ)) and u_x(right) = p λ/(4μ(λ+μ)); the same as the
// traction [0, −p], and the sign says the pressure pushes into the body.
TEST(RunControls, APressureIsTheTractionAlongTheInwardNormal) {
  json j = uniaxial_case(1.0);
  j["boundary"] = {{"top", {{"type", "pressure"}, {"pressure", 0.01}}},
                   {"left", {{"type", "dirichlet"}, {"displacement", {0, nullptr}}}},
                   {"bottom", {{"type", "dirichlet"}, {"displacement", {nullptr, 0}}}}};
  json traction = j;
  traction["boundary"]["top"] = {{"type", "neumann"}, {"traction", {0, -0.01}}};
  const CaseReadResult read = read_case(j), read_traction = read_case(traction);
  ASSERT_TRUE(read.spec && read_traction.spec);
  RunControl ascii;  // point_array reads the VTU's text
  ascii.vtu_ascii = true;
  const RunOutput out = run_case(*read.spec, ascii),
                  out_traction = run_case(*read_traction.spec, ascii);
  ASSERT_EQ(out.result["converged"], true);
  const std::vector<double> u = point_array(out.vtu, "u");
  ASSERT_FALSE(u.empty());
  constexpr std::size_t components = 3;  // VTK vectors: (u_x, u_y, 0)
  double uy_min = 0.0, ux_max = 0.0;
  for (std::size_t i = 0; i + 2 < u.size(); i += components) {
    ux_max = std::max(ux_max, u[i]);
    uy_min = std::min(uy_min, u[i + 1]);
  }
  EXPECT_NEAR(uy_min, -0.01 * 3.0 / 8.0, 1e-8);
  EXPECT_NEAR(ux_max, 0.01 / 8.0, 1e-8);
  EXPECT_EQ(u, point_array(out_traction.vtu, "u"));

  // On the right side the outward normal is +x: the pressure is the traction [−p, 0] there.
  j["boundary"]["right"] = {{"type", "pressure"}, {"pressure", 0.01}};
  traction["boundary"]["right"] = {{"type", "neumann"}, {"traction", {-0.01, 0}}};
  const RunOutput both = run_case(*read_case(j).spec, ascii);
  const RunOutput both_traction = run_case(*read_case(traction).spec, ascii);
  EXPECT_EQ(point_array(both.vtu, "u"), point_array(both_traction.vtu, "u"));
  EXPECT_NE(point_array(both.vtu, "u"), u);
}

TEST(RunControls, ADisplacementWithBothComponentsNullIsRefused) {
  json j = uniaxial_case(1.0);
  j["boundary"]["top"]["displacement"] = {nullptr, nullptr};
  const CaseReadResult read = read_case(j);
  ASSERT_FALSE(read.errors.empty());
  EXPECT_EQ(read.errors[0].pointer, "/boundary/top/displacement");
  EXPECT_NE(read.errors[0].detail.find("neumann"), std::string::npos);
}

// How many solves a run makes at most (a job's progress.steps): one per sweep point, and
// adaptivity.steps + 1 per adaptive run; not known for an accuracy loop.
TEST(RunControls, MostSolvesCountsPointsAndAdaptiveSteps) {
  auto most = [](const json& j) {
    const CaseReadResult read = read_case(j);
    EXPECT_TRUE(read.spec) << (read.errors.empty() ? "" : read.errors[0].detail);
    return read.spec ? most_solves(*read.spec) : -1;
  };
  json j = hertz(1);
  EXPECT_EQ(most(j), 1);
  j["sweep"] = {{"pointer", "/material/mu"}, {"values", {1, 2, 3}}};
  EXPECT_EQ(most(j), 3);
  j["adaptivity"] = {{"steps", 4}};
  EXPECT_EQ(most(j), 15);
  json accurate = hertz(1);
  accurate["accuracy"] = {{"force", 1e-3}};
  EXPECT_EQ(most(accurate), 0);
}

}  // namespace
}  // namespace fosls
