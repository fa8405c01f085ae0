// `fosls-contact estimate` (build/bin) on the cases where its table was wrong or unreadable:
// an adaptive case's per-method memory must follow the rule its memory line states (the
// hierarchy factor at adaptivity.max_dofs, docs/case-format.md "Resources"), and long times
// read in minutes, not as "3.5e+02 s".
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

#include "../shipped_example.hpp"

namespace {

/// stdout of `fosls-contact estimate` on `j` written to a file; the exit code in `status`.
std::string estimate(const nlohmann::json& j, const std::string& name, int& status) {
  const std::string file = ::testing::TempDir() + name + ".json";
  std::ofstream(file) << j.dump();
  const std::string command =
      std::string(FOSLS_BIN_DIR) + "/fosls-contact estimate " + file + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[256];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  status = pipe ? pclose(pipe) : -1;
  return out;
}

/// The MiB of the method's row.
double row_mib(const std::string& out, const std::string& method) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("\n  " + method + " +([0-9]+) MiB"))) return -1;
  return std::stod(m[1]);
}

TEST(CliEstimate, AdaptiveRowsUseTheAdaptiveRuleOfTheMemoryLine) {
  nlohmann::json j = fosls::testing::load_shipped_example("hertz_adaptive");
  j["adaptivity"]["max_dofs"] = 200000;
  int status = -1;
  const std::string out = estimate(j, "adaptive", status);
  ASSERT_EQ(status, 0) << out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex("memory: +about ([0-9.]+) MiB"))) << out;
  // The memory line is mmg's (the case's method): its row must say the same.
  EXPECT_NEAR(row_mib(out, "mmg"), std::stod(m[1]), 1.0) << out;
  EXPECT_NE(out.find("an adaptive run solves every one of its up to"), std::string::npos) << out;
}

TEST(CliEstimate, AnAdaptiveAccuracyLoopsRowsUseTheRuleOfTheMemoryLine) {
  nlohmann::json j = fosls::testing::load_shipped_example("hertz_accuracy");
  j["accuracy"]["refinement"] = "adaptive";
  j["accuracy"]["max_dofs"] = 200000;
  int status = -1;
  const std::string out = estimate(j, "adaptive_accuracy", status);
  ASSERT_EQ(status, 0) << out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex("memory: +about ([0-9.]+) MiB"))) << out;
  EXPECT_NEAR(row_mib(out, "mmg"), std::stod(m[1]), 1.0) << out;
}

TEST(CliEstimate, LongTimesReadInMinutes) {
  nlohmann::json j = fosls::testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = 7;  // 2.1 M unknowns: pdas takes minutes
  int status = -1;
  const std::string out = estimate(j, "large", status);
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find(" min\n"), std::string::npos) << out;
  EXPECT_EQ(out.find("e+"), std::string::npos) << out;
}

}  // namespace

namespace {

/// stdout and stderr of `fosls-contact ARGS` on `j` written to a file; the exit code in `status`.
std::string run_cli(const std::string& command, const nlohmann::json& j, const std::string& name,
                    const std::string& options, int& status) {
  const std::string file = ::testing::TempDir() + name + ".json";
  std::ofstream(file) << j.dump();
  const std::string line = std::string(FOSLS_BIN_DIR) + "/fosls-contact " + command + " " + file +
                           " " + options + " 2>&1 >/dev/null";
  FILE* pipe = popen(line.c_str(), "r");
  std::string out;
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  status = pipe ? WEXITSTATUS(pclose(pipe)) : -1;
  return out;
}

TEST(CliEstimate, EstimateRefusesWhatSolveRefusesWithTheSameWords) {
  struct Probe {
    const char* what;
    nlohmann::json case_json;
    std::string options;
  };
  nlohmann::json huge = fosls::testing::load_shipped_example("hertz");
  huge["mesh"]["refinements"] = 8;  // about 29 M unknowns estimated before meshing
  nlohmann::json big = fosls::testing::load_shipped_example("signorini_square");
  big["mesh"]["refinements"] = 6;  // 526 338 unknowns, exact
  for (const Probe& p :
       {Probe{"over max_dofs", huge, ""}, Probe{"over --max-memory", big, "--max-memory 100M"}}) {
    int estimate_status = -1, solve_status = -1;
    const std::string estimate_errors =
        run_cli("estimate", p.case_json, "probe", p.options, estimate_status);
    const std::string solve_errors =
        run_cli("solve", p.case_json, "probe", p.options, solve_status);
    EXPECT_EQ(estimate_status, 2) << p.what << ": " << estimate_errors;
    EXPECT_EQ(solve_status, 2) << p.what << ": " << solve_errors;
    EXPECT_EQ(estimate_errors, solve_errors) << p.what;
    EXPECT_NE(estimate_errors.find("error: /mesh/refinements: "), std::string::npos)
        << estimate_errors;
  }
}

TEST(CliEstimate, AdviceForACaseThatDoesNotFitNamesOnlyMethodsThatConverge) {
  nlohmann::json j = fosls::testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = 6;
  j["solver"] = {{"method", "pdas"}};  // about 1 GiB; mmg needs about 400 MiB
  int status = -1;
  const std::string out = run_cli("estimate", j, "advice", "--max-memory 600M", status);
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("or solver.method mmg (about"), std::string::npos) << out;
  EXPECT_NE(out.find("or solver.method tnnmg (about"), std::string::npos) << out;
  EXPECT_EQ(out.find("pgs"), std::string::npos) << out;
}

}  // namespace
