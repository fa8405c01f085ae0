// A body too thin for double precision is the case's problem, said as such (issue 50, item 10:
// a 1 x 1 x 1e-9 plate ended in "the FOSLS matrix is not positive definite" as an internal
// error, exit 1). A plate of 1e-3 still solves.

#include <gtest/gtest.h>

#include <string>

#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json plate(double thickness) {
  return {{"dimension", 3},
          {"mesh",
           {{"builtin", {{"name", "box"}, {"lengths", {1, 1, thickness}}}}, {"refinements", 0}}},
          {"material", {{"E", 1}, {"nu", 0.3}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {0, 0, -1e-3 * thickness}}}},
            {"bottom",
             {{"type", "contact"},
              {"obstacle", {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}}}}}}}};
}

TEST(ThinBody, APlateTooThinForDoublePrecisionIsACaseErrorAtTheMesh) {
  const CaseReadResult read = read_case(plate(1e-9));
  ASSERT_TRUE(read.spec);
  try {
    run_case(*read.spec);
    FAIL() << "a 1e-9 plate was solved";
  } catch (const CaseException& e) {
    ASSERT_FALSE(e.errors().empty());
    EXPECT_EQ(e.errors()[0].pointer, "/mesh");
    EXPECT_NE(e.errors()[0].detail.find("thin"), std::string::npos) << e.errors()[0].detail;
  }
}

TEST(ThinBody, APlateOfAThousandthSolves) {
  const CaseReadResult read = read_case(plate(1e-3));
  ASSERT_TRUE(read.spec);
  const json r = run_case(*read.spec).result;
  EXPECT_TRUE(r["converged"].get<bool>());
  EXPECT_GT(r["contact"]["force"][2].get<double>(), 0.0);
}

}  // namespace
}  // namespace fosls
