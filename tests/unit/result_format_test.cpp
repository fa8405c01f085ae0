// Every field of the result JSON and every array of the VTU file that a solve produces is
// documented (result_rules.hpp and vtu_arrays(), the sources of docs/result-format.md), with
// the documented type; and the documented summary numbers mean what they say.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "../shipped_example.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/rule_checker.hpp"
#include "case/result/result_rules.hpp"
#include "case/run/case_runner.hpp"
#include "post/vtu_writer.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json load_example(const std::string& name) { return testing::load_shipped_example(name); }

RunOutput solve(const json& j) {
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec);
  return run_case(*read.spec);
}

std::string undocumented(const json& result) {
  RuleChecker checker(CaseReadOptions{});
  checker.check_object(result, *result_rule(), "");
  std::string s;
  for (const auto& e : checker.errors()) s += "  " + e.pointer + ": " + e.detail + "\n";
  return s;
}

/// Names of the DataArrays inside <PointData> and <CellData>.
std::set<std::string> data_arrays(const std::string& vtu) {
  std::set<std::string> names;
  for (const char* section : {"PointData", "CellData"}) {
    const auto begin = vtu.find(std::string("<") + section);
    const auto end = vtu.find(std::string("</") + section + ">");
    if (begin == std::string::npos || end == std::string::npos) continue;
    const std::string part = vtu.substr(begin, end - begin);
    static const std::regex name("<DataArray[^>]* Name=\"([^\"]+)\"");
    for (auto it = std::sregex_iterator(part.begin(), part.end(), name);
         it != std::sregex_iterator(); ++it)
      names.insert((*it)[1]);
  }
  return names;
}

TEST(ResultFormat, EveryEmittedFieldAndArrayIsDocumented) {
  for (const char* example : {"signorini_square", "linear_square", "signorini_square_adaptive",
                              "hertz_accuracy", "cattaneo_mindlin"}) {
    json j = load_example(example);
    j["mesh"]["refinements"] = 2;
    if (j.contains("adaptivity")) j["adaptivity"]["steps"] = 2;
    const RunOutput out = solve(j);
    EXPECT_EQ(undocumented(out.result), "") << example;
    std::set<std::string> documented;
    for (const auto& a : vtu_arrays()) documented.insert(a.name);
    EXPECT_EQ(data_arrays(out.vtu), documented) << example;
  }
}

TEST(ResultFormat, TheCheckFindsAnUndocumentedField) {
  json j = load_example("linear_square");
  j["mesh"]["refinements"] = 1;
  json result = solve(j).result;
  result["contact"]["surprise"] = 1;
  result["iterations"] = "many";
  const std::string problems = undocumented(result);
  EXPECT_NE(problems.find("/contact/surprise"), std::string::npos) << problems;
  EXPECT_NE(problems.find("/iterations"), std::string::npos) << problems;
}

TEST(ResultFormat, NotConvergedSaysWhyWithRealNumbers) {
  json j = load_example("signorini_square");
  j["mesh"]["refinements"] = 2;
  j["solver"]["max_iterations"] = 3;
  const json r = solve(j).result;
  EXPECT_EQ(undocumented(r), "");
  EXPECT_FALSE(r["converged"].get<bool>());
  EXPECT_EQ(r["stop_reason"], "max_iterations");
  const std::string message = r["message"];
  EXPECT_NE(message.find("after 3 iterations"), std::string::npos) << message;
  EXPECT_EQ(message.find("0.000000"), std::string::npos) << message;
  // The relative residual it quotes is the result's own.
  std::ostringstream relative;
  relative.precision(3);
  relative << r["relative_kkt_residual"].get<double>();
  EXPECT_NE(message.find(relative.str()), std::string::npos) << message << " " << relative.str();
  EXPECT_GT(r["relative_kkt_residual"].get<double>(), 1e-8);
  ASSERT_FALSE(r["warnings"].empty());
  EXPECT_EQ(r["warnings"][0], message);
}

TEST(ResultFormat, ContactZoneSummarisesTheEdges) {
  json j = load_example("signorini_square");
  j["mesh"]["refinements"] = 2;
  const json r = solve(j).result;
  const json& c = r["contact"];
  ASSERT_TRUE(r["converged"].get<bool>());
  int in_contact = 0;
  double length = 0, peak = 0;
  for (std::size_t i = 0; i < c["active"].size(); ++i)
    if (c["active"][i].get<bool>()) {
      ++in_contact;
      length += c["length"][i].get<double>();
      peak = std::max(peak, c["pressure"][i].get<double>());
    }
  ASSERT_GT(in_contact, 0);
  EXPECT_LT(in_contact, static_cast<int>(c["active"].size()));  // a proper sub-interval
  EXPECT_EQ(c["zone"]["edges"], in_contact);
  EXPECT_NEAR(c["zone"]["length"].get<double>(), length, 1e-12);
  EXPECT_EQ(c["zone"]["peak_pressure"].get<double>(), peak);
  EXPECT_GE(c["zone"]["s_end"].get<double>() - c["zone"]["s_start"].get<double>(), length - 1e-12);
  EXPECT_NEAR(r["functional"]["estimator"].get<double>(),
              std::sqrt(r["functional"]["total"].get<double>()), 1e-15);
  EXPECT_EQ(r["active_bounds"], r["active"]);
}

}  // namespace
}  // namespace fosls
