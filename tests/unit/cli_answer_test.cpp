// What `fosls-contact solve` tells a user at the moment it matters: exit code 4 and a REVIEW
// line for a converged answer without contact; the contact width it prints is the result's
// contact.zone.length; declared units in the summary; why an adaptive run stopped; a number
// with a unit explained as unit-agnostic; every problem of a case in one round. Runs
// build/bin/fosls-contact.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../shipped_example.hpp"
#include "process/child_process.hpp"

namespace fosls {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

struct SolveRun {
  int exit_code = -1;
  std::string err;
  json result;
};

/// Solves `j` with the real program; the result JSON when it wrote one.
SolveRun solve(const json& j, const std::string& label) {
  const fs::path work = fs::temp_directory_path() / ("fosls_cli_answer_" + label);
  fs::create_directories(work);
  const fs::path out = work / "result.json";
  fs::remove(out);
  ChildOptions o;
  o.argv = {std::string(FOSLS_BIN_DIR) + "/fosls-contact", "solve", "-", "--out", out.string()};
  o.input = j.dump();
  const ChildResult r = run_child(o);
  SolveRun run;
  EXPECT_EQ(r.end, ChildResult::End::kExited) << r.describe();
  run.exit_code = r.exit_code;
  run.err = r.errors;
  std::ifstream in(out);
  if (in) run.result = json::parse(in);
  fs::remove_all(work);
  return run;
}

json hertz(int refinements) {
  json j = testing::load_shipped_example("hertz");
  j["mesh"]["refinements"] = refinements;
  return j;
}

std::string g4(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

TEST(CliAnswer, NoContactExitsWithFourAndSaysReview) {
  json j = hertz(1);
  j["boundary"]["contact"]["obstacle"]["normal"] = {0, -1};
  const SolveRun r = solve(j, "no_contact");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("warning: no contact"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("REVIEW: converged, but"), std::string::npos) << r.err;
  ASSERT_TRUE(r.result.is_object());
  EXPECT_TRUE(r.result["converged"].get<bool>());
  EXPECT_TRUE(r.result["review_required"].get<bool>());
  // The shipped case itself: exit 0, no review line.
  const SolveRun ok = solve(hertz(1), "contact");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.err.find("REVIEW"), std::string::npos) << ok.err;
}

TEST(CliAnswer, ThePrintedWidthIsTheResultsContactWidthInTheDeclaredUnits) {
  json j = hertz(2);
  j["units"] = {{"length", "mm"}, {"stress", "MPa"}};
  const SolveRun r = solve(j, "width");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double width = r.result["contact"]["zone"]["width"];
  EXPECT_NE(r.err.find("width " + g4(width) + " mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(") N/mm (per mm of thickness)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("p_max = " + g4(r.result["contact"]["zone"]["peak_pressure"]) + " MPa"),
            std::string::npos)
      << r.err;
}

TEST(CliAnswer, AnAdaptiveRunSaysWhyItStoppedAndWhatTheTargetMeans) {
  json j = testing::load_shipped_example("hertz_adaptive");
  j["adaptivity"]["steps"] = 2;
  const SolveRun r = solve(j, "adaptive");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.result["adaptivity"]["stop_reason"], "steps");
  const std::string m = r.result["adaptivity"]["stop_message"];
  EXPECT_NE(r.err.find("adaptive run        3 solves"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(m), std::string::npos) << r.err;
  EXPECT_NE(m.find("the 2 refinement steps were made"), std::string::npos) << m;
  EXPECT_NE(m.find("not the relative accuracy"), std::string::npos) << m;
  const auto& steps = r.result["adaptivity"]["steps"];
  EXPECT_DOUBLE_EQ(r.result["adaptivity"]["estimator_reduction"].get<double>(),
                   steps.back()["estimator"].get<double>() / steps[0]["estimator"].get<double>());
  EXPECT_TRUE(r.result["adaptivity"]["last_force_change"].is_number());
}

TEST(CliAnswer, ANumberWithAUnitIsExplainedAsUnitAgnostic) {
  json j = hertz(0);
  j["material"] = {{"E", "210 GPa"}, {"nu", 0.3}};
  const SolveRun r = solve(j, "unit_hint");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/material/E: expected a number, got the string \"210 GPa\""),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("unit-agnostic"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"units\""), std::string::npos) << r.err;
  j["material"] = {{"E", 2.5}, {"nu", 0.25}};
  j["units"] = {{"length", "inch"}, {"stress", "MPa"}};
  const SolveRun bad_units = solve(j, "bad_units");
  EXPECT_EQ(bad_units.exit_code, 2);
  EXPECT_NE(bad_units.err.find("/units/length: unknown value \"inch\""), std::string::npos)
      << bad_units.err;
}

TEST(CliAnswer, AWrongGroupNameComesInTheSameRoundAsTheFieldErrors) {
  json j = hertz(0);
  j["material"]["mu"] = -1;
  j["boundary"]["bottom"] = j["boundary"]["contact"];  // the hertz mesh has no group "bottom"
  j["boundary"].erase("contact");
  const SolveRun r = solve(j, "one_round");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/material/mu"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/boundary/bottom: the mesh has no boundary group 'bottom'"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace fosls
