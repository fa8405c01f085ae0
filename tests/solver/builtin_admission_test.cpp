// What a 3D builtin's parameters alone decide is refused at admission, before a job is queued
// (issue 50, item 10: a half ball whose grading folds a tetrahedron failed only when it ran).

#include <gtest/gtest.h>

#include <string>

#include "case/admission/case_admission.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json half_ball(double grading, int cells) {
  return {
      {"dimension", 3},
      {"mesh",
       {{"builtin", {{"name", "half_ball"}, {"radius", 1}, {"grading", grading}, {"cells", cells}}},
        {"refinements", 0}}},
      {"material", {{"E", 1}, {"nu", 0.3}}},
      {"boundary",
       {{"top", {{"type", "dirichlet"}, {"displacement", {0, 0, -0.01}}}},
        {"contact",
         {{"type", "contact"},
          {"obstacle", {{"type", "plane"}, {"point", {0, 0, -1}}, {"normal", {0, 0, 1}}}}}}}}};
}

TEST(BuiltinAdmission, AGradingThatFoldsATetrahedronIsRefusedAtAdmission) {
  const CaseAdmission folded = admit_case(half_ball(4, 8));
  ASSERT_EQ(folded.errors.size(), 1u);
  EXPECT_EQ(folded.errors[0].pointer, "/mesh/builtin");
  EXPECT_NE(folded.errors[0].detail.find("folds"), std::string::npos) << folded.errors[0].detail;
  EXPECT_TRUE(admit_case(half_ball(2, 4)).errors.empty());
}

}  // namespace
}  // namespace fosls
