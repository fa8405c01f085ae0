// The check that the dirichlet groups hold the body against every rigid motion (3D): what it
// refuses it names, and a slender body clamped along its length is held (issue 50, item 10: a
// 10^5 × 1 × 1 box with its top clamped was refused as free to rotate about its long axis).

#include <gtest/gtest.h>

#include <string>

#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json box_case(double length, const json& top_displacement) {
  return {{"dimension", 3},
          {"mesh",
           {{"builtin", {{"name", "box"}, {"lengths", {length, 1, 1}}, {"cells", {2, 2, 2}}}},
            {"refinements", 0}}},
          {"material", {{"E", 1}, {"nu", 0.3}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", top_displacement}}},
            {"bottom",
             {{"type", "contact"},
              {"obstacle", {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}}}}}}}};
}

std::string boundary_error(const json& c) {
  for (const CaseError& e : validate_case(c))
    if (e.pointer == "/boundary") return e.detail;
  return "";
}

TEST(RigidMotionCheck, AClampedFaceHoldsTheBodyWhateverItsAspect) {
  for (double length : {1.0, 1e3, 1e5, 1e7})
    EXPECT_EQ(boundary_error(box_case(length, {0, 0, -0.01})), "") << "length " << length;
}

}  // namespace
}  // namespace fosls
