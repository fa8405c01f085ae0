// Every shipped example with contact reaches a requested force accuracy of 10⁻³ (the issue's
// promise for the shipped cases): its adaptivity or load steps removed (accuracy chooses the
// levels and is not combined with them), started from refinements 2 at most to keep the test
// short (the loop adds the levels it needs).
#include <gtest/gtest.h>

#include <algorithm>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"

namespace fosls {
namespace {

using nlohmann::json;

class AccuracyExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(AccuracyExamples, ReachTenToTheMinusThree) {
  json j = testing::load_shipped_example(GetParam());
  j.erase("adaptivity");
  j.erase("load_steps");
  j["mesh"]["refinements"] = std::min(2, j["mesh"]["refinements"].get<int>());
  j["accuracy"] = {{"force", 1e-3}};
  const json r = testing::solved_case(j);
  ASSERT_TRUE(r.contains("accuracy"));
  EXPECT_TRUE(r["accuracy"]["reached"].get<bool>()) << r["accuracy"]["stop_message"];
  EXPECT_LE(r["accuracy"]["estimate"].get<double>(), 1e-3);
  for (const json& s : r["accuracy"]["steps"]) EXPECT_TRUE(s["converged"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Shipped, AccuracyExamples,
                         ::testing::Values("hertz", "hertz_accuracy", "hertz_incompressible",
                                           "hertz_adaptive", "hertz_friction", "cattaneo_mindlin",
                                           "signorini_square", "signorini_square_incompressible",
                                           "signorini_square_adaptive", "signorini_square_order2"));

}  // namespace
}  // namespace fosls
